/*---------------------------------------------------------------------------*\
  pimpleDLMFoam: particle-resolved simulation of fluid-particle flows with the
  distributed Lagrange multiplier method, built on OpenFOAM.
  License: GNU General Public License v3 or later.
-------------------------------------------------------------------------------
Description
    Unit tests of the near-cell search (cellBins) against a brute-force
    search over all boxes: graded and flat (2D) layouts, boxes touching at
    faces, queries partly or wholly outside.

\*---------------------------------------------------------------------------*/

#include <catch2/catch.hpp>

#include "cellBins.H"
#include "Random.H"
#include "HashSet.H"

using namespace Foam;

namespace
{

//- Boxes of a grid graded geometrically in x (ratio 1.1 per cell), uniform
//  in y, and in z unless flat (one layer)
List<boundBox> gradedGrid(const label n, const bool flat)
{
    scalarList x(n + 1, Zero);
    scalar h = 1;
    for (label i = 0; i < n; ++i)
    {
        x[i + 1] = x[i] + h;
        h *= 1.1;
    }
    const label nz = flat ? 1 : n;
    List<boundBox> boxes;
    for (label k = 0; k < nz; ++k)
    {
        for (label j = 0; j < n; ++j)
        {
            for (label i = 0; i < n; ++i)
            {
                boxes.append
                (
                    boundBox
                    (
                        point(x[i], j, flat ? 0 : k),
                        point(x[i + 1], j + 1, flat ? 0.1 : k + 1)
                    )
                );
            }
        }
    }
    return boxes;
}


void checkAgainstBruteForce(const List<boundBox>& boxes)
{
    const cellBins bins(boxes);
    boundBox all;
    for (const boundBox& bb : boxes)
    {
        all.add(bb);
    }
    Random rnd(7);
    for (label q = 0; q < 200; ++q)
    {
        // Queries from a fraction of a cell to a third of the layout,
        // reaching past its sides
        const point c
        (
            cmptMultiply(rnd.sample01<vector>(), 1.2*all.span())
          + all.min() - 0.1*all.span()
        );
        const vector half(0.5*rnd.sample01<scalar>()*all.span()/3);
        const boundBox query(c - half, c + half);

        DynamicList<label> found;
        bins.findBox(query, found);
        const labelHashSet foundSet(found);
        CHECK(foundSet.size() == found.size());

        label expected = 0;
        forAll(boxes, celli)
        {
            if (query.overlaps(boxes[celli]))
            {
                ++expected;
                CHECK(foundSet.found(celli));
            }
        }
        CHECK(found.size() == expected);
    }

    // A query whose side lies on cell faces finds the cells that touch it
    const boundBox& first = boxes[0];
    DynamicList<label> found;
    bins.findBox(boundBox(first.max(), first.max() + first.span()), found);
    CHECK(labelHashSet(found).found(0));
}

} // End anonymous namespace


TEST_CASE("near-cell search finds what brute force finds", "[geometry]")
{
    SECTION("graded 3D grid")
    {
        checkAgainstBruteForce(gradedGrid(20, false));
    }
    SECTION("flat (2D) grid")
    {
        checkAgainstBruteForce(gradedGrid(30, true));
    }
}


// ************************************************************************* //
