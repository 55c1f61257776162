/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Description
    Unit tests of the packing's box and bins (packingBox, sphereBins)
    against brute force over all pairs: minimum-image separations, wrapping
    into the box, and every pair closer than the bin width visited once,
    across the periodic faces too. The random insertion of mixed shapes
    (randomShapeInsertion) checked independently of its separating-plane
    test: no point of a fine grid inside two particles, every point of
    each particle's surface inside the box; the same seed gives the same
    placement, an impossible request an error.

\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>

#include "sphereBins.H"
#include "randomShapeInsertion.H"
#include "IStringStream.H"
#include "Random.H"

using namespace Foam;

namespace
{

//- A box off the origin, periodic in x and y, walls in z
packingBox testBox()
{
    return packingBox
    (
        dictionary
        (
            IStringStream
            (
                "box (-1 0.5 2) (2 2.5 4); periodic (yes yes no);"
            )()
        ),
        0.1
    );
}


//- Random points spread over twice the box, around it
pointField randomPoints(const packingBox& box, const label n, const label seed)
{
    Random rnd(seed);
    pointField points(n);
    for (point& p : points)
    {
        p = box.lowerCorner() - 0.5*box.length()
          + cmptMultiply(rnd.sample01<vector>(), 2*box.length());
    }
    return points;
}

} // End anonymous namespace


TEST_CASE("packing box wraps and takes minimum images", "[geometry]")
{
    const packingBox box(testBox());
    const pointField points(randomPoints(box, 200, 1));
    for (const point& p : points)
    {
        point wrapped(p);
        box.wrap(wrapped);
        for (direction i = 0; i < 2; ++i)
        {
            CHECK(wrapped[i] >= box.lowerCorner()[i]);
            CHECK(wrapped[i] < box.upperCorner()[i]);
            const scalar shifts = (p[i] - wrapped[i])/box.length()[i];
            CHECK(std::abs(shifts - std::round(shifts)) < 1e-12);
        }
        CHECK(wrapped.z() == p.z());

        const vector d(box.separation(p, points[0]));
        CHECK(std::abs(d.x()) <= 0.5*box.length().x());
        CHECK(std::abs(d.y()) <= 0.5*box.length().y());
        CHECK(d.z() == p.z() - points[0].z());
    }
}


TEST_CASE("sphere bins visit each close pair once", "[geometry]")
{
    const packingBox box(testBox());
    pointField centres(randomPoints(box, 300, 2));
    for (point& p : centres)
    {
        box.wrap(p);
        p.z() = Foam::min(box.upperCorner().z(), p.z());
        p.z() = Foam::max(box.lowerCorner().z(), p.z());
    }
    const label n = centres.size();

    label seed = 3;
    for (const scalar width : {0.3, 0.7, 1.1})
    {
        sphereBins bins(box, width, n);
        bins.fill(centres);
        REQUIRE(bins.minWidth() >= width);

        // Half the spheres moved by the bins, as in the compression
        pointField moved(randomPoints(box, n/2, seed++));
        forAll(moved, i)
        {
            box.wrap(moved[i]);
            moved[i].z() = centres[i].z();
            bins.move(i, centres[i], moved[i]);
            centres[i] = moved[i];
        }

        labelList pairVisits(n*n, Zero);
        bins.forAllPairs
        (
            [&](const label i, const label j)
            {
                CHECK(i < j);
                ++pairVisits[i*n + j];
            }
        );
        for (label i = 0; i < n; ++i)
        {
            for (label j = i + 1; j < n; ++j)
            {
                CHECK(pairVisits[i*n + j] <= 1);
                if (mag(box.separation(centres[i], centres[j])) < width)
                {
                    CHECK(pairVisits[i*n + j] == 1);
                }
            }
        }

        // The neighbours of a point include all centres closer than width
        const point& p = centres[0];
        labelList visits(n, Zero);
        bins.forNeighbours(p, [&](const label j) { ++visits[j]; return true; });
        forAll(centres, j)
        {
            CHECK(visits[j] <= 1);
            if (mag(box.separation(p, centres[j])) < width)
            {
                CHECK(visits[j] == 1);
            }
        }
    }
}


namespace
{

//- Two dozen spheres, ellipsoids, boxes and cylinders in a box walled in x
//  and y, periodic in z, with a gap of 0.2 mm
dictionary mixedShapes(const label seed, const label nBalls)
{
    return dictionary
    (
        IStringStream
        (
            "box (0 0 0) (0.03 0.03 0.024); periodic (no no yes);"
            "gap 0.0002; seed " + Foam::name(seed) + ";"
            "particles {"
            "  ball { number " + Foam::name(nBalls) + "; shape sphere;"
            "         radius 0.003; density 2500; }"
            "  egg { number 6; shape ellipsoid; semiAxes (0.004 0.0025 0.002);"
            "        density 1400; }"
            "  brick { number 6; shape box; halfExtents (0.0035 0.003 0.0015);"
            "          density 2000; }"
            "  can { number 6; shape cylinder; radius 0.0025; length 0.006;"
            "        density 2000; orientation (1 (0 0 0)); }"
            "}"
        )()
    );
}

} // End anonymous namespace


TEST_CASE("random insertion places mixed shapes apart", "[geometry]")
{
    randomShapeInsertion packing(mixedShapes(3, 6));
    packing.pack();
    const List<point>& X = packing.positions();
    REQUIRE(X.size() == 24);

    // Every pair whose bounding spheres meet: a grid of 40^3 points over
    // the box around their common part, none inside both shapes
    const scalar period = 0.024;
    const label nGrid = 40;
    label nClose = 0;
    forAll(X, i)
    {
        const particleShape& a = packing.shape(i);
        const tensor Ra(packing.orientations()[i].R());
        for (label j = i + 1; j < X.size(); ++j)
        {
            const particleShape& b = packing.shape(j);
            const tensor Rb(packing.orientations()[j].R());
            vector d(X[j] - X[i]);
            d.z() -= period*std::round(d.z()/period);
            const scalar ra = a.boundingRadius();
            const scalar rb = b.boundingRadius();
            if (mag(d) >= ra + rb)
            {
                continue;
            }
            ++nClose;
            const boundBox lens
            (
                max(-ra*vector::one, d - rb*vector::one),
                min(ra*vector::one, d + rb*vector::one)
            );
            label nInBoth = 0;
            vector normal;
            for (label l = 0; l < nGrid; ++l)
            {
                for (label m = 0; m < nGrid; ++m)
                {
                    for (label k = 0; k < nGrid; ++k)
                    {
                        const vector r
                        (
                            lens.min()
                          + cmptMultiply
                            (
                                vector(l + 0.5, m + 0.5, k + 0.5)/nGrid,
                                lens.span()
                            )
                        );
                        if
                        (
                            a.signedDistance(Ra.T() & r, normal) < 0
                         && b.signedDistance(Rb.T() & (r - d), normal) < 0
                        )
                        {
                            ++nInBoth;
                        }
                    }
                }
            }
            CHECK(nInBoth == 0);
        }
    }
    // The test is not empty: the bounding spheres of many pairs meet
    CHECK(nClose > 10);

    // Every particle inside the walls in x and y by the gap: each point
    // of its drawn surface (on the surface, with the exact corners of a
    // box and rims of a cylinder)
    forAll(X, i)
    {
        pointField points;
        faceList faces;
        packing.shape(i).drawing(points, faces);
        const tensor R(packing.orientations()[i].R());
        for (const point& r : points)
        {
            const point p(X[i] + (R & r));
            for (direction c = 0; c < 2; ++c)
            {
                CHECK(p[c] >= 0.0002 - 1e-12);
                CHECK(p[c] <= 0.03 - 0.0002 + 1e-12);
            }
        }
    }
}


TEST_CASE("random insertion repeats with its seed", "[geometry]")
{
    randomShapeInsertion first(mixedShapes(3, 6));
    randomShapeInsertion again(mixedShapes(3, 6));
    randomShapeInsertion other(mixedShapes(4, 6));
    first.pack();
    again.pack();
    other.pack();
    REQUIRE(first.positions().size() == again.positions().size());
    bool same = true;
    bool sameAsOther = true;
    forAll(first.positions(), i)
    {
        same = same
         && first.positions()[i] == again.positions()[i]
         && first.orientations()[i].w() == again.orientations()[i].w()
         && first.orientations()[i].v() == again.orientations()[i].v()
         && first.name(i) == again.name(i);
        sameAsOther = sameAsOther
         && mag(first.positions()[i] - other.positions()[i]) < 1e-9;
    }
    CHECK(same);
    CHECK_FALSE(sameAsOther);

    // The cylinders keep the orientation given, the others turn at random
    label nTurned = 0;
    forAll(first.positions(), i)
    {
        const quaternion& q = first.orientations()[i];
        if (first.name(i).substr(0, 4) == "can_")
        {
            CHECK(q.w() == 1);
        }
        else
        {
            CHECK(mag(q.w()*q.w() + magSqr(q.v()) - 1) < 1e-12);
            nTurned += mag(q.w()) < 0.99;
        }
    }
    CHECK(nTurned > 10);
}


TEST_CASE("random insertion stops on an impossible request", "[geometry]")
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    // 200 balls of 6 mm in 21.6 cm3: a solid fraction of 1.05
    randomShapeInsertion packing(mixedShapes(1, 200));
    CHECK_THROWS(packing.pack());

    FatalError.dontThrowExceptions();
    FatalIOError.dontThrowExceptions();
}


// ************************************************************************* //
