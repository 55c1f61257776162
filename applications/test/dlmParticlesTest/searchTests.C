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

//- Boxes of a grid graded geometrically in x (ratio per cell), uniform
//  in y, and in z unless flat (one layer)
List<boundBox> gradedGrid(const label n, const bool flat, const scalar ratio)
{
    scalarList x(n + 1, Zero);
    scalar h = 1;
    for (label i = 0; i < n; ++i)
    {
        x[i + 1] = x[i] + h;
        h *= ratio;
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

    // Queries whose sides or corners lie on cell faces (on a uniform grid
    // also on bin edges) find the cells that touch them
    for (const label celli : {label(0), label(boxes.size()/2)})
    {
        const boundBox& bb = boxes[celli];
        DynamicList<label> found;
        bins.findBox(boundBox(bb.max(), bb.max() + bb.span()), found);
        CHECK(labelHashSet(found).found(celli));
        found.clear();
        bins.findBox(boundBox(bb.max(), bb.max()), found);
        CHECK(labelHashSet(found).found(celli));
    }
}

} // End anonymous namespace


TEST_CASE("near-cell search finds what brute force finds", "[geometry]")
{
    SECTION("uniform 3D grid (cell faces on bin edges)")
    {
        checkAgainstBruteForce(gradedGrid(20, false, 1));
    }
    SECTION("graded 3D grid")
    {
        checkAgainstBruteForce(gradedGrid(20, false, 1.1));
    }
    SECTION("flat (2D) grid")
    {
        checkAgainstBruteForce(gradedGrid(30, true, 1.1));
    }
}


// ************************************************************************* //
