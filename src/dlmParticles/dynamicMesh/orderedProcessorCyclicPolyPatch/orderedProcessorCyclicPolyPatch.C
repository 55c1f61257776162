/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "orderedProcessorCyclicPolyPatch.H"
#include "fvMesh.H"
#include "matchPoints.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::orderedProcessorCyclicPolyPatch::orderedProcessorCyclicPolyPatch
(
    const processorCyclicPolyPatch& pp,
    const polyBoundaryMesh& bm
)
:
    processorCyclicPolyPatch(pp, bm)
{}


Foam::orderedProcessorCyclicPolyPatch::orderedProcessorCyclicPolyPatch
(
    const processorCyclicPolyPatch& pp,
    const polyBoundaryMesh& bm,
    const label index,
    const label newSize,
    const label newStart
)
:
    processorCyclicPolyPatch(pp, bm, index, newSize, newStart)
{}


Foam::orderedProcessorCyclicPolyPatch::orderedProcessorCyclicPolyPatch
(
    const processorCyclicPolyPatch& pp,
    const polyBoundaryMesh& bm,
    const label index,
    const labelUList& mapAddressing,
    const label newStart
)
:
    processorCyclicPolyPatch(pp, bm, index, mapAddressing, newStart)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::orderedProcessorCyclicPolyPatch::order
(
    PstreamBuffers& pBufs,
    const primitivePatch& pp,
    labelList& faceMap,
    labelList& rotation
) const
{
    if
    (
        !Pstream::parRun()
     || owner()
     || !parallel()
     || transform() == NOORDERING
     || transform() == COINCIDENTFULLMATCH
    )
    {
        return processorCyclicPolyPatch::order(pBufs, pp, faceMap, rotation);
    }

    // What the owner's initOrder sent: its face centres, normals, the
    // anchor (first) points and the averages of the faces' points
    vectorField masterCentres;
    vectorField masterNormals;
    pointField masterAnchors;
    pointField masterPointAverages;
    {
        UIPstream fromNeighbour(neighbProcNo(), pBufs);
        fromNeighbour
            >> masterCentres >> masterNormals >> masterAnchors
            >> masterPointAverages;
    }
    transformPosition(masterCentres);
    transformPosition(masterAnchors);

    faceMap.setSize(pp.size());
    faceMap = -1;
    rotation.setSize(pp.size());
    rotation = 0;

    const scalarField tols
    (
        matchTolerance()*calcFaceTol(pp, pp.points(), pp.faceCentres())
    );

    if
    (
        masterCentres.size() != pp.size()
     || !matchPoints
        (
            pp.faceCentres(),
            masterCentres,
            pp.faceNormals(),
            masterNormals,
            tols,
            false,
            faceMap
        )
    )
    {
        FatalErrorInFunction
            << "Patch " << name() << ": after a change of the mesh, "
            << pp.size() << " faces here do not match the "
            << masterCentres.size() << " of processor " << neighbProcNo()
            << " across the cyclic patch " << referPatch().name()
            << exit(FatalError);
    }

    bool change = false;
    forAll(faceMap, oldFacei)
    {
        const label newFacei = faceMap[oldFacei];
        rotation[newFacei] = getRotation
        (
            pp.points(),
            pp[oldFacei],
            masterAnchors[newFacei],
            tols[oldFacei]
        );
        if (rotation[newFacei] == -1)
        {
            FatalErrorInFunction
                << "Patch " << name() << ": no point of face " << oldFacei
                << " at " << pp.faceCentres()[oldFacei]
                << " matches the first point of its face on processor "
                << neighbProcNo() << exit(FatalError);
        }
        change = change || newFacei != oldFacei || rotation[newFacei] != 0;
    }
    return change;
}


void Foam::orderedProcessorCyclicPolyPatch::replacePatches(fvMesh& mesh)
{
    const polyBoundaryMesh& patches = mesh.boundaryMesh();

    bool found = false;
    for (const polyPatch& patch : patches)
    {
        found = found || isA<processorCyclicPolyPatch>(patch);
    }
    // Every processor rebuilds its boundary (a collective operation)
    if (!returnReduce(found, orOp<bool>()))
    {
        return;
    }

    PtrList<polyPatch> newPatches(patches.size());
    forAll(patches, patchi)
    {
        if (isA<processorCyclicPolyPatch>(patches[patchi]))
        {
            newPatches.set
            (
                patchi,
                new orderedProcessorCyclicPolyPatch
                (
                    refCast<const processorCyclicPolyPatch>(patches[patchi]),
                    patches
                )
            );
        }
        else
        {
            newPatches.set(patchi, patches[patchi].clone(patches));
        }
    }
    mesh.removeFvBoundary();
    mesh.addFvPatches(newPatches);
}


// ************************************************************************* //
