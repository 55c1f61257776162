/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
\*---------------------------------------------------------------------------*/

#include "solidCylinder.H"
#include "vector2D.H"
#include "gaussLegendre.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace particleShapes
{
    defineTypeNameAndDebug(solidCylinder, 0);
    addToRunTimeSelectionTable(particleShape, solidCylinder, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleShapes::solidCylinder::solidCylinder
(
    const scalar radius,
    const scalar length
)
:
    radius_(radius),
    length_(length)
{}


Foam::particleShapes::solidCylinder::solidCylinder(const dictionary& dict)
:
    radius_(dict.get<scalar>("radius")),
    length_(dict.get<scalar>("length"))
{
    if (radius_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "radius " << radius_ << " of particle " << dict.dictName()
            << " must be positive" << exit(FatalIOError);
    }
    if (length_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "length " << length_ << " of particle " << dict.dictName()
            << " must be positive" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::particleShapes::solidCylinder::typeKeywords()
{
    return wordList({"radius", "length"});
}


Foam::wordList Foam::particleShapes::solidCylinder::keywords() const
{
    return typeKeywords();
}


Foam::label Foam::particleShapes::solidCylinder::nDimensions() const
{
    return 3;
}


Foam::scalar Foam::particleShapes::solidCylinder::boundingRadius() const
{
    return Foam::sqrt(sqr(radius_) + sqr(0.5*length_));
}


Foam::scalar Foam::particleShapes::solidCylinder::volume() const
{
    return constant::mathematical::pi*sqr(radius_)*length_;
}


Foam::symmTensor Foam::particleShapes::solidCylinder::inertiaPerUnitDensity() const
{
    const scalar V = volume();
    const scalar transverse = V*(3*sqr(radius_) + sqr(length_))/12;
    return symmTensor(transverse, 0, 0, transverse, 0, 0.5*V*sqr(radius_));
}


Foam::scalar Foam::particleShapes::solidCylinder::signedDistance
(
    const vector& r,
    vector& normal
) const
{
    const scalar rho = Foam::sqrt(sqr(r.x()) + sqr(r.y()));
    const vector radial
    (
        rho > VSMALL ? vector(r.x()/rho, r.y()/rho, 0) : vector(1, 0, 0)
    );
    const vector axial(0, 0, r.z() < 0 ? -1 : 1);

    // Beyond the mantle (dRadial > 0) and beyond an end (dAxial > 0)
    const scalar dRadial = rho - radius_;
    const scalar dAxial = mag(r.z()) - 0.5*length_;

    if (dRadial > 0 && dAxial > 0)
    {
        // Nearest the rim
        const scalar d = Foam::sqrt(sqr(dRadial) + sqr(dAxial));
        normal = (dRadial*radial + dAxial*axial)/d;
        return d;
    }
    if (dRadial > dAxial)
    {
        normal = radial;
        return dRadial;
    }
    normal = axial;
    return dAxial;
}


Foam::scalar Foam::particleShapes::solidCylinder::surfaceCrossing
(
    const vector& r0,
    const vector& e,
    const scalar L
) const
{
    // Entering the solid is entering both the slab between the ends and
    // the infinite solidCylinder: the later of the two entries
    scalar t = 0;

    if (mag(e.z()) > SMALL)
    {
        const scalar halfLength = 0.5*length_;
        const scalar t1 = (-halfLength - r0.z())/e.z();
        const scalar t2 = (halfLength - r0.z())/e.z();
        t = max(t, min(t1, t2));
    }

    const scalar a = sqr(e.x()) + sqr(e.y());
    if (a > SMALL)
    {
        const scalar b = (r0.x()*e.x() + r0.y()*e.y())/a;
        const scalar c = (sqr(r0.x()) + sqr(r0.y()) - sqr(radius_))/a;
        const scalar disc = max(sqr(b) - c, scalar(0));
        t = max(t, -b - Foam::sqrt(disc));
    }

    return min(t, L);
}


void Foam::particleShapes::solidCylinder::drawing
(
    pointField& points,
    faceList& faces
) const
{
    // Points 0..n-1 round the lower end, n..2n-1 round the upper end
    const label n = 48;
    points.setSize(2*n);
    faces.setSize(n + 2);
    face lower(n);
    face upper(n);
    for (label i = 0; i < n; ++i)
    {
        const scalar angle = constant::mathematical::twoPi*i/n;
        const scalar x = radius_*cos(angle);
        const scalar y = radius_*sin(angle);
        points[i] = point(x, y, -0.5*length_);
        points[n + i] = point(x, y, 0.5*length_);
        lower[i] = n - 1 - i;
        upper[i] = n + i;
        const label next = (i + 1) % n;
        faces[i] = face{i, next, n + next, n + i};
    }
    faces[n] = lower;
    faces[n + 1] = upper;
}


Foam::scalar Foam::particleShapes::solidCylinder::support
(
    const vector& u
) const
{
    return radius_*mag(vector(u.x(), u.y(), 0)) + 0.5*length_*mag(u.z());
}


bool Foam::particleShapes::solidCylinder::planeCut
(
    const vector& n,
    const scalar distance,
    scalar& volume,
    vector& centroid,
    scalar& sectionArea
) const
{
    // Across the disk, along s = u.(x, y) with u the normal's direction in
    // the end plane, the chord is 2 c(s), c = sqrt(r^2 - s^2), and the
    // part beyond the plane spans z from zLow(s) to the upper end (the
    // normal turned to point up, z mirrored back at the end). zLow is
    // -H where the plane passes below the lower end (closed-form integrals
    // of c and s c), linear in s where it crosses the mantle and above H
    // (nothing) elsewhere.
    const scalar r = radius_;
    const scalar H = 0.5*length_;
    const scalar t = Foam::sqrt(sqr(n.x()) + sqr(n.y()));
    const scalar nz = mag(n.z());
    const scalar flip = n.z() < 0 ? -1 : 1;

    volume = 0;
    sectionArea = 0;
    centroid = Zero;

    if (t < SMALL)
    {
        // A plane across the axis: a slab of the cylinder
        const scalar zLow = max(distance/nz, -H);
        if (zLow < H)
        {
            volume = constant::mathematical::pi*sqr(r)*(H - zLow);
            centroid = vector(0, 0, flip*0.5*(H + zLow));
            sectionArea = distance/nz > -H ? constant::mathematical::pi*sqr(r) : 0;
        }
        return true;
    }

    // Antiderivatives of c and s c, s clipped to the disk
    auto integrals = [r](const scalar s0)
    {
        const scalar s = min(max(s0, -r), r);
        const scalar c = Foam::sqrt(max(sqr(r) - sqr(s), scalar(0)));
        const scalar angle = Foam::asin(s/r);
        return vector2D(0.5*(s*c + sqr(r)*angle), -pow3(c)/3);
    };

    const vector u(n.x()/t, n.y()/t, 0);
    scalar Ms = 0;
    scalar Mz = 0;

    // The plane crosses the mantle over the strip sTop < s < sTop + width
    const scalar width = nz*length_/t;
    const scalar sTop = (distance - nz*H)/t;
    if (width < 1e-6*r)
    {
        // A plane along the axis, or so nearly that the strip is a step at
        // its middle s0 (to second order in the strip's width; its
        // first-order lift of the centroid along the axis kept)
        const scalar s0 = distance/t;
        const vector2D I(integrals(r) - integrals(s0));
        const scalar c0 = Foam::sqrt(max(sqr(r) - sqr(s0), scalar(0)));
        volume = 2*length_*I.x();
        Ms = 2*length_*I.y();
        Mz = c0*width*sqr(length_)/6;
        sectionArea = 2*c0*length_/t;
    }
    else
    {
        // Over the strip the height beyond the plane ramps up linearly
        // from 0 to the length: integrated by Gauss-Legendre in the angle
        // theta, s = r sin(theta), whose integrands are smooth (closed
        // forms, divided by nz, lose the precision of a narrow strip)
        const scalar sBottom = sTop + width;
        const scalar thetaTop =
            Foam::asin(min(max(sTop/r, scalar(-1)), scalar(1)));
        const scalar thetaBottom =
            Foam::asin(min(max(sBottom/r, scalar(-1)), scalar(1)));
        const scalar half = 0.5*(thetaBottom - thetaTop);
        const scalar mid = 0.5*(thetaBottom + thetaTop);
        static const gaussLegendre rule(16);
        scalar strip = 0;
        forAll(rule.nodes(), k)
        {
            const scalar theta = mid + half*rule.nodes()[k];
            const scalar s = r*Foam::sin(theta);
            // c ds = r^2 cos^2(theta) dtheta
            const scalar w = rule.weights()[k]*half*sqr(r*Foam::cos(theta));
            const scalar height =
                length_*min(max((s - sTop)/width, scalar(0)), scalar(1));
            strip += w;
            volume += 2*w*height;
            Ms += 2*w*s*height;
            Mz += w*(2*H*height - sqr(height));
        }
        // The section over the strip, seen along the normal
        sectionArea = 2*strip*length_/(t*width);

        // Below the lower end: the full length
        const vector2D J(integrals(r) - integrals(sBottom));
        volume += 2*length_*J.x();
        Ms += 2*length_*J.y();
    }

    if (volume > 0)
    {
        centroid = (Ms/volume)*u + vector(0, 0, flip*Mz/volume);
    }
    return true;
}


void Foam::particleShapes::solidCylinder::supportKinks
(
    DynamicList<vector>& ridgeAxes,
    DynamicList<vector>& cornerDirections
) const
{
    ridgeAxes.append(vector(0, 0, 1));
    cornerDirections.append(vector(0, 0, 1));
    cornerDirections.append(vector(0, 0, -1));
}


void Foam::particleShapes::solidCylinder::write(Ostream& os) const
{
    os.writeEntry("shape", typeName);
    os.writeEntry("radius", radius_);
    os.writeEntry("length", length_);
}


// ************************************************************************* //
