/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "overlapGeometry.H"
#include "mathematicalConstants.H"
#include "scalarOps.H"

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::overlapGeometry::sphereCapVolume
(
    const scalar R,
    const scalar h
)
{
    const scalar depth = min(max(h, scalar(0)), 2*R);
    return pi*sqr(depth)*(3*R - depth)/3;
}


Foam::scalar Foam::overlapGeometry::sphereLensVolume
(
    const scalar R1,
    const scalar R2,
    const scalar d
)
{
    if (d >= R1 + R2)
    {
        return 0;
    }
    if (d <= mag(R1 - R2))
    {
        return 4*pi*pow3(min(R1, R2))/3;
    }
    // The two caps cut off by the plane of the intersection circle
    const scalar a1 = lensPlaneDistance(R1, R2, d);
    return sphereCapVolume(R1, R1 - a1) + sphereCapVolume(R2, R2 - (d - a1));
}


Foam::scalar Foam::overlapGeometry::circleSegmentArea
(
    const scalar R,
    const scalar h
)
{
    const scalar depth = min(max(h, scalar(0)), 2*R);
    // Half the angle subtended by the chord: area R^2 (t - sin t cos t),
    // t - sin(2t)/2 by its series for small t (no cancellation)
    const scalar t = 2*std::asin(std::sqrt(0.5*depth/R));
    const scalar x = 2*t;
    if (x < 1e-2)
    {
        const scalar x3 = pow3(x);
        return 0.5*sqr(R)*(x3/6 - x3*sqr(x)/120 + x3*pow4(x)/5040);
    }
    return sqr(R)*(t - 0.5*std::sin(x));
}


Foam::scalar Foam::overlapGeometry::circleLensArea
(
    const scalar R1,
    const scalar R2,
    const scalar d
)
{
    if (d >= R1 + R2)
    {
        return 0;
    }
    if (d <= mag(R1 - R2))
    {
        return pi*sqr(min(R1, R2));
    }
    const scalar a1 = lensPlaneDistance(R1, R2, d);
    return circleSegmentArea(R1, R1 - a1) + circleSegmentArea(R2, R2 - (d - a1));
}


Foam::scalar Foam::overlapGeometry::lensPlaneDistance
(
    const scalar R1,
    const scalar R2,
    const scalar d
)
{
    return 0.5*(d + (R1 - R2)*(R1 + R2)/d);
}


Foam::scalar Foam::overlapGeometry::equivalentRadius
(
    const scalar sectionArea,
    const scalar volume,
    const label nDimensions
)
{
    // Sphere: V = pi R delta^2, A = 2 pi R delta; disk: V = 4/3 sqrt(2R)
    // delta^1.5, c = 2 sqrt(2 R delta)
    return
        nDimensions == 3
      ? sqr(sectionArea)/(4*pi*volume)
      : pow3(sectionArea)/(12*volume);
}


// ************************************************************************* //
