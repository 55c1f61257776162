/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Description
    Tests of the particle shape read from a triangulated surface: a box's
    surface against the box (volume, inertia, distances, cuts, contacts), a
    tessellated sphere against the sphere within its tessellation's error,
    solid fractions against the volume, and the checks of the surface.

\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>

#include "particleShape.H"
#include "triSurfaceShape.H"
#include "convexOverlap.H"
#include "shapeChecks.H"
#include "Random.H"
#include "quaternion.H"
#include "mathematicalConstants.H"
#include "IStringStream.H"
#include "OSspecific.H"

using namespace Foam;
using constant::mathematical::pi;
using shapeChecks::show;
using shapeChecks::gridVolume;
using shapeChecks::surfaceDirectory;
using shapeChecks::writeSurface;

namespace
{

// The triangles of the box of the given half extents centred at offset,
// facing outwards
void boxTriangles
(
    const vector& halfExtents,
    const vector& offset,
    pointField& points,
    faceList& faces
)
{
    points.setSize(8);
    forAll(points, i)
    {
        points[i] = offset + cmptMultiply
        (
            halfExtents,
            vector(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1)
        );
    }
    const faceList quads
    ({
        face{0, 4, 6, 2}, face{1, 3, 7, 5},
        face{0, 1, 5, 4}, face{2, 6, 7, 3},
        face{0, 2, 3, 1}, face{4, 5, 7, 6}
    });
    faces.setSize(0);
    for (const face& q : quads)
    {
        faces.append(face{q[0], q[1], q[2]});
        faces.append(face{q[0], q[2], q[3]});
    }
}


autoPtr<particleShape> makeShape(const string& entries)
{
    IStringStream is(entries);
    dictionary dict(is);
    dict.name() = "particleProperties.p0";
    return particleShape::New(dict);
}


// The message of the error that f raises ("" if none)
template<class Function>
std::string errorOf(const Function& f)
{
    try
    {
        f();
    }
    catch (const Foam::error& err)
    {
        return err.message();
    }
    return "";
}


autoPtr<particleShape> surfaceShape(const fileName& file, const string& more = "")
{
    return makeShape("shape triSurface; file \"" + file + "\";" + more);
}

} // End anonymous namespace


TEST_CASE("a box's surface is the box", "[geometry]")
{
    // Sizes exact in the file's single precision
    const vector halfExtents(0.125, 0.25, 0.375);
    const tensor turn(quaternion(vector(1, 2, 3)/Foam::sqrt(14.0), 0.7).R());
    pointField points;
    faceList faces;
    boxTriangles(halfExtents, vector(1, 2, 3), points, faces);
    autoPtr<particleShape> box(makeShape("shape box; halfExtents (0.125 0.25 0.375);"));
    autoPtr<particleShape> surface(surfaceShape(writeSurface("box", points, faces)));

    // The file's axes turned: the inertia turns with them, a full tensor
    // (to the 6 digits of the file's turned coordinates)
    pointField turned(points.size());
    forAll(points, i)
    {
        turned[i] = turn & points[i];
    }
    autoPtr<particleShape> turnedSurface
    (
        surfaceShape(writeSurface("turnedBox", turned, faces))
    );

    const scalar V = box->volume();
    CHECK(surface->volume() == Approx(V).epsilon(1e-12));
    CHECK(surface->boundingRadius() == Approx(box->boundingRadius()).epsilon(1e-12));
    const symmTensor I(box->inertiaPerUnitDensity());
    CHECK(mag(surface->inertiaPerUnitDensity() - I) < 1e-12*mag(I));
    const tensor turnedI(turn & tensor(I) & turn.T());
    CHECK(mag(tensor(turnedSurface->inertiaPerUnitDensity()) - turnedI) < 1e-4*mag(I));
    CHECK(surface->convex());

    // With a scale: volume by its cube
    CHECK
    (
        surfaceShape(writeSurface("box", points, faces), " scale 2;")->volume()
     == Approx(8*V).epsilon(1e-12)
    );

    // Distances, supports and cuts are the box's
    Random rnd(5);
    for (label sample = 0; sample < 200; ++sample)
    {
        const vector r(0.5*(2*rnd.sample01<vector>() - vector::one));
        vector nBox, nSurface;
        const scalar dBox = box->signedDistance(r, nBox);
        const scalar dSurface = surface->signedDistance(r, nSurface);
        INFO("at " << show(r));
        CHECK(dSurface == Approx(dBox).margin(1e-12));
        // On the closest point, along the normal
        vector n;
        CHECK(box->signedDistance(r - dSurface*nSurface, n) == Approx(0).margin(1e-12));

        const vector u(normalised(2*rnd.sample01<vector>() - vector::one));
        CHECK(surface->support(u) == Approx(box->support(u)).epsilon(1e-12));
        const scalar d = box->support(u)*(2*rnd.sample01<scalar>() - 1);
        scalar Vb, Vs, Ab, As;
        vector Cb, Cs;
        box->planeCut(u, d, Vb, Cb, Ab);
        REQUIRE(surface->planeCut(u, d, Vs, Cs, As));
        INFO("normal " << show(u) << " distance " << d);
        CHECK(Vs == Approx(Vb).epsilon(1e-10));
        CHECK(mag(Cs - Cb) < 1e-10);
        CHECK(As == Approx(Ab).epsilon(1e-10));
    }

    // The box's faces and edges are the kinks of the support function
    DynamicList<vector> ridges, corners;
    surface->supportKinks(ridges, corners);
    CHECK(ridges.size() == 3);
    CHECK(corners.size() == 6);

    // The contact between two of them is the boxes' contact
    const convexOverlap overlap;
    const tensor tilt(quaternion(vector(0, 1, 0), 0.3).R());
    const point Xb(0.05, 0.02, 0.55);
    const convexOverlap::result ofBoxes =
        overlap.overlap(*box, Zero, tensor::I, *box, Xb, tilt);
    const convexOverlap::result ofSurfaces =
        overlap.overlap(*surface, Zero, tensor::I, *surface, Xb, tilt);
    REQUIRE(ofBoxes.volume > 0);
    CHECK(ofSurfaces.depth == Approx(ofBoxes.depth).epsilon(1e-6));
    CHECK(ofSurfaces.volume == Approx(ofBoxes.volume).epsilon(1e-6));
    CHECK(mag(ofSurfaces.normal - ofBoxes.normal) < 1e-6);
}


TEST_CASE("a tessellated sphere's surface approaches the sphere", "[geometry]")
{
    // The sphere's drawing (icosahedron split three times: 1280 triangles
    // on the sphere) is an inscribed polyhedron: its volume and inertia are
    // below the sphere's by about the square of the edge over the radius
    // (measured: -0.86 % and -1.43 %)
    const scalar radius = 0.2;
    autoPtr<particleShape> sphere(makeShape("shape sphere; radius 0.2;"));
    pointField points;
    faceList faces;
    sphere->drawing(points, faces);
    REQUIRE(faces.size() == 1280);
    autoPtr<particleShape> surface(surfaceShape(writeSurface("sphere", points, faces)));

    const scalar V = 4.0/3.0*pi*pow3(radius);
    const scalar volumeError = surface->volume()/V - 1;
    INFO("volume error " << volumeError);
    CHECK(volumeError < 0);
    CHECK(volumeError > -0.01);
    const symmTensor I(surface->inertiaPerUnitDensity());
    const scalar inertiaError = I.xx()/(0.4*V*sqr(radius)) - 1;
    INFO("inertia error " << inertiaError);
    CHECK(inertiaError < 0);
    CHECK(inertiaError > -0.02);
    CHECK(mag(I.xy()) + mag(I.xz()) + mag(I.yz()) < 1e-3*I.xx());
    CHECK(surface->convex());

    // Many faces: no kinks reported, the search finds the least depth
    DynamicList<vector> ridges, corners;
    surface->supportKinks(ridges, corners);
    CHECK(ridges.empty());
    CHECK(corners.empty());

    // Cuts: the section is the rate of change of the volume, and the cap
    // is the sphere's within the tessellation's error
    for (const vector& raw : {vector(0, 0, 1), vector(1, 2, 2), vector(0.3, -0.7, 0.1)})
    {
        const vector n(raw/mag(raw));
        for (const scalar d : {-0.1, 0.05, 0.15})
        {
            scalar Vcut, area;
            vector centroid;
            surface->planeCut(n, d, Vcut, centroid, area);
            const scalar dd = 1e-7;
            scalar Vlow, Vhigh, a;
            vector c;
            surface->planeCut(n, d - dd, Vlow, c, a);
            surface->planeCut(n, d + dd, Vhigh, c, a);
            const scalar cap = pi*sqr(radius - d)*(2*radius + d)/3;
            INFO("normal " << show(n) << " distance " << d);
            CHECK(area == Approx((Vlow - Vhigh)/(2*dd)).epsilon(1e-5));
            CHECK(Vcut == Approx(cap).epsilon(0.03));
            CHECK(area == Approx(pi*(sqr(radius) - sqr(d))).epsilon(0.03));
            // On the normal through the centre: the cap's symmetry axis
            CHECK(mag(centroid - (centroid & n)*n) < 0.01*radius);
        }
    }

    // Signed distances: the sphere's, less the inscribed polyhedron's
    // sagitta at most
    Random rnd(7);
    const scalar sagitta = radius - surface->support(vector(1, 1, 1)/Foam::sqrt(3.0));
    for (label sample = 0; sample < 100; ++sample)
    {
        const vector r(0.4*(2*rnd.sample01<vector>() - vector::one));
        vector n;
        const scalar expected = mag(r) - radius;
        const scalar d = surface->signedDistance(r, n);
        INFO("at " << show(r) << ": " << d << " against " << expected);
        CHECK(d >= expected - 1e-12);
        CHECK(d <= expected + 0.02*radius);
        CHECK(mag(n - r/mag(r)) < 0.2);
    }
    CHECK(sagitta >= 0);
}


TEST_CASE("a surface's fractions integrate to its volume", "[geometry]")
{
    // A box's surface, aligned and turned, fractions down to the solver's
    // default leaves: measured 1.4e-4 and 4.4e-4 at 8 and 16 cells per
    // smallest side (the leaves' tangent planes; the box primitive turned:
    // 3.9e-4)
    pointField points;
    faceList faces;
    boxTriangles(vector(0.5, 0.375, 0.25), Zero, points, faces);
    autoPtr<particleShape> surface(surfaceShape(writeSurface("fractionBox", points, faces)));
    const tensor turn(quaternion(vector(1, 2, 3)/Foam::sqrt(14.0), 0.7).R());
    Random rnd(29);
    for (const label cells : {8, 16})
    {
        const scalar h = 0.5/cells;
        const point X(h*rnd.sample01<vector>());
        const scalar alignedError = gridVolume(*surface, X, tensor::I, h)/surface->volume() - 1;
        const scalar turnedError = gridVolume(*surface, X, turn, h)/surface->volume() - 1;
        INFO(cells << " cells: aligned " << alignedError << ", turned " << turnedError);
        CHECK(mag(alignedError) < 5e-4);
        CHECK(mag(turnedError) < 5e-4);
    }
}


TEST_CASE("a particle's surface is checked", "[geometry]")
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    pointField points;
    faceList faces;
    boxTriangles(vector(0.125, 0.25, 0.375), Zero, points, faces);

    // Missing, open, inconsistently oriented: refused
    CHECK_THAT
    (
        errorOf([] { surfaceShape(surfaceDirectory()/"none.stl"); }),
        Catch::Contains("Particle p0: cannot find the surface file")
    );
    faceList open(faces);
    open.setSize(11);
    CHECK_THAT
    (
        errorOf([&] { surfaceShape(writeSurface("open", points, open)); }),
        Catch::Contains("Particle p0: the surface")
     && Catch::Contains("is not closed")
    );
    faceList misoriented(faces);
    misoriented[3] = misoriented[3].reverseFace();
    CHECK_THAT
    (
        errorOf
        (
            [&] { surfaceShape(writeSurface("misoriented", points, misoriented)); }
        ),
        Catch::Contains("not consistently oriented")
    );

    // Inwards throughout: turned, the same solid
    faceList inwards(faces);
    for (face& f : inwards)
    {
        f = f.reverseFace();
    }
    autoPtr<particleShape> turned(surfaceShape(writeSurface("inwards", points, inwards)));
    CHECK(turned->volume() == Approx(8*0.125*0.25*0.375).epsilon(1e-12));
    vector n;
    CHECK(turned->signedDistance(Zero, n) == Approx(-0.125).epsilon(1e-12));

    // Two boxes side by side, and an L of them sharing a face: not convex
    pointField second;
    faceList secondFaces;
    boxTriangles(vector(0.125, 0.25, 0.375), vector(0.5, 0, 0), second, secondFaces);
    pointField both(points);
    both.append(second);
    faceList bothFaces(faces);
    for (const face& f : secondFaces)
    {
        bothFaces.append(face{f[0] + 8, f[1] + 8, f[2] + 8});
    }
    autoPtr<particleShape> apart(surfaceShape(writeSurface("apart", both, bothFaces)));
    CHECK_FALSE(apart->convex());
    CHECK(apart->volume() == Approx(2*8*0.125*0.25*0.375).epsilon(1e-12));

    // An L: a block with a notch, the prism over an L-shaped section
    const List<vector2D> section
    ({
        {0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}
    });
    pointField prism;
    for (const scalar z : {0.0, 1.0})
    {
        for (const vector2D& p : section)
        {
            prism.append(vector(p.x(), p.y(), z));
        }
    }
    faceList prismFaces;
    prismFaces.append(face{0, 2, 1});
    prismFaces.append(face{0, 3, 2});
    prismFaces.append(face{0, 5, 3});
    prismFaces.append(face{3, 5, 4});
    prismFaces.append(face{6, 7, 8});
    prismFaces.append(face{6, 8, 9});
    prismFaces.append(face{6, 9, 11});
    prismFaces.append(face{9, 10, 11});
    for (label k = 0; k < 6; ++k)
    {
        const label next = (k + 1) % 6;
        prismFaces.append(face{k, next, next + 6});
        prismFaces.append(face{k, next + 6, k + 6});
    }
    autoPtr<particleShape> notched(surfaceShape(writeSurface("notched", prism, prismFaces)));
    CHECK(notched->volume() == Approx(3).epsilon(1e-12));
    CHECK_FALSE(notched->convex());

    // Its cut across the notch: the two arms beyond the plane x = 1.5
    // (centroid of the L at (5/6 5/6 1/2))
    scalar V, area;
    vector centroid;
    notched->planeCut(vector(1, 0, 0), 1.5 - 5.0/6.0, V, centroid, area);
    CHECK(V == Approx(0.5).epsilon(1e-12));
    CHECK(area == Approx(1).epsilon(1e-12));
    CHECK(centroid.x() == Approx(1.75 - 5.0/6.0).epsilon(1e-12));

    FatalError.dontThrowExceptions();
    FatalIOError.dontThrowExceptions();
}


// ************************************************************************* //
