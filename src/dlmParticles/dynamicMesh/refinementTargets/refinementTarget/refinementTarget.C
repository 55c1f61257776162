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

Foam::scalar Foam::refinementTarget::targetCellSize
(
    const scalar size,
    const label cellLevel
) const
{
    return size*pow(2.0, scalar(cellLevel - level_));
}


Foam::scalar Foam::refinementTarget::largestBaseCellSize
(
    const dlmParticleCloud& cloud,
    const labelList& cellLevel
)
{
    scalar largest = 0;
    forAll(cellLevel, celli)
    {
        largest = max
        (
            largest,
            cmptMax(cloud.cellBoxes()[celli].span())*pow(2.0, cellLevel[celli])
        );
    }
    return largest;
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

Foam::wordList Foam::refinementTarget::keywords() const
{
    return wordList({"type", "level"});
}


// ************************************************************************* //
