/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "cellAspectRatio.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::cellAspectRatioMax(const fvMesh& mesh)
{
    const vectorField& faceCentres = mesh.faceCentres();
    const vectorField& faceAreas = mesh.faceAreas();
    const vectorField& cellCentres = mesh.cellCentres();

    boolList inPlane(mesh.nFaces(), true);
    for (const polyPatch& patch : mesh.boundaryMesh())
    {
        if (isA<emptyPolyPatch>(patch) || isA<wedgePolyPatch>(patch))
        {
            SubList<bool>(inPlane, patch.size(), patch.start()) = false;
        }
    }

    scalarField nearest(mesh.nCells(), GREAT);
    scalarField farthest(mesh.nCells(), Zero);
    const auto measure = [&](const label celli, const label facei)
    {
        const scalar distance =
            mag((faceCentres[facei] - cellCentres[celli]) & faceAreas[facei])
           /mag(faceAreas[facei]);
        nearest[celli] = min(nearest[celli], distance);
        farthest[celli] = max(farthest[celli], distance);
    };

    const labelUList& owner = mesh.faceOwner();
    const labelUList& neighbour = mesh.faceNeighbour();
    forAll(owner, facei)
    {
        if (inPlane[facei])
        {
            measure(owner[facei], facei);
            if (facei < mesh.nInternalFaces())
            {
                measure(neighbour[facei], facei);
            }
        }
    }

    scalar largest = 1;
    forAll(nearest, celli)
    {
        if (nearest[celli] > VSMALL && nearest[celli] < GREAT)
        {
            largest = max(largest, farthest[celli]/nearest[celli]);
        }
    }

    return returnReduce(largest, maxOp<scalar>());
}


// ************************************************************************* //
