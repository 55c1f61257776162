/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "planarRefinement.H"
#include "polyMesh.H"
#include "polyTopoChange.H"
#include "mapPolyMesh.H"
#include "emptyPolyPatch.H"
#include "syncTools.H"
#include "globalIndex.H"
#include "HashSet.H"
#include "DynamicField.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(planarRefinement, 0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::planarRefinement::front(const label pointi) const
{
    return mesh_.points()[pointi][normal_] < midPlane_;
}


bool Foam::planarRefinement::onPlane(const label facei) const
{
    if (mesh_.isInternalFace(facei))
    {
        return false;
    }
    const label patchi = mesh_.boundaryMesh().whichPatch(facei);
    return isA<emptyPolyPatch>(mesh_.boundaryMesh()[patchi]);
}


Foam::labelList Foam::planarRefinement::partners() const
{
    // From the side faces' edges across the thickness (the mesh's edge
    // list, built for this alone, took 15 % of a change)
    labelList partner(mesh_.nPoints(), -1);
    const faceList& faces = mesh_.faces();
    forAll(faces, facei)
    {
        if (onPlane(facei))
        {
            continue;
        }
        const face& f = faces[facei];
        forAll(f, i)
        {
            const label a = f[i];
            const label b = f.nextLabel(i);
            if (front(a) != front(b))
            {
                partner[a] = b;
                partner[b] = a;
            }
        }
    }
    return partner;
}


void Foam::planarRefinement::planeFaces
(
    const label celli,
    label& frontFace,
    label& backFace
) const
{
    frontFace = -1;
    backFace = -1;
    for (const label facei : mesh_.cells()[celli])
    {
        if (onPlane(facei))
        {
            if (front(mesh_.faces()[facei][0]))
            {
                frontFace = facei;
            }
            else
            {
                backFace = facei;
            }
        }
    }
    if (frontFace < 0 || backFace < 0)
    {
        FatalErrorInFunction
            << "Cell " << celli << " at " << mesh_.cellCentres()[celli]
            << " has no face on the front or back empty patch: the mesh is"
            << " not one cell thick" << exit(FatalError);
    }
}


Foam::FixedList<Foam::label, 4> Foam::planarRefinement::corners
(
    const face& f,
    const label level
) const
{
    FixedList<label, 4> position(-1);
    label n = 0;
    forAll(f, i)
    {
        if (pointLevel_[f[i]] <= level)
        {
            if (n == 4)
            {
                n = 5;
                break;
            }
            position[n++] = i;
        }
    }
    if (n != 4)
    {
        FatalErrorInFunction
            << "A cell of level " << level << " with front face "
            << f.points(mesh_.points()) << " has not 4 corners: in-plane"
            << " refinement needs a 2D mesh of hexahedra" << exit(FatalError);
    }
    return position;
}


Foam::label Foam::planarRefinement::frontEdgeStart(const face& f) const
{
    if (f.size() == 4)
    {
        forAll(f, i)
        {
            if (front(f[i]) && front(f.nextLabel(i)))
            {
                return i;
            }
        }
    }
    FatalErrorInFunction
        << "Side face " << f.points(mesh_.points()) << " is not a quad"
        << " between the front and back planes: in-plane refinement needs"
        << " a 2D mesh of hexahedra" << exit(FatalError);
    return -1;
}


void Foam::planarRefinement::setFace
(
    polyTopoChange& meshMod,
    const face& f,
    const label facei,
    label own,
    label nei,
    const label masterFacei,
    const label patchi,
    const label zonei,
    const bool zoneFlip
) const
{
    face newFace(f);
    bool flip = false;
    if (nei >= 0 && nei < own)
    {
        newFace = f.reverseFace();
        std::swap(own, nei);
        flip = true;
    }
    const bool newZoneFlip = (zonei >= 0 && (zoneFlip != flip));
    if (facei < 0)
    {
        meshMod.addFace
        (
            newFace, own, nei, -1, -1, masterFacei, flip, patchi, zonei,
            newZoneFlip
        );
    }
    else
    {
        meshMod.modifyFace
        (
            newFace, facei, own, nei, flip, patchi, zonei, newZoneFlip
        );
    }
}


void Foam::planarRefinement::zoneOf
(
    const label facei,
    label& zonei,
    bool& zoneFlip
) const
{
    zonei = mesh_.faceZones().whichZone(facei);
    zoneFlip = false;
    if (zonei >= 0)
    {
        const faceZone& zone = mesh_.faceZones()[zonei];
        zoneFlip = zone.flipMap()[zone.whichFace(facei)];
    }
}


void Foam::planarRefinement::mapLevels
(
    const labelList& reverseMap,
    const labelList& forwardMap,
    const label nNew,
    DynamicList<label>& pending,
    labelList& level
)
{
    labelList newLevel(nNew, Zero);
    if (pending.size() == reverseMap.size())
    {
        // After setRefinement or setUnrefinement: the levels set there,
        // renumbered
        forAll(reverseMap, oldi)
        {
            if (reverseMap[oldi] >= 0)
            {
                newLevel[reverseMap[oldi]] = pending[oldi];
            }
        }
    }
    else
    {
        forAll(forwardMap, newi)
        {
            if (forwardMap[newi] >= 0)
            {
                newLevel[newi] = level[forwardMap[newi]];
            }
        }
    }
    level.transfer(newLevel);
    pending.clear();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::planarRefinement::planarRefinement(const polyMesh& mesh)
:
    mesh_(mesh),
    cellLevel_
    (
        IOobject
        (
            "cellLevel",
            mesh.facesInstance(),
            polyMesh::meshSubDir,
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE
        ),
        labelList(mesh.nCells(), Zero)
    ),
    pointLevel_
    (
        IOobject
        (
            "pointLevel",
            mesh.facesInstance(),
            polyMesh::meshSubDir,
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE
        ),
        labelList(mesh.nPoints(), Zero)
    ),
    normal_(0),
    midPlane_(0)
{
    const Vector<label>& solutionD = mesh.solutionD();
    label nEmpty = 0;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (solutionD[d] < 0)
        {
            normal_ = d;
            ++nEmpty;
        }
    }
    if (nEmpty != 1)
    {
        FatalErrorInFunction
            << "In-plane refinement needs a 2D mesh (one empty direction);"
            << " this mesh has " << nEmpty << exit(FatalError);
    }
    const scalarField coordinate(mesh.points().component(normal_));
    midPlane_ = 0.5*(gMin(coordinate) + gMax(coordinate));

    if
    (
        cellLevel_.size() != mesh.nCells()
     || pointLevel_.size() != mesh.nPoints()
    )
    {
        FatalErrorInFunction
            << cellLevel_.objectPath() << " (" << cellLevel_.size()
            << " values) and " << pointLevel_.objectPath() << " ("
            << pointLevel_.size() << ") do not fit the mesh's "
            << mesh.nCells() << " cells and " << mesh.nPoints() << " points"
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::bitSet Foam::planarRefinement::consistentRefinement
(
    const bitSet& refineCell
) const
{
    bitSet refine(refineCell);
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    const label nInternal = mesh_.nInternalFaces();

    while (true)
    {
        labelList newLevel(cellLevel_);
        for (const label celli : refine)
        {
            ++newLevel[celli];
        }
        labelList neiNewLevel;
        syncTools::swapBoundaryCellList(mesh_, newLevel, neiNewLevel);

        label nAdded = 0;
        for (label facei = 0; facei < nInternal; ++facei)
        {
            const label ownLevel = newLevel[own[facei]];
            const label neiLevel = newLevel[nei[facei]];
            if (ownLevel > neiLevel + 1 && !refine.test(nei[facei]))
            {
                refine.set(nei[facei]);
                ++nAdded;
            }
            else if (neiLevel > ownLevel + 1 && !refine.test(own[facei]))
            {
                refine.set(own[facei]);
                ++nAdded;
            }
        }
        forAll(neiNewLevel, bFacei)
        {
            const label celli = own[nInternal + bFacei];
            if
            (
                neiNewLevel[bFacei] > newLevel[celli] + 1
             && !refine.test(celli)
            )
            {
                refine.set(celli);
                ++nAdded;
            }
        }
        if (returnReduce(nAdded, sumOp<label>()) == 0)
        {
            return refine;
        }
    }
}


Foam::labelList Foam::planarRefinement::splitPoints() const
{
    const labelListList& pointCells = mesh_.pointCells();
    const labelListList& pointFaces = mesh_.pointFaces();
    const faceList& faces = mesh_.faces();

    DynamicList<label> split;
    forAll(pointCells, pointi)
    {
        const label level = pointLevel_[pointi];
        const labelList& pCells = pointCells[pointi];
        if (level == 0 || pCells.size() != 4 || !front(pointi))
        {
            continue;
        }

        bool centre = true;
        for (const label facei : pointFaces[pointi])
        {
            if (!mesh_.isInternalFace(facei) && !onPlane(facei))
            {
                centre = false;
            }
        }
        for (const label celli : pCells)
        {
            if (!centre || cellLevel_[celli] != level)
            {
                centre = false;
                break;
            }
            label frontFace, backFace;
            planeFaces(celli, frontFace, backFace);
            const face& f = faces[frontFace];
            const FixedList<label, 4> corner(corners(f, level));
            const label position = f.find(pointi);
            label k = 0;
            while (k < 4 && corner[k] != position)
            {
                ++k;
            }
            if (k == 4 || pointLevel_[f[corner[(k + 2) % 4]]] >= level)
            {
                centre = false;
            }
        }
        if (centre)
        {
            split.append(pointi);
        }
    }
    return labelList(std::move(split));
}


Foam::labelList Foam::planarRefinement::consistentUnrefinement
(
    const labelList& splitPoints
) const
{
    // A merged cell must not border a cell two levels finer: cancel those
    // with a neighbour finer than their cells
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    const label nInternal = mesh_.nInternalFaces();
    labelList neiLevel;
    syncTools::swapBoundaryCellList(mesh_, cellLevel_, neiLevel);

    DynamicList<label> consistent(splitPoints.size());
    for (const label pointi : splitPoints)
    {
        bool ok = true;
        for (const label celli : mesh_.pointCells()[pointi])
        {
            for (const label facei : mesh_.cells()[celli])
            {
                label level = -1;
                if (facei < nInternal)
                {
                    const label other =
                        (own[facei] == celli ? nei[facei] : own[facei]);
                    level = cellLevel_[other];
                }
                else if (!onPlane(facei))
                {
                    level = neiLevel[facei - nInternal];
                }
                if (level > cellLevel_[celli])
                {
                    ok = false;
                }
            }
        }
        if (ok)
        {
            consistent.append(pointi);
        }
    }
    return labelList(std::move(consistent));
}


void Foam::planarRefinement::setRefinement
(
    const label level,
    const labelList& cellsToRefine,
    polyTopoChange& meshMod
)
{
    const pointField& points = mesh_.points();
    const faceList& faces = mesh_.faces();
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    const label nInternal = mesh_.nInternalFaces();
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    const labelList partner(partners());

    newCellLevel_ = cellLevel_;
    newPointLevel_ = pointLevel_;

    bitSet refineCell(mesh_.nCells(), cellsToRefine);
    boolList refineFlag(mesh_.nCells(), false);
    for (const label celli : cellsToRefine)
    {
        refineFlag[celli] = true;
        if (cellLevel_[celli] != level)
        {
            FatalErrorInFunction
                << "Cell " << celli << " of level " << cellLevel_[celli]
                << " refined with the cells of level " << level
                << abort(FatalError);
        }
    }
    boolList neiRefine;
    syncTools::swapBoundaryCellList(mesh_, refineFlag, neiRefine);

    // New points: their positions, and each one's partner across the
    // thickness
    DynamicField<point> newPoints;
    Map<label> newPartner;
    auto addPoint = [&](const point& p, const label masterPointi)
    {
        const label pointi = meshMod.addPoint(p, masterPointi, -1, true);
        newPointLevel_(pointi) = level + 1;
        newPoints(pointi - mesh_.nPoints()) = p;
        return pointi;
    };
    auto position = [&](const label pointi) -> const point&
    {
        return
            pointi < mesh_.nPoints()
          ? points[pointi]
          : newPoints[pointi - mesh_.nPoints()];
    };
    auto partnerOf = [&](const label pointi)
    {
        return pointi < mesh_.nPoints() ? partner[pointi] : newPartner[pointi];
    };

    // The side faces that a refined cell touches; those between two corners
    // of the refined level are split at their middle
    DynamicList<label> sideFaces;
    Map<label> faceMidPoint;
    forAll(faces, facei)
    {
        if (onPlane(facei))
        {
            continue;
        }
        const bool touched =
            refineCell.test(own[facei])
         || (facei < nInternal && refineCell.test(nei[facei]))
         || (
                facei >= nInternal
             && patches[patches.whichPatch(facei)].coupled()
             && neiRefine[facei - nInternal]
            );
        if (!touched)
        {
            continue;
        }
        sideFaces.append(facei);

        const face& f = faces[facei];
        const label i = frontEdgeStart(f);
        const label a = f[i];
        const label b = f.nextLabel(i);
        if (pointLevel_[a] <= level && pointLevel_[b] <= level)
        {
            const label midFront =
                addPoint(0.5*(points[a] + points[b]), a);
            const label midBack =
                addPoint
                (
                    0.5*(points[partner[a]] + points[partner[b]]),
                    partner[a]
                );
            newPartner.insert(midFront, midBack);
            newPartner.insert(midBack, midFront);
            faceMidPoint.insert(facei, midFront);
        }
    }

    // Each refined cell: its 4 corners, the middles of its 4 sides and its
    // centre (front points), and its 4 children (the first the cell)
    List<FixedList<label, 4>> cellCorners(cellsToRefine.size());
    List<FixedList<label, 4>> cellMids(cellsToRefine.size());
    List<FixedList<label, 4>> cellChildren(cellsToRefine.size());
    labelList cellCentre(cellsToRefine.size());
    Map<label> refineIndex(2*cellsToRefine.size());

    forAll(cellsToRefine, index)
    {
        const label celli = cellsToRefine[index];
        refineIndex.insert(celli, index);
        label frontFace, backFace;
        planeFaces(celli, frontFace, backFace);
        const face& f = faces[frontFace];
        const FixedList<label, 4> corner(corners(f, level));

        FixedList<label, 4>& c = cellCorners[index];
        FixedList<label, 4>& m = cellMids[index];
        point frontCentre(Zero);
        point backCentre(Zero);
        for (label k = 0; k < 4; ++k)
        {
            c[k] = f[corner[k]];
            frontCentre += 0.25*points[c[k]];
            backCentre += 0.25*points[partner[c[k]]];
        }
        for (label k = 0; k < 4; ++k)
        {
            const label next = corner[(k + 1) % 4];
            if (f.fcIndex(corner[k]) != next)
            {
                // A hanging point: the cell across is finer
                m[k] = f[f.fcIndex(corner[k])];
                continue;
            }
            m[k] = -1;
            for (const label facei : mesh_.cells()[celli])
            {
                const face& side = faces[facei];
                if
                (
                    faceMidPoint.found(facei)
                 && side.found(c[k])
                 && side.found(c[(k + 1) % 4])
                )
                {
                    m[k] = faceMidPoint[facei];
                }
            }
            if (m[k] < 0)
            {
                FatalErrorInFunction
                    << "No side face of cell " << celli << " between "
                    << points[c[k]] << " and " << points[c[(k + 1) % 4]]
                    << abort(FatalError);
            }
        }

        cellCentre[index] = addPoint(frontCentre, c[0]);
        const label centreBack = addPoint(backCentre, partner[c[0]]);
        newPartner.insert(cellCentre[index], centreBack);
        newPartner.insert(centreBack, cellCentre[index]);

        const label zonei = mesh_.cellZones().whichZone(celli);
        cellChildren[index][0] = celli;
        newCellLevel_[celli] = level + 1;
        for (label k = 1; k < 4; ++k)
        {
            const label childi = meshMod.addCell(-1, -1, -1, celli, zonei);
            newCellLevel_(childi) = level + 1;
            cellChildren[index][k] = childi;
        }

        // Front and back faces of the children, as the cell's are oriented
        FixedList<face, 4> childFront;
        for (label k = 0; k < 4; ++k)
        {
            childFront[k] =
                face
                ({
                    m[(k + 3) % 4], c[k], m[k], cellCentre[index]
                });
        }
        for (const label planeFacei : {frontFace, backFace})
        {
            label zonei;
            bool zoneFlip;
            zoneOf(planeFacei, zonei, zoneFlip);
            const label patchi = patches.whichPatch(planeFacei);
            for (label k = 0; k < 4; ++k)
            {
                face childFace(childFront[k]);
                if (planeFacei == backFace)
                {
                    forAll(childFace, j)
                    {
                        childFace[j] = partnerOf(childFace[j]);
                    }
                    childFace = childFace.reverseFace();
                }
                setFace
                (
                    meshMod,
                    childFace,
                    (k == 0 ? planeFacei : -1),
                    cellChildren[index][k],
                    -1,
                    planeFacei,
                    patchi,
                    zonei,
                    zoneFlip
                );
            }
        }

        // Faces between the children, pointing from child k to child k + 1
        for (label k = 0; k < 4; ++k)
        {
            const label centre = cellCentre[index];
            const face inner
            ({
                m[k], centre, partnerOf(centre), partnerOf(m[k])
            });
            const vector area =
                (position(inner[2]) - position(inner[0]))
              ^ (position(inner[3]) - position(inner[1]));
            const point& corner = position(c[k]);
            const point& nextCorner = position(c[(k + 1) % 4]);
            const face oriented
            (
                (area & (nextCorner - corner)) > 0 ? inner : inner.reverseFace()
            );
            setFace
            (
                meshMod,
                oriented,
                -1,
                cellChildren[index][k],
                cellChildren[index][(k + 1) % 4],
                -1,
                -1,
                -1,
                false
            );
        }
    }

    // The child of a refined cell whose side holds the front segment a-b
    // (the cell itself if not refined)
    auto childOf = [&](const label celli, const label a, const label b)
    {
        const auto iter = refineIndex.cfind(celli);
        if (!iter.found())
        {
            return celli;
        }
        const FixedList<label, 4>& c = cellCorners[iter.val()];
        const FixedList<label, 4>& m = cellMids[iter.val()];
        for (label k = 0; k < 4; ++k)
        {
            if ((a == c[k] && b == m[k]) || (b == c[k] && a == m[k]))
            {
                return cellChildren[iter.val()][k];
            }
            const label next = (k + 1) % 4;
            if ((a == m[k] && b == c[next]) || (b == m[k] && a == c[next]))
            {
                return cellChildren[iter.val()][next];
            }
        }
        FatalErrorInFunction
            << "Segment " << position(a) << " " << position(b)
            << " is not on a side of cell " << celli << abort(FatalError);
        return label(-1);
    };

    // Side faces: split, or given to the child they bound; the unrefined
    // cells beside a split face get its middle in their front and back
    HashTable<DynamicList<FixedList<label, 3>>, label, Hash<label>>
        hangingPoints;
    for (const label facei : sideFaces)
    {
        const face& f = faces[facei];
        const label i = frontEdgeStart(f);
        const label a = f[i];
        const label b = f.nextLabel(i);
        const label patchi =
            facei < nInternal ? -1 : patches.whichPatch(facei);
        label zonei;
        bool zoneFlip;
        zoneOf(facei, zonei, zoneFlip);
        const label owner = own[facei];
        const label neighbour = facei < nInternal ? nei[facei] : -1;

        const auto midIter = faceMidPoint.cfind(facei);
        if (!midIter.found())
        {
            setFace
            (
                meshMod, f, facei,
                childOf(owner, a, b),
                neighbour < 0 ? -1 : childOf(neighbour, a, b),
                -1, patchi, zonei, zoneFlip
            );
            continue;
        }

        const label mid = midIter.val();
        const face half0({a, mid, partnerOf(mid), f[(i + 3) % 4]});
        const face half1({mid, b, f[(i + 2) % 4], partnerOf(mid)});
        setFace
        (
            meshMod, half0, facei,
            childOf(owner, a, mid),
            neighbour < 0 ? -1 : childOf(neighbour, a, mid),
            -1, patchi, zonei, zoneFlip
        );
        setFace
        (
            meshMod, half1, -1,
            childOf(owner, mid, b),
            neighbour < 0 ? -1 : childOf(neighbour, mid, b),
            facei, patchi, zonei, zoneFlip
        );

        for (const label celli : {owner, neighbour})
        {
            if (celli >= 0 && !refineCell.test(celli))
            {
                label frontFace, backFace;
                planeFaces(celli, frontFace, backFace);
                hangingPoints(frontFace).append(FixedList<label, 3>({a, b, mid}));
                hangingPoints(backFace).append
                (
                    FixedList<label, 3>({partner[a], partner[b], partnerOf(mid)})
                );
            }
        }
    }

    forAllConstIters(hangingPoints, iter)
    {
        const label facei = iter.key();
        const face& f = faces[facei];
        DynamicList<label> points(f.size() + iter.val().size());
        forAll(f, i)
        {
            points.append(f[i]);
            for (const FixedList<label, 3>& hanging : iter.val())
            {
                const label next = f.nextLabel(i);
                if
                (
                    (f[i] == hanging[0] && next == hanging[1])
                 || (f[i] == hanging[1] && next == hanging[0])
                )
                {
                    points.append(hanging[2]);
                }
            }
        }
        label zonei;
        bool zoneFlip;
        zoneOf(facei, zonei, zoneFlip);
        meshMod.modifyFace
        (
            face(points), facei, own[facei], -1, false,
            patches.whichPatch(facei), zonei, zoneFlip
        );
    }
}


void Foam::planarRefinement::setUnrefinement
(
    const label level,
    const labelList& splitPoints,
    polyTopoChange& meshMod
)
{
    const faceList& faces = mesh_.faces();
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    const label nInternal = mesh_.nInternalFaces();
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    const labelListList& pointFaces = mesh_.pointFaces();
    const labelListList& pointCells = mesh_.pointCells();
    const vectorField& areas = mesh_.faceAreas();
    const labelList partner(partners());

    newCellLevel_ = cellLevel_;
    newPointLevel_ = pointLevel_;

    // The cell each merged cell goes into: the lowest of its family
    labelList masterOf(mesh_.nCells(), -1);
    for (const label pointi : splitPoints)
    {
        const labelList& family = pointCells[pointi];
        const label master = min(family);
        for (const label celli : family)
        {
            masterOf[celli] = master;
        }
        newCellLevel_[master] = level - 1;
    }
    auto cellAfter = [&](const label celli)
    {
        return masterOf[celli] >= 0 ? masterOf[celli] : celli;
    };

    // Across coupled faces: the cell after the merge (global label), and
    // whether it merges
    const globalIndex globalCells(mesh_.nCells());
    labelList globalAfter(mesh_.nCells());
    boolList merging(mesh_.nCells(), false);
    forAll(globalAfter, celli)
    {
        globalAfter[celli] = globalCells.toGlobal(cellAfter(celli));
        merging[celli] = masterOf[celli] >= 0;
    }
    labelList neiGlobalAfter;
    boolList neiMerging;
    syncTools::swapBoundaryCellList(mesh_, globalAfter, neiGlobalAfter);
    syncTools::swapBoundaryCellList(mesh_, merging, neiMerging);

    // What is on the other side of a side face, as seen from the side of
    // celli: a cell after the merge (its global label) or a patch
    auto across = [&](const label facei, const label celli)
    {
        if (facei < nInternal)
        {
            return globalAfter[own[facei] == celli ? nei[facei] : own[facei]];
        }
        const label patchi = patches.whichPatch(facei);
        if (patches[patchi].coupled())
        {
            return neiGlobalAfter[facei - nInternal];
        }
        return -1 - patchi;
    };

    // Middles of the merged cells' sides, and of sides across coupled faces
    // from cells that merge: each side's two halves are merged, and its
    // middle removed, where each side of it becomes one cell
    labelHashSet candidates;
    forAll(masterOf, celli)
    {
        if (masterOf[celli] < 0)
        {
            continue;
        }
        for (const label facei : mesh_.cells()[celli])
        {
            if (!onPlane(facei))
            {
                for (const label pointi : faces[facei])
                {
                    if (front(pointi) && pointLevel_[pointi] == level)
                    {
                        candidates.insert(pointi);
                    }
                }
            }
        }
    }
    forAll(neiMerging, bFacei)
    {
        if (neiMerging[bFacei])
        {
            for (const label pointi : faces[nInternal + bFacei])
            {
                if (front(pointi) && pointLevel_[pointi] == level)
                {
                    candidates.insert(pointi);
                }
            }
        }
    }
    for (const label pointi : splitPoints)
    {
        candidates.erase(pointi);
    }

    labelHashSet removedPoints;
    labelHashSet modifiedFaces;
    for (const label mid : candidates)
    {
        // The side's two halves: the side faces through the middle whose
        // other front point is a corner of the coarser level
        FixedList<label, 2> half(-1);
        label nHalves = 0;
        for (const label facei : pointFaces[mid])
        {
            if (onPlane(facei))
            {
                continue;
            }
            const face& f = faces[facei];
            const label i = frontEdgeStart(f);
            const label other = (f[i] == mid ? f.nextLabel(i) : f[i]);
            if (pointLevel_[other] < level)
            {
                if (nHalves < 2)
                {
                    half[nHalves] = facei;
                }
                ++nHalves;
            }
        }
        if (nHalves != 2)
        {
            continue;
        }
        const label cellA0 = own[half[0]];
        const label cellA1 =
            (areas[half[0]] & areas[half[1]]) > 0
          ? own[half[1]]
          : (half[1] < nInternal ? nei[half[1]] : -1);
        if (cellA1 < 0 || cellAfter(cellA0) != cellAfter(cellA1))
        {
            continue;
        }
        if (across(half[0], cellA0) != across(half[1], cellA1))
        {
            continue;
        }

        // Merge: half 0 takes the whole side
        const face& f1 = faces[half[1]];
        const label i1 = frontEdgeStart(f1);
        const label end = (f1[i1] == mid ? f1.nextLabel(i1) : f1[i1]);
        face whole(faces[half[0]]);
        whole[whole.find(mid)] = end;
        whole[whole.find(partner[mid])] = partner[end];
        const label neighbour =
            half[0] < nInternal ? cellAfter(nei[half[0]]) : -1;
        label zonei;
        bool zoneFlip;
        zoneOf(half[0], zonei, zoneFlip);
        setFace
        (
            meshMod, whole, half[0], cellAfter(own[half[0]]), neighbour, -1,
            half[0] < nInternal ? -1 : patches.whichPatch(half[0]),
            zonei, zoneFlip
        );
        meshMod.removeFace(half[1], half[0]);
        modifiedFaces.insert(half[0]);
        modifiedFaces.insert(half[1]);
        removedPoints.insert(mid);
        removedPoints.insert(partner[mid]);
    }

    // The merged cells' front and back faces: their outline, without the
    // centre and the removed middles
    for (const label pointi : splitPoints)
    {
        const labelList& family = pointCells[pointi];
        const label master = min(family);
        for (const label centre : {pointi, partner[pointi]})
        {
            Map<label> next(16);
            label keptFace = -1;
            for (const label celli : family)
            {
                label frontFace, backFace;
                planeFaces(celli, frontFace, backFace);
                const label facei = front(centre) ? frontFace : backFace;
                const face& f = faces[facei];
                forAll(f, i)
                {
                    if (f[i] != centre && f.nextLabel(i) != centre)
                    {
                        next.set(f[i], f.nextLabel(i));
                    }
                }
                if (celli == master)
                {
                    keptFace = facei;
                }
                else
                {
                    meshMod.removeFace(facei, -1);
                }
                modifiedFaces.insert(facei);
            }
            DynamicList<label> outline(next.size());
            const label start = next.begin().key();
            label pointj = start;
            do
            {
                if (!removedPoints.found(pointj))
                {
                    outline.append(pointj);
                }
                pointj = next[pointj];
            }
            while (pointj != start && outline.size() <= next.size());
            if (pointj != start)
            {
                FatalErrorInFunction
                    << "The cells about " << mesh_.points()[pointi]
                    << " do not make one cell's outline" << abort(FatalError);
            }
            label zonei;
            bool zoneFlip;
            zoneOf(keptFace, zonei, zoneFlip);
            meshMod.modifyFace
            (
                face(outline), keptFace, master, -1, false,
                patches.whichPatch(keptFace), zonei, zoneFlip
            );
        }
        meshMod.removePoint(pointi, -1);
        meshMod.removePoint(partner[pointi], -1);
        for (const label celli : family)
        {
            if (celli != master)
            {
                meshMod.removeCell(celli, master);
            }
        }
    }

    // Faces within a family go; the other faces of its cells go to its
    // master cell
    forAll(masterOf, celli)
    {
        if (masterOf[celli] < 0)
        {
            continue;
        }
        for (const label facei : mesh_.cells()[celli])
        {
            if (modifiedFaces.found(facei))
            {
                continue;
            }
            modifiedFaces.insert(facei);
            if
            (
                facei < nInternal
             && masterOf[own[facei]] >= 0
             && masterOf[own[facei]] == masterOf[nei[facei]]
            )
            {
                meshMod.removeFace(facei, -1);
                continue;
            }
            label zonei;
            bool zoneFlip;
            zoneOf(facei, zonei, zoneFlip);
            setFace
            (
                meshMod, faces[facei], facei, cellAfter(own[facei]),
                facei < nInternal ? cellAfter(nei[facei]) : -1, -1,
                facei < nInternal ? -1 : patches.whichPatch(facei),
                zonei, zoneFlip
            );
        }
    }

    // Removed middles leave the front and back faces of the cells beside
    for (const label pointi : removedPoints)
    {
        for (const label facei : pointFaces[pointi])
        {
            if (modifiedFaces.found(facei) || !onPlane(facei))
            {
                continue;
            }
            modifiedFaces.insert(facei);
            DynamicList<label> kept(faces[facei].size());
            for (const label pointj : faces[facei])
            {
                if (!removedPoints.found(pointj))
                {
                    kept.append(pointj);
                }
            }
            label zonei;
            bool zoneFlip;
            zoneOf(facei, zonei, zoneFlip);
            meshMod.modifyFace
            (
                face(kept), facei, own[facei], -1, false,
                patches.whichPatch(facei), zonei, zoneFlip
            );
        }
        meshMod.removePoint(pointi, -1);
    }
}


void Foam::planarRefinement::updateMesh(const mapPolyMesh& map)
{
    mapLevels
    (
        map.reverseCellMap(), map.cellMap(), mesh_.nCells(), newCellLevel_,
        cellLevel_
    );
    mapLevels
    (
        map.reversePointMap(), map.pointMap(), mesh_.nPoints(),
        newPointLevel_, pointLevel_
    );
}


bool Foam::planarRefinement::write(const word& instance) const
{
    bool writeOk = true;
    for (const labelIOList* levels : {&cellLevel_, &pointLevel_})
    {
        const labelIOList written
        (
            IOobject
            (
                levels->name(),
                instance,
                polyMesh::meshSubDir,
                mesh_,
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            *levels
        );
        writeOk = writeOk && written.write();
    }
    return writeOk;
}


// ************************************************************************* //
