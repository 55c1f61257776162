/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "sphere.H"
#include <typeinfo>
#include "cutCellFraction.H"
#include "overlapGeometry.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleShapes
{
    defineTypeNameAndDebug(sphere, 0);
    addToRunTimeSelectionTable(particleShape, sphere, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleShapes::sphere::sphere(const scalar radius)
:
    radius_(radius)
{}


Foam::particleShapes::sphere::sphere(const dictionary& dict)
:
    radius_(dict.get<scalar>("radius"))
{
    if (radius_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "radius " << radius_ << " of particle " << dict.dictName()
            << " must be positive" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::particleShapes::sphere::typeKeywords()
{
    return wordList({"radius"});
}


Foam::wordList Foam::particleShapes::sphere::keywords() const
{
    return typeKeywords();
}


Foam::label Foam::particleShapes::sphere::nDimensions() const
{
    return 3;
}


Foam::scalar Foam::particleShapes::sphere::boundingRadius() const
{
    return radius_;
}


Foam::scalar Foam::particleShapes::sphere::volume() const
{
    return 4.0/3.0*constant::mathematical::pi*pow3(radius_);
}


Foam::symmTensor Foam::particleShapes::sphere::inertiaPerUnitDensity() const
{
    return 0.4*volume()*sqr(radius_)*symmTensor::I;
}


Foam::scalar Foam::particleShapes::sphere::signedDistance
(
    const vector& r,
    vector& normal
) const
{
    const scalar magR = mag(r);
    normal = magR > VSMALL ? r/magR : vector(1, 0, 0);
    return magR - radius_;
}


Foam::scalar Foam::particleShapes::sphere::surfaceCrossing
(
    const vector& r0,
    const vector& e,
    const scalar L
) const
{
    // |r0 + t e|^2 = R^2, entering root
    const scalar b = r0 & e;
    const scalar c = magSqr(r0) - sqr(radius_);
    const scalar disc = max(sqr(b) - c, scalar(0));
    return min(max(-b - Foam::sqrt(disc), scalar(0)), L);
}


Foam::scalar Foam::particleShapes::sphere::boxFraction
(
    const boundBox& bb,
    const point& X,
    const tensor& R,
    const vector& splitDirections,
    const scalar leafSize
) const
{
    const vector lo(bb.min() - X);
    const vector hi(bb.max() - X);
    const vector nearest(max(lo, min(vector::zero, hi)));
    if (magSqr(nearest) >= sqr(radius_))
    {
        return 0;
    }
    const vector farthest(max(cmptMag(lo), cmptMag(hi)));
    if (magSqr(farthest) <= sqr(radius_))
    {
        return 1;
    }
    return cutCellFraction::sphereBoxVolume(radius_, lo, hi)/bb.volume();
}


Foam::scalar Foam::particleShapes::sphere::planeOverlap
(
    const vector& n,
    const scalar distance
) const
{
    return overlapGeometry::sphereCapVolume(radius_, radius_ - distance);
}


bool Foam::particleShapes::sphere::planeCut
(
    const vector& n,
    const scalar distance,
    scalar& volume,
    vector& centroid,
    scalar& sectionArea
) const
{
    const scalar R = radius_;
    const scalar h = min(max(R - distance, scalar(0)), 2*R);
    volume = overlapGeometry::sphereCapVolume(R, h);
    sectionArea = constant::mathematical::pi*h*(2*R - h);
    centroid = h > 0 ? n*3*sqr(2*R - h)/(4*(3*R - h)) : vector::zero;
    return true;
}


bool Foam::particleShapes::sphere::pairOverlap
(
    const particleShape& other,
    const scalar distance,
    scalar& volume,
    scalar& planeDistance
) const
{
    // The exact type, not a dynamic_cast (a tenth of the contact
    // sub-step's instructions): this runs for every touching pair
    if (typeid(other) != typeid(sphere))
    {
        return false;
    }
    const scalar otherRadius = static_cast<const sphere&>(other).radius_;
    volume = overlapGeometry::sphereLensVolume(radius_, otherRadius, distance);
    planeDistance =
        distance > VSMALL
      ? overlapGeometry::lensPlaneDistance(radius_, otherRadius, distance)
      : 0;
    return true;
}


Foam::scalar Foam::particleShapes::sphere::support(const vector& u) const
{
    return radius_;
}


void Foam::particleShapes::sphere::write(Ostream& os) const
{
    os.writeEntry("shape", typeName);
    os.writeEntry("radius", radius_);
}


// ************************************************************************* //
