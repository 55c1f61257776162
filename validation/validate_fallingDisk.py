#!/usr/bin/env python3
"""The paper's falling disk (Kanarska et al. section 3.3, tutorials/
fallingDisk) on a uniform mesh and on a coarser one refined in the plane at
the disk, both with the same finest cells: what the refinement
costs in accuracy and saves in time.

For each fluid (mu = 3, 0.1, 0.002 Pa s: Re about 0.2, 100 and 2000) the
tutorial runs on a uniform mesh of N cells per diameter and on a base mesh
of N/2^L refined L levels at the disk's surface (one level less in its
wake, tutorials/fallingDisk/constant/dynamicMeshDict.refine). Reported: the
settling velocity at the end (the mean over the last tenth of the run; at
Re 0.2 and 100 the disk is at or near its terminal velocity), the refined
run's difference from the uniform one in it, the largest difference of
the two runs' heights over the run (in % of the uniform run's fall) and
of their lateral positions (in diameters: at Re 2000 the disk, released on
the channel's axis, leaves it when round-off has grown into its wake's
instability, at a time no two runs share); the solver's wall time (its
log's ClockTime, rendering apart) and the speed-up. Rows go to
results/fallingDisk.csv (a rerun replaces its row); results/fallingDisk_N<N>.png
shows the settling velocity and the lateral position against time, uniform
and refined. --report-only measures the runs found under validation/runs.

    validation/validate_fallingDisk.py [--mu 3,0.1,0.002] [--levels 2]
                                        [--end-time 1] [--report-only] [N]
                                        (default N = 16)
"""

import argparse
import re

import numpy as np

from common import RESULTS, ROOT, RUNS, Case, foam_environment, merge_row, stored_rows

D = 0.02
TABLE = RESULTS / "fallingDisk.csv"
HEADER = ["mu", "mesh", "finestCellsPerDiameter", "levels", "baseCellsPerDiameter",
          "settlingVelocity", "relDifference", "maxHeightDifference_relFall",
          "maxLateralDifference_D", "wallTime_s", "steps", "lastCells"]


def case_path(mu, n, levels):
    return RUNS / (f"fallingDisk_mu{mu:g}_N{n}" + (f"_ref{levels}" if levels else ""))


def run(mu, n, levels, end_time, env):
    """Run the tutorial on the finest cells n, refined by levels."""
    case = Case.copy(ROOT / "tutorials" / "fallingDisk", case_path(mu, n, levels), env)
    case.set("system/controlDict", "endTime", end_time)
    case.run("./Allrun", f"{mu:g}", n >> levels, 1, levels)


def measured(mu, n, levels, env):
    """A run's history, wall time and last cell count."""
    case = Case(case_path(mu, n, levels), env)
    base = n >> levels
    log = (case.path / "log.pimpleDLMFoam").read_text()
    wall = float(re.findall(r"ClockTime = ([\d.e+-]+) s", log)[-1])
    changes = re.findall(r"^Mesh changed: (\d+) cells", log, re.M)
    cells = int(changes[-1]) if changes else 10*base*20*base
    return case.history()["disk"], wall, cells


def settling_velocity(h):
    window = h[:, 0] >= 0.9*h[-1, 0]
    return -h[window, 5].mean()


def trajectory_differences(reference, h):
    """Largest differences from the reference's trajectory at its times: of
    the height, relative to its fall, and of the lateral position, in
    diameters."""
    x = np.interp(reference[:, 0], h[:, 0], h[:, 1])
    y = np.interp(reference[:, 0], h[:, 0], h[:, 2])
    fall = reference[0, 2] - reference[:, 2].min()
    return (np.abs(y - reference[:, 2]).max()/fall,
            np.abs(x - reference[:, 1]).max()/D)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--mu", default="3,0.1,0.002")
    parser.add_argument("--levels", type=int, default=2)
    parser.add_argument("--end-time", type=float, default=1.0)
    parser.add_argument("--report-only", action="store_true")
    parser.add_argument("resolution", nargs="?", type=int, default=16)
    args = parser.parse_args()
    n, levels = args.resolution, args.levels
    if n % (1 << levels) or (n >> levels) < 3:
        raise SystemExit(f"{n} cells per diameter: the base mesh of {levels} levels"
                         " needs a whole number of cells per diameter, 3 or more")

    env = foam_environment()
    RESULTS.mkdir(parents=True, exist_ok=True)
    histories = {}
    for mu in (float(v) for v in args.mu.split(",")):
        if not args.report_only:
            run(mu, n, 0, args.end_time, env)
            run(mu, n, levels, args.end_time, env)
        uniform, uniform_wall, uniform_cells = measured(mu, n, 0, env)
        refined, refined_wall, refined_cells = measured(mu, n, levels, env)
        histories[mu] = (uniform, refined)
        v_uniform, v_refined = settling_velocity(uniform), settling_velocity(refined)
        difference = v_refined/v_uniform - 1
        height, lateral = trajectory_differences(uniform, refined)
        merge_row(TABLE, HEADER, [mu, "uniform", n, 0, n, v_uniform, 0.0, 0.0, 0.0,
                                  uniform_wall, len(uniform), uniform_cells], key_columns=4)
        merge_row(TABLE, HEADER, [mu, "refined", n, levels, n >> levels, v_refined,
                                  difference, height, lateral, refined_wall, len(refined),
                                  refined_cells], key_columns=4)
        print(f"mu={mu:g} N={n}: uniform v={v_uniform:.5f} m/s wall={uniform_wall:.0f}s"
              f" cells={uniform_cells}; refined {n >> levels}+{levels}: v={v_refined:.5f}"
              f" ({100*difference:+.2f}%) height within {100*height:.2f}% of the fall,"
              f" lateral within {lateral:.3f} d, wall={refined_wall:.0f}s"
              f" cells={refined_cells}, speed-up {uniform_wall/refined_wall:.1f}x",
              flush=True)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.5))
    for k, (mu, (uniform, refined)) in enumerate(histories.items()):
        for h, style, label in [(uniform, "-", f"uniform {n}"),
                                (refined, "--", f"refined {n >> levels}+{levels}")]:
            axes[0].plot(h[:, 0], -h[:, 5], style, color=f"C{k}",
                         label=f"mu {mu:g}: {label}")
            axes[1].plot(h[:, 0], (h[:, 1] - h[0, 1])/D, style, color=f"C{k}")
    axes[0].set_xlabel("t [s]")
    axes[0].set_ylabel("settling velocity [m/s]")
    axes[0].legend(fontsize=7)
    axes[1].set_xlabel("t [s]")
    axes[1].set_ylabel("lateral displacement [d]")
    fig.suptitle(f"Falling disk: uniform {n} cells per diameter against a base of"
                 f" {n >> levels} refined {levels} levels at the disk", fontsize=9)
    fig.tight_layout()
    fig.savefig(RESULTS / f"fallingDisk_N{n}.png", dpi=120)
    print(f"{len(stored_rows(TABLE))} rows in {TABLE}")


if __name__ == "__main__":
    main()
