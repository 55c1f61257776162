/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "grid.H"
#include "dlmParticleCloud.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace overlapMethods
{
    defineTypeNameAndDebug(grid, 0);
    addToRunTimeSelectionTable(overlapMethod, grid, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::overlapMethods::grid::grid
(
    const dictionary& dict,
    const dlmParticleCloud& cloud,
    const boolList& pairParticles
)
:
    overlapMethod(cloud)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::overlapMethods::grid::equivalentDepth
(
    const scalar V,
    const scalar R,
    const label nDimensions
)
{
    // Small-overlap lens: pi R delta^2, or 4/3 sqrt(2R) delta^1.5 in 2D
    return
        nDimensions == 3
      ? sqrt(V/(constant::mathematical::pi*R))
      : pow(0.75*V/sqrt(2*R), 2.0/3.0);
}


void Foam::overlapMethods::grid::prepare(const UList<labelPair>& pairs)
{
    commonCells_.setSize(pairs.size());
    forAll(pairs, pairi)
    {
        labelList a(cloud_.nearCells(pairs[pairi].first()));
        labelList b(cloud_.nearCells(pairs[pairi].second()));
        Foam::sort(a);
        Foam::sort(b);

        DynamicList<label> common(min(a.size(), b.size()));
        label ia = 0;
        label ib = 0;
        while (ia < a.size() && ib < b.size())
        {
            if (a[ia] < b[ib])
            {
                ++ia;
            }
            else if (b[ib] < a[ia])
            {
                ++ib;
            }
            else
            {
                common.append(a[ia]);
                ++ia;
                ++ib;
            }
        }
        commonCells_[pairi].transfer(common);
    }
}


Foam::vector Foam::overlapMethods::grid::surfaceNormal
(
    const particleShape& a,
    const point& Xa,
    const tensor& Ra,
    const particleShape& b,
    const point& Xb,
    const tensor& Rb,
    const point& location,
    const vector& fallback
)
{
    vector na, nb;
    a.signedDistance(Ra.T() & (location - Xa), na);
    b.signedDistance(Rb.T() & (location - Xb), nb);
    const vector n((Ra & na) - (Rb & nb));
    const scalar magN = mag(n);
    return magN > 1e-6 ? n/magN : fallback;
}


void Foam::overlapMethods::grid::overlaps
(
    const UList<labelPair>& pairs,
    const label start,
    const UList<point>& positions,
    const UList<quaternion>& orientations,
    UList<pairOverlap>& result
) const
{
    const PtrList<dlmParticle>& particles = cloud_.particles();
    const List<boundBox>& boxes = cloud_.cellBoxes();
    const vector& split = cloud_.splitDirections();
    const scalarField& V = cloud_.mesh().V();
    const vectorField& C = cloud_.mesh().C();
    const label nDims = cloud_.twoD() ? 2 : 3;

    // Volume and first moment of each pair's doubly covered volume
    scalarList sums(4*result.size(), Zero);
    forAll(result, b)
    {
        const label i = pairs[start + b].first();
        const label j = pairs[start + b].second();
        const particleShape& shapei = particles[i].shape();
        const particleShape& shapej = particles[j].shape();
        const tensor Ri(orientations[i].R());
        const tensor Rj(orientations[j].R());
        for (const label celli : commonCells_[start + b])
        {
            const scalar fi = shapei.boxFraction
            (
                boxes[celli], positions[i], Ri, split, cloud_.leafSize(i)
            );
            if (fi <= 0)
            {
                continue;
            }
            const scalar fj = shapej.boxFraction
            (
                boxes[celli], positions[j], Rj, split, cloud_.leafSize(j)
            );
            const scalar doubled = (fi + fj - 1)*V[celli];
            if (doubled > 0)
            {
                sums[4*b] += doubled;
                for (direction d = 0; d < 3; ++d)
                {
                    sums[4*b + 1 + d] += doubled*C[celli][d];
                }
            }
        }
    }
    Pstream::listCombineGather(sums, plusEqOp<scalar>());
    Pstream::listCombineScatter(sums);

    const scalar depth = cloud_.meshDepth();
    forAll(result, b)
    {
        const label i = pairs[start + b].first();
        const label j = pairs[start + b].second();
        const scalar Ri = particles[i].shape().boundingRadius();
        const scalar Rj = particles[j].shape().boundingRadius();
        pairOverlap& o = result[b];
        o.curvatureRadius = -1;
        o.volumeExponent = -1;
        o.sectionArea = -1;

        o.volume = nDims == 3 ? sums[4*b] : sums[4*b]/depth;
        o.depth = equivalentDepth(o.volume, Ri*Rj/(Ri + Rj), nDims);
        o.normal = centreNormal(positions[i], positions[j]);
        o.location =
            sums[4*b] > 0
          ? point(sums[4*b + 1], sums[4*b + 2], sums[4*b + 3])/sums[4*b]
          : 0.5*(positions[i] + positions[j]);
        if (nDims == 2)
        {
            o.location.z() = positions[i].z();
        }
        if
        (
            sums[4*b] > 0
         && !(particles[i].shape().round() && particles[j].shape().round())
        )
        {
            o.normal = surfaceNormal
            (
                particles[i].shape(), positions[i], orientations[i].R(),
                particles[j].shape(), positions[j], orientations[j].R(),
                o.location, o.normal
            );
            if (nDims == 2)
            {
                o.normal.z() = 0;
                o.normal = normalised(o.normal);
            }
        }
    }
}


// ************************************************************************* //
