/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "surfaceFields.H"
#include "emptyPolyPatch.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
void Foam::dlmRefineFvMesh::mapNewInternalPlanarFaces(const labelList& faceMap)
{
    typedef GeometricField<Type, fvsPatchField, surfaceMesh> FieldType;

    const labelUList& own = faceOwner();
    const labelUList& nei = faceNeighbour();
    const cellList& cells = this->cells();
    const vectorField& areas = faceAreas();

    // The faces whose values count: mapped, not on an empty patch (whose
    // fields hold no values)
    bitSet counted(nFaces());
    forAll(faceMap, facei)
    {
        counted.set(facei, faceMap[facei] >= 0);
    }
    for (const polyPatch& patch : boundaryMesh())
    {
        if (isA<emptyPolyPatch>(patch))
        {
            counted.unset(labelRange(patch.start(), patch.size()));
        }
    }

    HashTable<FieldType*> fields(lookupClass<FieldType>());
    forAllIters(fields, iter)
    {
        FieldType& field = *iter();
        const bool oriented = field.oriented()();
        if (oriented && pTraits<Type>::nComponents != 1)
        {
            // Oriented fields are fluxes, scalars
            continue;
        }

        // Every face's value (oriented: per unit area, along the normal)
        Field<Type> faceValue(nFaces(), Zero);
        SubField<Type>(faceValue, nInternalFaces()) = field.primitiveField();
        forAll(field.boundaryField(), patchi)
        {
            const fvsPatchField<Type>& patchField = field.boundaryField()[patchi];
            SubField<Type>(faceValue, patchField.size(), patchField.patch().start())
                = patchField;
        }

        for (label facei = 0; facei < nInternalFaces(); ++facei)
        {
            if (faceMap[facei] >= 0)
            {
                continue;
            }
            Type sum(Zero);
            vector normalSum(Zero);
            label n = 0;
            for (const label celli : {own[facei], nei[facei]})
            {
                for (const label facej : cells[celli])
                {
                    if (counted.test(facej))
                    {
                        if (oriented)
                        {
                            normalSum +=
                                component(faceValue[facej], 0)
                               *areas[facej]/magSqr(areas[facej]);
                        }
                        else
                        {
                            sum += faceValue[facej];
                        }
                        ++n;
                    }
                }
            }
            if (n > 0)
            {
                field[facei] =
                    oriented
                  ? pTraits<Type>::one*((normalSum/n) & areas[facei])
                  : sum/n;
            }
        }
    }
}


// ************************************************************************* //
