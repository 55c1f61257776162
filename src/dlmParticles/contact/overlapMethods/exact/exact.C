/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "exact.H"
#include "dlmParticleCloud.H"
#include "addToRunTimeSelectionTable.H"
#include "overlapGeometry.H"

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
    const dlmParticleCloud& cloud,
    const boolList& pairParticles
)
:
    overlapMethod(cloud)
{
    // Fail at start, not at the first contact, for shapes without formulas:
    // one particle of each shape type stands for the others
    // (a type meets itself only if two particles have it); particles that
    // touch no other (an immersed wall) need none
    const PtrList<dlmParticle>& particles = cloud.particles();
    DynamicList<label> representatives;
    DynamicList<label> counts;
    forAll(particles, i)
    {
        if (!pairParticles[i])
        {
            continue;
        }
        label seen = -1;
        forAll(representatives, k)
        {
            if
            (
                particles[representatives[k]].shape().type()
             == particles[i].shape().type()
            )
            {
                seen = k;
            }
        }
        if (seen < 0)
        {
            representatives.append(i);
            counts.append(1);
        }
        else
        {
            ++counts[seen];
        }
    }
    // The common-plane overlap takes the shapes as convex
    if (sum(counts) > 1)
    {
        forAll(particles, i)
        {
            if (pairParticles[i] && !particles[i].shape().convex())
            {
                FatalIOErrorInFunction(dict)
                    << "Particle " << particles[i].name() << " ("
                    << particles[i].shape().type() << ") is not convex: the"
                    << " exact overlap between particles needs convex"
                    << " shapes. Use 'overlap grid', or a convex shape"
                    << exit(FatalIOError);
            }
        }
    }

    forAll(representatives, a)
    {
        forAll(representatives, b)
        {
            const label i = representatives[a];
            const label j = representatives[b];
            const particleShape& shapeI = particles[i].shape();
            const particleShape& shapeJ = particles[j].shape();
            scalar volume, planeDistance, area;
            vector centroid;
            if
            (
                (a != b || counts[a] > 1)
             && !shapeI.pairOverlap(shapeJ, 0, volume, planeDistance)
             && !(
                    shapeI.planeCut(vector(0, 0, 1), 0, volume, centroid, area)
                 && shapeJ.planeCut(vector(0, 0, 1), 0, volume, centroid, area)
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
        o.curvatureRadius = -1;
        o.volumeExponent = -1;
        o.sectionArea = -1;

        if (!shapes_[i].round() || !shapes_[j].round())
        {
            o.volume = 0;
            o.depth = radii_[i] + radii_[j] - mag(positions[j] - Xi);
            o.normal = centreNormal(Xi, positions[j]);
            o.location = Xi;
            if (o.depth > 0)
            {
                const convexOverlap::result c = convex_.overlap
                (
                    shapes_[i], Xi, orientations[i].R(),
                    shapes_[j], positions[j], orientations[j].R()
                );
                o.depth = c.depth;
                o.normal = c.normal;
                if (c.volume > 0 && c.sectionArea > 0)
                {
                    o.volume = c.volume;
                    o.location = c.location;
                    o.curvatureRadius = overlapGeometry::equivalentRadius
                    (
                        c.sectionArea, c.volume, shapes_[i].nDimensions()
                    );
                    o.volumeExponent =
                        min(max(c.sectionArea*c.depth/c.volume, scalar(1)), scalar(3));
                    o.sectionArea = c.sectionArea;
                }
            }
            continue;
        }

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
