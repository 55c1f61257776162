/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Description
    Tests of the contact pieces: exact overlap volumes and areas against
    quadrature and their small-overlap limits, the contact laws' restitution
    and contact time in dimensional collisions at several speeds, and the
    nearest points of the contact walls.

\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>

#include "overlapGeometry.H"
#include "contactLaw.H"
#include "contactWall.H"
#include "testCase.H"
#include "triSurface.H"
#include "OSspecific.H"
#include "mathematicalConstants.H"
#include "IStringStream.H"

using namespace Foam;
using constant::mathematical::pi;

namespace
{

// Midpoint quadrature along the line of centres of the common part of two
// spheres (slices pi r^2) or circles (chords 2 r)
scalar lensQuadrature
(
    const scalar R1,
    const scalar R2,
    const scalar d,
    const bool sphere
)
{
    const label n = 200000;
    const scalar lo = d - R2;
    const scalar hi = R1;
    const scalar dx = (hi - lo)/n;
    scalar sum = 0;
    for (label i = 0; i < n; ++i)
    {
        const scalar x = lo + (i + 0.5)*dx;
        const scalar r2 =
            min(sqr(R1) - sqr(x), sqr(R2) - sqr(x - d));
        if (r2 > 0)
        {
            sum += sphere ? pi*r2 : 2*Foam::sqrt(r2);
        }
    }
    return sum*dx;
}


// Collision of a particle of mass m with a wall under the law, integrated
// with small RK4 steps independently of the solver: the restitution and the
// duration (from first to last instant with a pushing force)
void collide
(
    const contactLaw& law,
    const scalar R,
    const scalar m,
    const scalar v0,
    const label nDims,
    scalar& e,
    scalar& duration
)
{
    auto volume = [&](const scalar delta)
    {
        return
            nDims == 3
          ? overlapGeometry::sphereCapVolume(R, delta)
          : overlapGeometry::circleSegmentArea(R, delta);
    };
    auto accel = [&](const scalar delta, const scalar rate)
    {
        scalar k, c;
        return -law.normalForce(volume(delta), delta, R, m, rate, k, c)/m;
    };

    const scalar h = law.contactTime(R, m, v0)/20000;
    scalar x = 0;
    scalar v = v0;
    scalar t = 0;
    while (t < 100*law.contactTime(R, m, v0))
    {
        const scalar k1x = v, k1v = accel(x, v);
        const scalar k2x = v + 0.5*h*k1v, k2v = accel(x + 0.5*h*k1x, k2x);
        const scalar k3x = v + 0.5*h*k2v, k3v = accel(x + 0.5*h*k2x, k3x);
        const scalar k4x = v + h*k3v, k4v = accel(x + h*k3x, k4x);
        x += h*(k1x + 2*k2x + 2*k3x + k4x)/6;
        v += h*(k1v + 2*k2v + 2*k3v + k4v)/6;
        t += h;
        if (x <= 0 || (v < 0 && accel(x, v) == 0))
        {
            break;
        }
    }
    e = -v/v0;
    duration = t;
}

} // End anonymous namespace


TEST_CASE("sphere and circle lenses match quadrature", "[contact]")
{
    for (const scalar d : {1.9, 1.5, 1.0, 0.6})
    {
        const scalar R1 = 1.0, R2 = 0.8;
        const scalar sphere = overlapGeometry::sphereLensVolume(R1, R2, d);
        const scalar circle = overlapGeometry::circleLensArea(R1, R2, d);
        CHECK(sphere == Approx(lensQuadrature(R1, R2, d, true)).epsilon(1e-6));
        CHECK(circle == Approx(lensQuadrature(R1, R2, d, false)).epsilon(1e-6));
    }

    // One inside the other, and apart
    CHECK
    (
        overlapGeometry::sphereLensVolume(1, 0.3, 0.5)
     == Approx(4*pi*pow3(0.3)/3)
    );
    CHECK(overlapGeometry::circleLensArea(1, 0.3, 1.31) == 0);
}


TEST_CASE("tiny overlaps keep their precision", "[contact]")
{
    // Small-overlap limits: lens pi R* delta^2 and 4/3 Foam::sqrt(2 R*) delta^1.5
    const scalar R1 = 1.0, R2 = 0.5;
    const scalar Reff = R1*R2/(R1 + R2);
    for (const scalar delta : {1e-3, 1e-6, 1e-9})
    {
        const scalar d = R1 + R2 - delta;
        CHECK
        (
            overlapGeometry::sphereLensVolume(R1, R2, d)
         == Approx(pi*Reff*sqr(delta)).epsilon(max(2*delta, 1e-6))
        );
        CHECK
        (
            overlapGeometry::circleLensArea(R1, R2, d)
         == Approx(4.0/3.0*Foam::sqrt(2*Reff)*Foam::pow(delta, 1.5)).epsilon(max(2*delta, 1e-6))
        );
        CHECK
        (
            overlapGeometry::sphereCapVolume(R1, delta)
         == Approx(pi*R1*sqr(delta)).epsilon(max(2*delta, 1e-6))
        );
        CHECK
        (
            overlapGeometry::circleSegmentArea(R1, delta)
         == Approx(4.0/3.0*Foam::sqrt(2*R1)*Foam::pow(delta, 1.5)).epsilon(max(2*delta, 1e-6))
        );
    }
}


TEST_CASE("contact laws give the requested restitution at any speed", "[contact]")
{
    const scalar R = 0.002;
    const scalar m = 2500*4*pi*pow3(R)/3;

    for (const word lawName : {"overlapVolume", "linearSpringDashpot"})
    {
        for (const label nDims : {3, 2})
        {
            for (const scalar e : {0.1, 0.5, 0.9, 0.99})
            {
                IStringStream is
                (
                    "{ law " + lawName + "; restitution " + Foam::name(e)
                  + "; friction 0.3; contactTime 1e-4; impactVelocity 1; }"
                );
                dictionary dict(is);
                if (lawName == "linearSpringDashpot")
                {
                    dict.remove("impactVelocity");
                }
                autoPtr<contactLaw> law
                (
                    contactLaw::New(dict, nDims, contactLaw::reference{m, R})
                );

                // The reference particle at the reference speed takes the
                // given contact time
                CHECK(law->contactTime(R, m, 1) == Approx(1e-4).epsilon(1e-9));

                for (const scalar v0 : {0.01, 1.0, 10.0})
                {
                    scalar measured, duration;
                    collide(*law, R, m, v0, nDims, measured, duration);
                    INFO(lawName << " " << nDims << "D e " << e << " v " << v0);
                    // The exact volumes depart from the small-overlap law
                    // as the overlap grows (delta/R about 1 % at 1 m/s and
                    // 5 % at 10 m/s)
                    const scalar tolerance =
                        v0 < 0.1 ? 1e-3 : v0 < 5 ? 3e-3 : 1e-2;
                    CHECK(measured == Approx(e).epsilon(tolerance));
                    CHECK
                    (
                        duration
                     == Approx(law->contactTime(R, m, v0)).epsilon(0.02)
                    );
                }
            }
        }
    }
}


TEST_CASE("unclipped linear damping is the textbook one", "[contact]")
{
    // Linear spring-dashpot ending at zero overlap: beta = 2 zeta with
    // zeta = -ln e/sqrt(pi^2 + ln^2 e) (reference README section 7)
    for (const scalar e : {0.1, 0.3, 0.5, 0.7, 0.9, 0.95})
    {
        const scalar zeta = -std::log(e)/Foam::sqrt(sqr(pi) + sqr(std::log(e)));
        CHECK(contactLaw::dampingFor(1, e, false) == Approx(2*zeta).epsilon(1e-6));
        // Clipping the pull at the end needs more damping for the same e
        CHECK(contactLaw::dampingFor(1, e, true) > 2*zeta);
    }
}


TEST_CASE("analytic walls find their nearest points", "[contact]")
{
    REQUIRE(testCase::available());
    const polyMesh& mesh = testCase::mesh();

    auto make = [&](const string& text)
    {
        IStringStream is(text);
        dictionary dict(is);
        dict.name() = "walls.test";
        return contactWall::New(dict, mesh);
    };

    DynamicList<label> features;
    DynamicList<wallContact> found;

    autoPtr<contactWall> plane
    (
        make("{ type plane; point (0 0 1); normal (0 0 2); }")
    );
    plane->near(point(3, 4, 1.5), 1, features);
    REQUIRE(features.size() == 1);
    plane->contacts(point(3, 4, 1.5), 1, features, found);
    REQUIRE(found.size() == 1);
    CHECK(found[0].distance == Approx(0.5));
    CHECK(mag(found[0].location - point(3, 4, 1)) < 1e-12);
    CHECK(mag(found[0].normal - vector(0, 0, 1)) < 1e-12);

    autoPtr<contactWall> cylinder
    (
        make("{ type cylinder; point (1 1 0); axis (0 0 1); radius 2; }")
    );
    found.clear();
    cylinder->contacts(point(2.5, 1, 7), 1, features, found);
    REQUIRE(found.size() == 1);
    CHECK(found[0].distance == Approx(0.5));
    CHECK(mag(found[0].normal - vector(-1, 0, 0)) < 1e-12);

    // Funnel: radius 2 at z = 2, radius 1 at z = 1 (45 degrees)
    autoPtr<contactWall> cone
    (
        make
        (
            "{ type cone; point1 (0 0 2); radius1 2; point2 (0 0 1);"
            " radius2 1; }"
        )
    );
    found.clear();
    cone->contacts(point(1.5 - 0.3/Foam::sqrt(2.0), 0, 1.5 + 0.3/Foam::sqrt(2.0)), 1,
        features, found);
    REQUIRE(found.size() == 1);
    CHECK(found[0].distance == Approx(0.3));
    CHECK(mag(found[0].location - point(1.5, 0, 1.5)) < 1e-12);
    // Below the lower rim: the rim circle is nearest
    found.clear();
    cone->contacts(point(0.5, 0, 0.9), 1, features, found);
    REQUIRE(found.size() == 1);
    CHECK(mag(found[0].location - point(1, 0, 1)) < 1e-12);
}


TEST_CASE("surface walls count faces once and rims where free", "[contact]")
{
    REQUIRE(testCase::available());
    const polyMesh& mesh = testCase::mesh();

    // Floor z = 0 of [0, 2] x [0, 2] with a square hole [1, 2] x [1, 2]
    // (three unit squares, two triangles each), and a wall x = 0
    const pointField points
    ({
        {0, 0, 0}, {1, 0, 0}, {2, 0, 0},
        {0, 1, 0}, {1, 1, 0}, {2, 1, 0},
        {0, 2, 0}, {1, 2, 0},
        {0, 0, 1}, {0, 1, 1}, {0, 2, 1}
    });
    const List<labelledTri> tris
    ({
        labelledTri(0, 1, 4, 0), labelledTri(0, 4, 3, 0),
        labelledTri(1, 2, 5, 0), labelledTri(1, 5, 4, 0),
        labelledTri(3, 4, 7, 0), labelledTri(3, 7, 6, 0),
        labelledTri(0, 3, 9, 0), labelledTri(0, 9, 8, 0),
        labelledTri(3, 6, 10, 0), labelledTri(3, 10, 9, 0)
    });
    const fileName dir(mesh.time().constantPath()/"triSurface");
    mkDir(dir);
    triSurface(tris, points).write(dir/"floor.stl");

    IStringStream is("{ type surface; file \"floor.stl\"; }");
    dictionary dict(is);
    dict.name() = "walls.floor";
    autoPtr<contactWall> floor(contactWall::New(dict, mesh));

    auto contactsAt = [&](const point& X, const scalar R)
    {
        DynamicList<label> features;
        floor->near(X, R, features);
        DynamicList<wallContact> found;
        floor->contacts(X, R, features, found);
        return List<wallContact>(found);
    };

    // Above an interior edge and above an interior vertex: one contact
    List<wallContact> c(contactsAt(point(0.5, 0.5, 0.1), 0.2));
    REQUIRE(c.size() == 1);
    CHECK(c[0].distance == Approx(0.1));
    c = contactsAt(point(1, 0.5, 0.1), 0.2);
    REQUIRE(c.size() == 1);
    c = contactsAt(point(1, 1 - 1e-3, 0.1), 0.2);
    REQUIRE(c.size() == 1);
    CHECK(mag(c[0].normal - vector(0, 0, 1)) < 1e-9);

    // Hanging over the hole's edge: the rim, normal towards the centre
    c = contactsAt(point(1.5, 1.05, 0.1), 0.2);
    REQUIRE(c.size() == 1);
    CHECK(mag(c[0].location - point(1.5, 1, 0)) < 1e-12);
    CHECK(c[0].distance == Approx(Foam::sqrt(0.0125)));

    // In the corner of floor and wall: two contacts
    c = contactsAt(point(0.1, 0.5, 0.1), 0.2);
    CHECK(c.size() == 2);

    // Near the hole's edge but over the floor: the floor only
    c = contactsAt(point(1.5, 0.95, 0.1), 0.2);
    REQUIRE(c.size() == 1);
    CHECK(c[0].distance == Approx(0.1));
}


// ************************************************************************* //
