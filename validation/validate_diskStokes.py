#!/usr/bin/env python3
"""Disk settling on the centreline between two walls in Stokes flow, against
the analytic terminal velocity (reference README section 2).

Disk d = 2 cm in a channel W = 10 cm (k = d/W = 0.2), 40 cm long with the
disk midway; rho_f = 2000, rho_s = 2500 kg/m3, mu = 30 Pa s (Re = 0.004).
U_t = (rho_s - rho_f) g a^2/(4 mu lambda), lambda(0.2) = 1.315610 (FEM).

For each mixed-cell treatment and resolution (cells per diameter): terminal
velocity, relative error, wall time; the observed order of convergence.
Writes results/diskStokes.csv and results/diskStokes.png.

    validation/validate_diskStokes.py [N ...]     (default 8 12 16)
"""

import sys

import numpy as np

from common import (Case, RESULTS, ROOT, RUNS, foam_environment,
                    observed_order, timed_run, write_table)

LAMBDA = 1.315610
RHO_F, RHO_S, MU, G, A, WIDTH, HEIGHT = 2000.0, 2500.0, 30.0, 9.81, 0.01, 0.1, 0.4
U_T = (RHO_S - RHO_F)*G*A**2/(4*MU*LAMBDA)
END_TIME = 0.6

# The explicit projection is stable for nu dt/h^2 up to about 10 and the
# terminal velocity depends on it: keep nu dt/h^2 = 2.4 at every resolution
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


def run(cells_per_diameter, mixed_cells, env):
    name = f"diskStokes_{mixed_cells}_{cells_per_diameter}"
    case = Case.copy(ROOT / "tutorials" / "fallingDisk", RUNS / name, env)
    nx = round(WIDTH/(2*A)*cells_per_diameter)
    (case.path / "system" / "blockMeshDict").write_text(
        BLOCKMESH.format(w=WIDTH, h=HEIGHT, nx=nx, ny=4*nx))
    case.set("constant/transportProperties", "nu", MU/RHO_F)
    case.set("constant/particleProperties", "particles/disk/position",
             f"({WIDTH/2} {HEIGHT/2} 0)")
    case.set("system/fvOptions", "rigidProjection/mixedCells", mixed_cells)
    h = 2*A/cells_per_diameter
    delta_t = VISCOUS_NUMBER*h**2/(MU/RHO_F)
    for entry, value in [("endTime", END_TIME), ("deltaT", delta_t),
                         ("adjustTimeStep", "no"), ("writeInterval", END_TIME)]:
        case.set("system/controlDict", entry, value)
    case.run("blockMesh")
    seconds = timed_run(case, "pimpleDLMFoam")
    history = case.history()["disk"]
    late = history[history[:, 0] > 0.8*END_TIME, 5]
    velocity = -late.mean()
    drift = np.ptp(late)/abs(velocity)
    return velocity, seconds, drift, len(history)


def main():
    resolutions = [int(n) for n in sys.argv[1:]] or [8, 12, 16]
    env = foam_environment()
    RESULTS.mkdir(parents=True, exist_ok=True)
    rows = []
    for mixed_cells in ["massWeighted", "volumeWeighted"]:
        for n in resolutions:
            velocity, seconds, drift, steps = run(n, mixed_cells, env)
            error = velocity/U_T - 1
            rows.append([mixed_cells, n, velocity, U_T, error, seconds, steps, drift])
            print(f"{mixed_cells:15s} N={n:3d} U={velocity:.6e} U_t={U_T:.6e} "
                  f"error={100*error:+.3f}% wall={seconds:.1f}s steps={steps} "
                  f"late drift={100*drift:.3f}%", flush=True)
    write_table(RESULTS / "diskStokes.csv",
                ["mixedCells", "cellsPerDiameter", "U", "U_t", "relError",
                 "wallTime_s", "steps", "lateDrift"], rows)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    for mixed_cells, marker in [("massWeighted", "o"), ("volumeWeighted", "s")]:
        sel = [r for r in rows if r[0] == mixed_cells]
        n = np.array([r[1] for r in sel], float)
        err = np.abs([r[4] for r in sel])
        wall = np.array([r[5] for r in sel])
        order = observed_order(1/n[-3:], err[-3:]) if len(n) >= 3 else float("nan")
        print(f"{mixed_cells}: observed order (3 finest) {order:.2f}")
        ax1.loglog(n, 100*err, marker + "-", label=f"{mixed_cells} (order {order:.2f})")
        ax2.loglog(wall, 100*err, marker + "-", label=mixed_cells)
        for ni, wi, ei in zip(n, wall, err):
            ax2.annotate(f"{int(ni)}", (wi, 100*ei), fontsize=7)
    ax1.set_xlabel("cells per diameter")
    ax1.set_ylabel("|U/U_t - 1| [%]")
    ax1.set_title("Disk between walls, Stokes flow (k = 0.2)")
    ax1.legend()
    ax2.set_xlabel("wall time [s]")
    ax2.set_ylabel("|U/U_t - 1| [%]")
    ax2.set_title("Speed against error (labels: cells per diameter)")
    ax2.legend()
    fig.tight_layout()
    fig.savefig(RESULTS / "diskStokes.png", dpi=120)


if __name__ == "__main__":
    main()
