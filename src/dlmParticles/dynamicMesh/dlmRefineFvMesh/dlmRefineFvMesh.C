/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "dlmRefineFvMesh.H"
#include "syncTools.H"
#include "dlmParticleCloud.H"
#include "checkKeywords.H"
#include "mapPolyMesh.H"
#include "orderedProcessorCyclicPolyPatch.H"
#include "volFields.H"
#include "polyTopoChange.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dlmRefineFvMesh, 0);
    addToRunTimeSelectionTable(dynamicFvMesh, dlmRefineFvMesh, IOobject);
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::dictionary Foam::dlmRefineFvMesh::refineCoeffs() const
{
    const IOdictionary dict
    (
        IOobject
        (
            "dynamicMeshDict",
            time().constant(),
            *this,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    return dict.optionalSubDict(dynamicRefineFvMesh::typeName + "Coeffs");
}


void Foam::dlmRefineFvMesh::warnAtMaxCells(const dictionary& coeffs)
{
    const label maxCells = coeffs.get<label>("maxCells");

    const label nCells = globalData().nTotalCells();
    if (nCells >= maxCells && !atMaxCells_)
    {
        WarningInFunction
            << time().constant()/"dynamicMeshDict" << ": the mesh has "
            << nCells << " cells, maxCells " << maxCells << ": nothing is"
            << " refined any more, near the particles neither, until cells"
            << " are unrefined" << endl;
    }
    atMaxCells_ = nCells >= maxCells;
}


void Foam::dlmRefineFvMesh::readTargets()
{
    const dictionary coeffs(refineCoeffs());
    const dictionary* targetsDict = coeffs.findDict("targets");
    if (!targetsDict)
    {
        if (planar_)
        {
            FatalIOErrorInFunction(coeffs)
                << "A 2D mesh is refined by the particles' targets: give"
                << " dynamicRefineFvMeshCoeffs a 'targets' dictionary"
                << " (refinement by a field's thresholds works in 3D only)"
                << exit(FatalIOError);
        }
        return;
    }

    checkKeywords
    (
        coeffs,
        wordHashSet(targetsCoeffsKeywords()),
        "for refinement by targets (dlmRefineFvMesh)"
    );

    for (const entry& e : *targetsDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(*targetsDict)
                << "Entry " << e.keyword() << " of targets is not a"
                << " dictionary: each target is a dictionary with its type"
                << " and level" << exit(FatalIOError);
        }
        targets_.append(refinementTarget::New(e.dict()));
    }
    if (targets_.empty())
    {
        FatalIOErrorInFunction(*targetsDict)
            << "No refinement target in targets" << exit(FatalIOError);
    }
}


const Foam::labelList& Foam::dlmRefineFvMesh::cellLevel() const
{
    return planar_ ? planar_->cellLevel() : meshCutter().cellLevel();
}


Foam::labelList Foam::dlmRefineFvMesh::targetLevels
(
    const dlmParticleCloud& cloud,
    const scalar lookAhead,
    const bool keep
) const
{
    labelList level(nCells(), Zero);
    for (const refinementTarget& target : targets_)
    {
        target.mark(cloud, cellLevel(), lookAhead, keep, level);
    }
    return level;
}


bool Foam::dlmRefineFvMesh::updateToTargets(const dictionary& coeffs)
{
    const label refineInterval = coeffs.getCheck<label>
    (
        "refineInterval",
        labelMinMax::ge(0)
    );
    const label timeIndex = time().timeIndex();
    if
    (
        refineInterval == 0
     || (timeIndex > 0 && timeIndex % refineInterval != 0)
    )
    {
        topoChanging(false);
        return false;
    }

    const dlmParticleCloud* cloudPtr =
        findObject<dlmParticleCloud>("particles");
    if (!cloudPtr)
    {
        FatalErrorInFunction
            << time().constant()/"dynamicMeshDict" << ": refinement targets"
            << " follow the particles, and this solver has none"
            << exit(FatalError);
    }
    const dlmParticleCloud& cloud = *cloudPtr;

    const label maxCells = coeffs.getCheck<label>("maxCells", labelMinMax::ge(1));
    const label nBufferLayers = coeffs.getCheckOrDefault<label>
    (
        "nBufferLayers",
        1,
        labelMinMax::ge(0)
    );
    label maxLevel = 0;
    for (const refinementTarget& target : targets_)
    {
        maxLevel = max(maxLevel, target.level());
    }

    const scalar lookAhead = refineInterval*time().deltaTValue();
    labelList keepLevel(targetLevels(cloud, lookAhead, true));

    bitSet refineCell(nCells());
    {
        const labelList level(targetLevels(cloud, lookAhead, false));
        const labelList& cellLevel = this->cellLevel();
        forAll(level, celli)
        {
            if (cellLevel[celli] < level[celli])
            {
                refineCell.set(celli);
            }
        }
    }

    bool changed = false;
    if (planar_)
    {
        changed = refinePlanar(refineCell, keepLevel, maxCells);
        if (timeIndex > 0)
        {
            for (label layer = 0; layer < nBufferLayers; ++layer)
            {
                extendMarkedCells(refineCell);
            }
            changed = unrefinePlanar(refineCell, keepLevel) || changed;
        }
        topoChanging(changed);
        if (changed)
        {
            moving(false);
        }
        return changed;
    }

    if (globalData().nTotalCells() < maxCells)
    {
        const labelList cellsToRefine
        (
            selectRefineCells(maxCells, maxLevel, refineCell)
        );
        if (returnReduce(cellsToRefine.size(), sumOp<label>()) > 0)
        {
            const autoPtr<mapPolyMesh> map = refine(cellsToRefine);
            const labelList& cellMap = map().cellMap();
            const labelList& reverseCellMap = map().reverseCellMap();

            // The refined cells (their children) are kept from unrefinement
            // this update, and take their parent's level to keep
            bitSet refined(cellMap.size());
            labelList newKeepLevel(cellMap.size(), maxLevel);
            forAll(cellMap, celli)
            {
                const label oldCelli = cellMap[celli];
                if (oldCelli >= 0)
                {
                    newKeepLevel[celli] = keepLevel[oldCelli];
                }
                if
                (
                    oldCelli < 0
                 || reverseCellMap[oldCelli] != celli
                 || refineCell.test(oldCelli)
                )
                {
                    refined.set(celli);
                }
            }
            refineCell.transfer(refined);
            keepLevel.transfer(newKeepLevel);
            changed = true;
        }
    }

    if (timeIndex > 0)
    {
        for (label layer = 0; layer < nBufferLayers; ++layer)
        {
            extendMarkedCells(refineCell);
        }

        // A split point may go where each of its cells is finer than the
        // level it keeps (0: may go, 1: stays)
        const labelList& cellLevel = meshCutter().cellLevel();
        const labelListList& pointCells = this->pointCells();
        scalarField staysRefined(nPoints(), Zero);
        forAll(pointCells, pointi)
        {
            for (const label celli : pointCells[pointi])
            {
                if (cellLevel[celli] <= keepLevel[celli])
                {
                    staysRefined[pointi] = 1;
                    break;
                }
            }
        }
        syncTools::syncPointList
        (
            *this,
            staysRefined,
            maxEqOp<scalar>(),
            scalar(0)
        );

        const labelList pointsToUnrefine
        (
            selectUnrefinePoints(0.5, refineCell, staysRefined)
        );
        if (returnReduce(pointsToUnrefine.size(), sumOp<label>()) > 0)
        {
            unrefine(pointsToUnrefine);
            changed = true;
        }

        if ((nRefinementIterations_ % 10) == 0)
        {
            // Unrefinement leaves holes in the refinement history
            const_cast<refinementHistory&>(meshCutter().history()).compact();
        }
        ++nRefinementIterations_;
    }

    topoChanging(changed);
    if (changed)
    {
        moving(false);
    }
    return changed;
}


Foam::autoPtr<Foam::mapPolyMesh> Foam::dlmRefineFvMesh::changePlanarMesh
(
    polyTopoChange& meshMod
)
{
    autoPtr<mapPolyMesh> map = meshMod.changeMesh(*this, false);
    updateMesh(*map);
    planar_->updateMesh(*map);
    return map;
}


bool Foam::dlmRefineFvMesh::refinePlanar
(
    bitSet& refineCell,
    labelList& keepLevel,
    const label maxCells
)
{
    bitSet refine(planar_->consistentRefinement(refineCell));
    const label nAdded = 3*returnReduce(refine.count(), sumOp<label>());
    if (nAdded == 0)
    {
        return false;
    }
    const label nCellsNow = globalData().nTotalCells();
    if (nCellsNow + nAdded > maxCells)
    {
        if (!heldAtMaxCells_)
        {
            WarningInFunction
                << time().constant()/"dynamicMeshDict" << ": refining would"
                << " take the mesh from " << nCellsNow << " to "
                << nCellsNow + nAdded << " cells, above maxCells " << maxCells
                << ": nothing is refined, near the particles neither, until"
                << " cells are unrefined" << endl;
        }
        heldAtMaxCells_ = true;
        return false;
    }
    heldAtMaxCells_ = false;

    bitSet marked(refineCell);
    marked |= refine;
    label maxLevel = 0;
    for (const label celli : refine)
    {
        maxLevel = max(maxLevel, planar_->cellLevel()[celli]);
    }
    reduce(maxLevel, maxOp<label>());

    // Level by level, the coarsest first: a side then has one hanging point
    // at most as its cells split
    for (label level = 0; level <= maxLevel; ++level)
    {
        const labelList oldLevel(planar_->cellLevel());
        DynamicList<label> cells;
        for (const label celli : refine)
        {
            if (oldLevel[celli] == level)
            {
                cells.append(celli);
            }
        }
        if (returnReduce(cells.size(), sumOp<label>()) == 0)
        {
            continue;
        }

        polyTopoChange meshMod(*this);
        planar_->setRefinement(level, cells, meshMod);
        const autoPtr<mapPolyMesh> map = changePlanarMesh(meshMod);

        const labelList& cellMap = map().cellMap();
        bitSet newRefine(nCells());
        bitSet newMarked(nCells());
        labelList newKeepLevel(nCells());
        forAll(cellMap, celli)
        {
            const label oldCelli = cellMap[celli];
            newKeepLevel[celli] = keepLevel[oldCelli];
            newMarked.set(celli, marked.test(oldCelli));
            newRefine.set
            (
                celli,
                refine.test(oldCelli) && oldLevel[oldCelli] > level
            );
        }
        refine.transfer(newRefine);
        marked.transfer(newMarked);
        keepLevel.transfer(newKeepLevel);
    }
    refineCell.transfer(marked);
    return true;
}


bool Foam::dlmRefineFvMesh::unrefinePlanar
(
    const bitSet& markedCell,
    const labelList& keepLevel
)
{
    const labelList& level = planar_->cellLevel();
    DynamicList<label> candidates;
    for (const label pointi : planar_->splitPoints())
    {
        bool merge = true;
        for (const label celli : pointCells()[pointi])
        {
            if (markedCell.test(celli) || level[celli] <= keepLevel[celli])
            {
                merge = false;
            }
        }
        if (merge)
        {
            candidates.append(pointi);
        }
    }
    labelList splitPoints(planar_->consistentUnrefinement(candidates));

    label maxLevel = 0;
    for (const label pointi : splitPoints)
    {
        maxLevel = max(maxLevel, planar_->pointLevel()[pointi]);
    }
    reduce(maxLevel, maxOp<label>());

    // Level by level, the finest first; cells merged once are not merged
    // again in this update (their split points were not found above)
    bool changed = false;
    for (label mergeLevel = maxLevel; mergeLevel > 0; --mergeLevel)
    {
        DynamicList<label> points;
        for (const label pointi : splitPoints)
        {
            if (planar_->pointLevel()[pointi] == mergeLevel)
            {
                points.append(pointi);
            }
        }
        if (returnReduce(points.size(), sumOp<label>()) == 0)
        {
            continue;
        }

        polyTopoChange meshMod(*this);
        planar_->setUnrefinement(mergeLevel, points, meshMod);
        const autoPtr<mapPolyMesh> map = changePlanarMesh(meshMod);
        changed = true;

        const labelList& reversePointMap = map().reversePointMap();
        DynamicList<label> remaining(splitPoints.size());
        for (const label pointi : splitPoints)
        {
            if (reversePointMap[pointi] >= 0)
            {
                remaining.append(reversePointMap[pointi]);
            }
        }
        splitPoints = std::move(remaining);
    }
    return changed;
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::dlmRefineFvMesh::selectRefineCandidates
(
    const scalar lowerRefineLevel,
    const scalar upperRefineLevel,
    const scalarField& vFld,
    bitSet& candidateCell
) const
{
    const labelListList& pointCells = this->pointCells();

    scalarField pointSum(nPoints(), Zero);
    labelList pointCount(nPoints(), Zero);
    forAll(pointCells, pointi)
    {
        for (const label celli : pointCells[pointi])
        {
            pointSum[pointi] += vFld[celli];
            ++pointCount[pointi];
        }
    }
    syncTools::syncPointList(*this, pointSum, plusEqOp<scalar>(), scalar(0));
    syncTools::syncPointList(*this, pointCount, plusEqOp<label>(), label(0));

    forAll(pointCells, pointi)
    {
        const scalar average = pointSum[pointi]/pointCount[pointi];
        if (average > lowerRefineLevel && average < upperRefineLevel)
        {
            for (const label celli : pointCells[pointi])
            {
                candidateCell.set(celli);
            }
        }
    }
}


Foam::labelList Foam::dlmRefineFvMesh::selectUnrefinePoints
(
    const scalar unrefineLevel,
    const bitSet& markedCell,
    const scalarField& pFld
) const
{
    // A point next to a marked cell on any processor is kept refined
    scalarField pointLargest(pFld);
    const labelListList& pointCells = this->pointCells();
    forAll(pointCells, pointi)
    {
        for (const label celli : pointCells[pointi])
        {
            if (markedCell.test(celli))
            {
                pointLargest[pointi] = GREAT;
            }
        }
    }
    syncTools::syncPointList(*this, pointLargest, maxEqOp<scalar>(), -GREAT);

    return dynamicRefineFvMesh::selectUnrefinePoints
    (
        unrefineLevel,
        markedCell,
        pointLargest
    );
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::wordList Foam::dlmRefineFvMesh::targetsCoeffsKeywords()
{
    return wordList
    ({
        "refineInterval", "maxCells", "nBufferLayers", "correctFluxes",
        "dumpLevel", "targets"
    });
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dlmRefineFvMesh::dlmRefineFvMesh(const IOobject& io)
:
    dynamicRefineFvMesh(io),
    atMaxCells_(false),
    heldAtMaxCells_(false)
{
    orderedProcessorCyclicPolyPatch::replacePatches(*this);
    if (nSolutionD() < 3)
    {
        planar_.reset(new planarRefinement(*this));
    }
    readTargets();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dlmRefineFvMesh::changeDue() const
{
    const label refineInterval =
        refineCoeffs().getOrDefault<label>("refineInterval", 0);
    return refineInterval > 0 && time().timeIndex() % refineInterval == 0;
}


bool Foam::dlmRefineFvMesh::update()
{
    const dictionary coeffs(refineCoeffs());

    if (targets_.size())
    {
        const bool changed = updateToTargets(coeffs);
        warnAtMaxCells(coeffs);
        return changed;
    }

    if (time().timeIndex() > 0)
    {
        const bool changed = dynamicRefineFvMesh::update();
        warnAtMaxCells(coeffs);
        return changed;
    }

    bool changed = false;
    const label maxCells = coeffs.get<label>("maxCells");
    if
    (
        coeffs.get<label>("refineInterval") > 0
     && globalData().nTotalCells() < maxCells
    )
    {
        bitSet candidates(nCells());
        selectRefineCandidates
        (
            coeffs.get<scalar>("lowerRefineLevel"),
            coeffs.get<scalar>("upperRefineLevel"),
            lookupObject<volScalarField>(coeffs.get<word>("field")),
            candidates
        );
        const labelList cellsToRefine
        (
            selectRefineCells
            (
                maxCells,
                coeffs.get<label>("maxRefinement"),
                candidates
            )
        );
        if (returnReduce(cellsToRefine.size(), sumOp<label>()) > 0)
        {
            refine(cellsToRefine);
            changed = true;
        }
    }

    topoChanging(changed);
    warnAtMaxCells(coeffs);
    return changed;
}


void Foam::dlmRefineFvMesh::mapFields(const mapPolyMesh& mpm)
{
    dynamicRefineFvMesh::mapFields(mpm);
    if (planar_)
    {
        mapNewInternalPlanarFaces<scalar>(mpm.faceMap());
        mapNewInternalPlanarFaces<vector>(mpm.faceMap());
    }
}


bool Foam::dlmRefineFvMesh::writeObject
(
    IOstream::streamFormat fmt,
    IOstream::versionNumber ver,
    IOstream::compressionType cmp,
    const bool valid
) const
{
    // The points of a changed mesh at full precision: rounded to the
    // fields' writePrecision, the cells of a restart would be boxes no more
    regIOobject& pointsIO = const_cast<pointIOField&>
    (
        lookupObject<pointIOField>("points")
    );
    const IOobject::writeOption pointsWrite = pointsIO.writeOpt();
    pointsIO.writeOpt() = IOobject::NO_WRITE;

    bool writeOk = true;
    if (!planar_)
    {
        writeOk = dynamicRefineFvMesh::writeObject(fmt, ver, cmp, valid);
    }
    else
    {
        writeOk =
            dynamicFvMesh::writeObject(fmt, ver, cmp, valid)
         && planar_->write(time().timeName());
        if (dumpLevel_)
        {
            volScalarField scalarCellLevel
            (
                IOobject
                (
                    "cellLevel",
                    time().timeName(),
                    *this,
                    IOobject::NO_READ,
                    IOobject::NO_WRITE,
                    false
                ),
                *this,
                dimensionedScalar(dimless, Zero)
            );
            forAll(planar_->cellLevel(), celli)
            {
                scalarCellLevel[celli] = planar_->cellLevel()[celli];
            }
            writeOk = writeOk && scalarCellLevel.write();
        }
    }

    pointsIO.writeOpt() = pointsWrite;
    if (pointsWrite == IOobject::AUTO_WRITE)
    {
        const unsigned precision = IOstream::defaultPrecision();
        IOstream::defaultPrecision(max(precision, 17u));
        writeOk = writeOk && pointsIO.writeObject(fmt, ver, cmp, valid);
        IOstream::defaultPrecision(precision);
    }
    return writeOk;
}


// ************************************************************************* //
