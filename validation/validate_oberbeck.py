#!/usr/bin/env python3
"""Stokes drag of a fixed prolate spheroid along and across its axis
against Oberbeck's closed forms (Happel & Brenner 1965, eqs. 5-11.13 and
5-11.14; tests/stokesFlow.py), the sphere (aspect 1) as the check of the
set-up.

The spheroid (semi-axes a = aspect b, b, b; b = 1 mm, its long axis along
x, turned to y by its orientation quaternion for the flow across it) is
held at the centre of a periodic cube of side L (a simple cubic array):
uniform cells of size h = 2b/N (N cells per minor diameter) around it, at
least three cells beyond its bounding box, growing geometrically (at most
1.2 from cell to cell) towards the periodic faces, so that L can be
several body lengths at little cost (blockMesh multi-grading; the cells stay
axis-aligned boxes). A mean velocity U = 1e-5 m/s along x is held by
meanVelocityForce (mu = 1 Pa s, Re = 2e-5), which removes the slow start-up
of the mean flow through a dilute array; the run ends after 0.12 L^2/nu,
where the drag has settled (its drift over the last fifth is reported;
the viscous number is held at 2 with three pressure correctors, see
VISCOUS_NUMBER).

The drag F over the superficial velocity u (packedBed: the particle's force
and the volume-averaged velocity) is the array's resistance; its leading
periodic part is removed as for a Stokeslet lattice (Hasimoto 1959):
1/R = u/F + 2.8373/(6 pi mu L), leaving O(L^-3) (for a sphere phi =
4/3 pi a^3/L^3 in 1/R: 0.1 % at L = 16 b; --box shows it for the
spheroids). Writes
results/oberbeck.csv and results/oberbeck.png (error against resolution and
against wall time); prints error, wall time and the observed order.

    validation/validate_oberbeck.py [--cases 1x,2x,2y,4x,4y] [--box L/b]
        [--viscous-number 2] [--pressure-correctors 3]
        [--no-momentum-predictor] [N ...]
        (default: the spheroids 2x 2y 4x 4y, N = 8 12 16; x: flow along the
        axis, y: across; the box is 16 b for the sphere and aspect 2, 24 b
        for aspect 4 unless --box)
"""

import argparse
import math
import re

import numpy as np

from common import (Case, RESULTS, ROOT, RUNS, foam_environment, merge_row,
                    observed_order, packed_bed_rows, plot_speed_error,
                    stored_rows, timed_run)
from foamcase import write_periodic_box
from stokesFlow import HASIMOTO, oberbeck_resistances, unbounded_resistance

TABLE = RESULTS / "oberbeck.csv"
HEADER = ["case", "cellsPerMinorDiameter", "box_b", "cells", "R_periodic",
          "R_corrected", "R_Oberbeck", "relError", "correction", "drift",
          "wallTime_s", "steps", "momentumPredictor", "viscousNumber",
          "pressureCorrectors"]
B = 1e-3                    # minor semi-axis [m]
MU, NU = 1.0, 1e-3          # dynamic [Pa s] and kinematic [m2/s] viscosity
U_MEAN = 1e-5               # mean velocity [m/s]
DEFAULT_BOX = {1: 16, 2: 16, 4: 24}     # in b
MARGIN = 3                  # uniform cells beyond the bounding box
GROWTH = 1.2                # largest ratio of neighbouring cell sizes
# The viscous number nu deltaT/h^2 and the pressure correctors per step:
# the flow swings from step to step and grows in the graded cells next to
# the periodic faces, long along one axis and h across, without a particle
# too and in OpenFOAM's own pimpleFoam. Three correctors hold 2 at N = 8-16;
# six hold 50 at N = 8 (a tenth of the steps) but not at 12, whose longest
# cells are longer (validation/cases/viscousLimit.md)
VISCOUS_NUMBER = 2
PRESSURE_CORRECTORS = 3
SETTLE = 0.12               # run time in L^2/nu


def graded_sections(length, core, h):
    """blockMesh multi-grading along one side of length 'length' with a
    uniform core of half-width 'core' (a whole number of cells h) at its
    centre: cells growing geometrically from h next to the core to the
    faces, at a ratio up to GROWTH. Returns the grading text and the
    number of cells."""
    outer = length/2 - core
    n_core = round(2*core/h)
    n = 0
    while h*sum(GROWTH**k for k in range(1, n + 1)) < outer:
        n += 1
    # The ratio r that fills the outer section with n cells h r, ..., h r^n
    lo, hi = 1.0, GROWTH
    for _ in range(100):
        r = 0.5*(lo + hi)
        if h*sum(r**k for k in range(1, n + 1)) < outer:
            lo = r
        else:
            hi = r
    r = 0.5*(lo + hi)
    grading = (f"(({outer!r} {n} {r**(1 - n)!r}) ({2*core!r} {n_core} 1)"
               f" ({outer!r} {n} {r**(n - 1)!r}))")
    return grading, n_core + 2*n


def make_case(name, aspect, across, n, box, predictor, viscous_number, correctors, env):
    case = Case.copy(ROOT / "tutorials" / "periodicArray",
                     RUNS / (f"oberbeck_{name}_N{n}_L{box:g}_VN{viscous_number:g}"
                            f"_p{correctors}" + ("" if predictor else "_noPredictor")),
                     env)
    h = 2*B/n
    L = box*B
    a = aspect*B
    extent = np.array([B, a, B]) if across else np.array([a, B, B])
    gradings, counts = zip(*(graded_sections(L, h*math.ceil(e/h + MARGIN), h)
                             for e in extent))
    write_periodic_box(case, (L, L, L), counts, gradings)
    # Long axis along body x; across the flow: turned 90 degrees about z
    half = math.pi/4
    orientation = f"({math.cos(half)!r} (0 0 {math.sin(half)!r}))" if across else "(1 (0 0 0))"
    (case.path / "constant" / "particleProperties").write_text(f"""\
FoamFile {{ version 2.0; format ascii; class dictionary; object particleProperties; }}
particles
{{
    spheroid
    {{
        shape       ellipsoid;
        semiAxes    ({a!r} {B!r} {B!r});
        orientation {orientation};
        density     1000;
        position    ({L/2!r} {L/2!r} {L/2!r});
        motion      fixed;
    }}
}}
""")
    # The mean velocity held first, then the particle made rigid
    (case.path / "system" / "fvOptions").write_text(f"""\
FoamFile {{ version 2.0; format ascii; class dictionary; object fvOptions; }}
meanVelocity
{{
    type            meanVelocityForce;
    selectionMode   all;
    fields          (U);
    Ubar            ({U_MEAN!r} 0 0);
}}
rigidProjection
{{
    type            rigidProjection;
}}
""")
    end = SETTLE*L**2/NU
    for (file, entry), value in {
        ("system/controlDict", "endTime"): end,
        ("system/controlDict", "writeInterval"): end,
        ("system/controlDict", "deltaT"): 1e-6,
        ("system/controlDict", "maxViscousNumber"): viscous_number,
        ("system/fvSolution", "PIMPLE/nCorrectors"): correctors,
        ("system/fvSolution", "PIMPLE/momentumPredictor"): "yes" if predictor else "no",
        ("system/fvSolution", "solvers/U"): "{ solver GAMG; smoother symGaussSeidel;"
                                            " tolerance 1e-10; relTol 0; }",
        ("system/fvSolution", "PIMPLE/pRefPoint"): f"({h/2!r} {h/2!r} {h/2!r})",
        ("constant/transportProperties", "nu"): NU,
    }.items():
        case.set(file, entry, value)
    case.run("blockMesh")
    return case, int(np.prod(counts))


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--cases", default="2x,2y,4x,4y")
    parser.add_argument("--box", type=float, help="side of the periodic cube in b")
    parser.add_argument("--no-momentum-predictor", action="store_true",
                        help="no momentum predictor (PIMPLE), against the step-to-step swing")
    parser.add_argument("--viscous-number", type=float, default=VISCOUS_NUMBER,
                        help="largest nu deltaT/h^2")
    parser.add_argument("--pressure-correctors", type=int, default=PRESSURE_CORRECTORS,
                        help="pressure correctors per step (PIMPLE nCorrectors)")
    parser.add_argument("resolutions", nargs="*", type=int, default=[8, 12, 16])
    args = parser.parse_args()

    env = foam_environment()
    RESULTS.mkdir(parents=True, exist_ok=True)
    for name in args.cases.split(","):
        aspect, across = int(name[:-1]), name[-1] == "y"
        box = args.box or DEFAULT_BOX[aspect]
        along_axis, across_axis = (oberbeck_resistances(aspect*B, B, MU) if aspect > 1
                                   else (6*math.pi*MU*B,)*2)
        exact = across_axis if across else along_axis
        for n in args.resolutions:
            predictor = not args.no_momentum_predictor
            case, cells = make_case(name, aspect, across, n, box, predictor,
                                    args.viscous_number, args.pressure_correctors, env)
            seconds = timed_run(case, "pimpleDLMFoam")
            rows = packed_bed_rows(case.path)
            t, u, drag = rows[:, 0], rows[:, 1], rows[:, 8]
            periodic = drag/u
            late = t >= 0.8*t[-1]
            drift = periodic[late][-1]/periodic[late][0] - 1
            corrected = unbounded_resistance(periodic[-1], MU, box*B)
            correction = corrected/periodic[-1] - 1
            error = corrected/exact - 1
            steps = len(re.findall(r"^Time = ", (case.path / "log.pimpleDLMFoam").read_text(),
                                   re.M))
            merge_row(TABLE, HEADER, [name, n, box, cells, periodic[-1], corrected, exact,
                                      error, correction, drift, seconds, steps, int(predictor),
                                      args.viscous_number, args.pressure_correctors],
                      key_columns=3)
            print(f"{name} N={n:3d} L={box:g}b cells={cells} F/u={periodic[-1]:.6g}"
                  f" corrected={corrected:.6g} (periodic part {100*correction:+.2f}%)"
                  f" Oberbeck={exact:.6g} error={100*error:+.2f}% drift={100*drift:+.3f}%"
                  f" wall={seconds:.0f}s steps={steps}", flush=True)

    plot(stored_rows(TABLE))


def plot(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    series = {}
    for name, box in sorted({(r[0], r[2]) for r in rows}):
        sel = sorted((r for r in rows if r[0] == name and r[2] == box), key=lambda r: r[1])
        n = np.array([r[1] for r in sel])
        err = np.abs([r[7] for r in sel])
        order = observed_order(1/n[-3:], err[-3:]) if len(n) >= 3 else float("nan")
        print(f"{name} L={box:g}b: observed order (3 finest) {order:.2f}")
        label = f"{name}, L {box:g} b"
        ax1.loglog(n, 100*err, "o-", label=f"{label} (order {order:.2f})")
        series[label] = [(r[10], abs(r[7]), int(r[1])) for r in sel]
    ax1.axhline(2, color="k", ls="--", lw=0.8, label="target 2 % at N = 16")
    ax1.set_xlabel("cells per minor diameter")
    ax1.set_ylabel("|R/R_Oberbeck - 1| [%]")
    ax1.set_title("Fixed prolate spheroid, Stokes flow\n(aspect, x along / y across the axis)")
    ax1.legend(fontsize=7)
    plot_speed_error(ax2, series)
    ax2.set_title("Speed against error (labels: cells per minor diameter)")
    fig.tight_layout()
    fig.savefig(RESULTS / "oberbeck.png", dpi=120)


if __name__ == "__main__":
    main()
