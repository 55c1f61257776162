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
// the shape at X (2D: one layer of depth 1, split only in x and y)
scalar gridVolume
(
    const particleShape& shape,
    const point& X,
    const scalar h,
    const bool twoD
)
{
    const scalar R = shape.boundingRadius();
    const label n = label(std::ceil(2*R/h)) + 2;
    const point origin(X - (R + h)*vector::one);
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
                sum += shape.boxFraction(bb, X, tensor::I, split, R/32)
                      *bb.volume();
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
    for (const label cellsPerDiameter : {8, 12, 16})
    {
        const scalar h = 2*R/cellsPerDiameter;
        for (label sample = 0; sample < 3; ++sample)
        {
            const point X
            (
                h*rnd.sample01<scalar>(),
                h*rnd.sample01<scalar>(),
                h*rnd.sample01<scalar>()
            );
            INFO("cells per diameter " << cellsPerDiameter);
            CHECK(gridVolume(*shape, X, h, false)/exact == Approx(1).epsilon(1e-3));
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
        CHECK(gridVolume(*shape, X, h, true)/exact == Approx(1).epsilon(1e-3));
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

    const dlmParticle fixed
    (
        particle("shape disk; radius 0.1; density 2; position (0 0 0); motion fixed; velocity (1 0 0);")
    );
    CHECK(fixed.velocity() == vector::zero);

    FatalError.dontThrowExceptions();
    FatalIOError.dontThrowExceptions();
}


// ************************************************************************* //
