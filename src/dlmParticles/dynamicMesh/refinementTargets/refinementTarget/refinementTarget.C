/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "refinementTarget.H"
#include "checkKeywords.H"
#include "dlmParticleCloud.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(refinementTarget, 0);
    defineRunTimeSelectionTable(refinementTarget, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::vector Foam::refinementTarget::solvedSpan
(
    const dlmParticleCloud& cloud,
    const vector& span
)
{
    const Vector<label>& solutionD = cloud.mesh().solutionD();
    vector solved(span);
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (solutionD[d] < 0)
        {
            solved[d] = 0;
        }
    }
    return solved;
}


Foam::scalar Foam::refinementTarget::cellSize
(
    const dlmParticleCloud& cloud,
    const label celli
)
{
    return cmptMax(solvedSpan(cloud, cloud.cellBoxes()[celli].span()));
}


Foam::scalar Foam::refinementTarget::reach
(
    const dlmParticleCloud& cloud,
    const label celli,
    const bool keep
)
{
    return reach(solvedSpan(cloud, cloud.cellBoxes()[celli].span()), keep);
}


Foam::scalar Foam::refinementTarget::targetCellSize
(
    const scalar size,
    const label cellLevel
) const
{
    return std::ldexp(size, cellLevel - level_);
}


Foam::scalar Foam::refinementTarget::searchMargin
(
    const dlmParticleCloud& cloud,
    const labelList& cellLevel,
    const scalar cells,
    const bool keep
) const
{
    // The largest local cell's size at the mesh's level 0 bounds them all
    scalar baseSize = 0;
    forAll(cellLevel, celli)
    {
        baseSize = max
        (
            baseSize,
            std::ldexp(cellSize(cloud, celli), cellLevel[celli])
        );
    }
    return
        cells*targetCellSize(baseSize, 0)
      + reach(solvedSpan(cloud, baseSize*vector::one), keep);
}


Foam::scalar Foam::refinementTarget::bandWidth
(
    const dlmParticleCloud& cloud,
    const labelList& cellLevel,
    const scalar cells,
    const label celli
) const
{
    return
        cells
       *targetCellSize(cellSize(cloud, celli), cellLevel[celli]);
}


Foam::scalar Foam::refinementTarget::surfaceDistance
(
    const dlmParticle& p,
    const point& x
)
{
    vector normal;
    return p.shape().signedDistance(p.R().T() & (x - p.position()), normal);
}


void Foam::refinementTarget::findCellsNear
(
    const dlmParticleCloud& cloud,
    const point& x,
    const scalar margin,
    DynamicList<label>& found
)
{
    found.clear();
    cloud.findCells
    (
        boundBox(x - margin*vector::one, x + margin*vector::one),
        found
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::refinementTarget::refinementTarget(const dictionary& dict)
:
    name_(dict.dictName()),
    level_(dict.get<label>("level"))
{
    if (level_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "level " << level_ << " of refinement target " << name_
            << ": a target's level is 1 or more (0 is the mesh as read)"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::refinementTarget> Foam::refinementTarget::New
(
    const dictionary& dict
)
{
    const word targetType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(targetType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "type",
            targetType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    autoPtr<refinementTarget> target(cstrIter()(dict));

    checkKeywords
    (
        dict,
        wordHashSet(target->keywords()),
        "for refinement target " + dict.dictName() + " (type " + targetType
      + ")"
    );

    return target;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::refinementTarget::typeKeywords()
{
    return wordList({"type", "level"});
}


Foam::wordList Foam::refinementTarget::keywords() const
{
    return typeKeywords();
}


// ************************************************************************* //
