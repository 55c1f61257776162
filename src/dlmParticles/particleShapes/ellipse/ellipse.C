/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "ellipse.H"
#include "ellipsoid.H"
#include "overlapGeometry.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleShapes
{
    defineTypeNameAndDebug(ellipse, 0);
    addToRunTimeSelectionTable(particleShape, ellipse, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using Foam::scalar;
using Foam::vector;

// Signed area of the unit circle about the origin within the triangle from
// the origin to the edge a-b (positive counter-clockwise): over the edge's
// pieces inside the circle the triangle, outside it the sector
scalar unitCircleEdgeArea(const vector& a, const vector& b)
{
    const vector d(b - a);
    const scalar dd = Foam::sqr(d.x()) + Foam::sqr(d.y());
    scalar cuts[4] = {0, 0, 0, 1};
    Foam::label nCuts = 1;
    if (dd > 0)
    {
        // |a + t d| = 1: t = (-p -+ sqrt(p^2 - q))
        const scalar p = (a.x()*d.x() + a.y()*d.y())/dd;
        const scalar q = (Foam::sqr(a.x()) + Foam::sqr(a.y()) - 1)/dd;
        const scalar disc = Foam::sqr(p) - q;
        if (disc > 0)
        {
            const scalar root = Foam::sqrt(disc);
            for (const scalar t : {-p - root, -p + root})
            {
                if (t > 0 && t < 1)
                {
                    cuts[nCuts++] = t;
                }
            }
        }
    }
    cuts[nCuts++] = 1;

    scalar area = 0;
    for (Foam::label k = 0; k + 1 < nCuts; ++k)
    {
        const vector P(a + cuts[k]*d);
        const vector Q(a + cuts[k + 1]*d);
        const vector M(0.5*(P + Q));
        const scalar cross = P.x()*Q.y() - P.y()*Q.x();
        if (Foam::sqr(M.x()) + Foam::sqr(M.y()) <= 1)
        {
            area += 0.5*cross;
        }
        else
        {
            area += 0.5*Foam::atan2(cross, P.x()*Q.x() + P.y()*Q.y());
        }
    }
    return area;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleShapes::ellipse::ellipse(const vector2D& semiAxes)
:
    semiAxes_(semiAxes)
{}


Foam::particleShapes::ellipse::ellipse(const dictionary& dict)
:
    semiAxes_(dict.get<vector2D>("semiAxes"))
{
    if (cmptMin(semiAxes_) <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "semiAxes " << semiAxes_ << " of particle " << dict.dictName()
            << " must both be positive" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::particleShapes::ellipse::typeKeywords()
{
    return wordList({"semiAxes"});
}


Foam::wordList Foam::particleShapes::ellipse::keywords() const
{
    return typeKeywords();
}


Foam::label Foam::particleShapes::ellipse::nDimensions() const
{
    return 2;
}


Foam::scalar Foam::particleShapes::ellipse::boundingRadius() const
{
    return cmptMax(semiAxes_);
}


Foam::scalar Foam::particleShapes::ellipse::volume() const
{
    return constant::mathematical::pi*semiAxes_.x()*semiAxes_.y();
}


Foam::symmTensor Foam::particleShapes::ellipse::inertiaPerUnitDensity() const
{
    // Per unit depth, as the disk's: the second moments of area about the
    // body x and y axes, and their sum (the polar moment) about z
    const scalar A4 = 0.25*volume();
    const scalar a2 = sqr(semiAxes_.x());
    const scalar b2 = sqr(semiAxes_.y());
    return symmTensor(A4*b2, 0, 0, A4*a2, 0, A4*(a2 + b2));
}


Foam::scalar Foam::particleShapes::ellipse::signedDistance
(
    const vector& r,
    vector& normal
) const
{
    // In the positive quadrant, the major axis first
    const direction major = semiAxes_.x() >= semiAxes_.y() ? 0 : 1;
    const direction minor = 1 - major;
    const scalar e0 = semiAxes_[major];
    const scalar e1 = semiAxes_[minor];
    scalar x0, x1;
    const scalar distance = ellipsoid::ellipseDistance
    (
        e0, e1, mag(r[major]), mag(r[minor]), x0, x1
    );

    // Outward normal at the closest point: the gradient of the level set
    vector n(Zero);
    n[major] = r[major] < 0 ? -x0/sqr(e0) : x0/sqr(e0);
    n[minor] = r[minor] < 0 ? -x1/sqr(e1) : x1/sqr(e1);
    normal = n/mag(n);

    const bool inside = sqr(r[major]/e0) + sqr(r[minor]/e1) < 1;
    return inside ? -distance : distance;
}


Foam::scalar Foam::particleShapes::ellipse::surfaceCrossing
(
    const vector& r0,
    const vector& e,
    const scalar L
) const
{
    // In the frame where the ellipse is the unit circle:
    // |u0 + t v|^2 = 1, entering root
    const vector u0(r0.x()/semiAxes_.x(), r0.y()/semiAxes_.y(), 0);
    const vector v(e.x()/semiAxes_.x(), e.y()/semiAxes_.y(), 0);
    const scalar a = magSqr(v);
    if (a < SMALL)
    {
        return 0;
    }
    const scalar b = (u0 & v)/a;
    const scalar c = (magSqr(u0) - 1)/a;
    const scalar disc = max(sqr(b) - c, scalar(0));
    return min(max(-b - Foam::sqrt(disc), scalar(0)), L);
}


Foam::scalar Foam::particleShapes::ellipse::boxFraction
(
    const boundBox& bb,
    const point& X,
    const tensor& R,
    const vector& splitDirections,
    const scalar leafSize
) const
{
    // The cell's rectangle in the frame u = E^-1 R^T (r - X), where the
    // ellipse is the unit circle: a parallelogram, counter-clockwise (the
    // map keeps orientation); areas there scale by 1/(ab)
    const point& lo = bb.min();
    const point& hi = bb.max();
    const point corners[4] =
    {
        point(lo.x(), lo.y(), 0), point(hi.x(), lo.y(), 0),
        point(hi.x(), hi.y(), 0), point(lo.x(), hi.y(), 0)
    };
    const point centre(X.x(), X.y(), 0);
    vector u[4];
    for (label k = 0; k < 4; ++k)
    {
        const vector body(R.T() & (corners[k] - centre));
        u[k] = vector(body.x()/semiAxes_.x(), body.y()/semiAxes_.y(), 0);
    }
    scalar unitArea = 0;
    for (label k = 0; k < 4; ++k)
    {
        unitArea += unitCircleEdgeArea(u[k], u[(k + 1) % 4]);
    }
    const scalar cellArea = (hi.x() - lo.x())*(hi.y() - lo.y());
    return min
    (
        max(semiAxes_.x()*semiAxes_.y()*unitArea/cellArea, scalar(0)),
        scalar(1)
    );
}


bool Foam::particleShapes::ellipse::planeCut
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

    // In the frame u = E^-1 r the ellipse is the unit circle and the line
    // is k.u = lineDistance/|E m|, k = E m/|E m|: its segment of depth h
    // has the half chord c = sqrt(h (2 - h)) and its centroid at
    // 2 c^3/(3 A) along k. Areas scale by ab, the chord (along E k^perp)
    // by ab/|E m|
    const scalar a = semiAxes_.x();
    const scalar b = semiAxes_.y();
    const vector Em(a*m.x(), b*m.y(), 0);
    const scalar scale = mag(Em);
    const scalar h = min(max(1 - lineDistance/scale, scalar(0)), scalar(2));
    const scalar unitArea = overlapGeometry::circleSegmentArea(1, h);
    const scalar halfChord = Foam::sqrt(h*(2 - h));

    volume = a*b*unitArea;
    sectionArea = 2*halfChord*a*b/scale;
    if (unitArea > 0)
    {
        const scalar along = 2*pow3(halfChord)/(3*unitArea);
        centroid = vector(a*Em.x(), b*Em.y(), 0)*along/scale;
    }
    return true;
}


Foam::scalar Foam::particleShapes::ellipse::support(const vector& u) const
{
    return Foam::sqrt(sqr(semiAxes_.x()*u.x()) + sqr(semiAxes_.y()*u.y()));
}


void Foam::particleShapes::ellipse::write(Ostream& os) const
{
    os.writeEntry("shape", typeName);
    os.writeEntry("semiAxes", semiAxes_);
}


// ************************************************************************* //
