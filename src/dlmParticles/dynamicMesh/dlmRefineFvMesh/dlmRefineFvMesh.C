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


void Foam::dlmRefineFvMesh::warnAtMaxCells()
{
    const label maxCells = refineCoeffs().get<label>("maxCells");

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
        return;
    }

    checkKeywords
    (
        coeffs,
        wordHashSet
        ({
            "refineInterval", "maxCells", "nBufferLayers", "correctFluxes",
            "dumpLevel", "targets"
        }),
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
        target.mark(cloud, meshCutter().cellLevel(), lookAhead, keep, level);
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

    bool changed = false;
    bitSet refineCell(nCells());
    {
        const labelList level(targetLevels(cloud, lookAhead, false));
        const labelList& cellLevel = meshCutter().cellLevel();
        forAll(level, celli)
        {
            if (cellLevel[celli] < level[celli])
            {
                refineCell.set(celli);
            }
        }
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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dlmRefineFvMesh::dlmRefineFvMesh(const IOobject& io)
:
    dynamicRefineFvMesh(io),
    atMaxCells_(false)
{
    orderedProcessorCyclicPolyPatch::replacePatches(*this);
    readTargets();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dlmRefineFvMesh::update()
{
    const dictionary coeffs(refineCoeffs());

    if (targets_.size())
    {
        const bool changed = updateToTargets(coeffs);
        warnAtMaxCells();
        return changed;
    }

    if (time().timeIndex() > 0)
    {
        const bool changed = dynamicRefineFvMesh::update();
        warnAtMaxCells();
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
    warnAtMaxCells();
    return changed;
}


// ************************************************************************* //
