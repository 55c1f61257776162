/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "patches.H"
#include "polyMesh.H"
#include "wallPolyPatch.H"
#include "wordRe.H"
#include "Map.H"
#include "mergePoints.H"
#include "ListListOps.H"
#include "PstreamReduceOps.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace contactWalls
{
    defineTypeNameAndDebug(patches, 0);
    addToRunTimeSelectionTable(contactWall, patches, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactWalls::patches::patches
(
    const dictionary& dict,
    const polyMesh& mesh
)
:
    surface(dict, true)
{
    const polyBoundaryMesh& bm = mesh.boundaryMesh();

    labelList patchIDs;
    if (dict.found("patches"))
    {
        const wordReList names(dict.get<wordReList>("patches"));
        patchIDs = bm.patchSet(names, false).sortedToc();
        if (patchIDs.empty())
        {
            FatalIOErrorInFunction(dict)
                << "Wall " << name() << ": no patch matches "
                << flatOutput(names) << ". Patches: "
                << flatOutput(bm.names()) << exit(FatalIOError);
        }
    }
    else
    {
        patchIDs = bm.findPatchIDs<wallPolyPatch>().sortedToc();
    }

    // Local triangles with their points, then gathered everywhere
    const pointField& meshPoints = mesh.points();
    DynamicList<point> points;
    DynamicList<labelledTri> tris;
    Map<label> pointIndex;
    auto index = [&](const label meshPointi)
    {
        auto iter = pointIndex.cfind(meshPointi);
        if (iter.found())
        {
            return *iter;
        }
        pointIndex.insert(meshPointi, points.size());
        points.append(meshPoints[meshPointi]);
        return points.size() - 1;
    };
    for (const label patchi : patchIDs)
    {
        for (const face& f : bm[patchi])
        {
            for (label k = 1; k + 1 < f.size(); ++k)
            {
                tris.append
                (
                    labelledTri(index(f[0]), index(f[k]), index(f[k + 1]), 0)
                );
            }
        }
    }

    List<pointField> allPoints(Pstream::nProcs());
    List<List<labelledTri>> allTris(Pstream::nProcs());
    allPoints[Pstream::myProcNo()] = points;
    allTris[Pstream::myProcNo()] = tris;
    Pstream::gatherList(allPoints);
    Pstream::gatherList(allTris);
    Pstream::scatterList(allPoints);
    Pstream::scatterList(allTris);

    // Processors share the points on their boundaries: merge by position
    pointField gathered
    (
        ListListOps::combine<pointField>(allPoints, accessOp<pointField>())
    );
    labelList offsets(allPoints.size() + 1, 0);
    forAll(allPoints, proci)
    {
        offsets[proci + 1] = offsets[proci] + allPoints[proci].size();
    }
    labelList pointMap;
    const label nUnique = mergePoints
    (
        gathered,
        1e-9*mag(mesh.bounds().span()),
        false,
        pointMap
    );
    pointField mergedPoints(nUnique);
    forAll(gathered, pointi)
    {
        mergedPoints[pointMap[pointi]] = gathered[pointi];
    }
    DynamicList<labelledTri> mergedTris;
    forAll(allTris, proci)
    {
        const label offset = offsets[proci];
        for (const labelledTri& t : allTris[proci])
        {
            mergedTris.append
            (
                labelledTri
                (
                    pointMap[offset + t[0]],
                    pointMap[offset + t[1]],
                    pointMap[offset + t[2]],
                    0
                )
            );
        }
    }

    setSurface
    (
        autoPtr<triSurface>::New
        (
            List<labelledTri>(mergedTris),
            mergedPoints
        )
    );
    Info<< "Contact wall " << name() << ": " << triangles().size()
        << " triangles of patches "
        << flatOutput(UIndirectList<word>(bm.names(), patchIDs)) << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::contactWalls::patches::typeKeywords()
{
    // The mesh's patches, not a surface file
    wordList words(contactWall::typeKeywords());
    words.append("patches");
    return words;
}


Foam::wordList Foam::contactWalls::patches::keywords() const
{
    return typeKeywords();
}


// ************************************************************************* //
