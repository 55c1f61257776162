#!/usr/bin/env python3
"""One pebble of the pebble discharge rising alone in still water:
its rise velocity against the standard drag curve, at several resolutions.

The discharge's rate depends on how much the water holds the pebbles back,
so this is its single-pebble check: d = 25 mm, 843 kg/m3, in water (1000
kg/m3, nu 1e-6), released from rest 2 d above the floor of a closed box
10 d x 10 d x 24 d (blockage (d/W)^2 = 1 %), with the discharge tutorial's
schemes and solvers (tutorials/pebbleDischarge: limitedLinearV, backward,
maxCo 0.5). The start's acceleration (the velocity after 0.02 s over
that time; the drag is then 0.2 % of the net buoyancy and the viscous
history force about 4 %) is compared with the added-mass value
(rho_f - rho_s) g/(rho_s + rho_f/2). The rise velocity is the mean over
the last 0.3 s of 1.4 s (displacement over time); the drift is the change
between that window's halves. Reference: the unbounded terminal velocity
of the drag curve of Brown & Lawler (2003, J. Environ. Eng. 129, 222),
C_D = 24/Re (1 + 0.150 Re^0.681) + 0.407/(1 + 8710/Re), and with the
wall factor of Di Felice (1996, Int. J. Multiphase Flow 22, 515) for a
tube of the box's area, ((1 - l)/(1 - 0.33 l))^a with
a = (3.3 + 0.085 Re)/(1 + 0.1 Re), l = d/D. A light sphere at this mass
ratio (0.843) and Reynolds number (about 9000) may oscillate about its
path (Horowitz & Williamson 2010), which lowers its mean rise by a few
per cent. Writes results/risingPebble.csv and results/risingPebble.png.

--boundary-layer-slip runs with the rigid projection's boundaryLayerSlip
(system/fvOptions): at this Reynolds number the viscous layer, about d/100
thick, is far thinner than a cell, and the profile cells' tangential
velocity then follows the flow beyond them instead of a no-slip profile
(a coarse-mesh correction: it overshoots as the mesh refines).

    validation/validate_risingPebble.py [--np 2] [--boundary-layer-slip] [N ...]
        (default N = 4 6 8)
"""

import argparse
import math

import numpy as np

from common import Case, RESULTS, ROOT, RUNS, foam_environment, merge_row, timed_run

TABLE = RESULTS / "risingPebble.csv"
HEADER = ["boundaryLayerSlip", "cellsPerDiameter", "ranks", "uRise", "drift", "uBrownLawler", "uWallCorrected",
          "relErrorWallCorrected", "lateralOffset", "wallTime_s", "steps", "startAcceleration",
          "addedMassAcceleration"]
D, RHO_S, RHO_F, NU, G = 0.025, 843.0, 1000.0, 1e-6, 9.81
WIDTH, HEIGHT, START = 10, 24, 2        # in diameters
END_TIME, WINDOW = 1.4, 0.3
START_WINDOW = 0.02
RUN_PREFIX = "risingPebble_N"          # a run's folder in validation/runs: prefix, N,
SLIP_SUFFIX = "_slip"                   # and this suffix with boundaryLayerSlip


def drag_coefficient(re_number):
    return (24/re_number*(1 + 0.150*re_number**0.681)
            + 0.407/(1 + 8710/re_number))


def terminal_velocity():
    """Unbounded terminal velocity of the drag curve (fixed point)."""
    u = 0.3
    for _ in range(200):
        u = math.sqrt(4*G*D*(1 - RHO_S/RHO_F)/(3*drag_coefficient(u*D/NU)))
    return u


def added_mass_acceleration():
    """Acceleration from rest with the added mass of a sphere (half the
    displaced fluid's), before any drag."""
    return (RHO_F - RHO_S)*G/(RHO_S + 0.5*RHO_F)


def wall_factor(u):
    ratio = D/(WIDTH*D*math.sqrt(4/math.pi))
    re_number = u*D/NU
    exponent = (3.3 + 0.085*re_number)/(1 + 0.1*re_number)
    return ((1 - ratio)/(1 - 0.33*ratio))**exponent


def make_case(n, ranks, env, slip=False):
    case = Case.copy(ROOT / "tutorials" / "tenCate",
                     RUNS / f"{RUN_PREFIX}{n}{SLIP_SUFFIX if slip else ''}", env)
    pebble = ROOT / "tutorials" / "pebbleDischarge" / "system"
    for name in ("fvSchemes", "fvSolution"):
        (case.path / "system" / name).write_text((pebble / name).read_text())
    W, H = WIDTH*D, HEIGHT*D
    (case.path / "system" / "blockMeshDict").write_text(f"""\
FoamFile {{ version 2.0; format ascii; class dictionary; object blockMeshDict; }}
vertices ((0 0 0) ({W!r} 0 0) ({W!r} {W!r} 0) (0 {W!r} 0)
          (0 0 {H!r}) ({W!r} 0 {H!r}) ({W!r} {W!r} {H!r}) (0 {W!r} {H!r}));
blocks (hex (0 1 2 3 4 5 6 7) ({WIDTH*n} {WIDTH*n} {HEIGHT*n}) simpleGrading (1 1 1));
boundary
(
    walls
    {{
        type wall;
        faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7));
    }}
);
""")
    # Off the axis by 0.1 mm, so that the wake's symmetry can break
    (case.path / "constant" / "particleProperties").write_text(f"""\
FoamFile {{ version 2.0; format ascii; class dictionary; object particleProperties; }}
particles
{{
    pebble
    {{
        shape       sphere;
        radius      {D/2!r};
        density     {RHO_S!r};
        position    ({W/2 + 1e-4!r} {W/2 - 1e-4!r} {START*D!r});
    }}
}}
""")
    (case.path / "constant" / "transportProperties").write_text(f"""\
FoamFile {{ version 2.0; format ascii; class dictionary; object transportProperties; }}
rho     {RHO_F!r};
nu      {NU!r};
""")
    for entry, value in {"endTime": END_TIME, "writeInterval": END_TIME,
                         "maxCo": 0.5, "maxDeltaT": 0.01}.items():
        case.set("system/controlDict", entry, value)
    if slip:
        case.set("system/fvOptions", "rigidProjection/boundaryLayerSlip", "true")
    case.run("blockMesh")
    if ranks > 1:
        case.set("system/decomposeParDict", "numberOfSubdomains", ranks)
        case.run("decomposePar")
    return case


def plot_runs(env, reference, bounded):
    """The rise velocity of every run kept in validation/runs against the
    references: results/risingPebble.png."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    runs = {}
    for run in RUNS.glob(f"{RUN_PREFIX}*"):
        label = run.name[len(RUN_PREFIX):]
        slip = label.endswith(SLIP_SUFFIX)
        runs[(slip, int(label[:-len(SLIP_SUFFIX)] if slip else label))] = run
    for (slip, n), run in sorted(runs.items()):
        if not (run / "postProcessing").exists():
            continue
        h = Case(run, env).history()["pebble"]
        ax.plot(h[:, 0], h[:, 6], ls="-" if slip else "--",
                label=f"N = {n}" + (", boundary-layer slip" if slip else ", no-slip"))
    ax.axhline(reference, color="k", ls="--", label="Brown & Lawler, unbounded")
    ax.axhline(bounded, color="k", ls=":", label="with Di Felice's wall factor")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("rise velocity [m/s]")
    ax.set_title("One pebble rising in water (d 25 mm, 843 kg/m3)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(RESULTS / "risingPebble.png", dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--np", type=int, default=1)
    parser.add_argument("--boundary-layer-slip", action="store_true")
    parser.add_argument("resolutions", nargs="*", type=int, default=[4, 6, 8])
    args = parser.parse_args()

    env = foam_environment()
    RESULTS.mkdir(parents=True, exist_ok=True)
    reference = terminal_velocity()
    bounded = reference*wall_factor(reference)
    print(f"Brown & Lawler: {reference:.4f} m/s (Re {reference*D/NU:.0f}); "
          f"in the box (Di Felice): {bounded:.4f} m/s", flush=True)
    for n in args.resolutions:
        slip = args.boundary_layer_slip
        case = make_case(n, args.np, env, slip)
        seconds = timed_run(case, "pimpleDLMFoam", np=args.np)
        h = case.history()["pebble"]
        t, z = h[:, 0], h[:, 3]

        def mean_rise(start, end):
            i, j = np.searchsorted(t, start), np.searchsorted(t, end) - 1
            return (z[j] - z[i])/(t[j] - t[i])

        rise = mean_rise(t[-1] - WINDOW, t[-1])
        drift = (mean_rise(t[-1] - WINDOW/2, t[-1])
                 - mean_rise(t[-1] - WINDOW, t[-1] - WINDOW/2))/rise
        lateral = np.hypot(h[:, 1] - h[0, 1], h[:, 2] - h[0, 2]).max()/D
        error = rise/bounded - 1
        start = np.searchsorted(t, START_WINDOW)
        acceleration = h[start, 6]/t[start]
        merge_row(TABLE, HEADER, [int(slip), n, args.np, rise, drift, reference, bounded, error,
                                  lateral, seconds, len(t) - 1, acceleration,
                                  added_mass_acceleration()], key_columns=2)
        print(f"N={n:2d}{' slip' if slip else ''} rise {rise:.4f} m/s ({100*error:+.1f} % against the box's "
              f"{bounded:.4f}), drift {100*drift:+.1f} %, lateral {lateral:.2f} d; start's "
              f"acceleration {acceleration:.3f} m/s2 (added mass: "
              f"{added_mass_acceleration():.3f}); {len(t) - 1} steps, {seconds:.0f} s on "
              f"{args.np} rank(s)", flush=True)

    plot_runs(env, reference, bounded)


if __name__ == "__main__":
    main()
