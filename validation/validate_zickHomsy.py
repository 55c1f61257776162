#!/usr/bin/env python3
"""Stokes flow through a simple cubic array of fixed spheres against Zick &
Homsy (1982) (reference README section 4): tutorials/periodicArray at each
solid fraction and resolution; the drag coefficient K = F/(6 pi mu a U) with
F the driving force per sphere and U the superficial velocity (flux through
the periodic face over its area).

For each solid fraction and resolution (cells per diameter): K, its error,
wall time; the observed order of convergence. Rows are merged into
results/zickHomsy.csv; results/zickHomsy.png plots error against
resolution and against wall time.

    validation/validate_zickHomsy.py [--phi 0.027,0.125] [N ...]
        (default: phi 0.027 0.064 0.125 0.216 0.343, N = 8 12 16)
"""

import argparse
import re

import numpy as np

from common import (Case, RESULTS, ROOT, RUNS, foam_environment, merge_row,
                    observed_order, plot_speed_error, read_csv, stored_rows,
                    timed_run)

TABLE = RESULTS / "zickHomsy.csv"
HEADER = ["solidFraction", "cellsPerDiameter", "K", "K_ZickHomsy", "relError",
          "wallTime_s", "steps"]


def run(phi, n, env):
    case = Case.copy(ROOT / "tutorials" / "periodicArray",
                     RUNS / f"zickHomsy_{phi}_{n}", env)
    seconds = timed_run(case, "./Allrun", phi, n)
    log = (case.path / "log.pimpleDLMFoam").read_text()
    steps = len(re.findall(r"^Time = ", log, re.M))
    K = float(re.search(r"K = F/\(6 pi mu a U\) = ([0-9.eE+-]+)",
                        (case.path / "log.Allrun").read_text()).group(1))
    return K, seconds, steps


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--phi", default="0.027,0.064,0.125,0.216,0.343")
    parser.add_argument("resolutions", nargs="*", type=int, default=[8, 12, 16])
    args = parser.parse_args()
    _, reference = read_csv("ZickHomsy1982_SC_drag.csv")
    exact = {round(r[0], 4): r[1] for r in reference}

    env = foam_environment()
    RESULTS.mkdir(parents=True, exist_ok=True)
    for phi in [float(p) for p in args.phi.split(",")]:
        for n in args.resolutions:
            K, seconds, steps = run(phi, n, env)
            error = K/exact[round(phi, 4)] - 1
            merge_row(TABLE, HEADER,
                      [phi, n, K, exact[round(phi, 4)], error, seconds, steps])
            print(f"phi={phi:.3f} N={n:3d} K={K:.4f} Z&H={exact[round(phi, 4)]:.3f} "
                  f"error={100*error:+.2f}% wall={seconds:.0f}s steps={steps}",
                  flush=True)

    rows = stored_rows(TABLE)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    series = {}
    for phi in sorted({r[0] for r in rows}):
        sel = sorted((r for r in rows if r[0] == phi), key=lambda r: r[1])
        n = np.array([r[1] for r in sel])
        err = np.abs([r[4] for r in sel])
        order = observed_order(1/n[-3:], err[-3:]) if len(n) >= 3 else float("nan")
        print(f"phi={phi:.3f}: observed order (3 finest) {order:.2f}")
        ax1.loglog(n, 100*err, "o-", label=f"phi {phi:g} (order {order:.2f})")
        series[f"phi {phi:g}"] = [(r[5], abs(r[4]), int(r[1])) for r in sel]
    ax1.axhline(2, color="k", ls="--", lw=0.8, label="target 2 % at N = 16")
    ax1.set_xlabel("cells per diameter")
    ax1.set_ylabel("|K/K_ZH - 1| [%]")
    ax1.set_title("Simple cubic array, Stokes flow")
    ax1.legend(fontsize=7)
    plot_speed_error(ax2, series)
    ax2.set_title("Speed against error (labels: cells per diameter)")
    fig.tight_layout()
    fig.savefig(RESULTS / "zickHomsy.png", dpi=120)


if __name__ == "__main__":
    main()
