#!/usr/bin/env python3
"""A prolate spheroid settling from rest at a tilt at a particle Reynolds
number of about 50 turns broadside to its fall, its long axis horizontal:
the known behaviour of elongated bodies settling with inertia (the wake's
pressure turns the long axis across the stream; in Stokes flow it keeps
its tilt, tests/test_shapes.py).

The spheroid (semi-axes 2, 1, 1 mm, aspect 2, the equivalent sphere's
diameter d = 2.52 mm; density 1500 kg/m3) starts at rest with its long axis
30 degrees from the vertical (turned 60 degrees about y) near the top of a
closed box 6 d wide and deep, 24 d high, in a liquid of density 1000 and
nu = 4e-6 m2/s (Re = U d/nu about 50 at the terminal speed U, about
0.08 m/s broadside; 5e-6 gives about 42), and falls some 17 d (10 body
lengths) in 0.5 s. N cells
across its minor diameter (uniform cells). The history gives the angle
between the long axis and the vertical (90 degrees: broadside) and its
pitch above the horizontal (signed: a body rocking about broadside swings
about 0), the velocity and Re against time;
results/settlingSpheroid_N<N>_nu<nu>.csv and settlingSpheroid.png, and a
summary row in results/settlingSpheroid.csv: the final angle, the largest
pitch over the last fifth (the rocking's amplitude), the time and fall to
come within 5 degrees of broadside, Re at the end, the sideways drift, the
wall time; the pitch's turning points are printed.

    validation/validate_settlingSpheroid.py [--tilt 30] [--nu 4e-6] [--end-time 0.5] [N ...]
        (default N = 6)
"""

import argparse
import math
import time

import numpy as np

from common import Case, RESULTS, ROOT, RUNS, foam_environment, merge_row

TABLE = RESULTS / "settlingSpheroid.csv"
HEADER = ["cellsPerMinorDiameter", "tilt_deg", "nu", "finalAngle_deg", "rockingAmplitude_deg",
          "timeToBroadside_s", "fallToBroadside_d", "Re_end", "speed_end",
          "drift_d", "wallTime_s", "steps"]
A, B = 0.002, 0.001                     # semi-axes [m]
D_EQ = 2*(A*B*B)**(1/3)                 # equivalent sphere's diameter
RHO_F, RHO_S = 1000.0, 1500.0
WIDTH = 6*D_EQ
HEIGHT = 24*D_EQ
START = HEIGHT - 2.5*D_EQ               # initial centroid height


def make_case(n, tilt, nu, end_time, env):
    case = Case.copy(ROOT / "tutorials" / "settlingShapes",
                     RUNS / f"settlingSpheroid_N{n}_tilt{tilt:g}_nu{nu:g}", env)
    h = 2*B/n
    nx = round(WIDTH/h)
    nz = round(HEIGHT/h)
    W, H = nx*h, nz*h
    (case.path / "system" / "blockMeshDict").write_text(f"""\
FoamFile {{ version 2.0; format ascii; class dictionary; object blockMeshDict; }}
vertices ((0 0 0) ({W!r} 0 0) ({W!r} {W!r} 0) (0 {W!r} 0)
          (0 0 {H!r}) ({W!r} 0 {H!r}) ({W!r} {W!r} {H!r}) (0 {W!r} {H!r}));
blocks (hex (0 1 2 3 4 5 6 7) ({nx} {nx} {nz}) simpleGrading (1 1 1));
boundary
(
    walls {{ type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); }}
);
""")
    # The long axis (body x) turned from horizontal by 90 - tilt degrees
    # about y: 'tilt' degrees from the vertical, its lower end at +x
    half = math.radians(90 - tilt)/2
    (case.path / "constant" / "particleProperties").write_text(f"""\
FoamFile {{ version 2.0; format ascii; class dictionary; object particleProperties; }}
particles
{{
    spheroid
    {{
        shape       ellipsoid;
        semiAxes    ({A!r} {B!r} {B!r});
        density     {RHO_S!r};
        position    ({W/2!r} {W/2!r} {START!r});
        orientation ({math.cos(half)!r} (0 {math.sin(half)!r} 0));
    }}
}}
""")
    for (file, entry), value in {
        ("constant/transportProperties", "rho"): RHO_F,
        ("constant/transportProperties", "nu"): nu,
        ("system/controlDict", "endTime"): end_time,
        ("system/controlDict", "writeInterval"): end_time,
        ("system/fvSolution", "PIMPLE/pRefPoint"): f"({W/2!r} {W/2!r} {H - h/2!r})",
    }.items():
        case.set(file, entry, value)
    case.run("blockMesh")
    return case


def axis_pitch(q):
    """Angle [degrees] of the body x axis (global: the rotation's first
    column) above the horizontal, of quaternions (n, 4) (w x y z): -90 + the
    tilt at the start, 0 broadside; a body rocking about broadside swings
    about 0, one tumbling passes +90."""
    w, x, y, z = q.T
    return np.degrees(np.arcsin(np.clip(2*(x*z - w*y), -1, 1)))


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--tilt", type=float, default=30.0,
                        help="initial angle of the long axis from the vertical [degrees]")
    parser.add_argument("--end-time", type=float, default=0.5)
    parser.add_argument("--nu", type=float, default=4e-6)
    parser.add_argument("resolutions", nargs="*", type=int, default=[6])
    args = parser.parse_args()

    env = foam_environment()
    RESULTS.mkdir(parents=True, exist_ok=True)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    for n in args.resolutions:
        case = make_case(n, args.tilt, args.nu, args.end_time, env)
        start = time.perf_counter()
        # A particle reaching a wall (no contacts here) ends the run with
        # an error after writing its state: its history still tells
        stopped = case.run("pimpleDLMFoam", check=False).returncode != 0
        seconds = time.perf_counter() - start
        hist = case.history()["spheroid"]
        t, speed = hist[:, 0], np.linalg.norm(hist[:, 4:7], axis=1)
        pitch = axis_pitch(hist[:, -4:])
        angle = 90 - np.abs(pitch)
        re_number = speed*D_EQ/args.nu
        fall = (START - hist[:, 3])/D_EQ
        drift = np.hypot(hist[:, 1] - hist[0, 1], hist[:, 2] - hist[0, 2])/D_EQ
        late = t >= 0.8*t[-1]
        near = np.nonzero(angle >= 85)[0]
        turned = t[near[0]] if len(near) else float("nan")
        fall_turned = fall[near[0]] if len(near) else float("nan")
        rocking = np.abs(pitch[late]).max()
        # Turning points of the pitch once broadside was first reached
        first = near[0] if len(near) else len(t)
        turning = [i for i in range(max(first, 1), len(t) - 1)
                   if (pitch[i] - pitch[i - 1])*(pitch[i + 1] - pitch[i]) < 0]
        np.savetxt(RESULTS / f"settlingSpheroid_N{n}_nu{args.nu:g}.csv",
                   np.column_stack([t, angle, pitch, hist[:, 4:7], re_number, fall, drift]),
                   delimiter=",", fmt="%.6g",
                   header="t,angleFromVertical_deg,pitch_deg,Ux,Uy,Uz,Re,fall_d,drift_d", comments="")
        merge_row(TABLE, HEADER, [n, args.tilt, args.nu, angle[-1], rocking, turned, fall_turned,
                                  re_number[-1], speed[-1], drift[-1], seconds, len(t)],
                  key_columns=3)
        print(f"N={n} tilt {args.tilt:g} deg: final angle {angle[-1]:.2f} deg from the"
              f" vertical (pitch within +-{rocking:.1f} over the last fifth), within 5 deg of"
              f" broadside at t = {turned:.3f} s after {fall_turned:.1f} d of fall;"
              f" Re {re_number[-1]:.1f} (max {re_number.max():.1f}), speed"
              f" {speed[-1]:.4f} m/s, drift {drift[-1]:.2f} d, wall {seconds:.0f} s,"
              f" {len(t)} steps" + (" (stopped at a wall)" if stopped else ""), flush=True)
        print("pitch turning points (t [s], deg): "
              + " ".join(f"{t[i]:.3f} {pitch[i]:+.1f}," for i in turning), flush=True)
        label = f"N = {n}, nu {args.nu:g}"
        ax1.plot(t, angle, label=f"from vertical, {label}")
        ax1.plot(t, pitch, ":", label=f"pitch above horizontal, {label}")
        ax2.plot(t, re_number, label=f"Re, {label}")
        ax2.plot(t, 10*drift, "--", label=f"10 x sideways drift / d, {label}")
    ax1.axhline(90, color="k", ls="--", lw=0.8, label="broadside")
    ax1.set_xlabel("t [s]")
    ax1.set_ylabel("long axis [deg]")
    ax1.set_title(f"Spheroid (aspect 2) settling from {args.tilt:g} deg")
    ax1.legend(fontsize=7)
    ax2.set_xlabel("t [s]")
    ax2.set_ylabel("Re = |U| d_eq/nu")
    ax2.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(RESULTS / "settlingSpheroid.png", dpi=120)


if __name__ == "__main__":
    main()
