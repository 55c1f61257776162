#!/usr/bin/env python3
"""Disk settling on the centreline between two walls in Stokes flow, against
the analytic terminal velocity (reference README section 2).

Disk d = 2 cm in a channel W = 10 cm (k = d/W = 0.2), 40 cm long with the
disk midway; rho_f = 2000, rho_s = 2500 kg/m3, mu = 30 Pa s (Re = 0.004).
U_t = (rho_s - rho_f) g a^2/(4 mu lambda), lambda(0.2) = 1.315610 (FEM).

For each mixed-cell treatment and resolution (cells per diameter): terminal
velocity, relative error, wall time; the observed order of convergence.
The velocity of a disk crossing the grid oscillates slightly with the period
h/U (its cut cells change): it is averaged over one such period after the
start-up. Writes results/diskStokes.csv and results/diskStokes.png.

    validation/validate_diskStokes.py [--mixed-cells a,b]
        [--viscous-number V] [--correctors C] [N ...]
        (default: all three treatments, V = 2.4, the tutorial's correctors,
        N = 8 12 16)
"""

import argparse

import numpy as np

from common import (Case, RESULTS, ROOT, RUNS, foam_environment,
                    observed_order, plot_speed_error, timed_run, write_table)

LAMBDA = 1.315610
RHO_F, RHO_S, MU, G, A, WIDTH, HEIGHT = 2000.0, 2500.0, 30.0, 9.81, 0.01, 0.1, 0.4
U_T = (RHO_S - RHO_F)*G*A**2/(4*MU*LAMBDA)
START_UP = 0.15
MIXED_CELLS = ["interpolated", "massWeighted", "volumeWeighted"]

# Same viscous number nu dt/h^2 at every resolution: the blended treatments
# depend on it
VISCOUS_NUMBER = 2.4

BLOCKMESH = """FoamFile {{ version 2.0; format ascii; class dictionary; object blockMeshDict; }}
vertices
(
    (0 0 0) ({w} 0 0) ({w} {h} 0) (0 {h} 0)
    (0 0 0.01) ({w} 0 0.01) ({w} {h} 0.01) (0 {h} 0.01)
);
blocks ( hex (0 1 2 3 4 5 6 7) ({nx} {ny} 1) simpleGrading (1 1 1) );
boundary
(
    walls {{ type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)); }}
    frontAndBack {{ type empty; faces ((0 3 2 1) (4 5 6 7)); }}
);
"""


def run(cells_per_diameter, mixed_cells, viscous_number, correctors, env):
    name = f"diskStokes_{mixed_cells}_{cells_per_diameter}_vn{viscous_number:g}"
    case = Case.copy(ROOT / "tutorials" / "fallingDisk", RUNS / name, env)
    nx = round(WIDTH/(2*A)*cells_per_diameter)
    (case.path / "system" / "blockMeshDict").write_text(
        BLOCKMESH.format(w=WIDTH, h=HEIGHT, nx=nx, ny=4*nx))
    case.set("constant/transportProperties", "nu", MU/RHO_F)
    case.set("constant/particleProperties", "particles/disk/position",
             f"({WIDTH/2} {HEIGHT/2} 0)")
    case.set("system/fvOptions", "rigidProjection/mixedCells", mixed_cells)
    h = 2*A/cells_per_diameter
    delta_t = viscous_number*h**2/(MU/RHO_F)
    end_time = START_UP + h/U_T
    for entry, value in [("endTime", end_time), ("deltaT", delta_t),
                         ("adjustTimeStep", "no"), ("writeInterval", end_time),
                         ("maxViscousNumber", 2*viscous_number)]:
        case.set("system/controlDict", entry, value)
    if correctors:
        case.set("system/fvSolution", "PIMPLE/nCorrectors", correctors)
    case.run("blockMesh")
    seconds = timed_run(case, "pimpleDLMFoam")
    history = case.history()["disk"]
    late = history[history[:, 0] > START_UP, 5]
    velocity = -late.mean()
    oscillation = np.ptp(late)/abs(velocity)
    return velocity, seconds, oscillation, len(history)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--mixed-cells", default=",".join(MIXED_CELLS))
    parser.add_argument("--viscous-number", type=float, default=VISCOUS_NUMBER)
    parser.add_argument("--correctors", type=int, default=0,
                        help="PIMPLE nCorrectors (default: the tutorial's)")
    parser.add_argument("resolutions", nargs="*", type=int, default=[8, 12, 16])
    args = parser.parse_args()
    env = foam_environment()
    RESULTS.mkdir(parents=True, exist_ok=True)
    # Runs of other treatments and resolutions stay in the table
    table = RESULTS / "diskStokes.csv"
    rows = []
    if table.exists():
        for line in table.read_text().splitlines()[1:]:
            v = line.split(",")
            rows.append([v[0], int(v[1])] + [float(x) for x in v[2:]])
    vn = args.viscous_number
    for mixed_cells in args.mixed_cells.split(","):
        for n in args.resolutions:
            rows = [r for r in rows if (r[0], r[1], r[8]) != (mixed_cells, n, vn)]
            velocity, seconds, oscillation, steps = run(
                n, mixed_cells, vn, args.correctors, env)
            error = velocity/U_T - 1
            rows.append([mixed_cells, n, velocity, U_T, error, seconds, steps,
                         oscillation, vn])
            print(f"{mixed_cells:15s} N={n:3d} nu dt/h^2={vn:g} U={velocity:.6e} "
                  f"U_t={U_T:.6e} error={100*error:+.3f}% wall={seconds:.1f}s "
                  f"steps={steps} oscillation={100*oscillation:.3f}%", flush=True)
            rows.sort(key=lambda r: (MIXED_CELLS.index(r[0]), r[8], r[1]))
            write_table(table,
                        ["mixedCells", "cellsPerDiameter", "U", "U_t", "relError",
                         "wallTime_s", "steps", "oscillation", "viscousNumber"],
                        rows)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    series = {}
    for mixed_cells, vn in dict.fromkeys((r[0], r[8]) for r in rows):
        sel = [r for r in rows if (r[0], r[8]) == (mixed_cells, vn)]
        label = f"{mixed_cells}, nu dt/h^2 {vn:g}"
        n = np.array([r[1] for r in sel], float)
        err = np.abs([r[4] for r in sel])
        order = observed_order(1/n[-3:], err[-3:]) if len(n) >= 3 else float("nan")
        print(f"{label}: observed order (3 finest) {order:.2f}")
        ax1.loglog(n, 100*err, "o-", label=f"{label} (order {order:.2f})")
        series[label] = [(r[5], abs(r[4]), r[1]) for r in sel]
    ax1.axhline(1, color="k", ls="--", lw=0.8, label="target 1 % at N = 16")
    ax1.set_xlabel("cells per diameter")
    ax1.set_ylabel("|U/U_t - 1| [%]")
    ax1.set_title("Disk between walls, Stokes flow (k = 0.2)")
    ax1.legend()
    plot_speed_error(ax2, series)
    ax2.set_title("Speed against error (labels: cells per diameter)")
    fig.tight_layout()
    fig.savefig(RESULTS / "diskStokes.png", dpi=120)


if __name__ == "__main__":
    main()
