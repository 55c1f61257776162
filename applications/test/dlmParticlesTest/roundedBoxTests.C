/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Description
    Tests of the box with rounded edges (shape box with edgeRadius): volume
    and inertia against the sphere (the radius equal to all half extents)
    and against sums over a fine grid, signed distances at chosen points,
    line crossings, its parts beyond planes against the sphere's exact caps
    and against sums over a fine grid, and its input checks.

\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>

#include "particleShape.H"
#include "shapeChecks.H"
#include "cutCellFraction.H"
#include "dlmParticle.H"
#include "Random.H"
#include "mathematicalConstants.H"
#include "IStringStream.H"
#include "Tuple2.H"
#include "edgeHashes.H"

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


// Sums over a grid of cubes of side h filling the outer box (its flat
// faces on grid planes): cells inside whole, cells the surface may cross
// split into 4^3 whose fractions are the parts below the tangent planes at
// their centres (cutCellFraction::box, second order). Volume and second
// moments (the integrals of x^2, y^2 and z^2: a cube's holds h^2/12 more
// than its centre's)
void gridMoments
(
    const particleShape& shape,
    const vector& halfExtents,
    const scalar h,
    scalar& volume,
    vector& secondMoments
)
{
    const label nSplit = 4;
    const scalar hSub = h/nSplit;
    volume = 0;
    secondMoments = Zero;
    auto add = [&](const point& r, const scalar side, const scalar fraction)
    {
        const scalar v = fraction*pow3(side);
        volume += v;
        secondMoments += v*(cmptMultiply(r, r) + sqr(side)/12*vector::one);
    };
    const label nx = std::lround(2*halfExtents.x()/h);
    const label ny = std::lround(2*halfExtents.y()/h);
    const label nz = std::lround(2*halfExtents.z()/h);
    for (label i = 0; i < nx; ++i)
    {
        for (label j = 0; j < ny; ++j)
        {
            for (label k = 0; k < nz; ++k)
            {
                const point lo(h*vector(i, j, k) - halfExtents);
                const point centre(lo + 0.5*h*vector::one);
                vector normal;
                const scalar d = shape.signedDistance(centre, normal);
                if (d < -h)
                {
                    add(centre, h, 1);
                }
                else if (d < h)
                {
                    for (label a = 0; a < nSplit; ++a)
                    {
                        for (label b = 0; b < nSplit; ++b)
                        {
                            for (label c = 0; c < nSplit; ++c)
                            {
                                const point r
                                (
                                    lo + hSub*vector(a + 0.5, b + 0.5, c + 0.5)
                                );
                                const scalar dSub =
                                    shape.signedDistance(r, normal);
                                add
                                (
                                    r,
                                    hSub,
                                    cutCellFraction::box
                                    (
                                        normal, dSub, hSub*vector::one
                                    )
                                );
                            }
                        }
                    }
                }
            }
        }
    }
}

} // End anonymous namespace


TEST_CASE("a rounded box's volume and inertia", "[geometry]")
{
    SECTION("the radius equal to all half extents: the sphere")
    {
        autoPtr<particleShape> shape
        (
            makeShape("shape box; halfExtents (0.3 0.3 0.3); edgeRadius 0.3;")
        );
        const scalar V = 4*pi*pow3(0.3)/3;
        CHECK(shape->volume() == Approx(V).epsilon(1e-14));
        CHECK(shape->boundingRadius() == Approx(0.3).epsilon(1e-14));
        const symmTensor I(shape->inertiaPerUnitDensity());
        for (const scalar moment : {I.xx(), I.yy(), I.zz()})
        {
            CHECK(moment == Approx(0.4*V*sqr(0.3)).epsilon(1e-14));
        }
        CHECK(I.xy() == 0);
        CHECK(I.xz() == 0);
        CHECK(I.yz() == 0);
    }

    SECTION("sphere, general and flat (the radius the smallest half extent) against a fine grid")
    {
        // Grid of cubes of side 0.005 (subdivided to 0.00125 where cut):
        // its error, measured on the sphere (the first), 5e-6 in volume and
        // 2.2e-5 in inertia (the cut cells' moments taken at their centres)
        const List<Tuple2<string, vector>> shapes
        ({
            {"shape box; halfExtents (0.3 0.3 0.3); edgeRadius 0.3;", vector(0.3, 0.3, 0.3)},
            {"shape box; halfExtents (0.5 0.3 0.2); edgeRadius 0.1;", vector(0.5, 0.3, 0.2)},
            {"shape box; halfExtents (0.5 0.3 0.2); edgeRadius 0.2;", vector(0.5, 0.3, 0.2)}
        });
        for (const auto& entriesAndSize : shapes)
        {
            const string& entries = entriesAndSize.first();
            const vector& a = entriesAndSize.second();
            autoPtr<particleShape> shape(makeShape(entries));
            scalar V;
            vector S;
            gridMoments(*shape, a, 0.005, V, S);
            const symmTensor I(shape->inertiaPerUnitDensity());
            INFO(entries << ": volume " << shape->volume() << " (grid " << V
                << "), inertia " << I.xx() << " " << I.yy() << " " << I.zz()
                << " (grid " << S.y() + S.z() << " " << S.x() + S.z() << " "
                << S.x() + S.y() << ")");
            CHECK(shape->volume() == Approx(V).epsilon(2e-5));
            CHECK(I.xx() == Approx(S.y() + S.z()).epsilon(5e-5));
            CHECK(I.yy() == Approx(S.x() + S.z()).epsilon(5e-5));
            CHECK(I.zz() == Approx(S.x() + S.y()).epsilon(5e-5));
            CHECK(I.xy() == 0);
            // Smaller than the sharp box's
            CHECK(shape->volume() < 8*cmptProduct(a));
        }
    }
}


TEST_CASE("a rounded box's signed distances and line crossings", "[geometry]")
{
    // Outer half extents (0.5 0.3 0.2), radius 0.1: inner box (0.4 0.2 0.1)
    autoPtr<particleShape> shape
    (
        makeShape("shape box; halfExtents (0.5 0.3 0.2); edgeRadius 0.1;")
    );
    vector normal;
    auto check = [&](const vector& r, const scalar d, const vector& n)
    {
        INFO("at " << show(r));
        CHECK(shape->signedDistance(r, normal) == Approx(d).margin(1e-12));
        CHECK(mag(normal - n) < 1e-12);
    };
    // Inside: the nearest face; within the rounding of an edge
    check(vector(0, 0, 0), -0.2, vector(0, 0, 1));
    check(vector(0.35, 0, 0), -0.15, vector(1, 0, 0));
    check
    (
        vector(0.45, 0.25, 0), 0.05*Foam::sqrt(2.0) - 0.1,
        vector(1, 1, 0)/Foam::sqrt(2.0)
    );
    // Outside: a face, an edge, a corner
    check(vector(0.6, 0.1, 0), 0.1, vector(1, 0, 0));
    check(vector(0.7, 0.6, 0), 0.4, vector(0.6, 0.8, 0));
    check(vector(-0.6, 0.5, -0.7), 0.6, vector(-2, 3, -6)/7);
    // The support: the inner box's plus the radius
    CHECK(shape->support(vector(1, 0, 0)) == Approx(0.5).epsilon(1e-14));
    CHECK
    (
        shape->support(vector(2, 3, -6)/7)
     == Approx((0.8 + 0.6 + 0.6)/7 + 0.1).epsilon(1e-14)
    );

    Random rnd(11);
    for
    (
        const string entries
      : {
            "shape box; halfExtents (0.5 0.3 0.2); edgeRadius 0.1;",
            "shape box; halfExtents (0.5 0.3 0.2); edgeRadius 0.2;",
            "shape box; halfExtents (0.4 0.4 0.4); edgeRadius 0.4;"
        }
    )
    {
        shapeChecks::checkLineCrossings(makeShape(entries)(), rnd, 400);
    }
}


TEST_CASE("a rounded box's cuts: exact sphere caps, smooth in the distance", "[geometry]")
{
    // The radius equal to all half extents: the sphere, whose cap beyond a
    // plane at distance d has volume pi (R - d)^2 (2R + d)/3, centroid
    // 3 (R + d)^2/(4 (2R + d)) along n and section pi (R^2 - d^2). Any
    // plane tilt makes the slices cut along their arcs.
    const scalar R = 0.3;
    autoPtr<particleShape> sphere
    (
        makeShape("shape box; halfExtents (0.3 0.3 0.3); edgeRadius 0.3;")
    );
    // A flat one: no kink where the inner box has no extent
    autoPtr<particleShape> flat
    (
        makeShape("shape box; halfExtents (0.5 0.3 0.2); edgeRadius 0.2;")
    );
    DynamicList<vector> ridges, corners;
    flat->supportKinks(ridges, corners);
    CHECK(ridges.size() == 2);
    ridges.clear();
    sphere->supportKinks(ridges, corners);
    CHECK(ridges.empty());

    const vector normals[] =
    {
        vector(0, 0, 1), vector(1, 2, 2)/3, vector(0.2, -0.5, 0.8),
        vector(0.6, -0.8, 0), vector(0.1, 0.2, -0.9)
    };
    scalar worstVolume = 0;
    scalar worstCentroid = 0;
    scalar worstArea = 0;
    for (const vector& nRaw : normals)
    {
        const vector n(nRaw/mag(nRaw));
        for (const scalar d : {-0.29, -0.2, -0.05, 0.0, 0.1, 0.25, 0.299})
        {
            scalar V, area;
            vector centroid;
            REQUIRE(sphere->planeCut(n, d, V, centroid, area));
            const scalar exactV = pi*sqr(R - d)*(2*R + d)/3;
            const vector exactC(3*sqr(R + d)/(4*(2*R + d))*n);
            const scalar exactA = pi*(sqr(R) - sqr(d));
            worstVolume = max(worstVolume, mag(V - exactV)/sphere->volume());
            worstCentroid = max(worstCentroid, mag(centroid - exactC)/R);
            worstArea = max(worstArea, mag(area - exactA)/(pi*sqr(R)));
        }
    }
    INFO("largest errors: volume " << worstVolume << " of the volume, "
        << "centroid " << worstCentroid << " of the radius, section "
        << worstArea << " of the largest section");
    // Measured: 4e-12, 1.5e-11 and 9e-10
    CHECK(worstVolume < 1e-10);
    CHECK(worstCentroid < 1e-10);
    CHECK(worstArea < 1e-8);

    // The whole, a half and the volume's rate of change (the section)
    // along a sweep of the plane: smooth, no step at the breakpoints
    for
    (
        const string entries
      : {
            "shape box; halfExtents (0.5 0.3 0.2); edgeRadius 0.1;",
            "shape box; halfExtents (0.5 0.3 0.2); edgeRadius 0.2;"
        }
    )
    {
        autoPtr<particleShape> shape(makeShape(entries));
        const scalar V0 = shape->volume();
        for (const vector& nRaw : normals)
        {
            const vector n(nRaw/mag(nRaw));
            const scalar reach = shape->support(n);
            INFO(entries << " normal " << show(n));
            CHECK(shape->planeOverlap(n, -reach) == Approx(V0).epsilon(1e-12));
            CHECK(shape->planeOverlap(n, 0) == Approx(0.5*V0).epsilon(1e-10));
            CHECK(shape->planeOverlap(n, reach) < 1e-14*V0);

            const label nSteps = 400;
            const scalar step = 2*reach/nSteps;
            scalar largestJump = 0;
            for (label s = 1; s < nSteps; ++s)
            {
                const scalar d = -reach + s*step;
                scalar V, area;
                vector centroid;
                shape->planeCut(n, d, V, centroid, area);
                // Central difference of the volume against the section
                const scalar dd = 1e-6*reach;
                const scalar slope =
                    (shape->planeOverlap(n, d - dd)
                   - shape->planeOverlap(n, d + dd))/(2*dd);
                largestJump = max(largestJump, mag(slope - area));
            }
            scalar V, area;
            vector centroid;
            shape->planeCut(n, 0, V, centroid, area);
            // Measured: 1e-9 of the section (the differences' round-off)
            INFO("largest difference of section and slope " << largestJump);
            CHECK(largestJump < 1e-7*area);
        }
    }
}


TEST_CASE("a rounded box's thin cuts keep their precision", "[geometry]")
{
    // A wall's first touch: the part beyond a plane at a depth of 1e-12 to
    // 1e-6 of the size below the support. On a face it grows as the flat
    // face's area times the depth (the rounding adds depth^1.5), at a
    // smooth point of the rounding as a cap (depth^2): area x depth /
    // volume, the exponent the contacts take for the damping, 1 or 2 (the
    // Green sums about the origin lost it all below 1e-10)
    autoPtr<particleShape> shape
    (
        makeShape("shape box; halfExtents (0.5 0.3 0.2); edgeRadius 0.1;")
    );
    const vector tilted(vector(1, 2, 2)/3);
    for (const scalar relativeDepth : {1e-12, 1e-10, 1e-8, 1e-6})
    {
        const scalar depth = 0.2*relativeDepth;
        scalar V, area;
        vector centroid;
        shape->planeCut(vector(0, 0, 1), 0.2 - depth, V, centroid, area);
        INFO("depth " << depth << ": on the face, volume " << V
            << ", section " << area);
        // The flat face (0.8 x 0.4) and the caps of the quarter cylinders
        // round its perimeter (2.4), 2/3 sqrt(2 r depth) depth a length
        const scalar flat = 0.32*depth;
        const scalar edges = 2.4*2.0/3.0*Foam::sqrt(0.2*depth)*depth;
        CHECK(V == Approx(flat + edges).epsilon(1e-3));
        CHECK(area*depth/V == Approx(1).epsilon(1e-3));
        CHECK(mag(centroid.z() - (0.2 - 0.5*depth)) < 0.01*depth);

        shape->planeCut(tilted, shape->support(tilted) - depth, V, centroid, area);
        INFO("at the corner's rounding, volume " << V << ", section " << area);
        CHECK(V == Approx(pi*0.1*sqr(depth)).epsilon(1e-3));
        CHECK(area*depth/V == Approx(2).epsilon(1e-3));
    }
}


TEST_CASE("a rounded box's drawing is its closed surface", "[geometry]")
{
    // Every point on the surface, every edge shared by two faces in
    // opposite directions, and the enclosed volume (outward faces) that of
    // the shape less what the flat quads cut off the rounding (8 per
    // quarter circle: 0.7 % less for these boxes, 1.7 % for the sphere)
    for
    (
        const string entries
      : {
            "shape box; halfExtents (0.5 0.3 0.2); edgeRadius 0.1;",
            "shape box; halfExtents (0.5 0.3 0.2); edgeRadius 0.2;",
            "shape box; halfExtents (0.3 0.3 0.3); edgeRadius 0.3;"
        }
    )
    {
        autoPtr<particleShape> shape(makeShape(entries));
        pointField points;
        faceList faces;
        shape->drawing(points, faces);
        INFO(entries << ": " << points.size() << " points, " << faces.size()
            << " faces");
        scalar farthest = 0;
        for (const point& r : points)
        {
            vector normal;
            farthest = max(farthest, mag(shape->signedDistance(r, normal)));
        }
        CHECK(farthest < 1e-12);

        EdgeMap<label> edgeUses;
        scalar enclosed = 0;
        for (const face& f : faces)
        {
            forAll(f, k)
            {
                edgeUses(edge(f[k], f.nextLabel(k))) +=
                    f[k] < f.nextLabel(k) ? 1 : -1;
            }
            // Divergence theorem over a fan of triangles
            for (label k = 1; k + 1 < f.size(); ++k)
            {
                enclosed +=
                    (points[f[0]] & (points[f[k]] ^ points[f[k + 1]]))/6;
            }
        }
        label unbalanced = 0;
        forAllConstIters(edgeUses, iter)
        {
            unbalanced += iter.val() != 0;
        }
        CHECK(unbalanced == 0);
        CHECK(enclosed < shape->volume());
        CHECK(enclosed > 0.98*shape->volume());
    }
}


TEST_CASE("a rounded box's input is checked", "[geometry]")
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

    CHECK_NOTHROW(particle("shape box; halfExtents (0.1 0.2 0.3); edgeRadius 0.05; density 2; position (0 0 0);"));
    CHECK_NOTHROW(particle("shape box; halfExtents (0.1 0.2 0.3); edgeRadius 0.1; density 2; position (0 0 0);"));
    CHECK_THROWS(particle("shape box; halfExtents (0.1 0.2 0.3); edgeRadius 0.15; density 2; position (0 0 0);"));
    CHECK_THROWS(particle("shape box; halfExtents (0.1 0.2 0.3); edgeRadius -0.01; density 2; position (0 0 0);"));

    // Written back as read: the radius only when the edges are rounded
    OStringStream sharp, rounded;
    makeShape("shape box; halfExtents (0.1 0.2 0.3);")->write(sharp);
    makeShape("shape box; halfExtents (0.1 0.2 0.3); edgeRadius 0.05;")->write(rounded);
    CHECK(sharp.str().find("edgeRadius") == std::string::npos);
    IStringStream is(rounded.str());
    CHECK(dictionary(is).get<scalar>("edgeRadius") == 0.05);

    FatalError.dontThrowExceptions();
    FatalIOError.dontThrowExceptions();
}


// ************************************************************************* //
