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

void Foam::overlapMethods::exact::prepare(const UList<labelPair>& pairs)
{
    const PtrList<dlmParticle>& particles = cloud_.particles();
    shapes_.setSize(particles.size());
    radii_.setSize(particles.size());
    forAll(particles, i)
    {
        shapes_.set(i, &particles[i].shape());
        radii_[i] = particles[i].shape().boundingRadius();
    }
}


void Foam::overlapMethods::exact::overlaps
(
    const UList<labelPair>& pairs,
    const label start,
    const UList<point>& positions,
    const UList<quaternion>& orientations,
    UList<pairOverlap>& result
) const
{
    forAll(result, b)
    {
        const label i = pairs[start + b].first();
        const label j = pairs[start + b].second();
        const point& Xi = positions[i];
        pairOverlap& o = result[b];

        const scalar distance = mag(positions[j] - Xi);
        o.normal = centreNormal(Xi, positions[j]);
        o.depth = radii_[i] + radii_[j] - distance;

        scalar planeDistance = 0;
        o.volume = 0;
        if (o.depth > 0)
        {
            shapes_[i].pairOverlap(shapes_[j], distance, o.volume, planeDistance);
        }
        o.location = Xi + planeDistance*o.normal;
    }
}


// ************************************************************************* //
