/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "vorticity.H"
#include "dlmParticleCloud.H"
#include "fvcCurl.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace refinementTargets
{
    defineTypeNameAndDebug(vorticity, 0);
    addToRunTimeSelectionTable(refinementTarget, vorticity, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::refinementTargets::vorticity::vorticity(const dictionary& dict)
:
    refinementTarget(dict),
    threshold_
    (
        dict.getCheckOrDefault<scalar>("threshold", 0.2, scalarMinMax::ge(0))
    ),
    UName_(dict.getOrDefault<word>("U", "U"))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::refinementTargets::vorticity::typeKeywords()
{
    wordList known(refinementTarget::typeKeywords());
    known.append(wordList({"threshold", "U"}));
    return known;
}


Foam::wordList Foam::refinementTargets::vorticity::keywords() const
{
    return typeKeywords();
}


void Foam::refinementTargets::vorticity::mark
(
    const dlmParticleCloud& cloud,
    const labelList& cellLevel,
    const scalar lookAhead,
    const bool keep,
    labelList& targetLevel
) const
{
    if (cloud.particles().empty())
    {
        return;
    }

    const volVectorField& U = cloud.mesh().lookupObject<volVectorField>(UName_);

    scalar speed = gMax(mag(U.primitiveField())());
    scalar radius = GREAT;
    for (const dlmParticle& p : cloud.particles())
    {
        speed = max(speed, p.surfaceSpeed());
        radius = min(radius, p.shape().boundingRadius());
    }

    const scalar limit = (keep ? 0.5 : 1)*threshold_*speed/radius;
    if (limit <= 0)
    {
        return;
    }

    const scalarField magVorticity(mag(fvc::curl(U)().primitiveField()));
    forAll(magVorticity, celli)
    {
        if (magVorticity[celli] > limit)
        {
            targetLevel[celli] = max(targetLevel[celli], level());
        }
    }
}


// ************************************************************************* //
