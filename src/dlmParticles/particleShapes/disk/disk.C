/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "disk.H"
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
    defineTypeNameAndDebug(disk, 0);
    addToRunTimeSelectionTable(particleShape, disk, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleShapes::disk::disk(const scalar radius)
:
    radius_(radius)
{}


Foam::particleShapes::disk::disk(const dictionary& dict)
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

Foam::wordList Foam::particleShapes::disk::typeKeywords()
{
    return wordList({"radius"});
}


Foam::wordList Foam::particleShapes::disk::keywords() const
{
    return typeKeywords();
}


Foam::label Foam::particleShapes::disk::nDimensions() const
{
    return 2;
}


Foam::scalar Foam::particleShapes::disk::boundingRadius() const
{
    return radius_;
}


Foam::scalar Foam::particleShapes::disk::volume() const
{
    return constant::mathematical::pi*sqr(radius_);
}


Foam::symmTensor Foam::particleShapes::disk::inertiaPerUnitDensity() const
{
    // Per unit depth: polar moment about the axis z, diametral about x and y
    const scalar diametral = 0.25*volume()*sqr(radius_);
    return symmTensor(diametral, 0, 0, diametral, 0, 2*diametral);
}


Foam::scalar Foam::particleShapes::disk::signedDistance
(
    const vector& r,
    vector& normal
) const
{
    const vector rPlane(r.x(), r.y(), 0);
    const scalar magR = mag(rPlane);
    normal = magR > VSMALL ? rPlane/magR : vector(1, 0, 0);
    return magR - radius_;
}


Foam::scalar Foam::particleShapes::disk::surfaceCrossing
(
    const vector& r0,
    const vector& e,
    const scalar L
) const
{
    // In the plane of the disk: |r0 + t e|^2 = R^2, entering root
    const vector rPlane(r0.x(), r0.y(), 0);
    const vector ePlane(e.x(), e.y(), 0);
    const scalar a = magSqr(ePlane);
    if (a < SMALL)
    {
        return 0;
    }
    const scalar b = (rPlane & ePlane)/a;
    const scalar c = (magSqr(rPlane) - sqr(radius_))/a;
    const scalar disc = max(sqr(b) - c, scalar(0));
    return min(max(-b - Foam::sqrt(disc), scalar(0)), L);
}


Foam::scalar Foam::particleShapes::disk::boxFraction
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
    const scalar area = (hi.x() - lo.x())*(hi.y() - lo.y());
    return
        cutCellFraction::circleRectangleArea
        (
            radius_,
            lo.x(),
            hi.x(),
            lo.y(),
            hi.y()
        )/area;
}


Foam::scalar Foam::particleShapes::disk::planeOverlap
(
    const vector& n,
    const scalar distance
) const
{
    return overlapGeometry::circleSegmentArea(radius_, radius_ - distance);
}


bool Foam::particleShapes::disk::planeCut
(
    const vector& n,
    const scalar distance,
    scalar& volume,
    vector& centroid,
    scalar& sectionArea
) const
{
    centroid = Zero;
    sectionArea = 0;
    vector m;
    scalar lineDistance;
    if (!meshPlaneLine(n, distance, m, lineDistance))
    {
        volume = distance < 0 ? this->volume() : 0;
        return true;
    }

    // The segment of depth h: half chord c = sqrt(h (2R - h)), centroid
    // at 2 c^3/(3 A) from the centre
    const scalar R = radius_;
    const scalar h = min(max(R - lineDistance, scalar(0)), 2*R);
    const scalar halfChord = Foam::sqrt(h*(2*R - h));
    volume = overlapGeometry::circleSegmentArea(R, h);
    sectionArea = 2*halfChord;
    if (volume > 0)
    {
        centroid = m*2*pow3(halfChord)/(3*volume);
    }
    return true;
}


bool Foam::particleShapes::disk::pairOverlap
(
    const particleShape& other,
    const scalar distance,
    scalar& volume,
    scalar& planeDistance
) const
{
    // The exact type, not a dynamic_cast (a tenth of the contact
    // sub-step's instructions): this runs for every touching pair
    if (typeid(other) != typeid(disk))
    {
        return false;
    }
    const scalar otherRadius = static_cast<const disk&>(other).radius_;
    volume = overlapGeometry::circleLensArea(radius_, otherRadius, distance);
    planeDistance =
        distance > VSMALL
      ? overlapGeometry::lensPlaneDistance(radius_, otherRadius, distance)
      : 0;
    return true;
}


Foam::scalar Foam::particleShapes::disk::support(const vector& u) const
{
    return radius_*mag(vector(u.x(), u.y(), 0));
}


void Foam::particleShapes::disk::write(Ostream& os) const
{
    os.writeEntry("shape", typeName);
    os.writeEntry("radius", radius_);
}


// ************************************************************************* //
