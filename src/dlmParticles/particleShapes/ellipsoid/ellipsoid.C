/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "ellipsoid.H"
#include <algorithm>
#include "overlapGeometry.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleShapes
{
    defineTypeNameAndDebug(ellipsoid, 0);
    addToRunTimeSelectionTable(particleShape, ellipsoid, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using Foam::scalar;
using Foam::label;

// Root s of sum_i (r_i z_i/(s + r_i))^2 = 1 by bisection, r_i the squared
// semi-axes over the smallest's, z_i the coordinates over the semi-axes and
// g = |z|^2 - 1 (Eberly, 2013): the root is bracketed by z_last - 1 and
// max(0, |r z| - 1), and bisection ends when the bracket cannot shrink
scalar closestPointRoot
(
    const label n,
    const scalar r[],
    const scalar z[],
    const scalar g
)
{
    scalar s0 = z[n - 1] - 1;
    scalar s1 = 0;
    if (g >= 0)
    {
        scalar sumSqr = 0;
        for (label i = 0; i < n; ++i)
        {
            sumSqr += Foam::sqr(r[i]*z[i]);
        }
        s1 = Foam::sqrt(sumSqr) - 1;
    }

    scalar s = 0;
    for (label iter = 0; iter < 200; ++iter)
    {
        s = 0.5*(s0 + s1);
        if (s == s0 || s == s1)
        {
            break;
        }
        scalar sum = 0;
        for (label i = 0; i < n; ++i)
        {
            sum += Foam::sqr(r[i]*z[i]/(s + r[i]));
        }
        if (sum > 1)
        {
            s0 = s;
        }
        else if (sum < 1)
        {
            s1 = s;
        }
        else
        {
            break;
        }
    }
    return s;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Static Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::particleShapes::ellipsoid::ellipseDistance
(
    const scalar e0,
    const scalar e1,
    const scalar y0,
    const scalar y1,
    scalar& x0,
    scalar& x1
)
{
    // Off the major axis by less than round-off: on it (the root of a
    // coordinate of 1e-16 of its semi-axis is -1 to round-off, where the
    // closest point divides by zero)
    if (y1 > 1e-12*e1)
    {
        if (y0 > 0)
        {
            const scalar z[2] = {y0/e0, y1/e1};
            const scalar g = sqr(z[0]) + sqr(z[1]) - 1;
            if (g == 0)
            {
                x0 = y0;
                x1 = y1;
                return 0;
            }
            const scalar r[2] = {sqr(e0/e1), 1};
            const scalar s = closestPointRoot(2, r, z, g);
            x0 = r[0]*y0/(s + r[0]);
            x1 = y1/(s + 1);
            return Foam::sqrt(sqr(x0 - y0) + sqr(x1 - y1));
        }
        x0 = 0;
        x1 = e1;
        return mag(y1 - e1);
    }

    // On the major axis: off it, where the evolute allows (inside), else
    // at its end
    const scalar numer0 = e0*y0;
    const scalar denom0 = sqr(e0) - sqr(e1);
    if (numer0 < denom0)
    {
        const scalar xde0 = numer0/denom0;
        x0 = e0*xde0;
        x1 = e1*Foam::sqrt(1 - sqr(xde0));
        return Foam::sqrt(sqr(x0 - y0) + sqr(x1));
    }
    x0 = e0;
    x1 = 0;
    return mag(y0 - e0);
}


Foam::scalar Foam::particleShapes::ellipsoid::octantDistance
(
    const vector& e,
    const vector& y,
    vector& x
)
{
    // Coordinates below round-off of their semi-axis are on the symmetry
    // planes (as in ellipseDistance)
    if (y.z() > 1e-12*e.z())
    {
        if (y.y() > 1e-12*e.y())
        {
            if (y.x() > 1e-12*e.x())
            {
                const scalar z[3] = {y.x()/e.x(), y.y()/e.y(), y.z()/e.z()};
                const scalar g = sqr(z[0]) + sqr(z[1]) + sqr(z[2]) - 1;
                if (g == 0)
                {
                    x = y;
                    return 0;
                }
                const scalar r[3] =
                    {sqr(e.x()/e.z()), sqr(e.y()/e.z()), 1};
                const scalar s = closestPointRoot(3, r, z, g);
                x = vector
                (
                    r[0]*y.x()/(s + r[0]),
                    r[1]*y.y()/(s + r[1]),
                    y.z()/(s + 1)
                );
                return mag(x - y);
            }
            x.x() = 0;
            return ellipseDistance(e.y(), e.z(), y.y(), y.z(), x.y(), x.z());
        }
        if (y.x() > 1e-12*e.x())
        {
            x.y() = 0;
            return ellipseDistance(e.x(), e.z(), y.x(), y.z(), x.x(), x.z());
        }
        x = vector(0, 0, e.z());
        return mag(y.z() - e.z());
    }

    // In the plane of the two larger axes: off it, where the evolute allows
    // (inside), else in that plane's ellipse
    const scalar denom0 = sqr(e.x()) - sqr(e.z());
    const scalar denom1 = sqr(e.y()) - sqr(e.z());
    const scalar numer0 = e.x()*y.x();
    const scalar numer1 = e.y()*y.y();
    if (numer0 < denom0 && numer1 < denom1)
    {
        const scalar xde0 = numer0/denom0;
        const scalar xde1 = numer1/denom1;
        const scalar discr = 1 - sqr(xde0) - sqr(xde1);
        if (discr > 0)
        {
            x = vector(e.x()*xde0, e.y()*xde1, e.z()*Foam::sqrt(discr));
            return mag(x - y);
        }
    }
    x.z() = 0;
    return ellipseDistance(e.x(), e.y(), y.x(), y.y(), x.x(), x.y());
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleShapes::ellipsoid::ellipsoid(const vector& semiAxes)
:
    semiAxes_(semiAxes)
{}


Foam::particleShapes::ellipsoid::ellipsoid(const dictionary& dict)
:
    semiAxes_(dict.get<vector>("semiAxes"))
{
    if (cmptMin(semiAxes_) <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "semiAxes " << semiAxes_ << " of particle " << dict.dictName()
            << " must all be positive" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::particleShapes::ellipsoid::typeKeywords()
{
    return wordList({"semiAxes"});
}


Foam::wordList Foam::particleShapes::ellipsoid::keywords() const
{
    return typeKeywords();
}


Foam::label Foam::particleShapes::ellipsoid::nDimensions() const
{
    return 3;
}


Foam::scalar Foam::particleShapes::ellipsoid::boundingRadius() const
{
    return cmptMax(semiAxes_);
}


Foam::scalar Foam::particleShapes::ellipsoid::volume() const
{
    return 4.0/3.0*constant::mathematical::pi*cmptProduct(semiAxes_);
}


Foam::symmTensor Foam::particleShapes::ellipsoid::inertiaPerUnitDensity() const
{
    const vector e2(cmptMultiply(semiAxes_, semiAxes_));
    const scalar V5 = 0.2*volume();
    return symmTensor
    (
        V5*(e2.y() + e2.z()), 0, 0,
        V5*(e2.x() + e2.z()), 0,
        V5*(e2.x() + e2.y())
    );
}


Foam::scalar Foam::particleShapes::ellipsoid::signedDistance
(
    const vector& r,
    vector& normal
) const
{
    // The closest point in the positive octant, with the axes sorted from
    // the largest semi-axis down
    FixedList<direction, 3> order({0, 1, 2});
    std::sort
    (
        order.begin(),
        order.end(),
        [this](const direction i, const direction j)
        {
            return semiAxes_[i] > semiAxes_[j];
        }
    );
    vector e, y;
    for (direction k = 0; k < 3; ++k)
    {
        e[k] = semiAxes_[order[k]];
        y[k] = mag(r[order[k]]);
    }
    vector x;
    const scalar distance = octantDistance(e, y, x);

    // Outward normal at the closest point: the gradient of the level set
    vector n;
    for (direction k = 0; k < 3; ++k)
    {
        const scalar component = x[k]/sqr(e[k]);
        n[order[k]] = r[order[k]] < 0 ? -component : component;
    }
    normal = n/mag(n);

    const bool inside =
        sqr(y.x()/e.x()) + sqr(y.y()/e.y()) + sqr(y.z()/e.z()) < 1;
    return inside ? -distance : distance;
}


Foam::scalar Foam::particleShapes::ellipsoid::surfaceCrossing
(
    const vector& r0,
    const vector& e,
    const scalar L
) const
{
    // In the frame where the ellipsoid is the unit sphere:
    // |u0 + t v|^2 = 1, entering root
    const vector u0(cmptDivide(r0, semiAxes_));
    const vector v(cmptDivide(e, semiAxes_));
    const scalar a = magSqr(v);
    const scalar b = (u0 & v)/a;
    const scalar c = (magSqr(u0) - 1)/a;
    const scalar disc = max(sqr(b) - c, scalar(0));
    return min(max(-b - Foam::sqrt(disc), scalar(0)), L);
}


Foam::scalar Foam::particleShapes::ellipsoid::planeOverlap
(
    const vector& n,
    const scalar distance
) const
{
    // The plane n.r = distance is m.u = distance/|E n| in the frame
    // u = E^-1 r where the ellipsoid is the unit sphere; volumes scale by
    // det E = abc
    const scalar unitDistance = distance/mag(cmptMultiply(semiAxes_, n));
    return
        cmptProduct(semiAxes_)
       *overlapGeometry::sphereCapVolume(1, 1 - unitDistance);
}


Foam::scalar Foam::particleShapes::ellipsoid::support(const vector& u) const
{
    return mag(cmptMultiply(semiAxes_, u));
}


bool Foam::particleShapes::ellipsoid::planeCut
(
    const vector& n,
    const scalar distance,
    scalar& volume,
    vector& centroid,
    scalar& sectionArea
) const
{
    // In the frame u = E^-1 r the ellipsoid is the unit sphere and the
    // plane is m.u = distance/|E n|, m = E n/|E n|: the cap of height h
    // has its centroid at 3 (2 - h)^2/(4 (3 - h)) along m and its base the
    // area pi (1 - (1 - h)^2); volumes scale by abc, areas along the
    // plane's normal by abc/|E n|
    const vector En(cmptMultiply(semiAxes_, n));
    const scalar scale = mag(En);
    const scalar unitDistance = distance/scale;
    const scalar h = min(max(1 - unitDistance, scalar(0)), scalar(2));
    const scalar abc = cmptProduct(semiAxes_);

    volume = abc*overlapGeometry::sphereCapVolume(1, h);
    sectionArea =
        abc/scale*constant::mathematical::pi
       *max(1 - sqr(unitDistance), scalar(0));
    centroid =
        h > 0
      ? cmptMultiply(semiAxes_, En/scale)*3*sqr(2 - h)/(4*(3 - h))
      : vector::zero;
    return true;
}


void Foam::particleShapes::ellipsoid::write(Ostream& os) const
{
    os.writeEntry("shape", typeName);
    os.writeEntry("semiAxes", semiAxes_);
}


// ************************************************************************* //
