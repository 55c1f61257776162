"""Shared helpers of the validation scripts: running cases, timing, tables."""

import pathlib
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
REFERENCE = ROOT.parent / "shared" / "reference"
RUNS = ROOT / "validation" / "runs"
RESULTS = ROOT / "validation" / "results"

sys.path.insert(0, str(ROOT / "tests"))
from foamcase import Case, foam_environment  # noqa: E402,F401


def read_csv(name):
    """Numeric columns of a reference CSV (lines with # skipped, header row)."""
    import numpy as np
    rows = []
    header = None
    for line in (REFERENCE / name).read_text().splitlines():
        if not line.strip() or line.startswith("#"):
            continue
        if header is None:
            header = [h.strip() for h in line.split(",")]
            continue
        rows.append([float(v) for v in line.split(",")])
    return header, np.array(rows)


def timed_run(case, *cmd, np=1):
    """Run and return the wall time in seconds."""
    start = time.perf_counter()
    case.run(*cmd, np=np)
    return time.perf_counter() - start


def observed_order(h, error):
    """Least-squares slope of log|error| against log h."""
    import numpy as np
    return np.polyfit(np.log(h), np.log(np.abs(error)), 1)[0]


def write_table(path, header, rows):
    with open(path, "w") as out:
        out.write(",".join(header) + "\n")
        for row in rows:
            out.write(",".join(str(v) for v in row) + "\n")


def plot_speed_error(ax, series, target=None):
    """Error [%] against wall time [s] on log axes, one line per series.

    series: {label: [(wall_s, abs_rel_error, point_label), ...]}
    """
    for label, points in series.items():
        points = sorted(points)
        wall = [p[0] for p in points]
        err = [100*p[1] for p in points]
        ax.loglog(wall, err, "o-", label=label)
        for w, e, (_, _, name) in zip(wall, err, points):
            ax.annotate(str(name), (w, e), fontsize=7)
    if target is not None:
        ax.axhline(target, color="k", ls="--", lw=0.8, label=f"target {target:g} %")
    ax.set_xlabel("wall time [s]")
    ax.set_ylabel("|error| [%]")
    ax.legend()
