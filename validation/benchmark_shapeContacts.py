#!/usr/bin/env python3
"""Cost and volume of one pair overlap by shape and method: the common-plane
construction of convex shapes (`overlap exact` for pairs without a closed
form, contact/convexOverlap), the sphere pair's closed form, and the paper's
grid sum max(0, phi_a + phi_b - 1) over cubic cells of 4, 8 and 16 per
smallest dimension (`overlap grid`, here on a grid of its own), for pairs of
spheres, ellipsoids, boxes, cylinders and triangulated surfaces (a box's 12
triangles, a sphere's 1280) at a least depth of 5 % of their smallest
dimension. Runs the hidden unit test [contactCost] of Test-dlmParticles,
prints the table and writes results/benchmark_shapeContacts.csv. A
benchmark, not a test: the times are CPU times of this machine under its
load at the time.

    validation/benchmark_shapeContacts.py
"""

import shutil

from common import Case, RESULTS, ROOT, RUNS, foam_environment, write_table


def main():
    env = foam_environment()
    case = Case.copy(ROOT / "tests" / "unit" / "box3D", RUNS / "shapeContacts", env)
    case.run("blockMesh")
    result = case.run("Test-dlmParticles", case.path, "[contactCost]", log="Test-dlmParticles")
    rows = []
    for line in result.log.splitlines():
        fields = line.split(",")
        if fields[0] == "contactCost" and fields[1] != "pair":
            rows.append((fields[1], fields[2], float(fields[3]), float(fields[4])))
    plane = {pair: volume for pair, method, volume, _ in rows if method == "commonPlane"}
    table = [(pair, method, f"{volume:.4e}", f"{volume/plane[pair]:.3f}", f"{us:.1f}")
             for pair, method, volume, us in rows]
    header = ["pair", "method", "volume", "volume/commonPlane", "microseconds"]
    write_table(RESULTS / "benchmark_shapeContacts.csv", header, table)
    width = max(len(r[0]) for r in table)
    print(f"{'pair':{width}}  {'method':12} {'volume':>11} {'/plane':>7} {'us':>9}")
    for pair, method, volume, ratio, us in table:
        print(f"{pair:{width}}  {method:12} {volume:>11} {ratio:>7} {us:>9}")
    shutil.rmtree(case.path, ignore_errors=True)


if __name__ == "__main__":
    main()
