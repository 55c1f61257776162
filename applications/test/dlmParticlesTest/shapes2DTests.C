/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Description
    Tests of the 2D shapes (ellipse, polygon; prisms along z): area,
    centroid and inertia per unit depth against closed forms, signed
    distances at chosen points, line crossings, the solid fractions summed
    over 2D grids, the parts beyond lines against closed forms and grid
    sums, the common-plane overlap searching the mesh plane, and the
    checks of their input.

\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>

#include "particleShape.H"
#include "polygon.H"
#include "convexOverlap.H"
#include "overlapGeometry.H"
#include "shapeChecks.H"
#include "dlmParticle.H"
#include "Random.H"
#include "quaternion.H"
#include "mathematicalConstants.H"
#include "IStringStream.H"

using namespace Foam;
using constant::mathematical::pi;
using shapeChecks::show;

namespace
{

autoPtr<particleShape> makeShape(const string& entries)
{
    IStringStream is(entries);
    const dictionary dict(is);
    return particleShape::New(dict);
}


// Rotation by angle about z
tensor turn(const scalar angle)
{
    return quaternion(vector(0, 0, 1), angle).R();
}


// Sum of fraction times cell area over a 2D grid of square cells of side h
// (one cell of depth 0.1 along z, split only in the plane as on a 2D mesh)
// around the shape at X with rotation R, leaves at bounding radius/32
scalar gridArea
(
    const particleShape& shape,
    const point& X,
    const tensor& R,
    const scalar h
)
{
    const scalar Rb = shape.boundingRadius();
    const label n = label(std::ceil(2*Rb/h)) + 2;
    const point origin(X - (Rb + h)*vector(1, 1, 0) - vector(0, 0, 0.05));
    scalar sum = 0;
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            const point lo(origin + h*vector(i, j, 0));
            const boundBox bb(lo, lo + vector(h, h, 0.1));
            sum +=
                shape.boxFraction(bb, X, R, vector(1, 1, 0), Rb/32)*sqr(h);
        }
    }
    return sum;
}


void checkClosestPoint
(
    const particleShape& shape,
    const vector& r,
    const scalar expected,
    const vector& expectedNormal
)
{
    vector normal;
    INFO(shape.type() << " at " << show(r));
    CHECK(shape.signedDistance(r, normal) == Approx(expected).margin(1e-12));
    CHECK(mag(normal - expectedNormal) < 1e-12);
    // A prism along z: the same off the mid-plane
    CHECK
    (
        shape.signedDistance(r + vector(0, 0, 0.3), normal)
     == Approx(expected).margin(1e-12)
    );
}


// An L of three unit squares, corner at the origin before the shift to
// the centroid (5/6, 5/6)
const char* const lShape =
    "shape polygon; vertices ((0 0) (2 0) (2 1) (1 1) (1 2) (0 2));";
const vector lCentroid(5.0/6.0, 5.0/6.0, 0);

// A U: three by two, a unit notch from the top middle
const char* const uShape =
    "shape polygon;"
    " vertices ((0 0) (3 0) (3 2) (2 2) (2 1) (1 1) (1 2) (0 2));";

} // End anonymous namespace


TEST_CASE("2D shapes: area, centroid and inertia per unit depth", "[2D]")
{
    SECTION("ellipse")
    {
        autoPtr<particleShape> shape
        (
            makeShape("shape ellipse; semiAxes (0.8 0.3);")
        );
        const scalar A = pi*0.8*0.3;
        CHECK(shape->nDimensions() == 2);
        CHECK(shape->volume() == Approx(A).epsilon(1e-14));
        CHECK(shape->boundingRadius() == 0.8);
        const symmTensor I(shape->inertiaPerUnitDensity());
        // pi a b (a^2 + b^2)/4 about z; about x and y the second moments
        // of area (per unit depth, as the disk's)
        CHECK(I.zz() == Approx(pi*0.8*0.3*(0.64 + 0.09)/4).epsilon(1e-14));
        CHECK(I.xx() == Approx(A*0.09/4).epsilon(1e-14));
        CHECK(I.yy() == Approx(A*0.64/4).epsilon(1e-14));
        CHECK(I.xy() == 0);
        CHECK(I.xz() == 0);
        CHECK(I.yz() == 0);
    }
    SECTION("ellipse with equal semi-axes: the disk")
    {
        autoPtr<particleShape> ellipse
        (
            makeShape("shape ellipse; semiAxes (0.4 0.4);")
        );
        autoPtr<particleShape> disk(makeShape("shape disk; radius 0.4;"));
        CHECK(ellipse->volume() == Approx(disk->volume()).epsilon(1e-14));
        const symmTensor Ie(ellipse->inertiaPerUnitDensity());
        const symmTensor Id(disk->inertiaPerUnitDensity());
        for (direction d = 0; d < symmTensor::nComponents; ++d)
        {
            CHECK(Ie[d] == Approx(Id[d]).epsilon(1e-14).margin(1e-15));
        }
    }
    SECTION("polygon: a rectangle, clockwise and off the origin")
    {
        autoPtr<particleShape> shape
        (
            makeShape("shape polygon; vertices ((1 2) (1 2.4) (2 2.4) (2 2));")
        );
        const scalar A = 1*0.4;
        CHECK(shape->nDimensions() == 2);
        CHECK(shape->volume() == Approx(A).epsilon(1e-14));
        CHECK(shape->boundingRadius() == Approx(Foam::sqrt(0.29)).epsilon(1e-14));
        const symmTensor I(shape->inertiaPerUnitDensity());
        CHECK(I.xx() == Approx(A*0.16/12).epsilon(1e-13));
        CHECK(I.yy() == Approx(A*1/12).epsilon(1e-13));
        CHECK(I.zz() == Approx(A*(1 + 0.16)/12).epsilon(1e-13));
        CHECK(I.xy() == Approx(0).margin(1e-15));
        CHECK(I.xz() == 0);
        CHECK(I.yz() == 0);

        // Shifted to the centroid, the list reversed to counter-clockwise
        const pointField& v =
            static_cast<const particleShapes::polygon&>(shape()).vertices();
        CHECK(mag(sum(v)) < 1e-14);
        CHECK(mag(v[0] - vector(0.5, -0.2, 0)) < 1e-14);
        CHECK(mag(v[1] - vector(0.5, 0.2, 0)) < 1e-14);
    }
    SECTION("polygon: a right triangle")
    {
        // Legs b = 0.6 along x and h = 0.3 along y from (1, 1), clockwise:
        // about the centroid (b/3, h/3) from the right angle, the second
        // moments b h^3/36 and b^3 h/36 and the product -b^2 h^2/72
        const scalar b = 0.6;
        const scalar h = 0.3;
        autoPtr<particleShape> shape
        (
            makeShape("shape polygon; vertices ((1 1) (1 1.3) (1.6 1));")
        );
        CHECK(shape->volume() == Approx(0.5*b*h).epsilon(1e-14));
        const pointField& v =
            static_cast<const particleShapes::polygon&>(shape()).vertices();
        CHECK(mag(v[2] - vector(-b/3, -h/3, 0)) < 1e-14);
        const symmTensor I(shape->inertiaPerUnitDensity());
        CHECK(I.xx() == Approx(b*pow3(h)/36).epsilon(1e-13));
        CHECK(I.yy() == Approx(pow3(b)*h/36).epsilon(1e-13));
        CHECK(I.zz() == Approx(b*pow3(h)/36 + pow3(b)*h/36).epsilon(1e-13));
        CHECK(I.xy() == Approx(sqr(b*h)/72).epsilon(1e-13));
    }
    SECTION("polygon: an L (not convex)")
    {
        autoPtr<particleShape> shape(makeShape(lShape));
        CHECK(shape->volume() == Approx(3).epsilon(1e-14));
        CHECK_FALSE(shape->convex());
        // Three unit squares at (0.5 0.5), (1.5 0.5), (0.5 1.5), each
        // 1/6 + d^2 about the centroid
        scalar xx = 0, yy = 0, xy = 0;
        for (const vector c : {vector(0.5, 0.5, 0), vector(1.5, 0.5, 0), vector(0.5, 1.5, 0)})
        {
            const vector d(c - lCentroid);
            xx += 1.0/12 + sqr(d.y());
            yy += 1.0/12 + sqr(d.x());
            xy -= d.x()*d.y();
        }
        const symmTensor I(shape->inertiaPerUnitDensity());
        CHECK(I.xx() == Approx(xx).epsilon(1e-13));
        CHECK(I.yy() == Approx(yy).epsilon(1e-13));
        CHECK(I.zz() == Approx(xx + yy).epsilon(1e-13));
        CHECK(I.xy() == Approx(xy).epsilon(1e-13));
        CHECK(makeShape("shape polygon; vertices ((0 0) (1 0) (0 1));")->convex());
    }
}


TEST_CASE("2D shapes: signed distances at chosen points", "[2D]")
{
    SECTION("ellipse, semi-axes (1 0.5)")
    {
        autoPtr<particleShape> shape
        (
            makeShape("shape ellipse; semiAxes (1 0.5);")
        );
        checkClosestPoint(*shape, vector(2, 0, 0), 1, vector(1, 0, 0));
        checkClosestPoint(*shape, vector(0, -0.7, 0), 0.2, vector(0, -1, 0));
        checkClosestPoint(*shape, vector(0, 0.2, 0), -0.3, vector(0, 1, 0));
        checkClosestPoint(*shape, vector(0, 0, 0), -0.5, vector(0, 1, 0));

        // Inside on the major axis the nearest point is off it:
        // x = a^2 r/(a^2 - b^2), y = b sqrt(1 - (x/a)^2)
        const scalar x = 0.5/(1 - 0.25);
        const scalar y = 0.5*Foam::sqrt(1 - sqr(x));
        const vector toSurface(x - 0.5, y, 0);
        const vector gradient(x, y/0.25, 0);
        checkClosestPoint
        (
            *shape, vector(0.5, 0, 0), -mag(toSurface), gradient/mag(gradient)
        );

        // Random points: r minus the distance along the normal is on the
        // ellipse, the normal its own, no sampled point nearer
        Random rnd(11);
        for (label sample = 0; sample < 100; ++sample)
        {
            const vector r
            (
                2.6*(rnd.sample01<scalar>() - 0.5),
                1.3*(rnd.sample01<scalar>() - 0.5),
                0
            );
            vector normal;
            const scalar d = shape->signedDistance(r, normal);
            const vector s(r - d*normal);
            INFO("r " << show(r));
            CHECK(sqr(s.x()) + sqr(s.y()/0.5) == Approx(1).margin(1e-12));
            const vector grad(s.x(), s.y()/0.25, 0);
            CHECK(mag(normal - grad/mag(grad)) < 1e-10);
            CHECK((d < 0) == (sqr(r.x()) + sqr(r.y()/0.5) < 1));
            scalar nearest = GREAT;
            const label n = 20000;
            for (label k = 0; k < n; ++k)
            {
                const scalar t = 2*pi*k/n;
                nearest = min
                (
                    nearest,
                    mag(r - vector(Foam::cos(t), 0.5*Foam::sin(t), 0))
                );
            }
            CHECK(mag(d) <= nearest + 1e-12);
            CHECK(mag(d) == Approx(nearest).margin(1e-6));
        }
    }
    SECTION("polygon, the L about its centroid")
    {
        autoPtr<particleShape> shape(makeShape(lShape));
        const vector c(lCentroid);
        // Outside: a face, a corner, in the notch
        checkClosestPoint(*shape, vector(3, 0.5, 0) - c, 1, vector(1, 0, 0));
        checkClosestPoint(*shape, vector(2.3, -0.4, 0) - c, 0.5, vector(0.6, -0.8, 0));
        checkClosestPoint(*shape, vector(1.5, 1.2, 0) - c, 0.2, vector(0, 1, 0));
        // Inside: the nearest edge; near the inner (reflex) corner, the
        // corner, the normal pointing on away from it
        checkClosestPoint(*shape, vector(0.5, 0.3, 0) - c, -0.3, vector(0, -1, 0));
        checkClosestPoint(*shape, vector(0.3, 1.8, 0) - c, -0.2, vector(0, 1, 0));
        checkClosestPoint
        (
            *shape, vector(0.9, 0.8, 0) - c, -Foam::sqrt(0.05),
            vector(1, 2, 0)/Foam::sqrt(5.0)
        );
    }
}


TEST_CASE("2D shapes: line crossings agree with the general root finding", "[2D]")
{
    Random rnd(5);
    for
    (
        const string entries
      : {
            "shape ellipse; semiAxes (0.7 0.35);",
            "shape polygon; vertices ((-0.5 -0.3) (0.6 -0.2) (0.1 0.5));"
        }
    )
    {
        autoPtr<particleShape> shape(makeShape(entries));
        shapeChecks::checkLineCrossings(shape(), rnd, 400);
    }

    // Not convex: a line may enter twice, the crossing is the first entry
    // (the root finding may take any)
    autoPtr<particleShape> shape
    (
        makeShape("shape polygon; vertices ((0 0) (0.6 0) (0.6 0.3) (0.3 0.3) (0.3 0.6) (0 0.6));")
    );
    label nTwice = 0;
    for (label sample = 0; sample < 2000; ++sample)
    {
        const vector r0(2*rnd.sample01<vector>() - vector::one);
        const vector r1(0.5*(2*rnd.sample01<vector>() - vector::one));
        vector normal;
        if
        (
            shape->signedDistance(r0, normal) <= 0
         || shape->signedDistance(r1, normal) >= 0
        )
        {
            continue;
        }
        const scalar L = mag(r1 - r0);
        const vector e((r1 - r0)/L);
        const scalar t = shape->surfaceCrossing(r0, e, L);
        INFO("from " << show(r0) << " to " << show(r1));
        CHECK(shape->signedDistance(r0 + t*e, normal) == Approx(0).margin(1e-12));
        bool outside = true;
        bool inAndOut = false;
        for (label k = 1; k < 200; ++k)
        {
            outside = outside && shape->signedDistance(r0 + k*t/200*e, normal) > 0;
        }
        for (label k = 1; k < 200; ++k)
        {
            const point r(r0 + t*e + k*(L - t)/200*e);
            inAndOut = inAndOut || shape->signedDistance(r, normal) > 0;
        }
        CHECK(outside);
        nTwice += inAndOut;
    }
    CHECK(nTwice > 5);
}


TEST_CASE("2D shapes: solid fractions summed over a 2D grid give the area", "[2D]")
{
    // Square cells of 8 and 16 per smallest dimension, one cell deep,
    // fractions split in the plane only down to bounding radius/32,
    // centre at random offsets, turned by 0 and 0.7 rad about z: exact
    // for both shapes (the ellipse the unit circle in a parallelogram, the
    // polygon clipped by the cell); the general subdivision gave the
    // ellipse 1.4e-4 (aligned) and 1.3e-4 (turned) at both resolutions
    struct sample
    {
        string entries;
        scalar smallest;
        scalar tolerance;
    };
    const List<sample> samples
    ({
        {"shape ellipse; semiAxes (1 0.4);", 0.8, 1e-12},
        {"shape polygon; vertices ((0 0) (1 0) (0.3 0.7));", 0.7, 1e-12},
        {lShape, 1, 1e-12}
    });

    Random rnd(23);
    for (const sample& s : samples)
    {
        autoPtr<particleShape> shape(makeShape(s.entries));
        for (const label cells : {8, 16})
        {
            const scalar h = s.smallest/cells;
            for (const scalar angle : {0.0, 0.7})
            {
                for (label offset = 0; offset < 2; ++offset)
                {
                    const point X
                    (
                        h*rnd.sample01<scalar>(), h*rnd.sample01<scalar>(), 0
                    );
                    const scalar error =
                        gridArea(*shape, X, turn(angle), h)/shape->volume() - 1;
                    INFO
                    (
                        s.entries << ", " << cells << " cells, angle "
                     << angle << ", error " << error
                    );
                    CHECK(mag(error) < s.tolerance);
                }
            }
        }
    }
}


TEST_CASE("2D shapes: the ellipse's exact cell fractions", "[2D]")
{
    // With equal semi-axes, the disk's closed form; otherwise within the
    // general subdivision's error (leaves of 1/512 of the size: 1e-3 of
    // a cell cut by the surface)
    autoPtr<particleShape> round(makeShape("shape ellipse; semiAxes (0.4 0.4);"));
    autoPtr<particleShape> disk(makeShape("shape disk; radius 0.4;"));
    autoPtr<particleShape> egg(makeShape("shape ellipse; semiAxes (0.8 0.3);"));
    Random rnd(29);
    label nCut = 0;
    for (label sample = 0; sample < 400; ++sample)
    {
        const point lo(1.8*rnd.sample01<scalar>() - 0.9, 1.8*rnd.sample01<scalar>() - 0.9, 0);
        const scalar h = 0.05 + 0.2*rnd.sample01<scalar>();
        const boundBox bb(lo, lo + vector(h, 0.7*h, 0.1));
        const point X(0.01, -0.02, 0.05);
        const tensor R(turn(6*rnd.sample01<scalar>()));
        INFO("cell from " << show(bb.min()) << " to " << show(bb.max()));
        CHECK
        (
            round->boxFraction(bb, X, R, vector(1, 1, 0), 0.4/32)
         == Approx(disk->boxFraction(bb, X, I, vector(1, 1, 0), 0.4/32)).margin(1e-12)
        );
        const scalar exact = egg->boxFraction(bb, X, R, vector(1, 1, 0), 0.8/32);
        const scalar subdivided =
            egg->particleShape::boxFraction(bb, X, R, vector(1, 1, 0), 0.8/512);
        CHECK(exact == Approx(subdivided).margin(1e-3));
        nCut += exact > 0 && exact < 1;
    }
    CHECK(nCut > 50);
}


TEST_CASE("2D shapes: parts beyond a line against closed forms", "[2D]")
{
    SECTION("ellipse: the circle's segment stretched")
    {
        // Beyond x = t a: area a b (acos t - t sqrt(1 - t^2)), chord
        // 2 b sqrt(1 - t^2), centroid 2 a (1 - t^2)^1.5/(3 (acos t -
        // t sqrt(1 - t^2))); along y the same with a and b swapped
        const scalar a = 0.8;
        const scalar b = 0.3;
        autoPtr<particleShape> shape(makeShape("shape ellipse; semiAxes (0.8 0.3);"));
        for (const scalar t : {-0.5, 0.0, 0.3, 0.99})
        {
            const scalar unitArea = Foam::acos(t) - t*Foam::sqrt(1 - sqr(t));
            const scalar cube = Foam::pow(1 - sqr(t), scalar(1.5));
            scalar A, chord;
            vector c;
            INFO("t " << t);
            REQUIRE(shape->planeCut(vector(1, 0, 0), t*a, A, c, chord));
            CHECK(A == Approx(a*b*unitArea).epsilon(1e-9));
            CHECK(chord == Approx(2*b*Foam::sqrt(1 - sqr(t))).epsilon(1e-9));
            CHECK(mag(c - vector(2*a*cube/(3*unitArea), 0, 0)) < 1e-9*a);
            shape->planeCut(vector(0, -1, 0), t*b, A, c, chord);
            CHECK(A == Approx(a*b*unitArea).epsilon(1e-9));
            CHECK(chord == Approx(2*a*Foam::sqrt(1 - sqr(t))).epsilon(1e-9));
            CHECK(mag(c - vector(0, -2*b*cube/(3*unitArea), 0)) < 1e-9*b);
        }
        // A tiny segment, as a stiff contact's, to full relative precision:
        // the leading term 4 sqrt(2)/3 a b (1 - t)^1.5
        scalar A, chord;
        vector c;
        shape->planeCut(vector(1, 0, 0), (1 - 1e-8)*a, A, c, chord);
        CHECK(A == Approx(4*Foam::sqrt(2.0)/3*a*b*Foam::pow(1e-8, 1.5)).epsilon(1e-7));
        // Through the centre: half, whatever the direction
        shape->planeCut(vector(0.6, 0.8, 0), 0, A, c, chord);
        CHECK(A == Approx(0.5*shape->volume()).epsilon(1e-12));
        // A plane parallel to the mesh plane cuts all or nothing
        shape->planeCut(vector(0, 0, 1), -0.1, A, c, chord);
        CHECK(A == shape->volume());
        shape->planeCut(vector(0, 0, 1), 0.1, A, c, chord);
        CHECK(A == 0);
    }
    SECTION("polygons by hand")
    {
        scalar A, chord;
        vector c;
        // Unit square about its centre: a slab and a corner
        autoPtr<particleShape> square
        (
            makeShape("shape polygon; vertices ((0 0) (1 0) (1 1) (0 1));")
        );
        square->planeCut(vector(1, 0, 0), 0.3, A, c, chord);
        CHECK(A == Approx(0.2).epsilon(1e-13));
        CHECK(chord == Approx(1).epsilon(1e-13));
        CHECK(mag(c - vector(0.4, 0, 0)) < 1e-13);
        const vector diagonal(vector(1, 1, 0)/Foam::sqrt(2.0));
        const scalar leg = 0.2;
        square->planeCut(diagonal, (1 - leg)/Foam::sqrt(2.0), A, c, chord);
        CHECK(A == Approx(0.5*sqr(leg)).epsilon(1e-12));
        CHECK(chord == Approx(leg*Foam::sqrt(2.0)).epsilon(1e-12));
        CHECK(mag(c - (vector(0.5, 0.5, 0) - leg/3*vector(1, 1, 0))) < 1e-13);
        // A tiny corner, as a stiff contact's: full relative precision
        const scalar tiny = 1e-7;
        square->planeCut(diagonal, (1 - tiny)/Foam::sqrt(2.0), A, c, chord);
        CHECK(A == Approx(0.5*sqr(tiny)).epsilon(1e-6));

        // The U above its notch's bottom: two squares, the line inside it
        // twice
        autoPtr<particleShape> u(makeShape(uShape));
        const vector uCentroid(1.5, 0.9, 0);   // (6 (1.5 1) - 1 (1.5 1.5))/5
        u->planeCut(vector(0, 1, 0), 1.5 - uCentroid.y(), A, c, chord);
        CHECK(A == Approx(1).epsilon(1e-13));
        CHECK(chord == Approx(2).epsilon(1e-13));
        CHECK(mag(c - (vector(1.5, 1.75, 0) - uCentroid)) < 1e-13);
        // Below it, seen from the centroid along -y
        u->planeCut(vector(0, -1, 0), uCentroid.y() - 0.5, A, c, chord);
        CHECK(A == Approx(1.5).epsilon(1e-13));
        CHECK(chord == Approx(3).epsilon(1e-13));
        CHECK(mag(c - (vector(1.5, 0.25, 0) - uCentroid)) < 1e-13);
    }
}


TEST_CASE("2D contacts: the equivalent radius of a small cut is the curvature's", "[2D]")
{
    // The contact laws' small-overlap relations (dV/ddepth = section)
    // hold for the radius equivalentRadius gives: a disk's segment and a
    // sphere's cap of depth 1e-6 R give R to 1e-6, an ellipse's segment
    // at its major axis' end the curvature radius b^2/a there
    const scalar R = 0.7;
    const scalar depth = 1e-6*R;
    scalar A, chord;
    vector c;
    autoPtr<particleShape> disk(makeShape("shape disk; radius 0.7;"));
    disk->planeCut(vector(0, 1, 0), R - depth, A, c, chord);
    CHECK(overlapGeometry::equivalentRadius(chord, A, 2) == Approx(R).epsilon(2e-6));
    autoPtr<particleShape> sphere(makeShape("shape sphere; radius 0.7;"));
    sphere->planeCut(vector(0, 1, 0), R - depth, A, c, chord);
    CHECK(overlapGeometry::equivalentRadius(chord, A, 3) == Approx(R).epsilon(2e-6));
    autoPtr<particleShape> ellipse(makeShape("shape ellipse; semiAxes (0.8 0.3);"));
    ellipse->planeCut(vector(1, 0, 0), 0.8 - depth, A, c, chord);
    CHECK(overlapGeometry::equivalentRadius(chord, A, 2) == Approx(0.09/0.8).epsilon(1e-5));
}


TEST_CASE("2D shapes: cuts and supports against sums over a fine grid", "[2D]")
{
    // Midpoint sums over n^2 points of a grid turned by 0.1234 rad (not
    // along any edge): the cut area and centroid, the chord as the area's
    // change over a small move of the line, the support as the farthest
    // point
    const std::string shapes[] =
    {
        "shape ellipse; semiAxes (1 0.4);",
        "shape disk; radius 0.7;",
        "shape polygon; vertices ((-0.5 -0.3) (0.6 -0.2) (0.1 0.5));",
        lShape,
        uShape
    };
    const vector normals[] =
    {
        vector(1, 0, 0), vector(0.6, -0.8, 0), vector(-0.28, 0.96, 0),
        vector(1, 1, 0)/Foam::sqrt(2.0)
    };
    const label n = 800;
    for (const std::string& entries : shapes)
    {
        autoPtr<particleShape> shape(makeShape(entries));
        const scalar Rb = shape->boundingRadius();
        const scalar h = 2*Rb/n;
        DynamicList<point> inside;
        for (label i = 0; i < n; ++i)
        {
            for (label j = 0; j < n; ++j)
            {
                const point r
                (
                    turn(0.1234) & point(h*(i + 0.5) - Rb, h*(j + 0.5) - Rb, 0)
                );
                vector normal;
                if (shape->signedDistance(r, normal) < 0)
                {
                    inside.append(r);
                }
            }
        }
        CHECK(inside.size()*sqr(h) == Approx(shape->volume()).epsilon(5e-3));
        for (const vector& nu : normals)
        {
            INFO(entries << " normal " << show(nu));
            const scalar reach =
                shapeChecks::checkSupportReach(*shape, nu, inside, h);
            for (const scalar fraction : {0.3, 0.8})
            {
                const scalar d = reach*(1 - fraction);
                scalar A, chord;
                vector centroid;
                REQUIRE(shape->planeCut(nu, d, A, centroid, chord));
                scalar sumA = 0;
                vector sumC(Zero);
                for (const point& r : inside)
                {
                    if ((r & nu) > d)
                    {
                        sumA += sqr(h);
                        sumC += sqr(h)*r;
                    }
                }
                INFO("distance " << d << ": area " << A << " (grid " << sumA
                    << "), chord " << chord);
                CHECK(mag(A - sumA) < 0.5*h*chord + 0.005*A);
                CHECK(mag(centroid - sumC/sumA) < 2*h);
                const scalar dd = 1e-6*reach;
                scalar Aminus, Aplus, unused;
                vector c;
                shape->planeCut(nu, d - dd, Aminus, c, unused);
                shape->planeCut(nu, d + dd, Aplus, c, unused);
                CHECK(chord == Approx((Aminus - Aplus)/(2*dd)).epsilon(1e-5));
            }
        }
    }
}


TEST_CASE("2D shapes: the common-plane overlap searches the mesh plane", "[2D]")
{
    const convexOverlap convex;
    const point Xa(0.01, 0.02, 0.05);

    SECTION("equal ellipses tip to tip: the exact lens")
    {
        // The common line halfway: each part the segment beyond x = d/2
        autoPtr<particleShape> a(makeShape("shape ellipse; semiAxes (0.8 0.3);"));
        // (Closer than 1.375, where the ellipses' elongation makes an
        // oblique direction the least deep, the common line would tilt)
        for (const scalar d : {1.59, 1.5, 1.4})
        {
            const convexOverlap::result o =
                convex.overlap(a(), Xa, I, a(), Xa + vector(d, 0, 0), I);
            const scalar t = 0.5*d/0.8;
            const scalar lens =
                2*0.8*0.3*(Foam::acos(t) - t*Foam::sqrt(1 - sqr(t)));
            INFO("d " << d);
            CHECK(o.depth == Approx(1.6 - d).epsilon(1e-10));
            // The depth is flat about its least (to second order): the
            // normal found to 1e-6 rad, the depth to round-off
            CHECK(mag(o.normal - vector(1, 0, 0)) < 1e-6);
            CHECK(o.volume == Approx(lens).epsilon(1e-8));
            CHECK(o.sectionArea == Approx(2*0.3*Foam::sqrt(1 - sqr(t))).epsilon(1e-8));
            CHECK(mag(o.location - (Xa + vector(0.5*d, 0, 0))) < 1e-8);
        }
    }
    SECTION("a square's face on a larger square's, turned with it")
    {
        // Both turned by 0.3 rad: the small square's face (side 0.4) 0.05
        // into the large one's
        autoPtr<particleShape> large
        (
            makeShape("shape polygon; vertices ((-0.5 -0.5) (0.5 -0.5) (0.5 0.5) (-0.5 0.5));")
        );
        autoPtr<particleShape> small
        (
            makeShape("shape polygon; vertices ((-0.2 -0.2) (0.2 -0.2) (0.2 0.2) (-0.2 0.2));")
        );
        const tensor R(turn(0.3));
        const vector up(R & vector(0, 1, 0));
        const convexOverlap::result o = convex.overlap
        (
            large(), Xa, R, small(), Xa + (0.7 - 0.05)*up + 0.1*(R & vector(1, 0, 0)), R
        );
        CHECK(o.depth == Approx(0.05).epsilon(1e-9));
        CHECK(mag(o.normal - up) < 1e-9);
        CHECK(o.volume == Approx(0.4*0.05).epsilon(1e-6));
    }
    SECTION("polygons and ellipses at angles: no in-plane direction overlaps less")
    {
        const std::string triangle("shape polygon; vertices ((-0.5 -0.3) (0.6 -0.2) (0.1 0.5));");
        const std::string egg("shape ellipse; semiAxes (0.6 0.25);");
        const std::pair<std::string, std::string> pairs[] =
        {
            {triangle, triangle}, {triangle, egg}, {egg, egg},
            {egg, "shape disk; radius 0.3;"}
        };
        for (const auto& p : pairs)
        {
            autoPtr<particleShape> a(makeShape(p.first));
            autoPtr<particleShape> b(makeShape(p.second));
            const tensor Ra(turn(0.4));
            const tensor Rb(turn(-1.1));
            for (const vector& e : {vector(1, 0, 0), vector(0.6, 0.8, 0)})
            {
                // b along e, 0.05 deep
                scalar near = 0;
                scalar far = a->boundingRadius() + b->boundingRadius();
                for (label iter = 0; iter < 60; ++iter)
                {
                    const scalar s = 0.5*(near + far);
                    const bool deeper =
                        convex.overlap(a(), Xa, Ra, b(), Xa + s*e, Rb).depth
                      > 0.05;
                    (deeper ? near : far) = s;
                }
                const point Xb(Xa + 0.5*(near + far)*e);
                const convexOverlap::result o =
                    convex.overlap(a(), Xa, Ra, b(), Xb, Rb);
                INFO(p.first << " and " << p.second << " along " << show(e));
                REQUIRE(o.depth == Approx(0.05).epsilon(1e-6));
                CHECK(o.normal.z() == 0);
                scalar least = GREAT;
                for (label k = 0; k < 100000; ++k)
                {
                    const scalar t = 2*pi*k/100000;
                    least = min
                    (
                        least,
                        convexOverlap::depth
                        (
                            a(), Xa, Ra, b(), Xb, Rb,
                            vector(Foam::cos(t), Foam::sin(t), 0)
                        )
                    );
                }
                CHECK(o.depth <= least + 1e-12);
                CHECK(o.volume > 0);
                CHECK(o.sectionArea > 0);
            }
        }
    }
}


TEST_CASE("2D shapes: their input is checked", "[2D]")
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const auto particle = [](const std::string& text)
    {
        IStringStream is(text + " density 2; position (0 0 0);");
        dictionary dict(is);
        dict.name() = "particleProperties.particles.p0";
        return dlmParticle(dict);
    };
    const auto message = [&](const std::string& text)
    {
        try
        {
            particle(text);
        }
        catch (const Foam::error& err)
        {
            return std::string(err.message());
        }
        return std::string("accepted");
    };

    CHECK_NOTHROW(particle("shape ellipse; semiAxes (0.1 0.2);"));
    CHECK_NOTHROW(particle("shape polygon; vertices ((0 0) (1 0) (0 1));"));
    CHECK_NOTHROW(particle("shape polygon; vertices ((0 0) (0 1) (1 0));"));
    CHECK_NOTHROW(particle(lShape));

    CHECK_THAT(message("shape ellipse; semiAxes (0.1 0);"), Catch::Contains("semiAxes (0.1 0) of particle p0 must both be positive"));
    CHECK_THAT(message("shape ellipse; semiAxes (0.1 -0.2);"), Catch::Contains("must both be positive"));
    CHECK_THROWS(particle("shape ellipse; semiAxes (0.1 0.2 0.3);"));
    CHECK_THROWS(particle("shape ellipse; radius 0.1;"));

    CHECK_THAT
    (
        message("shape polygon; vertices ((0 0) (1 0));"),
        Catch::Contains("vertices of particle p0") && Catch::Contains("at least 3 vertices, 2 given")
    );
    // A bow tie, an edge through a vertex, a spike folding back
    CHECK_THAT
    (
        message("shape polygon; vertices ((0 0) (2 2) (2 0) (0 1));"),
        Catch::Contains("vertices of particle p0") && Catch::Contains("intersects itself: edge 0-1 meets edge 2-3")
    );
    CHECK_THAT
    (
        message("shape polygon; vertices ((0 0) (2 0) (2 2) (1 0) (0 2));"),
        Catch::Contains("intersects itself")
    );
    CHECK_THAT
    (
        message("shape polygon; vertices ((0 0) (2 0) (2 1) (3 1) (1 1) (0 1));"),
        Catch::Contains("intersects itself")
    );
    CHECK_THAT
    (
        message("shape polygon; vertices ((0 0) (1 1) (2 2));"),
        Catch::Contains("vertices of particle p0") && Catch::Contains("zero area")
    );
    CHECK_THAT
    (
        message("shape polygon; vertices ((0 0) (1 0) (1 0) (0 1));"),
        Catch::Contains("vertex 2 repeats vertex 1")
    );
    CHECK_THROWS(particle("shape polygon; vertices ((0 0 0) (1 0 0) (0 1 0));"));

    FatalError.dontThrowExceptions();
    FatalIOError.dontThrowExceptions();
}


// ************************************************************************* //
