/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Description
    Tests of the particle geometry: cut-cell fractions, shape selection and
    input checks, and the volume fraction of spheres and disks on grids of
    box cells.

\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>

#include "cutCellFraction.H"
#include "particleShape.H"
#include "shapeChecks.H"
#include "dlmParticle.H"
#include "Random.H"
#include "mathematicalConstants.H"
#include "IStringStream.H"

using namespace Foam;

namespace
{

// Independent reference: midpoint quadrature of the height of the region
// m1 x + m2 y + m3 z < alpha over the unit square (m3 the largest)
scalar quadratureUnitCube
(
    const scalar m1,
    const scalar m2,
    const scalar m3,
    const scalar alpha
)
{
    const label n = 1000;
    scalar sum = 0;
    for (label i = 0; i < n; ++i)
    {
        const scalar x = (i + 0.5)/n;
        for (label j = 0; j < n; ++j)
        {
            const scalar y = (j + 0.5)/n;
            sum += min(max((alpha - m1*x - m2*y)/m3, scalar(0)), scalar(1));
        }
    }
    return sum/scalar(n*n);
}


// Sum of fraction times cell volume over a grid of cubes of side h around
// the shape at X (2D: one layer of depth 1, split only in x and y), with the
// shape's own fraction or the general subdivision down to R/32
scalar gridVolume
(
    const particleShape& shape,
    const point& X,
    const scalar h,
    const bool twoD,
    const bool subdivide = false
)
{
    const scalar R = shape.boundingRadius();
    // The grid of cells of side h from the global origin: X's place in its
    // cell sets how the surface cuts the cells
    const label n = label(std::ceil(2*R/h)) + 3;
    point origin(X - (R + h)*vector::one);
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        origin[d] = h*std::floor(origin[d]/h);
    }
    const vector split(1, 1, twoD ? 0 : 1);
    const label nz = twoD ? 1 : n;
    const scalar hz = twoD ? 1 : h;

    scalar sum = 0;
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            for (label k = 0; k < nz; ++k)
            {
                point lo(origin + vector(i*h, j*h, k*h));
                if (twoD)
                {
                    lo.z() = X.z() - 0.5;
                }
                const boundBox bb(lo, lo + vector(h, h, hz));
                const scalar f =
                    subdivide
                  ? shape.particleShape::boxFraction
                    (
                        bb, X, tensor::I, split, R/32
                    )
                  : shape.boxFraction(bb, X, tensor::I, split, R/32);
                sum += f*bb.volume();
            }
        }
    }
    return sum;
}


autoPtr<particleShape> makeShape(const word& type, const scalar radius)
{
    dictionary dict;
    dict.add("shape", type);
    dict.add("radius", radius);
    return particleShape::New(dict);
}

} // End anonymous namespace


TEST_CASE("cut fraction of the unit cube agrees with quadrature", "[geometry]")
{
    Random rnd(1234);
    for (label sample = 0; sample < 40; ++sample)
    {
        scalar m[3] =
        {
            rnd.sample01<scalar>(),
            rnd.sample01<scalar>(),
            rnd.sample01<scalar>()
        };
        std::sort(m, m + 3);
        const scalar sum = m[0] + m[1] + m[2];
        for (scalar& mi : m)
        {
            mi /= sum;
        }
        const scalar alpha = rnd.sample01<scalar>();

        const scalar exact = cutCellFraction::unitCube(m[0], m[1], m[2], alpha);
        CHECK(exact == Approx(quadratureUnitCube(m[0], m[1], m[2], alpha))
            .margin(2e-6));
    }
}


TEST_CASE("cut fraction handles planes parallel to cube faces", "[geometry]")
{
    // Normal along one axis: the fraction is alpha
    CHECK(cutCellFraction::unitCube(0, 0, 1, 0.3) == Approx(0.3).margin(1e-14));
    CHECK(cutCellFraction::unitCube(0, 0, 1, 0.8) == Approx(0.8).margin(1e-14));

    // Normal in a plane of the cube: 2D formula
    for (const scalar alpha : {0.1, 0.25, 0.5, 0.7, 0.95})
    {
        CHECK
        (
            cutCellFraction::unitCube(0, 0.3, 0.7, alpha)
         == Approx(quadratureUnitCube(0, 0.3, 0.7, alpha)).margin(2e-6)
        );
    }

    // Outside the cube
    CHECK(cutCellFraction::unitCube(0.2, 0.3, 0.5, -0.1) == 0);
    CHECK(cutCellFraction::unitCube(0.2, 0.3, 0.5, 1.1) == 1);
}


TEST_CASE("cut fraction of a box", "[geometry]")
{
    const vector span(2, 1, 0.5);

    // Plane x = c - 0.5 cuts a quarter of the box width 2 off
    CHECK(cutCellFraction::box(vector(1, 0, 0), 0.5, span) == Approx(0.25));

    // Through the centre, any normal: half
    CHECK
    (
        cutCellFraction::box(normalised(vector(1, 2, 3)), 0, span)
     == Approx(0.5).margin(1e-14)
    );

    // Complementary half-spaces add up to one
    const vector n(normalised(vector(-0.3, 0.5, 0.8)));
    CHECK
    (
        cutCellFraction::box(n, 0.2, span) + cutCellFraction::box(-n, -0.2, span)
     == Approx(1).margin(1e-14)
    );
}


TEST_CASE("sphere fractions integrate to its volume", "[geometry]")
{
    const scalar R = 1;
    autoPtr<particleShape> shape(makeShape("sphere", R));
    const scalar exact = 4.0/3.0*constant::mathematical::pi*pow3(R);
    REQUIRE(shape->volume() == Approx(exact));

    Random rnd(42);
    for (const label cellsPerDiameter : {3, 4, 8, 12, 16})
    {
        const scalar h = 2*R/cellsPerDiameter;
        // Random centres, and centres on a grid node or just off it, where
        // the surface grazes cell faces and edges
        for (label sample = 0; sample < 5; ++sample)
        {
            const point X
            (
                sample == 3 ? point::zero
              : sample == 4 ? point(1e-9*h, 0.5*h, 1e-12*h)
              : point
                (
                    h*rnd.sample01<scalar>(),
                    h*rnd.sample01<scalar>(),
                    h*rnd.sample01<scalar>()
                )
            );
            INFO("cells per diameter " << cellsPerDiameter << ", sample " << sample << ", error " << gridVolume(*shape, X, h, false)/exact - 1);
            CHECK(gridVolume(*shape, X, h, false)/exact == Approx(1).epsilon(1e-13));
            CHECK
            (
                gridVolume(*shape, X, h, false, true)/exact
             == Approx(1).epsilon(1e-3)
            );
        }
    }
}


TEST_CASE("disk fractions integrate to its area", "[geometry]")
{
    const scalar R = 0.5;
    autoPtr<particleShape> shape(makeShape("disk", R));
    const scalar exact = constant::mathematical::pi*sqr(R);
    REQUIRE(shape->volume() == Approx(exact));
    REQUIRE(shape->nDimensions() == 2);

    Random rnd(7);
    for (const label cellsPerDiameter : {8, 16})
    {
        const scalar h = 2*R/cellsPerDiameter;
        const point X(h*rnd.sample01<scalar>(), h*rnd.sample01<scalar>(), 0);
        CHECK(gridVolume(*shape, X, h, true)/exact == Approx(1).epsilon(1e-12));
        CHECK
        (
            gridVolume(*shape, X, h, true, true)/exact
         == Approx(1).epsilon(1e-3)
        );
    }
}


TEST_CASE("circle-rectangle areas in closed form", "[geometry]")
{
    using namespace cutCellFraction;
    const scalar pi = constant::mathematical::pi;
    const scalar rho = 0.7;

    CHECK(circleRectangleArea(rho, -1, 1, -1, 1) == Approx(pi*sqr(rho)));
    CHECK(circleRectangleArea(rho, 0, 1, 0, 1) == Approx(0.25*pi*sqr(rho)));
    CHECK(circleRectangleArea(rho, 1, 2, -1, 1) == 0);

    // Circular segment beyond z = rho/2
    const scalar segment = sqr(rho)*(std::acos(0.5) - 0.5*std::sqrt(0.75));
    CHECK(circleRectangleArea(rho, -1, 1, 0.5*rho, 1) == Approx(segment));

    // Random rectangles against a fine midpoint rule in y of the chord
    Random rnd(11);
    for (label sample = 0; sample < 20; ++sample)
    {
        const scalar y0 = 2*rnd.sample01<scalar>() - 1;
        const scalar y1 = y0 + rnd.sample01<scalar>();
        const scalar z0 = 2*rnd.sample01<scalar>() - 1;
        const scalar z1 = z0 + rnd.sample01<scalar>();
        const label n = 200000;
        scalar sum = 0;
        for (label i = 0; i < n; ++i)
        {
            const scalar y = y0 + (i + 0.5)*(y1 - y0)/n;
            if (mag(y) < rho)
            {
                const scalar s = std::sqrt(sqr(rho) - sqr(y));
                sum += max(min(z1, s) - max(z0, -s), scalar(0));
            }
        }
        sum *= (y1 - y0)/n;
        CHECK(circleRectangleArea(rho, y0, y1, z0, z1) == Approx(sum).margin(1e-8));
    }
}


TEST_CASE("sphere-box volumes agree with fine subdivision", "[geometry]")
{
    const scalar R = 1;
    autoPtr<particleShape> shape(makeShape("sphere", R));
    const vector split(1, 1, 1);

    // Boxes of a cell's size (8 per diameter) cut by the surface
    Random rnd(5);
    label nCut = 0;
    for (label sample = 0; sample < 200 && nCut < 20; ++sample)
    {
        const scalar h = 0.25;
        const point lo
        (
            (2*rnd.sample01<vector>() - vector::one)*(R + h) - 0.5*h*vector::one
        );
        const boundBox bb(lo, lo + h*vector::one);
        const scalar exact =
            shape->boxFraction(bb, Zero, tensor::I, split, R/32);
        if (exact <= 0 || exact >= 1)
        {
            continue;
        }
        ++nCut;
        const scalar fine = shape->particleShape::boxFraction
        (
            bb, Zero, tensor::I, split, R/1024
        );
        CHECK(exact == Approx(fine).margin(2e-6));
    }
    CHECK(nCut == 20);
}


TEST_CASE("line crossings agree with the general root finding", "[geometry]")
{
    Random rnd(17);
    for (const word type : {"sphere", "disk"})
    {
        autoPtr<particleShape> shape(makeShape(type, 0.6));
        shapeChecks::checkLineCrossings(shape(), rnd, 200);
    }
}


TEST_CASE("particle input is checked", "[geometry]")
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

    const dlmParticle p
    (
        particle("shape sphere; radius 0.1; density 2; position (1 2 3);")
    );
    CHECK(p.name() == "p0");
    CHECK(p.isFree());
    CHECK(p.shape().type() == "sphere");

    CHECK_THROWS(particle("shape sphere; radius -0.1; density 2; position (0 0 0);"));
    CHECK_THROWS(particle("shape sphere; radius 0.1; density 0; position (0 0 0);"));
    CHECK_THROWS(particle("shape sphere; radius 0.1; position (0 0 0);"));
    CHECK_THROWS(particle("shape sphere; radus 0.1; density 2; position (0 0 0);"));
    CHECK_THROWS(particle("shape cube; radius 0.1; density 2; position (0 0 0);"));
    CHECK_THROWS(particle("shape sphere; radius 0.1; density 2; position (0 0 0); motion flying;"));
    CHECK_THROWS(particle("shape sphere; radius 0.1; density 2; position (0 0 0); orientation (0 (0 0 0));"));
    CHECK_THROWS(particle("shape sphere; radius 0.1; density 2; position (0 0 0); motion prescribed;"));
    CHECK_NOTHROW(particle("shape sphere; radius 0.1; density 2; position (0 0 0); motion prescribed; angularVelocity (0 0 1);"));

    const dlmParticle fixed
    (
        particle("shape disk; radius 0.1; density 2; position (0 0 0); motion fixed; velocity (1 0 0);")
    );
    CHECK(fixed.velocity() == vector::zero);

    FatalError.dontThrowExceptions();
    FatalIOError.dontThrowExceptions();
}


// ************************************************************************* //
