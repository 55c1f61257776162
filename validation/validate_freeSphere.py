#!/usr/bin/env python3
"""A free sphere settling at Re 185-365 against Uhlmann & Dusek (2014;
reference README section 8): density ratio 1.5, Galileo numbers 144
(steady vertical), 178.46 (steady oblique), 190 (oscillating oblique) and
250 (chaotic).

The sphere (d = 10 mm, tests/sphereInBox.py) settles in a box of width W
diameters with slip side walls, closed at top and bottom, started at the
published speed less 5 % (an impulsive start, so that the wake forms
within a few diameters) 4 diameters under the lid. After the first third
of the fall (the start-up), the mean vertical speed u_V is the fall's
displacement over its time, the mean horizontal speed u_H the lateral
displacement's over the last third, the angle atan(u_H/u_V); for Ga 190
and 250 the dominant frequency of the lateral velocity as f d/u_g. Reported: each against the
published (large domain), the drift of u_V over the last third against
the middle third, the wall time, the steps, the cells and the share of
the mesh changes. N is the base mesh's cells per diameter; --levels L
refines the sphere's surface band to N 2^L and its wake (vorticity above
0.2 U/R) to N 2^(L-1), every --refine-interval steps (3; the band looks
ahead by as many steps). --offset X starts the sphere X diameters off the
axis along x and --lateral-speed V moving at V u_g along x (an oblique
path's start, away from the nearer wall); --prescribed-start P moves it at
the published velocity for P diameters, then frees it (analysed over the
free part). --surface-cells B sets the surface band's width outside the
surface (3 cells of the finest level).

--frame stream holds the sphere in the box instead, for the long runs the
oblique and oscillating paths need (Uhlmann & Dusek ran 250 time units
d/u_g, some 340 diameters of fall): the fluid enters the box from below at
the published u_V and leaves at the top, the sides are periodic (the
oblique path crosses them), the sphere starts at rest in that stream a
third of the box's height above the inlet, moving sideways at
--lateral-speed (the seed of the path's instability), and runs for
--time-units d/u_g (250); the speeds are taken relative to the stream.

Writes results/freeSphere.csv and a plot per run
(results/freeSphere_Ga<Ga>_N<N>_L<L>_W<W>_H<H>_Co<Co>_R<R>.png). With
--case DIR it runs nothing: it reports the finished case DIR (the
settlingSphere tutorial's) at --ga and plots it into DIR/freeSphere.png.

    validation/validate_freeSphere.py [--ga 144,178.46] [--levels 2]
        [--width 6] [--height 30] [--max-co 0.5] [--np 1]
        [--refine-interval 3] [--offset 0] [--lateral-speed 0]
        [--prescribed-start 0] [--surface-cells 3]
        [--frame box|stream] [--time-units 250] [N ...]
        (default N = 4)
    validation/validate_freeSphere.py --ga 144 --case tutorials/settlingSphere
"""

import argparse
import math
import pathlib
import re
import shutil

import numpy as np

from common import (REFERENCE, RESULTS, RUNS, Case, foam_environment,
                    merge_row, timed_run)
from sphereInBox import D, G, gravitational_speed, sphere_in_box, viscosity_for_galileo

TABLE = RESULTS / "freeSphere.csv"
HEADER = ["Ga", "baseCellsPerDiameter", "levels", "surfaceCellsPerDiameter", "widthD",
          "heightD", "maxCo", "refineInterval", "uV_ug", "uV_reference", "uV_error", "uV_drift",
          "uH_ug", "uH_reference", "angle_deg", "angle_reference", "frequency",
          "wallTime_s", "steps", "lastCells", "meshChangeShare", "surfaceBandCells",
          "frame"]
DENSITY_RATIO = 1.5


def reference(galileo):
    """Uhlmann & Dusek's large-domain u_V/u_g, u_H/u_g and angle (NaN if not
    given) of the case nearest to galileo."""
    lines = [line for line in (REFERENCE / "UhlmannDusek2014_single_sphere.csv")
             .read_text().splitlines() if line.strip() and not line.startswith("#")]
    header = lines[0].split(",")
    rows = [dict(zip(header, line.split(","))) for line in lines[1:]]
    row = min(rows, key=lambda r: abs(float(r["Ga"]) - galileo))
    return tuple(float(row[k]) if row[k] else math.nan for k in
                 ("uV_over_ug_large", "uH_over_ug_large", "angle_deg_large"))


def mesh_changes(log):
    """Cells after the last change and the share of the execution time the
    changes took (the solver's summary line), or (None, 0)."""
    cells = re.findall(r"^Mesh changed: (\d+) cells", log, re.M)
    share = re.search(
        r"following the change [0-9.e+-]+ s, ([0-9.e+-]+) % of the execution time", log)
    return (int(cells[-1]) if cells else None), (float(share.group(1)) if share else 0.0)


def in_fluid_frame(history, speed, period):
    """A history in the stream frame (the fluid entering at speed along +z,
    the sides periodic with the given period) as a fall through fluid at
    rest: the crossings of the sides undone, the stream's motion added."""
    history = history.copy()
    t = history[:, 0] - history[0, 0]
    for column in (1, 2):
        jumps = np.diff(history[:, column])
        history[1:, column] -= period*np.cumsum(np.round(jumps/period))
    history[:, 3] -= speed*t
    history[:, 6] -= speed
    return history


def analyse(history, ug):
    """u_V, u_H (over u_g), angle [deg], drift of u_V, dominant lateral
    frequency f d/u_g, over the fall after its first third."""
    t, x, y, z = history[:, 0], history[:, 1], history[:, 2], history[:, 3]
    fall = z[0] - z
    thirds = [np.searchsorted(fall, k*fall[-1]/3) for k in (1, 2)]
    i0, i1, i2 = thirds[0], thirds[1], len(t) - 1

    def speeds(a, b):
        dt = t[b] - t[a]
        return (z[a] - z[b])/dt, math.hypot(x[b] - x[a], y[b] - y[a])/dt

    u_v = speeds(i0, i2)[0]
    # The oblique path's lateral speed once its slower start-up has passed
    u_h = speeds(i1, i2)[1]
    drift = speeds(i1, i2)[0]/speeds(i0, i1)[0] - 1
    lateral = history[i0:, 4:6]
    lateral = lateral - lateral.mean(axis=0)
    # The lateral velocity's component along its main direction
    axis = np.linalg.svd(lateral, full_matrices=False)[2][0]
    signal = lateral @ axis
    times = np.linspace(t[i0], t[-1], 2*len(signal))
    uniform = np.interp(times, t[i0:], signal)
    spectrum = np.abs(np.fft.rfft(uniform*np.hanning(len(uniform))))
    freqs = np.fft.rfftfreq(len(uniform), times[1] - times[0])
    frequency = freqs[1 + np.argmax(spectrum[1:])]*D/ug
    return u_v/ug, u_h/ug, math.degrees(math.atan2(u_h, u_v)), drift, frequency


def plot(history, ug, galileo, ref_v, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    t, z = history[:, 0], history[:, 3]
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    axes[0].plot((z[0] - z)/D, -history[:, 6]/ug, label="vertical")
    axes[0].plot((z[0] - z)/D, np.hypot(history[:, 4], history[:, 5])/ug,
                 label="horizontal")
    axes[0].axhline(ref_v, color="k", ls="--", label="Uhlmann & Dusek (2014)")
    axes[0].set_xlabel("fall / d")
    axes[0].set_ylabel("speed / u_g")
    axes[0].legend()
    axes[1].plot(history[:, 1]/D, (z - z[0])/D)
    axes[1].plot(history[:, 2]/D, (z - z[0])/D)
    axes[1].set_xlabel("x/d, y/d")
    axes[1].set_ylabel("z/d")
    fig.suptitle(f"free sphere, Ga {galileo:g}, rho_s/rho_f {DENSITY_RATIO:g}")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--ga", default="144")
    parser.add_argument("--levels", type=int, default=2)
    parser.add_argument("--width", type=float, default=6)
    parser.add_argument("--height", type=float, default=30)
    parser.add_argument("--max-co", type=float, default=0.5)
    parser.add_argument("--np", type=int, default=1)
    parser.add_argument("--refine-interval", type=int, default=3)
    parser.add_argument("--offset", type=float, default=0)
    parser.add_argument("--lateral-speed", type=float, default=0)
    parser.add_argument("--surface-cells", type=int, default=3)
    parser.add_argument("--prescribed-start", type=float, default=0)
    parser.add_argument("--frame", choices=("box", "stream"), default="box")
    parser.add_argument("--time-units", type=float, default=250)
    parser.add_argument("--case", type=pathlib.Path)
    parser.add_argument("resolutions", nargs="*", type=int, default=[4])
    args = parser.parse_args()

    env = foam_environment()
    if args.case:
        analyse_case(args.case, float(args.ga), env)
        return
    RESULTS.mkdir(parents=True, exist_ok=True)
    ug = gravitational_speed(DENSITY_RATIO)
    for galileo in [float(g) for g in args.ga.split(",")]:
        ref_v, ref_h, ref_angle = reference(galileo)
        for n in args.resolutions:
            name = (f"freeSphere_Ga{galileo:g}_N{n}_L{args.levels}_W{args.width:g}"
                    f"_H{args.height:g}_Co{args.max_co:g}_R{args.refine_interval}"
                    + (f"_X{args.offset:g}_V{args.lateral_speed:g}"
                       if args.offset or args.lateral_speed else "")
                    + (f"_S{args.surface_cells}" if args.surface_cells != 3 else "")
                    + (f"_P{args.prescribed_start:g}" if args.prescribed_start else "")
                    + (f"_stream{args.time_units:g}" if args.frame == "stream" else ""))
            case = Case(RUNS / name, env)
            if case.path.exists():
                shutil.rmtree(case.path)
            case.path.mkdir(parents=True)
            end_time = (args.height - 8)*D/(ref_v*ug)
            release = args.prescribed_start*D/(ref_v*ug)
            if args.frame == "stream":
                stream_case(case, galileo, n, ref_v*ug, args)
            elif release:
                # The published motion, its wake forming, then free
                start, lateral = ref_v*ug, (0 if math.isnan(ref_h) else ref_h)*ug
            else:
                start, lateral = 0.95*ref_v*ug, args.lateral_speed*ug
            if args.frame == "box":
                sphere_in_box(case, "free", n, ref_v*ug,
                              viscosity_for_galileo(galileo, DENSITY_RATIO), DENSITY_RATIO,
                              width=args.width, below=4, above=args.height - 4,
                              max_co=args.max_co, levels=args.levels, start_speed=start,
                              end_time=release or end_time, write_interval=release or None,
                              refine_interval=args.refine_interval, offset=args.offset,
                              lateral_speed=lateral, surface_cells=args.surface_cells)
            if release:
                prescribe(case, True)
            case.run("blockMesh")
            if args.np > 1:
                case.set("system/decomposeParDict", "numberOfSubdomains", args.np)
                case.run("decomposePar")
            seconds = timed_run(case, "pimpleDLMFoam", np=args.np)
            if release:
                released = release_sphere(case, end_time)
                seconds += timed_run(case, "pimpleDLMFoam", np=args.np)
                history = case.history(released)["sphere"]
            else:
                history = case.history()["sphere"]
            if args.frame == "stream":
                history = in_fluid_frame(history, ref_v*ug, args.width*D)
            measured = analyse(history, ug)
            u_v, u_h, angle, drift, frequency = measured
            log = (case.path / "log.pimpleDLMFoam").read_text()
            cells, share = mesh_changes(log)
            merge_row(TABLE, HEADER,
                      [galileo, n, args.levels, n << args.levels, args.width, args.height,
                       args.max_co, args.refine_interval, u_v, ref_v, u_v/ref_v - 1, drift,
                       u_h, ref_h, angle, ref_angle, frequency, seconds, len(history),
                       cells or 0, share, args.surface_cells, args.frame],
                      key_columns=[0, 1, 2, 4, 5, 6, 7, 21, 22])
            plot(history, ug, galileo, ref_v, RESULTS / f"{name}.png")
            print(f"Ga={galileo:g} N={n} L={args.levels} W={args.width:g}: "
                  + summary(galileo, measured, cells, share, len(history), seconds),
                  flush=True)


def stream_case(case, galileo, n, speed, args):
    """The sphere free in an upward stream at speed (tests/sphereInBox.py's
    held sphere with gravity on and periodic sides), a third of the box
    above the inlet, moving sideways at args.lateral_speed u_g."""
    ug = gravitational_speed(DENSITY_RATIO)
    below = args.height/3
    sphere_in_box(case, "held", n, speed, viscosity_for_galileo(galileo, DENSITY_RATIO),
                  DENSITY_RATIO, width=args.width, below=below, above=args.height - below,
                  end_time=args.time_units*D/ug, max_co=args.max_co, levels=args.levels,
                  refine_interval=args.refine_interval, surface_cells=args.surface_cells,
                  periodic_sides=True)
    g = case.path / "constant" / "g"
    g.write_text(g.read_text().replace("value (0 0 0);", f"value (0 0 {-G!r});"))
    properties = case.path / "constant" / "particleProperties"
    properties.write_text(properties.read_text().replace(
        "motion fixed;", f"velocity ({args.lateral_speed*ug!r} 0 0);"))


def prescribe(case, prescribed):
    """The sphere's motion in constant/particleProperties: prescribed at
    its start velocity, or free."""
    path = case.path / "constant" / "particleProperties"
    text = path.read_text().replace("motion prescribed; ", "")
    if prescribed:
        text = text.replace("velocity (", "motion prescribed; velocity (", 1)
    path.write_text(text)


def release_sphere(case, end_time):
    """Make the prescribed sphere free from the last written time on (the
    input and the written state alike) and run to end_time: returns that
    time's name."""
    prescribe(case, False)
    released = case.times()[-1]
    states = [case.path / released / "uniform" / "particles"] + [
        processor / released / "uniform" / "particles"
        for processor in case.path.glob("processor*")]
    for state in states:
        if state.exists():
            state.write_text(re.sub(r"motion\s+prescribed;", "motion free;", state.read_text()))
    case.set("system/controlDict", "endTime", end_time)
    case.set("system/controlDict", "writeInterval", end_time)
    return released


def summary(galileo, measured, cells, share, steps, seconds):
    """The run's speeds, angle and frequency (analyse()'s) against Uhlmann
    & Dusek's, its cost and the mesh changes' share, on one line."""
    ref_v, ref_h, ref_angle = reference(galileo)
    u_v, u_h, angle, drift, frequency = measured
    return (f"u_V/u_g={u_v:.4f} (Uhlmann & Dusek {ref_v:.4f}, {100*(u_v/ref_v - 1):+.2f} %, "
            f"drift {100*drift:+.2f} %), u_H/u_g={u_h:.4f} ({ref_h:.4f}), "
            f"angle {angle:.2f} deg ({ref_angle:.2f}), f d/u_g={frequency:.4f}, "
            f"wall {seconds:.0f} s, {steps} steps, cells {cells}, "
            f"mesh changes {share:.0f} %")


def analyse_case(path, galileo, env):
    """Report a finished case (the settlingSphere tutorial's) and plot it
    into the case as freeSphere.png."""
    case = Case(path, env)
    history = case.history()["sphere"]
    ug = gravitational_speed(DENSITY_RATIO)
    log = (case.path / "log.pimpleDLMFoam").read_text()
    clock = re.findall(r"ClockTime = ([0-9.e+-]+) s", log)
    print(f"Ga={galileo:g}: " + summary(galileo, analyse(history, ug), *mesh_changes(log),
                                         len(history), float(clock[-1]) if clock else math.nan))
    plot(history, ug, galileo, reference(galileo)[0], case.path / "freeSphere.png")


if __name__ == "__main__":
    main()
