"""Shared helpers of the validation scripts: running cases, timing, tables."""

import fcntl
import os
import pathlib
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
REFERENCE = ROOT / "validation" / "reference"
RUNS = ROOT / "validation" / "runs"
RESULTS = ROOT / "validation" / "results"

sys.path.insert(0, str(ROOT / "tests"))
from foamcase import Case, foam_environment, packed_bed_rows  # noqa: E402,F401


def refinement_dict(targets):
    """constant/dynamicMeshDict refining at the particles (dlmRefineFvMesh),
    every third step, by the given entries of its targets dictionary."""
    return f"""\
FoamFile {{ version 2.0; format ascii; class dictionary; object dynamicMeshDict; }}
dynamicFvMesh   dlmRefineFvMesh;
dynamicRefineFvMeshCoeffs
{{
    refineInterval  3;
    nBufferLayers   1;
    maxCells        4000000;
    correctFluxes
    (
        (phi none) (phi_0 none) (phi_0_0 none) (ghf none) (UBlendingFactor none)
    );
    dumpLevel       true;
    targets
    {{
{targets}
    }}
}}
"""


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


def plot_speed_error(ax, series, target=None, fmt="o-", colors=None):
    """Error [%] against wall time [s] on log axes, one line per series.

    series: {label: [(wall_s, abs_rel_error, point_label), ...]}
    colors: {label: colour}, else matplotlib's cycle
    """
    for label, points in series.items():
        points = sorted(points)
        wall = [p[0] for p in points]
        err = [100*p[1] for p in points]
        color = colors.get(label) if colors else None
        ax.loglog(wall, err, fmt, label=label, color=color)
        for w, e, (_, _, name) in zip(wall, err, points):
            ax.annotate(str(name), (w, e), fontsize=7)
    if target is not None:
        ax.axhline(target, color="k", ls="--", lw=0.8, label=f"target {target:g} %")
    ax.set_xlabel("wall time [s]")
    ax.set_ylabel("|error| [%]")
    ax.legend()


def ergun_lambda(re_number):
    """Ergun's friction coefficient, Lambda = 150 + 1.75 Re."""
    return 150 + 1.75*re_number


def correlation_lambda(drag, porosity, re_number):
    """Lambda (the DLM paper's eq. 25, its Re = D u/(nu (1 - eps))) of a
    drag correlation F(phi, Re_s) for random arrays of spheres, in the
    normalisation of van der Hoef et al. (2005): the drag per sphere without
    the mean pressure gradient's share over the Stokes drag 3 pi mu D u at
    the superficial velocity u, Re_s = D u/nu. The pressure gradient is
    F 18 mu u phi/(D^2 eps), so Lambda = 18 F eps^2/phi; Carman-Kozeny's
    F = 10 phi/eps^2 gives 180, Ergun's (150 phi + 1.75 Re_s)/(18 eps^2)
    gives 150 + 1.75 Re."""
    solid = 1 - porosity
    return 18*drag(solid, solid*re_number)*porosity**2/solid


def beetstra_drag(phi, re_s):
    """Beetstra, van der Hoef and Kuipers (2007), AIChE J. 53: 489, fitted
    to lattice-Boltzmann simulations of random arrays, phi <= 0.6,
    Re_s <= 1000."""
    eps = 1 - phi
    return (10*phi/eps**2 + eps**2*(1 + 1.5*phi**0.5)
            + 0.413*re_s/(24*eps**2)
            * (1/eps + 3*phi*eps + 8.4*re_s**-0.343)
            / (1 + 10**(3*phi)*re_s**(-(1 + 4*phi)/2)))


def tang_drag(phi, re_s):
    """Tang, Peters, Kuipers, Kriebitzsch and van der Hoef (2015), AIChE J.
    61: 688, fitted to immersed-boundary simulations of random arrays,
    0.1 <= phi <= 0.6, 50 <= Re_s <= 1000."""
    eps = 1 - phi
    return (10*phi/eps**2 + eps**2*(1 + 1.5*phi**0.5)
            + re_s*(0.11*phi*(1 + phi) - 0.00456/eps**4
                    + (0.169*eps + 0.0644/eps**4)*re_s**-0.343))


def stored_rows(path):
    """Rows of a results CSV, numbers as floats and other values as text
    (none if it does not exist)."""
    def value(text):
        try:
            return float(text)
        except ValueError:
            return text

    if not path.exists():
        return []
    return [[value(v) for v in line.split(",")]
            for line in path.read_text().splitlines()[1:]]


def merge_row(path, header, row, key_columns=2, sort_key=None):
    """Put row into a results CSV, replacing the row with the same first
    key_columns values (the case and resolution; or the values of the
    columns a list of indices names), rows sorted; older rows
    without the header's last columns get nan there. A stored header that
    is not the start of this one (columns renamed or inserted, say by a
    newer version of the script) is an error: merging would shift the
    columns. The results folder is locked meanwhile, so that runs in
    parallel keep each other's rows."""
    folder = os.open(path.parent, os.O_RDONLY)
    try:
        fcntl.flock(folder, fcntl.LOCK_EX)
        if path.exists():
            stored = path.read_text().split("\n", 1)[0].split(",")
            if stored != list(header[:len(stored)]):
                raise SystemExit(
                    f"{path}: its columns ({','.join(stored)}) are not this script's"
                    f" ({','.join(header)}): the row is not written ({row}); update"
                    " the file's rows to the new columns, or run the script's"
                    " current version")
        if isinstance(key_columns, int):
            key_columns = range(key_columns)

        def key(r):
            return [r[i] for i in key_columns]

        rows = [r + [float("nan")]*(len(header) - len(r)) for r in stored_rows(path)]
        rows = [r for r in rows if key(r) != key(row)]
        rows.append(row)
        rows.sort(key=sort_key)
        write_table(path, header, rows)
    finally:
        os.close(folder)


def three_point_order(n, f):
    """Order p of f(h) = f0 + C h^p through three resolutions n (cells per
    diameter), by bisection on the ratio of the differences; nan if the
    differences change sign or no order in [0.05, 8] fits them."""
    import numpy as np
    h = 1/np.asarray(n, float)
    d1, d2 = f[1] - f[0], f[2] - f[1]
    if d1 == 0 or d2/d1 <= 0:
        return float("nan")
    target = d2/d1

    def ratio(p):
        return (h[2]**p - h[1]**p)/(h[1]**p - h[0]**p)

    lo, hi = 0.05, 8.0
    if (ratio(lo) - target)*(ratio(hi) - target) > 0:
        # The differences do not shrink as any order in the bracket would
        return float("nan")
    for _ in range(200):
        mid = 0.5*(lo + hi)
        if (ratio(mid) - target)*(ratio(lo) - target) > 0:
            lo = mid
        else:
            hi = mid
    return 0.5*(lo + hi)


def richardson(n, f):
    """Observed order and extrapolate of the three finest resolutions (nan,
    and the finest value, with fewer than three or no monotonic trend)."""
    if len(n) < 3:
        return float("nan"), f[-1]
    order = three_point_order(n[-3:], f[-3:])
    if order != order:
        return order, f[-1]
    return order, f[-1] + (f[-1] - f[-2])/((n[-1]/n[-2])**order - 1)
