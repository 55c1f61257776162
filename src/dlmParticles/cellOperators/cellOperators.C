/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "cellOperators.H"
#include "emptyFvPatch.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cellOperators::cellOperators(const fvMesh& mesh)
:
    mesh_(mesh),
    faceStarts_(1, 0)
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::PtrList<Foam::vectorField> Foam::cellOperators::neighbourValues
(
    const volVectorField& vf
) const
{
    PtrList<vectorField> values(vf.boundaryField().size());
    forAll(values, patchi)
    {
        if (vf.boundaryField()[patchi].coupled())
        {
            values.set
            (
                patchi,
                vf.boundaryField()[patchi].patchNeighbourField().ptr()
            );
        }
    }
    return values;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::cellOperators::setCells(const labelUList& cells)
{
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    cells_ = cells;
    faceStarts_.setSize(cells.size() + 1);
    DynamicList<label> faces(6*cells.size());
    DynamicList<label> facePatches(6*cells.size());
    DynamicList<label> patchFaces(6*cells.size());
    labelList cellFaces;
    faceStarts_[0] = 0;
    forAll(cells, c)
    {
        cellFaces = mesh_.cells()[cells[c]];
        sort(cellFaces);
        for (const label facei : cellFaces)
        {
            label patchi = -1;
            label patchFacei = facei;
            if (!mesh_.isInternalFace(facei))
            {
                patchi = patches.whichPatch(facei);
                if (isA<emptyFvPatch>(mesh_.boundary()[patchi]))
                {
                    continue;
                }
                patchFacei = facei - patches[patchi].start();
            }
            faces.append(facei);
            facePatches.append(patchi);
            patchFaces.append(patchFacei);
        }
        faceStarts_[c + 1] = faces.size();
    }
    faces_.transfer(faces);
    facePatches_.transfer(facePatches);
    patchFaces_.transfer(patchFaces);
}


Foam::tmp<Foam::tensorField> Foam::cellOperators::grad
(
    const volVectorField& vf
) const
{
    tmp<tensorField> tgradVf(new tensorField(cells_.size()));
    tensorField& gradVf = tgradVf.ref();

    const PtrList<vectorField> across(neighbourValues(vf));
    const labelUList& owner = mesh_.owner();
    const labelUList& neighbour = mesh_.neighbour();
    const surfaceVectorField& Sf = mesh_.Sf();
    const surfaceScalarField& w = mesh_.weights();
    const vectorField& v = vf.primitiveField();

    forAll(cells_, c)
    {
        const label celli = cells_[c];
        tensor g(Zero);
        for (label k = faceStarts_[c]; k < faceStarts_[c + 1]; ++k)
        {
            const label facei = faces_[k];
            const label patchi = facePatches_[k];
            if (patchi < 0)
            {
                // surfaceInterpolationScheme::dotInterpolate with 'linear'
                const vector vFace
                (
                    w[facei]*(v[owner[facei]] - v[neighbour[facei]])
                  + v[neighbour[facei]]
                );
                const tensor SfvFace(Sf[facei]*vFace);
                if (owner[facei] == celli)
                {
                    g += SfvFace;
                }
                else
                {
                    g -= SfvFace;
                }
                continue;
            }
            const label i = patchFaces_[k];
            const fvPatchVectorField& pvf = vf.boundaryField()[patchi];
            const scalar pw = w.boundaryField()[patchi][i];
            const vector vFace
            (
                pvf.coupled()
              ? pw*v[celli] + (1.0 - pw)*across[patchi][i]
              : pvf[i]
            );
            g += Sf.boundaryField()[patchi][i]*vFace;
        }
        gradVf[c] = g/mesh_.V()[celli];
    }
    return tgradVf;
}


Foam::tmp<Foam::vectorField> Foam::cellOperators::product
(
    const fvMatrix<vector>& M,
    const scalarField& rate,
    const volVectorField& vf
) const
{
    tmp<vectorField> tMVf(new vectorField(cells_.size()));
    vectorField& MVf = tMVf.ref();

    const PtrList<vectorField> across(neighbourValues(vf));
    const labelUList& owner = M.lduAddr().lowerAddr();
    const labelUList& neighbour = M.lduAddr().upperAddr();
    const vectorField& v = vf.primitiveField();
    const scalarField& diag = M.diag();
    const bool offDiagonal = M.hasUpper();
    const scalarField& upper = offDiagonal ? M.upper() : diag;
    const scalarField& lower = M.hasLower() ? M.lower() : upper;
    const scalarField& V = mesh_.V();

    forAll(cells_, c)
    {
        const label celli = cells_[c];
        vector sum(diag[celli]*v[celli] + (rate[celli]*V[celli])*v[celli]);

        // The internal faces, then each patch's internal coefficients and,
        // if it is coupled, its coupling to the values across it
        label k = faceStarts_[c];
        const label end = faceStarts_[c + 1];
        for (; k < end && facePatches_[k] < 0; ++k)
        {
            const label facei = faces_[k];
            if (!offDiagonal)
            {
                continue;
            }
            if (owner[facei] == celli)
            {
                sum += upper[facei]*v[neighbour[facei]];
            }
            else
            {
                sum += lower[facei]*v[owner[facei]];
            }
        }
        while (k < end)
        {
            const label patchi = facePatches_[k];
            label patchEnd = k;
            while (patchEnd < end && facePatches_[patchEnd] == patchi)
            {
                ++patchEnd;
            }
            const vectorField& internal = M.internalCoeffs()[patchi];
            for (label j = k; j < patchEnd; ++j)
            {
                sum += cmptMultiply(internal[patchFaces_[j]], v[celli]);
            }
            if (vf.boundaryField()[patchi].coupled())
            {
                const vectorField& coupling = M.boundaryCoeffs()[patchi];
                for (label j = k; j < patchEnd; ++j)
                {
                    const label i = patchFaces_[j];
                    sum -= cmptMultiply(coupling[i], across[patchi][i]);
                }
            }
            k = patchEnd;
        }
        MVf[c] = sum/V[celli];
    }
    return tMVf;
}


// ************************************************************************* //
