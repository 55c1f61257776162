/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "overlapMethod.H"
#include "dlmParticleCloud.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(overlapMethod, 0);
    defineRunTimeSelectionTable(overlapMethod, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::overlapMethod::overlapMethod(const dlmParticleCloud& cloud)
:
    cloud_(cloud)
{}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::overlapMethod> Foam::overlapMethod::New
(
    const dictionary& dict,
    const dlmParticleCloud& cloud,
    const boolList& pairParticles
)
{
    const word methodType(dict.getOrDefault<word>("overlap", "exact"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(methodType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "overlap",
            methodType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<overlapMethod>(cstrIter()(dict, cloud, pairParticles));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::overlapMethod::centreNormal(const point& a, const point& b)
{
    const vector d(b - a);
    const scalar distance = mag(d);
    return distance > VSMALL ? d/distance : vector(Zero);
}


// ************************************************************************* //
