#!/usr/bin/env python3
"""Simple cubic packing of touching spheres (D = 4 mm, porosity 1 - pi/6 =
47.64 %, superficial velocity 0.5 m/s), the DLM paper's section 3.1: the
friction coefficient Lambda = G eps^3 D^2/((1 - eps)^2 mu u) (its eq. 25)
against Ergun (reference README section 5) at each Reynolds number
Re = D u/(nu (1 - eps)) and resolution.

The fully developed bed: one sphere in a periodic cube of side D
(tutorials/periodicArray at solid fraction pi/6, resized to the paper's
sphere), driven to the superficial velocity by OpenFOAM's meanVelocityForce;
G is the drag per unit volume (packedBed function object), averaged over the
last fifth of the run. Re = 0.1 is the Stokes limit, where Zick & Homsy's
K = 42.1 for touching spheres gives the exact Lambda = 3 pi K eps^3/(1 -
eps)^2 = 156.6. The seed paper compares cubic packings with Franzen's
constants (A = 164.97, B = 1.976, C = 0.9: Lambda = A + B Re^C), which
could not be confirmed from a primary source: reported beside Ergun as the
paper's statement only.

At high Re (>= 100) the flow does not settle: the run lasts --flow-times
convective times D/u (default 60) and Lambda is averaged from 20 D/u on;
the relative difference between the means of the window's two halves
(halvesDiff) says how well that mean is converged in time.

For each run: Lambda, its difference from Ergun (and Franzen, and Zick &
Homsy at Re 0.1), the drift of Lambda over the averaging window (its range
over its mean), halvesDiff, wall time and steps; per Re the observed order
of convergence and the Richardson extrapolate of the three finest
resolutions. Rows are merged into
results/ergun.csv; results/ergun.png plots Lambda against resolution and
the discretisation error (against the extrapolate) against wall time.

    validation/validate_ergun.py [--re 0.1,18,900] [--flow-times 60] [N ...]
        (default Re 0.1 18 900, N = 16 24 32)
"""

import argparse
import math
import re

import numpy as np

from common import (Case, RESULTS, ROOT, RUNS, ergun_lambda, foam_environment,
                    merge_row, packed_bed_rows, plot_speed_error, richardson,
                    stored_rows, timed_run)

TABLE = RESULTS / "ergun.csv"
HEADER = ["Re", "cellsPerDiameter", "Lambda", "Lambda_Ergun", "relErrorErgun",
          "Lambda_Franzen", "relErrorFranzen", "drift", "wallTime_s", "steps",
          "halvesDiff"]

D, U = 0.004, 0.5
EPS = 1 - math.pi/6
K_ZICK_HOMSY = 42.1
LAMBDA_STOKES = 3*math.pi*K_ZICK_HOMSY*EPS**3/(1 - EPS)**2


def franzen(re_number):
    return 164.97 + 1.976*re_number**0.9


def end_time(re_number, nu, flow_times):
    """Steady at low Re after a few viscous times D^2/nu (the carried
    constraint force converges with them); at high Re, unsteady, averaged
    over flow_times convective times D/u."""
    return 3*D**2/nu if re_number < 100 else flow_times*D/U


def averaging_start(re_number, end):
    """The last fifth of a steady run; an unsteady one after its start-up of
    20 D/u."""
    return 0.8*end if re_number < 100 else 20*D/U


def make_case(re_number, n, flow_times, env):
    case = Case.copy(ROOT / "tutorials" / "periodicArray",
                     RUNS / f"ergun_{re_number:g}_{n}", env)
    nu = D*U/(re_number*(1 - EPS))
    path = case.path

    def edit(relative, old, new):
        f = path / relative
        text = f.read_text()
        assert old in text, (relative, old)
        f.write_text(text.replace(old, new))

    # The paper's sphere: the periodic cube of side D
    edit("Allrun", "L = 0.01", f"L = {D}")
    edit("system/blockMeshDict", "L   0.01;", f"L   {D};")
    edit("constant/particleProperties", "position    (0.005 0.005 0.005);",
         f"position    ({D/2} {D/2} {D/2});")
    edit("constant/transportProperties", "nu              1e-3;",
         f"nu              {nu:.8g};")
    controls = (path / "system" / "controlDict").read_text()
    controls = re.sub(r"^endTime .*$", f"endTime         {end_time(re_number, nu, flow_times):.6g};",
                      controls, flags=re.M)
    controls = re.sub(r"^writeInterval .*$", "writeInterval   1e6;", controls,
                      flags=re.M)
    (path / "system" / "controlDict").write_text(controls)
    (path / "system" / "fvOptions").write_text(f"""FoamFile
{{
    version 2.0; format ascii; class dictionary; object fvOptions;
}}
superficialVelocity
{{
    type            meanVelocityForce;
    selectionMode   all;
    fields          (U);
    Ubar            ({U} 0 0);
}}
rigidProjection
{{
    type            rigidProjection;
}}
""")
    edit("0/U", "internalField   uniform (0 0 0);",
         f"internalField   uniform ({U} 0 0);")
    return case


def run(re_number, n, flow_times, env):
    case = make_case(re_number, n, flow_times, env)
    seconds = timed_run(case, "./Allrun", math.pi/6, n)
    log = (case.path / "log.pimpleDLMFoam").read_text()
    steps = len(re.findall(r"^Time = ", log, re.M))
    rows = packed_bed_rows(case.path)
    window = rows[rows[:, 0] >= averaging_start(re_number, rows[-1, 0])]
    lam = window[:, 6]
    # Samples come at every (adjustable) step: weight them by time
    t = window[:, 0]
    weights = np.gradient(t)
    mean = np.average(lam, weights=weights)
    middle = 0.5*(t[0] + t[-1])
    halves = [np.average(lam[side], weights=weights[side])
              for side in (t < middle, t >= middle)]
    return mean, (lam.max() - lam.min())/mean, seconds, steps, \
        abs(halves[1] - halves[0])/mean


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--re", default="0.1,18,900")
    parser.add_argument("--flow-times", type=float, default=60,
                        help="run length at Re >= 100 in convective times D/u")
    parser.add_argument("resolutions", nargs="*", type=int, default=[16, 24, 32])
    args = parser.parse_args()

    env = foam_environment()
    RESULTS.mkdir(parents=True, exist_ok=True)
    for re_number in [float(r) for r in args.re.split(",")]:
        for n in args.resolutions:
            lam, drift, seconds, steps, halves = run(re_number, n, args.flow_times, env)
            merge_row(TABLE, HEADER,
                      [re_number, n, lam, ergun_lambda(re_number),
                       lam/ergun_lambda(re_number) - 1, franzen(re_number),
                       lam/franzen(re_number) - 1, drift, seconds, steps, halves])
            extra = (f" Zick&Homsy {LAMBDA_STOKES:.1f} ({100*(lam/LAMBDA_STOKES - 1):+.2f}%)"
                     if re_number < 1 else "")
            print(f"Re={re_number:g} N={n:3d} Lambda={lam:.2f} Ergun={ergun_lambda(re_number):.1f} "
                  f"({100*(lam/ergun_lambda(re_number) - 1):+.1f}%) Franzen={franzen(re_number):.1f} "
                  f"({100*(lam/franzen(re_number) - 1):+.1f}%){extra} drift={100*drift:.2f}% "
                  f"halves={100*halves:.2f}% "
                  f"wall={seconds:.0f}s steps={steps}", flush=True)
    summarise()


def summarise():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = stored_rows(TABLE)
    fig, axes = plt.subplots(1, 3, figsize=(15, 4))
    series = {}
    for re_number in sorted({r[0] for r in rows}):
        sel = sorted((r for r in rows if r[0] == re_number), key=lambda r: r[1])
        n = np.array([r[1] for r in sel])
        lam = np.array([r[2] for r in sel])
        reference = LAMBDA_STOKES if re_number < 1 else None
        order, extrapolate = richardson(n, lam)
        target = reference if reference is not None else extrapolate
        print(f"Re={re_number:g}: Lambda {', '.join(f'{v:.1f}' for v in lam)} at N = "
              f"{', '.join(str(int(v)) for v in n)}; observed order {order:.2f}, "
              f"extrapolate {extrapolate:.1f} (Ergun {ergun_lambda(re_number):.1f}, "
              f"{100*(extrapolate/ergun_lambda(re_number) - 1):+.1f}%)")
        ax = axes[0] if re_number < 100 else axes[1]
        ax.plot(n, lam, "o-", label=f"Re {re_number:g} (order {order:.2f})")
        ax.axhline(ergun_lambda(re_number), ls="--", lw=0.8, color=ax.lines[-1].get_color(),
                   label=f"Ergun, Re {re_number:g}")
        if reference is not None:
            ax.axhline(reference, ls=":", lw=0.8, color="k", label="Zick & Homsy (Stokes)")
        series[f"Re {re_number:g}"] = [(r[8], abs(r[2]/target - 1), int(r[1])) for r in sel]
    for ax in axes[:2]:
        ax.set_xlabel("cells per diameter")
        ax.set_ylabel("Lambda")
        if ax.lines:
            ax.legend(fontsize=7)
    axes[0].set_title("Cubic packing, low Re")
    axes[1].set_title("Cubic packing, high Re")
    plot_speed_error(axes[2], series)
    axes[2].set_title("Error against the exact (Re 0.1) or extrapolated value")
    fig.tight_layout()
    fig.savefig(RESULTS / "ergun.png", dpi=120)


if __name__ == "__main__":
    main()
