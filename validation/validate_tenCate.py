#!/usr/bin/env python3
"""ten Cate et al. (2002) sphere settling in a box, cases E1-E4, at several
resolutions (cells per diameter), on 2 processes.

For each run: maximum settling velocity against the experiment's u_max, the
RMS deviation of the velocity from the digitised curve (up to the end of the
run), and the wall time. Writes results/tenCate.csv, results/tenCate_<E>.png
(velocity and gap against time) and results/tenCate_speed_error.png.

    validation/validate_tenCate.py [--cases E1,E2] [--np 2] [--step-factor F]
                                   [--end-time T] [--levels L] [--plot-only]
                                   [N ...]   (default all cases, N = 6 8 12)

--step-factor scales the tutorial's step limits (maxCo, maxDeltaT): 0.5 runs
at half the default step, to measure how far u_max depends on the step.
--end-time ends the runs earlier than the tutorial's end (after the landing):
E1 reaches u_max at about 2 s of its 4.1, so 2.3 halves its cost.
--levels refines the mesh at the sphere (the tutorial's Allrun, 5th
argument): N is then the base mesh's cells per diameter, the sphere's
surface has N 2^L, its wake N 2^(L-1); those runs go to
results/tenCate_refined.csv (with the last mesh's cell count) and appear
beside the uniform ones in the plots, their labels "N+L".
The plots show every run of the case (and step factor) found under
validation/runs, so that resolutions run one at a time end in one plot;
--plot-only redraws them without running.
"""

import argparse
import re

import numpy as np

from common import (Case, RESULTS, ROOT, RUNS, foam_environment, plot_speed_error,
                    timed_run, write_table)
import tenCate


def rms_velocity_deviation(case, history):
    """RMS deviation from the experiment's velocity until the gap falls to
    a tenth of a diameter: the landing itself takes a few hundredths of a
    second, where a small shift in time gives large deviations."""
    t_ref, u_ref = tenCate.reference_velocity(case)
    gap = (history[:, 3] - 0.0075)/0.015
    landing = np.nonzero(gap < 0.1)[0]
    end = history[landing[0], 0] if len(landing) else history[-1, 0]
    inside = t_ref <= end
    u = np.interp(t_ref[inside], history[:, 0], history[:, 6])
    return np.sqrt(np.mean((u - u_ref[inside])**2))/tenCate.CASES[case][2]


# The table of the coupling before its changes of 2026-12-04 (explicit
# projection, viscous number at most 1), kept for comparison
BEFORE = RESULTS / "tenCate_before_coupling_fixes.csv"


def scale_step(case, factor):
    """Scale maxCo and maxDeltaT in the copy's controlDict by factor."""
    control = case.path / "system" / "controlDict"
    text = control.read_text()
    for key in ("maxCo", "maxDeltaT"):
        text, found = re.subn(
            rf"^({key}\s+)([^;]+);",
            lambda m: f"{m.group(1)}{float(m.group(2))*factor:g};",
            text, flags=re.M)
        if found != 1:
            raise SystemExit(f"{control}: no single '{key}' entry to scale")
    control.write_text(text)


def stored_histories(case_name, tag, env):
    """Sphere histories of the runs of a case under RUNS at one step factor
    (tag), uniform and refined, by resolution: label -> history."""
    found = []
    for path in RUNS.glob(f"tenCate_{case_name}_*"):
        match = re.fullmatch(rf"tenCate_{case_name}_(\d+)(?:_ref(\d+))?{re.escape(tag)}",
                             path.name)
        data = path / "postProcessing" / "particles" / "0" / "particles.dat"
        if match and data.exists():
            n, levels = int(match.group(1)), int(match.group(2) or 0)
            found.append((n << levels, levels, Case(path, env).history()["sphere"]))
    label_tag = tag.replace("_", ", ")

    def label(finest, levels):
        if levels:
            return f"{finest >> levels}, refined to {finest} cells/d{label_tag}"
        return f"{finest} cells/d{label_tag}"
    return {label(n, levels): h for n, levels, h in sorted(found, key=lambda f: f[:2])}


def last_cell_count(case):
    """Cells of the last mesh of a refined run (its log's last change)."""
    changes = re.findall(r"^Mesh changed: (\d+) cells",
                         (case.path / "log.pimpleDLMFoam").read_text(), re.M)
    return int(changes[-1])


HEADER = ["case", "cellsPerDiameter", "stepFactor", "u_max", "u_max_exp",
          "relError", "rmsVelocityDeviation", "wallTime_s", "steps", "endTime_s"]
REFINED_HEADER = ["case", "baseCellsPerDiameter", "levels", "surfaceCellsPerDiameter",
                  "u_max", "u_max_exp", "relError", "rmsVelocityDeviation",
                  "wallTime_s", "steps", "endTime_s", "lastCells"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cases", default="E1,E2,E3,E4")
    parser.add_argument("--np", type=int, default=2)
    parser.add_argument("--step-factor", type=float, default=1.0)
    parser.add_argument("--end-time", type=float)
    parser.add_argument("--levels", type=int, default=0)
    parser.add_argument("--plot-only", action="store_true")
    parser.add_argument("resolutions", nargs="*", type=int, default=[6, 8, 12])
    args = parser.parse_args()

    env = foam_environment()
    RESULTS.mkdir(parents=True, exist_ok=True)
    table = RESULTS / "tenCate.csv"
    refined_table = RESULTS / "tenCate_refined.csv"

    def stored_rows(path=table, header=HEADER):
        """Rows of the table as written now: runs of other cases or
        resolutions (possibly by another instance of this script) stay."""
        if not path.exists():
            return []
        lines = path.read_text().splitlines()
        if lines[0].split(",") != header:
            raise SystemExit(f"{path}: header is not {','.join(header)}")
        return [line.split(",") for line in lines[1:]]

    rows = stored_rows()
    for case_name in args.cases.split(","):
        factor = args.step_factor
        tag = "" if factor == 1 else f"_step{factor:g}"
        refined = f"_ref{args.levels}" if args.levels else ""
        for n in [] if args.plot_only else args.resolutions:
            case = Case.copy(ROOT / "tutorials" / "tenCate",
                             RUNS / f"tenCate_{case_name}_{n}{refined}{tag}", env)
            if factor != 1:
                scale_step(case, factor)
            end = "" if args.end_time is None else args.end_time
            seconds = timed_run(case, "./Allrun", case_name, n, args.np, end, args.levels)
            h = case.history()["sphere"]
            u_max, error = tenCate.summary(case_name, h)
            rms = rms_velocity_deviation(case_name, h)
            if args.levels:
                refined_rows = [r for r in stored_rows(refined_table, REFINED_HEADER)
                                if not (r[0] == case_name and int(r[1]) == n
                                        and int(r[2]) == args.levels)]
                refined_rows.append([case_name, n, args.levels, n << args.levels, u_max,
                                     tenCate.CASES[case_name][2], error, rms, seconds,
                                     len(h), h[-1, 0], last_cell_count(case)])
                print(f"{case_name} N={n}+{args.levels} u_max={u_max:.5f} "
                      f"error={100*error:+.2f}% rms={100*rms:.2f}% wall={seconds:.0f}s "
                      f"steps={len(h)} cells={last_cell_count(case)}", flush=True)
                write_table(refined_table, REFINED_HEADER, refined_rows)
                continue
            rows = [r for r in stored_rows()
                    if not (r[0] == case_name and int(r[1]) == n
                            and float(r[2]) == factor)]
            rows.append([case_name, n, factor, u_max, tenCate.CASES[case_name][2],
                         error, rms, seconds, len(h), h[-1, 0]])
            print(f"{case_name} N={n:3d} step x{factor:g} u_max={u_max:.5f} "
                  f"error={100*error:+.2f}% "
                  f"rms={100*rms:.2f}% wall={seconds:.0f}s steps={len(h)} "
                  f"end={h[-1, 0]:.3f}s", flush=True)
            write_table(table, HEADER, rows)
        histories = stored_histories(case_name, tag, env)
        if histories:
            tenCate.plot(case_name, histories,
                         RESULTS / f"tenCate_{case_name}{tag}.png")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 5))
    colors = {c: f"C{i}" for i, c in enumerate(tenCate.CASES)}
    before = {}
    for r in (line.split(",") for line in BEFORE.read_text().splitlines()[1:]):
        before.setdefault(f"{r[0]} before", []).append(
            (float(r[6]), abs(float(r[4])), r[1]))
    plot_speed_error(ax, before, fmt="x:",
                     colors={f"{c} before": colors[c] for c in colors})
    series = {}
    for r in rows:
        if float(r[2]) == 1:
            series.setdefault(r[0], []).append((float(r[7]), abs(float(r[5])), r[1]))
    plot_speed_error(ax, series, target=2, colors=colors)
    refined_series = {}
    for r in stored_rows(refined_table, REFINED_HEADER):
        refined_series.setdefault(f"{r[0]} refined", []).append(
            (float(r[8]), abs(float(r[6])), f"{r[1]}+{r[2]}"))
    plot_speed_error(ax, refined_series, fmt="s--",
                     colors={f"{c} refined": colors[c] for c in colors})
    ax.set_ylabel("|u_max error| [%]")
    ax.set_title("ten Cate: speed against error (labels: cells/d, refined: base+levels;\n"
                 "dotted: the coupling before 2026-12-04; 2 ranks)", fontsize=9)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(RESULTS / "tenCate_speed_error.png", dpi=120)


if __name__ == "__main__":
    main()
