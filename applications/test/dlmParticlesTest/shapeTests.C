/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Description
    Tests of the non-spherical particle shapes (ellipsoid, cylinder, box):
    volume and inertia against closed forms, signed distances at chosen
    points, the ellipsoid with equal semi-axes against the sphere, line
    crossings, plane overlaps, and the volume fractions on grids of box
    cells at two resolutions and two orientations.

\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>

#include "particleShape.H"
#include "convexOverlap.H"
#include "overlapGeometry.H"
#include "shapeChecks.H"
#include "dlmParticle.H"
#include "Random.H"
#include "quaternion.H"
#include "mathematicalConstants.H"
#include "IStringStream.H"
#include "OStringStream.H"

using namespace Foam;
using constant::mathematical::pi;
using shapeChecks::show;
using shapeChecks::gridVolume;

namespace
{

autoPtr<particleShape> makeShape(const string& entries)
{
    IStringStream is(entries);
    const dictionary dict(is);
    return particleShape::New(dict);
}


// Signed distance and normal at r, checked as a closest point: r minus the
// signed distance along the normal is on the surface, where the normal is
// the surface's
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
}

} // End anonymous namespace


TEST_CASE("shape volumes and inertias have their closed forms", "[geometry]")
{
    SECTION("ellipsoid")
    {
        autoPtr<particleShape> shape
        (
            makeShape("shape ellipsoid; semiAxes (1 0.6 0.3);")
        );
        const scalar V = 4.0/3.0*pi*1*0.6*0.3;
        CHECK(shape->volume() == Approx(V).epsilon(1e-14));
        CHECK(shape->boundingRadius() == 1);
        CHECK(shape->nDimensions() == 3);
        const symmTensor I(shape->inertiaPerUnitDensity());
        CHECK(I.xx() == Approx(V/5*(0.36 + 0.09)).epsilon(1e-14));
        CHECK(I.yy() == Approx(V/5*(1 + 0.09)).epsilon(1e-14));
        CHECK(I.zz() == Approx(V/5*(1 + 0.36)).epsilon(1e-14));
        CHECK(I.xy() == 0);
        CHECK(I.xz() == 0);
        CHECK(I.yz() == 0);
    }
    SECTION("cylinder")
    {
        autoPtr<particleShape> shape
        (
            makeShape("shape cylinder; radius 0.4; length 1.5;")
        );
        const scalar V = pi*sqr(0.4)*1.5;
        CHECK(shape->volume() == Approx(V).epsilon(1e-14));
        CHECK(shape->boundingRadius() == Approx(0.85).epsilon(1e-14));
        const symmTensor I(shape->inertiaPerUnitDensity());
        // Rod about its middle plus disk about a diameter; disk about its axis
        const scalar transverse = V*sqr(1.5)/12 + V*sqr(0.4)/4;
        CHECK(I.xx() == Approx(transverse).epsilon(1e-14));
        CHECK(I.yy() == Approx(transverse).epsilon(1e-14));
        CHECK(I.zz() == Approx(V*sqr(0.4)/2).epsilon(1e-14));
        CHECK(I.xy() == 0);
        CHECK(I.xz() == 0);
        CHECK(I.yz() == 0);
    }
    SECTION("box")
    {
        autoPtr<particleShape> shape
        (
            makeShape("shape box; halfExtents (0.5 0.3 0.2);")
        );
        // Sides 1, 0.6 and 0.4: m (w^2 + h^2)/12
        const scalar V = 1*0.6*0.4;
        CHECK(shape->volume() == Approx(V).epsilon(1e-14));
        CHECK(shape->boundingRadius() == Approx(Foam::sqrt(0.38)).epsilon(1e-14));
        const symmTensor I(shape->inertiaPerUnitDensity());
        CHECK(I.xx() == Approx(V*(0.36 + 0.16)/12).epsilon(1e-14));
        CHECK(I.yy() == Approx(V*(1 + 0.16)/12).epsilon(1e-14));
        CHECK(I.zz() == Approx(V*(1 + 0.36)/12).epsilon(1e-14));
        CHECK(I.xy() == 0);
        CHECK(I.xz() == 0);
        CHECK(I.yz() == 0);
    }
}


TEST_CASE("an ellipsoid with equal semi-axes is the sphere", "[geometry]")
{
    autoPtr<particleShape> ellipsoid
    (
        makeShape("shape ellipsoid; semiAxes (0.7 0.7 0.7);")
    );
    autoPtr<particleShape> sphere(makeShape("shape sphere; radius 0.7;"));

    CHECK(ellipsoid->volume() == Approx(sphere->volume()).epsilon(1e-14));
    CHECK(ellipsoid->boundingRadius() == sphere->boundingRadius());
    const symmTensor Ie(ellipsoid->inertiaPerUnitDensity());
    const symmTensor Is(sphere->inertiaPerUnitDensity());
    for (direction d = 0; d < symmTensor::nComponents; ++d)
    {
        CHECK(Ie[d] == Approx(Is[d]).epsilon(1e-14).margin(1e-15));
    }

    Random rnd(3);
    for (label sample = 0; sample < 200; ++sample)
    {
        // Inside and outside, on and off the symmetry planes
        vector r(2*rnd.sample01<vector>() - vector::one);
        if (sample % 4 == 0)
        {
            r[sample % 3] = 0;
        }
        vector ne, ns;
        const scalar de = ellipsoid->signedDistance(r, ne);
        const scalar ds = sphere->signedDistance(r, ns);
        INFO("r " << show(r));
        CHECK(de == Approx(ds).margin(1e-12));
        CHECK(mag(ne - ns) < 1e-12);
    }
}


TEST_CASE("signed distances at chosen points", "[geometry]")
{
    SECTION("box, half extents (0.5 0.3 0.2)")
    {
        autoPtr<particleShape> shape
        (
            makeShape("shape box; halfExtents (0.5 0.3 0.2);")
        );
        // Inside: the nearest face
        checkClosestPoint(*shape, vector(0, 0, 0), -0.2, vector(0, 0, 1));
        checkClosestPoint(*shape, vector(0.4, 0, 0), -0.1, vector(1, 0, 0));
        checkClosestPoint(*shape, vector(0, -0.25, 0.1), -0.05, vector(0, -1, 0));
        // Outside: a face, an edge, a corner
        checkClosestPoint(*shape, vector(0.6, 0.1, 0), 0.1, vector(1, 0, 0));
        checkClosestPoint(*shape, vector(0.8, 0.7, 0), 0.5, vector(0.6, 0.8, 0));
        checkClosestPoint
        (
            *shape, vector(-0.6, 0.5, -0.4), 0.3, vector(-1, 2, -2)/3
        );
    }
    SECTION("cylinder, radius 0.4, length 1.5")
    {
        autoPtr<particleShape> shape
        (
            makeShape("shape cylinder; radius 0.4; length 1.5;")
        );
        // On the axis, inside and outside
        checkClosestPoint(*shape, vector(0, 0, 0.5), -0.25, vector(0, 0, 1));
        checkClosestPoint(*shape, vector(0, 0, -1), 0.25, vector(0, 0, -1));
        // Inside, nearer an end than the mantle, and the reverse
        checkClosestPoint(*shape, vector(0.3, 0, 0.7), -0.05, vector(0, 0, 1));
        checkClosestPoint(*shape, vector(0, 0.3, -0.1), -0.1, vector(0, 1, 0));
        // Outside the mantle and beyond the rim
        checkClosestPoint(*shape, vector(0, 0.7, 0.1), 0.3, vector(0, 1, 0));
        checkClosestPoint(*shape, vector(0.7, 0, 1.15), 0.5, vector(0.6, 0, 0.8));
        checkClosestPoint
        (
            *shape, vector(-0.42, -0.56, -0.75 - 0.3),
            Foam::sqrt(sqr(0.3) + sqr(0.3)),
            vector(-0.6, -0.8, -1)/Foam::sqrt(2.0)
        );
    }
    SECTION("ellipsoid, semi-axes (1 0.6 0.3)")
    {
        autoPtr<particleShape> shape
        (
            makeShape("shape ellipsoid; semiAxes (1 0.6 0.3);")
        );
        // On the axes: the axis ends, and from the centre the nearest one
        checkClosestPoint(*shape, vector(2, 0, 0), 1, vector(1, 0, 0));
        checkClosestPoint(*shape, vector(0, -0.7, 0), 0.1, vector(0, -1, 0));
        checkClosestPoint(*shape, vector(0, 0, 0.5), 0.2, vector(0, 0, 1));
        checkClosestPoint(*shape, vector(0, 0, 0.1), -0.2, vector(0, 0, 1));
        checkClosestPoint(*shape, vector(0, 0, 0), -0.3, vector(0, 0, 1));

        // Inside on the major axis the nearest point is off it, where the
        // circle about r touches the ellipse of the x-z plane:
        // x = a^2 r/(a^2 - c^2), z = c sqrt(1 - (x/a)^2)
        const scalar x = 0.5/(1 - 0.09);
        const scalar z = 0.3*Foam::sqrt(1 - sqr(x));
        const vector toSurface(x - 0.5, 0, z);
        const vector gradient(x, 0, z/0.09);
        checkClosestPoint
        (
            *shape, vector(0.5, 0, 0), -mag(toSurface), gradient/mag(gradient)
        );

        // At random points: r minus the distance along the normal lies on
        // the surface, where the normal is the surface's, and no sampled
        // surface point is nearer
        Random rnd(11);
        const vector e(1, 0.6, 0.3);
        for (label sample = 0; sample < 50; ++sample)
        {
            const vector r(cmptMultiply(2*rnd.sample01<vector>() - vector::one, 1.3*e));
            vector normal;
            const scalar d = shape->signedDistance(r, normal);
            const vector x(r - d*normal);
            const vector u(cmptDivide(x, e));
            const vector grad(cmptDivide(u, e));
            INFO("r " << show(r));
            CHECK(magSqr(u) == Approx(1).margin(1e-12));
            CHECK(mag(normal - grad/mag(grad)) < 1e-10);
            CHECK((d < 0) == (magSqr(cmptDivide(r, e)) < 1));

            scalar nearest = GREAT;
            const label n = 400;
            for (label i = 0; i <= n; ++i)
            {
                const scalar theta = pi*i/n;
                for (label j = 0; j < 2*n; ++j)
                {
                    const scalar phi = pi*j/n;
                    const vector s
                    (
                        e.x()*Foam::sin(theta)*Foam::cos(phi),
                        e.y()*Foam::sin(theta)*Foam::sin(phi),
                        e.z()*Foam::cos(theta)
                    );
                    nearest = min(nearest, mag(r - s));
                }
            }
            // Sampling spacing 0.008 at most: the nearest sample is within
            // 1e-4 of the nearest point
            CHECK(mag(d) <= nearest + 1e-12);
            CHECK(mag(d) == Approx(nearest).margin(1e-4));
        }
    }
}


TEST_CASE("non-spherical line crossings agree with the general root finding", "[geometry]")
{
    Random rnd(5);
    for
    (
        const string entries
      : {
            "shape ellipsoid; semiAxes (0.6 0.4 0.25);",
            "shape cylinder; radius 0.3; length 0.9;",
            "shape box; halfExtents (0.5 0.3 0.2);"
        }
    )
    {
        autoPtr<particleShape> shape(makeShape(entries));
        shapeChecks::checkLineCrossings(shape(), rnd, 400);
    }
}


TEST_CASE("plane overlaps of the ellipsoid and the box", "[geometry]")
{
    // An ellipsoid's cap is the unit sphere's cap scaled by abc: beyond the
    // plane x = 0.5 a, the cap of depth 0.5 of the unit sphere
    autoPtr<particleShape> ellipsoid
    (
        makeShape("shape ellipsoid; semiAxes (1 0.6 0.3);")
    );
    const scalar unitCap = pi*sqr(0.5)*(3 - 0.5)/3;
    CHECK
    (
        ellipsoid->planeOverlap(vector(1, 0, 0), 0.5)
     == Approx(0.18*unitCap).epsilon(1e-12)
    );
    CHECK
    (
        ellipsoid->planeOverlap(vector(0, 0, 1), 0.15)
     == Approx(0.18*unitCap).epsilon(1e-12)
    );
    // Through the centroid: half, whatever the normal
    CHECK
    (
        ellipsoid->planeOverlap(vector(1, 2, 2)/3, 0)
     == Approx(0.5*ellipsoid->volume()).epsilon(1e-12)
    );

    autoPtr<particleShape> box
    (
        makeShape("shape box; halfExtents (0.5 0.3 0.2);")
    );
    // A slab along a face, a corner cut off (a tetrahedron with legs 0.3)
    CHECK
    (
        box->planeOverlap(vector(0, 1, 0), 0.1)
     == Approx(1*0.2*0.4).epsilon(1e-12)
    );
    const vector n(vector::one/Foam::sqrt(3.0));
    const point corner(0.5, 0.3, 0.2);
    CHECK
    (
        box->planeOverlap(n, (corner & n) - 0.3/Foam::sqrt(3.0))
     == Approx(pow3(0.3)/6).epsilon(1e-12)
    );
}


TEST_CASE("plane cuts and support functions against sums over a fine grid", "[geometry]")
{
    // Midpoint sums over a grid of n^3 points on the bounding box: the cut
    // volume and centroid, the section area from the exact volume's change
    // over a small move of the plane, and the support as the farthest point
    const std::string shapes[] =
    {
        "shape ellipsoid; semiAxes (1 0.6 0.3);",
        "shape box; halfExtents (0.5 0.3 0.2);",
        "shape cylinder; radius 0.4; length 0.6;",
        "shape box; halfExtents (0.5 0.3 0.2); edgeRadius 0.1;"
    };
    const vector normals[] =
    {
        vector(0, 0, 1), vector(1, 2, 2)/3, vector(0.2, -0.5, 0.8),
        vector(0.6, -0.8, 0), vector(0.1, 0.2, -0.9)
    };
    const label n = 160;
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
                for (label k = 0; k < n; ++k)
                {
                    const point r(h*vector(i + 0.5, j + 0.5, k + 0.5) - Rb*vector::one);
                    vector normal;
                    if (shape->signedDistance(r, normal) < 0)
                    {
                        inside.append(r);
                    }
                }
            }
        }
        const scalar cellVolume = pow3(h);
        for (const vector& nRaw : normals)
        {
            const vector nu(nRaw/mag(nRaw));
            INFO(entries << " normal " << show(nu));
            const scalar reach =
                shapeChecks::checkSupportReach(*shape, nu, inside, h);

            for (const scalar fraction : {0.3, 0.8})
            {
                const scalar d = reach*(1 - fraction);
                scalar V, area;
                vector centroid;
                REQUIRE(shape->planeCut(nu, d, V, centroid, area));
                CHECK(V == Approx(shape->planeOverlap(nu, d)).epsilon(1e-12));

                scalar sumV = 0;
                vector sumC(Zero);
                for (const point& r : inside)
                {
                    if ((r & nu) > d)
                    {
                        sumV += cellVolume;
                        sumC += cellVolume*r;
                    }
                }
                INFO("distance " << d << ": volume " << V << " (grid "
                    << sumV << "), section " << area);
                // The grid's error: up to half a spacing of the section
                // (the plane between two layers of points)
                CHECK(mag(V - sumV) < 0.5*h*area + 0.01*V);
                CHECK(mag(centroid - sumC/sumV) < h);

                const scalar dd = 1e-6*reach;
                const scalar slope =
                    (shape->planeOverlap(nu, d - dd)
                   - shape->planeOverlap(nu, d + dd))/(2*dd);
                CHECK(area == Approx(slope).epsilon(1e-5));
            }
        }
    }
}


TEST_CASE("a cylinder cut nearly along its axis: the same part as along it", "[geometry]")
{
    // A plane tilted by 1e-15 to 1e-2 from the axis: the part beyond it
    // changes smoothly from the exact segment prism (the closed forms
    // divided by the tilt lost all precision below 1e-8)
    autoPtr<particleShape> shape(makeShape("shape cylinder; radius 0.4; length 0.6;"));
    const scalar d = 0.39;
    scalar V0, area0;
    vector c0;
    shape->planeCut(vector(1, 0, 0), d, V0, c0, area0);
    CHECK(V0 == Approx(0.6*overlapGeometry::circleSegmentArea(0.4, 0.01)).epsilon(1e-12));
    for (const scalar tilt : {1e-15, 1e-12, 1e-9, 1e-6, 1e-4, 1e-2})
    {
        const vector n(Foam::cos(tilt), 0, Foam::sin(tilt));
        scalar V, area;
        vector c;
        shape->planeCut(n, d, V, c, area);
        INFO("tilt " << tilt << ": volume " << V << ", section " << area);
        // The segment's prism cut by the tilted plane: its volume changes
        // at second order (0.058 tilt^2 here), its section at first, and
        // its centroid at first along the axis (c0 L^3/(6 V) = 4.5 tilt)
        CHECK(mag(V - V0) < 1e-12*V0 + 0.1*sqr(tilt));
        CHECK(mag(area - area0) < 1e-9*area0 + tilt*area0);
        CHECK(mag(c - c0) < 1e-9 + 5*tilt);
    }
}


TEST_CASE("convex overlaps: the sphere lens exactly, other pairs against fine-grid sums", "[geometry]")
{
    const convexOverlap convex;

    SECTION("two spheres: the lens, its plane and the centre line")
    {
        autoPtr<particleShape> a(makeShape("shape sphere; radius 1;"));
        autoPtr<particleShape> b(makeShape("shape sphere; radius 0.6;"));
        const vector e(vector(1, -2, 2)/3);
        for (const scalar d : {1.59, 1.5, 1.2})
        {
            const convexOverlap::result o = convex.overlap
            (
                a(), point(0.1, 0.2, 0.3), I,
                b(), point(0.1, 0.2, 0.3) + d*e, I
            );
            INFO("d " << d);
            CHECK(o.volume == Approx(overlapGeometry::sphereLensVolume(1, 0.6, d)).epsilon(1e-8));
            CHECK(o.depth == Approx(1.6 - d).epsilon(1e-10));
            CHECK(mag(o.normal - e) < 1e-8);
            const scalar plane = overlapGeometry::lensPlaneDistance(1, 0.6, d);
            CHECK(o.sectionArea == Approx(pi*(1 - sqr(plane))).epsilon(1e-8));
        }
    }

    SECTION("other shapes: least depth, volume and centroid")
    {
        struct pairCase
        {
            std::string a, b;
            quaternion qa, qb;
            vector direction;
            scalar tolerance;
        };
        const quaternion level(quaternion::I);
        const quaternion turned(vector(0, 0, 1), 0.5*pi);
        const quaternion tilted(vector(1, 2, 0)/Foam::sqrt(5.0), 0.6);
        const std::string egg("shape ellipsoid; semiAxes (1 0.6 0.3);");
        const std::string brick("shape box; halfExtents (0.5 0.3 0.2);");
        const std::string can("shape cylinder; radius 0.4; length 0.6;");
        const std::string rounded
        (
            "shape box; halfExtents (0.3 0.2 0.2); edgeRadius 0.1;"
        );
        // The tolerance of the volume (above 1 % of grid error): the
        // construction is exact for the lens of similar, aligned shapes and
        // for a face on a larger face; crossed or tilted shapes it
        // overestimates, most for crossed edges, whose caps are wedges
        // along the edges where the common part is a corner (measured: 14 %
        // for crossed ellipsoids, 3 % for a tilted ellipsoid on a sphere,
        // a factor 6.6 for a box's edge across another's, 43 % for a
        // cylinder's rim on a box, 44 % for a rounded box's edge across
        // another's)
        const pairCase cases[] =
        {
            {egg, egg, level, level, vector(0, 0, 1), 1e-3},
            {egg, egg, level, turned, vector(0, 0, 1), 0.2},
            {egg, "shape sphere; radius 0.5;", tilted, level, vector(0.3, 0.2, 0.8), 0.05},
            {brick, "shape box; halfExtents (0.3 0.2 0.2);", level, level, vector(0, 0, 1), 1e-3},
            {brick, brick, tilted, level, vector(0.2, 0.1, 0.6), 6},
            {can, brick, tilted, level, vector(0.1, 0.3, 0.6), 0.5},
            {can, can, level, quaternion(vector(1, 0, 0), 0.5*pi), vector(0, 0.1, 1), 0.05},
            {brick, rounded, level, level, vector(0, 0, 1), 1e-3},
            {rounded, rounded, tilted, level, vector(0.2, 0.1, 0.6), 0.5}
        };
        for (const pairCase& c : cases)
        {
            autoPtr<particleShape> a(makeShape(c.a));
            autoPtr<particleShape> b(makeShape(c.b));
            const tensor Ra(c.qa.R());
            const tensor Rb(c.qb.R());
            const point Xa(0.01, 0.02, 0.03);

            // b along the direction, where the least depth is 0.05
            const vector e(c.direction/mag(c.direction));
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
            INFO(c.a << " and " << c.b << " along " << show(e));
            REQUIRE(o.depth == Approx(0.05).epsilon(1e-6));

            // No direction overlaps less
            Random rnd(7);
            scalar least = GREAT;
            for (label k = 0; k < 20000; ++k)
            {
                vector e(rnd.sample01<vector>() - 0.5*vector::one);
                e /= mag(e);
                least = min(least, convexOverlap::depth(a(), Xa, Ra, b(), Xb, Rb, e));
            }
            CHECK(o.depth <= least + 1e-12);

            // The common part by midpoint sums over the slab of thickness
            // depth between the two supporting planes normal to o.normal
            const vector n(o.normal);
            vector t1(n ^ vector(1, 0, 0));
            if (magSqr(t1) < 0.1)
            {
                t1 = n ^ vector(0, 1, 0);
            }
            t1 /= mag(t1);
            const vector t2(n ^ t1);
            const scalar base =
                (n & Xa) + a->support(Ra.T() & n) - o.depth;
            const scalar reach = a->boundingRadius();
            const label m = 300;
            const label layers = 30;
            const scalar hIn = 2*reach/m;
            const scalar hN = o.depth/layers;
            scalar sumV = 0;
            vector sumC(Zero);
            for (label i = 0; i < m; ++i)
            {
                for (label j = 0; j < m; ++j)
                {
                    for (label k = 0; k < layers; ++k)
                    {
                        const point r
                        (
                            ((Xa - (Xa & n)*n) + (base + (k + 0.5)*hN)*n)
                          + (-reach + (i + 0.5)*hIn)*t1
                          + (-reach + (j + 0.5)*hIn)*t2
                        );
                        vector normal;
                        if
                        (
                            a->signedDistance(Ra.T() & (r - Xa), normal) < 0
                         && b->signedDistance(Rb.T() & (r - Xb), normal) < 0
                        )
                        {
                            sumV += 1;
                            sumC += r;
                        }
                    }
                }
            }
            const point centroid(sumC/sumV);
            sumV *= sqr(hIn)*hN;
            INFO("volume " << o.volume << ", grid " << sumV << " (error "
                << (o.volume - sumV)/sumV << "); centroid "
                << show(o.location) << ", grid " << show(centroid));
            CHECK(o.volume > 0.99*sumV);
            CHECK(o.volume < (1.01 + c.tolerance)*sumV);
            CHECK(mag(o.location - centroid) < 0.3*reach);
        }
    }
}


TEST_CASE("the grid overlap converges to the common-plane overlap", "[geometry]")
{
    // The paper's overlap, max(0, phi_a + phi_b - 1) summed over the cells,
    // on cubic grids of 4, 8 and 16 cells across the shapes' smallest
    // dimension, for pairs whose common-plane overlap is exact (aligned
    // ellipsoids tip to tip, a box's face on a larger face): its error
    // falls at least as fast as the spacing (measured: 9.0, 3.0, 0.49 %
    // and 6.7, 3.0, 0.77 %)
    const convexOverlap convex;
    const quaternion level(quaternion::I);
    const std::pair<std::string, std::string> pairs[] =
    {
        {"shape ellipsoid; semiAxes (0.6 0.45 0.3);", "shape ellipsoid; semiAxes (0.6 0.45 0.3);"},
        {"shape box; halfExtents (0.5 0.4 0.3);", "shape box; halfExtents (0.4 0.3 0.3);"}
    };
    for (const auto& names : pairs)
    {
        autoPtr<particleShape> a(makeShape(names.first));
        autoPtr<particleShape> b(makeShape(names.second));
        const point Xa(0.013, 0.021, 0.017);
        const point Xb(Xa + vector(0, 0, 0.6 - 0.12));
        const convexOverlap::result o = convex.overlap(a(), Xa, I, b(), Xb, I);
        REQUIRE(o.depth == Approx(0.12).epsilon(1e-9));

        scalar lastError = GREAT;
        for (const label perMinor : {4, 8, 16})
        {
            const scalar h = 0.6/perMinor;
            const scalar reach = a->boundingRadius() + h;
            const label n = label(std::ceil(2*reach/h));
            const point origin(o.location - reach*vector::one);
            scalar sum = 0;
            for (label i = 0; i < n; ++i)
            {
                for (label j = 0; j < n; ++j)
                {
                    for (label k = 0; k < n; ++k)
                    {
                        const point lo(origin + h*vector(i, j, k));
                        const boundBox bb(lo, lo + h*vector::one);
                        const scalar phiA = a->boxFraction
                        (
                            bb, Xa, I, vector::one, a->boundingRadius()/32
                        );
                        const scalar phiB = b->boxFraction
                        (
                            bb, Xb, I, vector::one, b->boundingRadius()/32
                        );
                        sum += max(phiA + phiB - 1, scalar(0))*bb.volume();
                    }
                }
            }
            const scalar error = mag(sum - o.volume)/o.volume;
            INFO(names.first << " and " << names.second << ": " << perMinor
                << " cells across, grid " << sum << " against " << o.volume
                << " (" << 100*error << " %)");
            CHECK(error < 0.6*lastError);
            lastError = error;
        }
        CHECK(lastError < 0.01);
    }
}


TEST_CASE("non-spherical fractions integrate to the volume", "[geometry]")
{
    // Cubic cells of 8 and 16 per smallest dimension, fractions subdivided
    // down to the solver's default leaf (bounding radius/32), centre at a
    // random offset, axes along the mesh's and rotated by 0.7 rad about
    // (1 2 3). Relative errors measured (the same to 3 digits at both
    // resolutions and every offset: the leaves are as large at both, and
    // the tangent planes of a convex surface add volume):
    //                 aligned     rotated
    //   ellipsoid     3.3e-4      3.3e-4
    //   ellipsoid 2:1 6.7e-4      6.7e-4   (the shapes of validation/
    //   ellipsoid 4:1 2.2e-3      2.2e-3    benchmark_shapeFractions.py)
    //   cylinder      3.1e-4      6.1e-4
    //   box           1e-13       3.9e-4   (aligned: exact fraction)
    //   rounded box   3.3e-4      3.3e-4   (edgeRadius 0.1)
    struct sample
    {
        string entries;
        scalar smallest;
        scalar alignedTolerance;
        scalar rotatedTolerance;
    };
    const List<sample> samples
    ({
        {"shape ellipsoid; semiAxes (1 0.6 0.3);", 0.6, 5e-4, 5e-4},
        {"shape ellipsoid; semiAxes (0.5 0.25 0.25);", 0.5, 1e-3, 1e-3},
        {"shape ellipsoid; semiAxes (1 0.25 0.25);", 0.5, 3e-3, 3e-3},
        {"shape cylinder; radius 0.4; length 1.5;", 0.8, 5e-4, 1e-3},
        {"shape box; halfExtents (0.5 0.3 0.2);", 0.4, 1e-12, 5e-4},
        {"shape box; halfExtents (0.5 0.3 0.2); edgeRadius 0.1;", 0.4, 5e-4, 5e-4}
    });
    const tensor rotated(quaternion(vector(1, 2, 3)/Foam::sqrt(14.0), 0.7).R());

    Random rnd(23);
    for (const sample& s : samples)
    {
        autoPtr<particleShape> shape(makeShape(s.entries));
        const scalar V = shape->volume();
        for (const label cells : {8, 16})
        {
            const scalar h = s.smallest/cells;
            for (const bool aligned : {true, false})
            {
                const tensor R(aligned ? tensor::I : rotated);
                const scalar tolerance =
                    aligned ? s.alignedTolerance : s.rotatedTolerance;
                for (label offset = 0; offset < 2; ++offset)
                {
                    const point X(h*rnd.sample01<vector>());
                    const scalar error = gridVolume(*shape, X, R, h)/V - 1;
                    INFO
                    (
                        shape->type() << ", " << cells << " cells, aligned "
                     << aligned << ", error " << error
                    );
                    CHECK(mag(error) < tolerance);
                }
            }
        }
    }
}


TEST_CASE("non-spherical shapes' input is checked", "[geometry]")
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    const auto particle = [](const char* text)
    {
        IStringStream is(text);
        dictionary dict(is);
        dict.name() = "particleProperties.p0";
        return dlmParticle(dict);
    };

    CHECK_NOTHROW(particle("shape ellipsoid; semiAxes (0.1 0.2 0.3); density 2; position (0 0 0);"));
    CHECK_NOTHROW(particle("shape cylinder; radius 0.1; length 0.3; density 2; position (0 0 0);"));
    CHECK_NOTHROW(particle("shape box; halfExtents (0.1 0.2 0.3); density 2; position (0 0 0);"));

    CHECK_THROWS(particle("shape ellipsoid; semiAxes (0.1 0 0.3); density 2; position (0 0 0);"));
    CHECK_THROWS(particle("shape ellipsoid; radius 0.1; density 2; position (0 0 0);"));
    CHECK_THROWS(particle("shape ellipsoid; semiAxes (0.1 0.2 0.3); radius 0.1; density 2; position (0 0 0);"));
    CHECK_THROWS(particle("shape cylinder; radius 0.1; density 2; position (0 0 0);"));
    CHECK_THROWS(particle("shape cylinder; radius 0.1; length -1; density 2; position (0 0 0);"));
    CHECK_THROWS(particle("shape box; halfExtents (0.1 0.2 -0.3); density 2; position (0 0 0);"));
    CHECK_THROWS(particle("shape box; halfExtent (0.1 0.2 0.3); density 2; position (0 0 0);"));

    FatalError.dontThrowExceptions();
    FatalIOError.dontThrowExceptions();
}


// ************************************************************************* //


TEST_CASE("a box's face lying in the cutting plane keeps its centroid", "[geometry]")
{
    // The common plane of a face on a larger face lies at the larger face,
    // and a wall's at a face resting on it: the part beyond it is a sheet
    // whose tetrahedra sum to round-off. Their moment over that sum put
    // the centroid kilometres away (a cylinder on a box in a dry pile got
    // a lever arm of 3 km and spun up to 700 rad/s); it is the face's
    autoPtr<particleShape> shape
    (
        makeShape("shape box; halfExtents (0.0025 0.002 0.0015);")
    );
    const vector h(0.0025, 0.002, 0.0015);
    Random rnd(7);
    label worst = 0, cut = 0;
    scalar farthest = 0;
    for (label sample = 0; sample < 2000; ++sample)
    {
        // A face's normal through a random rotation and back, as the
        // contacts take it, at the face's distance give or take round-off
        const vector axis(normalised(2*rnd.sample01<vector>() - vector::one));
        const tensor R(quaternion(axis, 2*pi*rnd.sample01<scalar>()).R());
        const direction d = sample % 3;
        vector e(Zero);
        e[d] = sample % 2 ? 1 : -1;
        const vector n(R.T() & (R & e));
        const scalar distance = h[d]*(1 + (sample % 9 - 4)*1e-16);
        scalar V, area;
        vector centroid;
        shape->planeCut(n, distance, V, centroid, area);
        const scalar off = V > 0 ? mag(centroid - h[d]*e) : 0;
        cut += V > 0;
        if (off > farthest)
        {
            farthest = off;
            worst = sample;
        }
    }
    INFO("farthest from the face's centre " << farthest << " (sample " << worst
        << "), " << cut << " cuts");
    CHECK(cut > 100);
    CHECK(farthest < 1e-9);
}
