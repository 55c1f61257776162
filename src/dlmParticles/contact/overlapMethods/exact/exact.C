/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "exact.H"
#include "dlmParticleCloud.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace overlapMethods
{
    defineTypeNameAndDebug(exact, 0);
    addToRunTimeSelectionTable(overlapMethod, exact, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::overlapMethods::exact::exact
(
    const dictionary& dict,
    const dlmParticleCloud& cloud
)
:
    overlapMethod(cloud)
{
    // Fail at start, not at the first contact, for shapes without formulas:
    // one particle of each shape type stands for the others
    const PtrList<dlmParticle>& particles = cloud.particles();
    DynamicList<label> representatives;
    forAll(particles, i)
    {
        bool seen = false;
        for (const label r : representatives)
        {
            seen = seen || particles[r].shape().type() == particles[i].shape().type();
        }
        if (!seen)
        {
            representatives.append(i);
        }
    }
    for (const label i : representatives)
    {
        for (const label j : representatives)
        {
            scalar volume, planeDistance;
            if
            (
                !particles[i].shape().pairOverlap
                (
                    particles[j].shape(), 0, volume, planeDistance
                )
            )
            {
                FatalIOErrorInFunction(dict)
                    << "No exact overlap formula for particles "
                    << particles[i].name() << " ("
                    << particles[i].shape().type() << ") and "
                    << particles[j].name() << " ("
                    << particles[j].shape().type() << "): use 'overlap grid'"
                    << exit(FatalIOError);
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::overlapMethods::exact::overlaps
(
    const UList<labelPair>& pairs,
    List<pairOverlap>& result
) const
{
    const PtrList<dlmParticle>& particles = cloud_.particles();
    result.setSize(pairs.size());

    forAll(pairs, pairi)
    {
        const dlmParticle& pi = particles[pairs[pairi].first()];
        const dlmParticle& pj = particles[pairs[pairi].second()];
        pairOverlap& o = result[pairi];

        const scalar distance = mag(pj.position() - pi.position());
        o.normal = centreNormal(pairs[pairi].first(), pairs[pairi].second());
        o.depth =
            pi.shape().boundingRadius() + pj.shape().boundingRadius() - distance;

        scalar planeDistance = 0;
        o.volume = 0;
        if (o.depth > 0)
        {
            pi.shape().pairOverlap(pj.shape(), distance, o.volume, planeDistance);
        }
        o.location = pi.position() + planeDistance*o.normal;
    }
}


// ************************************************************************* //
