/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "dlmRefineFvMesh.H"
#include "syncTools.H"
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
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::dlmRefineFvMesh::update()
{
    if (time().timeIndex() > 0)
    {
        const bool changed = dynamicRefineFvMesh::update();
        warnAtMaxCells();
        return changed;
    }

    const dictionary coeffs(refineCoeffs());

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
