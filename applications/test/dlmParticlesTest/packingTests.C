/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Description
    Unit tests of the packing's box and bins (packingBox, sphereBins)
    against brute force over all pairs: minimum-image separations, wrapping
    into the box, and every pair closer than the bin width visited once,
    across the periodic faces too.

\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>

#include "sphereBins.H"
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


// ************************************************************************* //
