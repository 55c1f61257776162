#!/usr/bin/env python3
"""Accuracy and cost of the solid fractions of each particle shape, as the
solver computes them: on meshes of cubic cells at 4, 8 and 16
cells per smallest dimension of the shape (the tutorials use about 8 to 16),
for several random centres (and random orientations where the row says so),
the relative error of the sum of fraction times cell volume against the
exact volume (mean and largest magnitude, and the signed mean: the bias),
and the CPU time of one particle's fractions against that of a sphere of the
same volume at the same cell size (the sphere's fractions are in closed
form). Each point is one run of the dlmShapeFractions utility (its Usage
tells how the fractions are computed). A benchmark, not a test: prints and
writes results/benchmark_shapeFractions.csv. The times depend on the
machine's load (the load average is printed with them).

A shape is added by one line in SHAPES: a label, its entries as in a
particle dictionary and whether it is turned at random (2D shapes lie in a
layer of unit depth and turn about z; their reference is the disk of the
same area).

    validation/benchmark_shapeFractions.py [--cells 4,8,16] [--samples 8]
"""

import argparse
import os
import re
import subprocess

from common import RESULTS, foam_environment, write_table

# Sizes in units of 1/128 m (about 8 mm): the cell sizes and faces are then
# exact binary fractions, so that where a cell's size over the leaf size is
# a power of two (the ellipsoids': bounding radius over smallest dimension 1
# and 2, surfaceResolution 32) every cell stops splitting at the same level
# (rounded spans would fall on either side of the leaf size, at random)
SHAPES = [
    # label, entries, random orientations
    ("sphere", "shape sphere; radius 0.0078125;", False),
    ("ellipsoid 2:1", "shape ellipsoid; semiAxes (0.015625 0.0078125 0.0078125);", True),
    ("ellipsoid 4:1", "shape ellipsoid; semiAxes (0.03125 0.0078125 0.0078125);", True),
    ("cylinder", "shape cylinder; radius 0.0078125; length 0.0234375;", True),
    ("box aligned", "shape box; halfExtents (0.015625 0.01171875 0.0078125);", False),
    ("box tilted", "shape box; halfExtents (0.015625 0.01171875 0.0078125);", True),
    ("rounded box", "shape box; halfExtents (0.015625 0.01171875 0.0078125); "
     "edgeRadius 0.00234375;", True),
]

COLUMNS = ["cellSize", "leafSize", "meanMagError", "maxMagError", "meanError", "timePerParticle",
           "sphereTimePerParticle", "timeRatio"]


def measure(env, entries, cells, samples, rotate):
    """The utility's results (its last line's name-value pairs)."""
    cmd = ["dlmShapeFractions", "-shape", entries, "-cells", str(cells),
           "-samples", str(samples)] + (["-rotate"] if rotate else [])
    out = subprocess.run(cmd, env=env, capture_output=True, text=True, check=True).stdout
    last = out.strip().splitlines()[-1].split()
    values = dict(zip(last[0::2], last[1::2]))
    return {name: float(values[name]) for name in COLUMNS}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cells", default="4,8,16")
    parser.add_argument("--samples", type=int, default=8)
    args = parser.parse_args()
    resolutions = [int(n) for n in args.cells.split(",")]

    env = foam_environment()
    print(f"load average at the start: {os.getloadavg()[0]:.2f}")
    print(f"{'shape':15s} {'cells':>5s} {'h/leaf':>6s} {'mean |err|':>10s} {'max |err|':>10s} "
          f"{'bias':>10s} {'ms/particle':>11s} {'x sphere':>8s}")
    rows = []
    for label, entries, rotate in SHAPES:
        for cells in resolutions:
            r = measure(env, entries, cells, args.samples, rotate)
            print(f"{label:15s} {cells:5d} {r['cellSize']/r['leafSize']:6.2f} {r['meanMagError']:10.2e} {r['maxMagError']:10.2e} "
                  f"{r['meanError']:10.2e} {1e3*r['timePerParticle']:11.3f} {r['timeRatio']:8.2f}")
            rows.append([label, re.sub(r"\s+", " ", entries), int(rotate), cells, args.samples]
                        + [r[name] for name in COLUMNS])
    print(f"load average at the end: {os.getloadavg()[0]:.2f}")
    write_table(RESULTS / "benchmark_shapeFractions.csv",
                ["shape", "entries", "rotated", "cellsPerSmallestDimension", "samples"]
                + COLUMNS, rows)


if __name__ == "__main__":
    main()
