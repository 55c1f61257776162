#!/usr/bin/env python3
"""Random bed against Ergun, the DLM paper's section 3.1: 100 fixed spheres
of radius 0.11283 m at porosity 40 % (dlmPackSpheres, seed 1) in a periodic
cube of side 1 m, driven to the superficial velocity 0.008 m/s
(tutorials/randomBed) at Re = D u/(nu (1 - eps)) = 900. The paper reports 7 %
from Ergun's Lambda = 150 + 1.75 Re for its converged solution; the target
here is 5 %.

For each resolution (cells per diameter): Lambda = G eps^3 D^2/((1 - eps)^2
mu u) (its eq. 25), G the particles' drag per unit volume (packedBed)
averaged over the last quarter of the run (from its start, which a
mapped run takes from the coarser run), its difference from Ergun, the
drift over that window, wall time and steps; then the observed order and
the Richardson extrapolate of the three finest resolutions, against Ergun
and the fits to fully resolved simulations of Beetstra et al. (2007) and
Tang et al. (2015). Rows are merged into results/randomBed.csv;
results/randomBed.png plots Lambda against resolution for each Re and the
error (against the extrapolate, and against Ergun, or in Stokes flow
Beetstra et al.) against wall time.

    validation/validate_randomBed.py [--re 900] [--end-time 80] [--np 1] [--box 1]
                                     [--direction x] [--write-interval T]
                                     [--max-co 0.5] [--continue] [--map-from M]
                                     [N ...]
        (default N = 8 12 16 20; --np: ranks, decomposePar and mpirun;
        --continue: run the existing runs on from their latest written time,
        as after a stop, to the end time; --map-from M: start from the run
        at M cells per diameter, its latest written fields mapped onto the
        finer mesh, and run from that time to the end time; --box 0.6: the
        tests' 22-sphere bed, results/randomBed_box0.6.csv; --direction y
        or z: the flow along that axis, results/randomBed_y.csv and so on;
        --max-co 1: the time step at Courant number 1 instead of the
        tutorial's 0.5, results/randomBed_co1.csv)
"""

import argparse
import pathlib
import re
import shutil
import typing

import numpy as np

from common import (Case, RESULTS, ROOT, RUNS, beetstra_drag, correlation_lambda,
                    ergun_lambda, foam_environment, merge_row, packed_bed_rows,
                    plot_speed_error, richardson, stored_rows, tang_drag, timed_run)

HEADER = ["Re", "cellsPerDiameter", "porosity", "Lambda", "Lambda_Ergun",
          "relErrorErgun", "drift", "wallTime_s", "steps"]


def set_controls(case, end_time, write_interval, start=0, max_co=None):
    """End time, write interval and, if given, the Courant number; by
    default the run writes at its end only (OpenFOAM counts write intervals
    from the start time)."""
    controls = case.path / "system" / "controlDict"
    text = re.sub(r"^endTime .*$", f"endTime         {end_time:g};",
                  controls.read_text(), flags=re.M)
    if max_co is not None:
        text = re.sub(r"^maxCo .*$", f"maxCo           {max_co:g};", text, flags=re.M)
    controls.write_text(re.sub(r"^writeInterval .*$",
                               f"writeInterval   {write_interval or end_time - start:g};",
                               text, flags=re.M))


class Bed(typing.NamedTuple):
    """The side of the periodic cube [m], the direction of the flow and the
    Courant number that sets the time step."""
    box: float = 1
    direction: str = "x"
    max_co: float = 0.5

    @property
    def name(self):
        """Runs and results of the paper's 1 m box along x at the tutorial's
        Courant number as randomBed, others with _box<side>, _<direction>
        and _co<Courant number> appended."""
        return ("randomBed" + ("" if self.box == 1 else f"_box{self.box:g}")
                + ("" if self.direction == "x" else f"_{self.direction}")
                + ("" if self.max_co == 0.5 else f"_co{self.max_co:g}"))


def turn_flow(case, direction):
    """Drive the flow along y or z instead of the tutorial's x: its driving
    velocity (Ubar), initial velocity and packedBed's direction turned."""
    axis = "xyz".index(direction)

    def turned(match):
        components = ["0", "0", "0"]
        components[axis] = match.group(2)
        return f"{match.group(1)}({' '.join(components)});"

    for file, key in (("system/fvOptions", "Ubar"), ("0/U", "internalField"),
                      ("system/controlDict", "direction")):
        path = case.path / file
        text, count = re.subn(rf"^(\s*{key}\s+(?:uniform\s+)?)\((\S+) 0 0\);", turned,
                              path.read_text(), flags=re.M)
        if count != 1:
            raise SystemExit(f"{path}: no {key} along x to turn")
        path.write_text(text)


def new_case(re_number, n, end_time, write_interval, bed, env, start=0):
    case = Case.copy(ROOT / "tutorials" / "randomBed",
                     RUNS / f"{bed.name}_{re_number:g}_{n}", env)
    set_controls(case, end_time, write_interval, start, bed.max_co)
    if bed.box != 1:
        mesh = case.path / "system" / "blockMeshDict"
        mesh.write_text(re.sub(r"^L .*$", f"L   {bed.box:g};", mesh.read_text(), flags=re.M))
    if bed.direction != "x":
        turn_flow(case, bed.direction)
    return case


def run(re_number, n, end_time, ranks, write_interval, bed, env):
    case = new_case(re_number, n, end_time, write_interval, bed, env)
    seconds = timed_run(case, "./Allrun", re_number, n, ranks)
    return reduce(case.path) + (seconds,)


def mapped_run(re_number, n, coarse, end_time, ranks, write_interval, bed, env):
    """Start at N = n from the latest written time of the run at N = coarse:
    its velocity, pressure and carried force mapped onto the finer mesh
    (mapFields -consistent) and its driving pressure gradient, then run to
    end_time. At fine N this settles in less than half the flow time of a
    start from rest (validation/cases/randomBed.md, N = 40). Lambda is
    averaged over the last quarter of this run; the wall time adds the
    coarse run's."""
    source = Case(RUNS / f"{bed.name}_{re_number:g}_{coarse}", env)
    source_ranks, written, start = latest_write(
        source, f"no run to map from (run N = {coarse} first)")
    if float(start) >= end_time:
        raise SystemExit(f"{source.path}: latest time {start} is not before the end "
                         f"time {end_time:g}")
    case = new_case(re_number, n, end_time, write_interval, bed, env, float(start))
    case.run("./Allrun.pre", re_number, n, log="Allrun.pre")
    (case.path / "0").rename(case.path / start)
    # mapFields maps only into fields the target has
    force = f"{start}/rigidForce"
    shutil.copy(case.path / start / "U", case.path / force)
    case.set(force, "FoamFile/object", "rigidForce")
    case.set(force, "dimensions", "[1 -2 -2 0 0 0 0]")
    case.set(force, "internalField", "uniform (0 0 0)")
    case.run("mapFields", source.path, "-consistent", "-sourceTime", start,
             *(["-parallelSource"] if source_ranks else []))
    (case.path / start / "uniform").mkdir()
    shutil.copy(written.path / start / "uniform" / "superficialVelocityProperties",
                case.path / start / "uniform")
    if ranks > 1:
        case.set("system/decomposeParDict", "numberOfSubdomains", ranks)
        case.run("decomposePar", "-force")
    case.run("pimpleDLMFoam", np=ranks)
    return reduce(case.path) + (solver_seconds(case.path),)


def extend(re_number, n, end_time, write_interval, bed, env):
    """Continue an earlier run from its latest written time to end_time, on
    the ranks it was decomposed for; the wall time is the sum of the solver
    logs' clock times (log.pimpleDLMFoam, then log.pimpleDLMFoam.<start>)."""
    case = Case(RUNS / f"{bed.name}_{re_number:g}_{n}", env)
    ranks, _, latest = latest_write(case, "no run to continue (run it without --continue)")
    if float(latest) <= 0:
        raise SystemExit(f"{case.path}: no written time after 0 to continue from")
    if float(latest) < end_time:
        set_controls(case, end_time, write_interval, float(latest))
        case.run("pimpleDLMFoam", np=max(ranks, 1), log=f"pimpleDLMFoam.{latest}")
    return reduce(case.path) + (solver_seconds(case.path),)


def latest_write(case, missing):
    """The ranks a run was decomposed for (0: serial), the case that holds
    its written times and the latest of them; stops with the message
    missing if the case never ran."""
    if not (case.path / "log.pimpleDLMFoam").exists():
        raise SystemExit(f"{case.path}: {missing}")
    ranks = len(list(case.path.glob("processor[0-9]*")))
    written = Case(case.path / "processor0", case.env) if ranks else case
    return ranks, written, written.times()[-1]


def solver_seconds(path):
    """Sum of the solver logs' clock times: the wall time of a run continued
    over several starts, and of a mapped run's source (log.mapFields)."""
    seconds = sum(float(re.findall(r"ClockTime = (\S+)", log.read_text())[-1])
                  for log in path.glob("log.pimpleDLMFoam*"))
    mapped = path / "log.mapFields"
    if mapped.exists():
        source = re.search(r'^Source: "(.*)" "(.*)"$', mapped.read_text(), flags=re.M)
        seconds += solver_seconds(pathlib.Path(*source.groups()))
    return seconds


def reduce(path):
    """Porosity, Re, Lambda averaged over the last quarter of the run, its
    drift over that window, and the steps."""
    rows = packed_bed_rows(path)
    start = float(min(path.glob("postProcessing/bed/*"), key=lambda d: float(d.name)).name)
    window = rows[rows[:, 0] >= start + 0.75*(rows[-1, 0] - start)]
    lam = window[:, 6]
    return rows[-1, 2], rows[-1, 5], lam.mean(), (lam.max() - lam.min())/lam.mean(), \
        len(rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--re", type=float, default=900)
    parser.add_argument("--end-time", type=float, default=80,
                        help="flow time [s]; steady after about 30 s")
    parser.add_argument("--np", type=int, default=1, help="MPI ranks")
    parser.add_argument("--write-interval", type=float,
                        help="flow time between written fields (default: the end time)")
    parser.add_argument("--continue", dest="extend", action="store_true",
                        help="continue the existing runs to the end time")
    parser.add_argument("--map-from", type=int, metavar="N",
                        help="start from the latest written fields of the run at N"
                        " cells per diameter, mapped onto the finer mesh")
    parser.add_argument("--box", type=float, default=1,
                        help="side of the periodic cube [m] (1: the paper's 100 spheres;"
                        " 0.6: 22 spheres, the tests' bed)")
    parser.add_argument("--direction", choices="xyz", default="x",
                        help="direction of the flow (y, z: results/<table>_<direction>.csv)")
    parser.add_argument("--max-co", type=float, default=0.5,
                        help="Courant number that sets the time step (other than 0.5:"
                        " results/<table>_co<value>.csv)")
    parser.add_argument("resolutions", nargs="*", type=int, default=[8, 12, 16, 20])
    args = parser.parse_args()
    bed = Bed(args.box, args.direction, args.max_co)

    env = foam_environment()
    RESULTS.mkdir(parents=True, exist_ok=True)
    for n in args.resolutions:
        if args.extend:
            eps, re_bed, lam, drift, steps, seconds = \
                extend(args.re, n, args.end_time, args.write_interval, bed, env)
        elif args.map_from:
            eps, re_bed, lam, drift, steps, seconds = \
                mapped_run(args.re, n, args.map_from, args.end_time, args.np,
                           args.write_interval, bed, env)
        else:
            eps, re_bed, lam, drift, steps, seconds = \
                run(args.re, n, args.end_time, args.np, args.write_interval, bed, env)
        merge_row(RESULTS / f"{bed.name}.csv", HEADER,
                  [args.re, n, eps, lam, ergun_lambda(re_bed),
                   lam/ergun_lambda(re_bed) - 1, drift, seconds, steps])
        print(f"Re={args.re:g} N={n:3d} porosity={eps:.4f} Lambda={lam:.1f} "
              f"Ergun={ergun_lambda(re_bed):.1f} ({100*(lam/ergun_lambda(re_bed) - 1):+.1f}%) "
              f"drift={100*drift:.2f}% wall={seconds:.0f}s steps={steps}", flush=True)
    summarise(bed.name)


def summarise(table):
    """Per Re: Lambda against resolution with Ergun, the correlations fitted
    to fully resolved simulations of random arrays (Beetstra et al. 2007,
    Tang et al. 2015) and the Richardson extrapolate; then the error against
    wall time. In Stokes flow (Re <= 1) the error is taken against
    Beetstra's correlation, which there is Carman-Kozeny's 180 fitted to
    lattice-Boltzmann data, rather than Ergun's 150."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = stored_rows(RESULTS / f"{table}.csv")
    re_numbers = sorted({r[0] for r in rows})
    fig, axes = plt.subplots(1, len(re_numbers) + 1, figsize=(5.5*(len(re_numbers) + 1), 4))
    series = {}
    for ax, re_number in zip(axes, re_numbers):
        sel = sorted((r for r in rows if r[0] == re_number), key=lambda r: r[1])
        n = np.array([r[1] for r in sel])
        lam = np.array([r[3] for r in sel])
        ergun = sel[-1][4]
        # the bed's Re (by its discrete porosity) from Ergun's linear Lambda
        porosity, re_bed = sel[-1][2], (ergun - ergun_lambda(0))/(ergun_lambda(1) - ergun_lambda(0))
        correlations = {label: correlation_lambda(drag, porosity, re_bed)
                        for label, drag in (("Beetstra et al. 2007", beetstra_drag),
                                            ("Tang et al. 2015", tang_drag))}
        order, extrapolate = richardson(n, lam)
        print(f"Re={re_number:g}: Lambda {', '.join(f'{v:.1f}' for v in lam)} at N = "
              f"{', '.join(str(int(v)) for v in n)}; observed order {order:.2f}, "
              f"extrapolate {extrapolate:.1f}; against it: Ergun {ergun:.1f} "
              f"({100*(extrapolate/ergun - 1):+.1f}%), "
              + ", ".join(f"{label} {value:.1f} ({100*(extrapolate/value - 1):+.1f}%)"
                          for label, value in correlations.items()))
        ax.plot(n, lam, "o-", label=f"computed (order {order:.2f})")
        ax.axhline(ergun, ls="--", lw=0.8, color="k", label="Ergun")
        for (label, value), style in zip(correlations.items(), ("-.", (0, (1, 3)))):
            ax.axhline(value, ls=style, lw=0.8, color="C2", label=label)
        if np.isfinite(order):
            ax.axhline(extrapolate, ls=":", lw=0.8, color="C1", label="Richardson extrapolate")
            series[f"Re {re_number:g}, against the extrapolate"] = \
                [(r[7], abs(r[3]/extrapolate - 1), int(r[1])) for r in sel]
        reference, label = (ergun, "Ergun") if re_number > 1 else \
            (correlations["Beetstra et al. 2007"], "Beetstra et al.")
        series[f"Re {re_number:g}, against {label}"] = \
            [(r[7], abs(r[3]/reference - 1), int(r[1])) for r in sel]
        ax.set_xlabel("cells per diameter")
        ax.set_ylabel("Lambda")
        ax.set_title(f"Random bed, Re {re_number:g} ({table}.csv)")
        ax.legend(fontsize=7)
    plot_speed_error(axes[-1], series, target=5)
    axes[-1].set_title("Error against wall time")
    fig.tight_layout()
    fig.savefig(RESULTS / f"{table}.png", dpi=120)


if __name__ == "__main__":
    main()
