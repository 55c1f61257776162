/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Description
    Benchmark (hidden: run with the tag [contactCost], by
    validation/benchmark_shapeContacts.py) of one pair overlap: the
    common-plane construction of convex shapes (convexOverlap) and the
    paper's grid sum max(0, phi_a + phi_b - 1) over cubic cells of 4, 8 and
    16 per smallest dimension, for pairs of each shape at a least depth of
    5 % of their size. Prints one line per pair and method: its volume and
    the CPU time of an evaluation. It asserts nothing about the times.

\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>

#include "particleShape.H"
#include "convexOverlap.H"
#include "shapeChecks.H"
#include "quaternion.H"
#include "IStringStream.H"
#include <chrono>

using namespace Foam;

namespace
{

autoPtr<particleShape> makeShape(const string& entries)
{
    IStringStream is(entries);
    dictionary dict(is);
    dict.name() = "particleProperties.p0";
    return particleShape::New(dict);
}


// CPU seconds per call of f, repeated for at least 0.2 s
template<class Function>
scalar secondsPerCall(const Function& f)
{
    using clock = std::chrono::steady_clock;
    label calls = 0;
    const auto start = clock::now();
    scalar elapsed = 0;
    while (elapsed < 0.2)
    {
        f();
        ++calls;
        elapsed = std::chrono::duration<scalar>(clock::now() - start).count();
    }
    return elapsed/calls;
}


// The grid overlap of a and b on cubes of side h: sum of
// max(0, fa + fb - 1) h^3 over the cells of both bounding boxes
scalar gridOverlap
(
    const particleShape& a,
    const point& Xa,
    const tensor& Ra,
    const particleShape& b,
    const point& Xb,
    const tensor& Rb,
    const scalar h
)
{
    const boundBox boxA(Xa - a.boundingRadius()*vector::one, Xa + a.boundingRadius()*vector::one);
    const boundBox boxB(Xb - b.boundingRadius()*vector::one, Xb + b.boundingRadius()*vector::one);
    const point lo(max(boxA.min(), boxB.min()));
    const point hi(min(boxA.max(), boxB.max()));
    const vector cells(cmptDivide(hi - lo, h*vector::one));
    scalar sum = 0;
    for (label i = 0; i < label(std::ceil(cells.x())); ++i)
    {
        for (label j = 0; j < label(std::ceil(cells.y())); ++j)
        {
            for (label k = 0; k < label(std::ceil(cells.z())); ++k)
            {
                const point corner(lo + h*vector(i, j, k));
                const boundBox cell(corner, corner + h*vector::one);
                const scalar fa = a.boxFraction(cell, Xa, Ra, vector::one, a.boundingRadius()/32);
                if (fa <= 0)
                {
                    continue;
                }
                const scalar fb = b.boxFraction(cell, Xb, Rb, vector::one, b.boundingRadius()/32);
                sum += max(fa + fb - 1, scalar(0))*pow3(h);
            }
        }
    }
    return sum;
}

} // End anonymous namespace


TEST_CASE("cost of one pair overlap by shape and method", "[.][contactCost]")
{
    // Sizes near 1; the tessellated sphere and the box's triangles as
    // surfaces (triSurface)
    autoPtr<particleShape> sphere(makeShape("shape sphere; radius 0.5;"));
    autoPtr<particleShape> brick(makeShape("shape box; halfExtents (0.5 0.3 0.2);"));
    pointField points;
    faceList faces;
    sphere->drawing(points, faces);
    const fileName sphereFile(shapeChecks::writeSurface("costSphere", points, faces));
    brick->drawing(points, faces);
    const fileName brickFile(shapeChecks::writeSurface("costBrick", points, faces));

    struct pairCase
    {
        word name;
        string a;
        string b;
        quaternion qb;
        vector direction;
        scalar smallest;
    };
    const quaternion level(quaternion::I);
    const quaternion tilted(vector(1, 2, 0)/Foam::sqrt(5.0), 0.6);
    const string egg("shape ellipsoid; semiAxes (1 0.6 0.3);");
    const string box("shape box; halfExtents (0.5 0.3 0.2);");
    const string can("shape cylinder; radius 0.4; length 0.6;");
    const List<pairCase> cases
    ({
        {"sphere-sphere", "shape sphere; radius 0.5;", "shape sphere; radius 0.5;", level, vector(0.3, 0.2, 0.8), 1},
        {"ellipsoid-ellipsoid", egg, egg, tilted, vector(0.3, 0.2, 0.8), 0.6},
        {"box-box", box, box, tilted, vector(0.2, 0.1, 0.6), 0.4},
        {"cylinder-box", can, box, tilted, vector(0.1, 0.3, 0.6), 0.4},
        {"cylinder-cylinder", can, can, tilted, vector(0, 0.1, 1), 0.6},
        {"boxSurface-boxSurface", "shape triSurface; file \"" + brickFile + "\";",
            "shape triSurface; file \"" + brickFile + "\";", tilted, vector(0.2, 0.1, 0.6), 0.4},
        {"sphereSurface-sphereSurface", "shape triSurface; file \"" + sphereFile + "\";",
            "shape triSurface; file \"" + sphereFile + "\";", level, vector(0.3, 0.2, 0.8), 1}
    });

    const convexOverlap convex;
    Info<< "contactCost,pair,method,volume,microseconds" << endl;
    for (const pairCase& c : cases)
    {
        autoPtr<particleShape> a(makeShape(c.a));
        autoPtr<particleShape> b(makeShape(c.b));
        const point Xa(0.01, 0.02, 0.03);
        const tensor Ra(tensor::I);
        const tensor Rb(c.qb.R());

        // b along the direction, at a least depth of 5 % of the smallest
        // dimension
        const vector e(c.direction/mag(c.direction));
        const scalar target = 0.05*c.smallest;
        scalar near = 0;
        scalar far = a->boundingRadius() + b->boundingRadius();
        for (label iter = 0; iter < 60; ++iter)
        {
            const scalar s = 0.5*(near + far);
            const bool deeper =
                convex.overlap(a(), Xa, Ra, b(), Xa + s*e, Rb).depth > target;
            (deeper ? near : far) = s;
        }
        const point Xb(Xa + 0.5*(near + far)*e);

        convexOverlap::result o;
        const scalar convexSeconds = secondsPerCall
        (
            [&] { o = convex.overlap(a(), Xa, Ra, b(), Xb, Rb); }
        );
        REQUIRE(o.volume > 0);
        Info<< "contactCost," << c.name << ",commonPlane," << o.volume << ","
            << 1e6*convexSeconds << endl;

        scalar planeDistance, lens;
        if (a->pairOverlap(b(), mag(Xb - Xa), lens, planeDistance))
        {
            const scalar closedSeconds = secondsPerCall
            (
                [&] { a->pairOverlap(b(), mag(Xb - Xa), lens, planeDistance); }
            );
            Info<< "contactCost," << c.name << ",closedForm," << lens << ","
                << 1e6*closedSeconds << endl;
        }

        for (const label cells : {4, 8, 16})
        {
            const scalar h = c.smallest/cells;
            scalar V = 0;
            const scalar gridSeconds = secondsPerCall
            (
                [&] { V = gridOverlap(a(), Xa, Ra, b(), Xb, Rb, h); }
            );
            Info<< "contactCost," << c.name << ",grid" << cells << "," << V
                << "," << 1e6*gridSeconds << endl;
        }
    }
}


// ************************************************************************* //
