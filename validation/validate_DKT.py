#!/usr/bin/env python3
"""Drafting, kissing and tumbling of two disks (tutorials/
draftingKissingTumbling) against Uhlmann (2005) (reference README section 3),
at several resolutions (cells per diameter).

For each run: the trailing disk's peak velocity before the kiss and its
time, the kiss time
(the centres first within 1.1 d), the time the trailing disk overtakes the
leading one, each against the reference events; the RMS deviation of the
position and velocity along gravity and of the lateral position from the
digitised curves (t <= 0.3 s, in units of d and of the reference peak
velocity); the wall time. The lateral direction in which the pair tumbles
is set by the tiny initial offsets; the lateral curves are compared with the
sign of the reference. Puts each resolution's row into results/DKT.csv
(replacing an earlier run at that resolution; the speed-error plot shows all
rows); writes results/DKT.png (the curves of this call's runs) and
results/DKT_speed_error.png. --end-time runs past the reference's 0.3 s to
see a late tumble.

--levels L refines the mesh in the plane at the disks: N is then
the finest cells per diameter, at the disks' surfaces and in the gap between
them, on a base mesh of N/2^L (their wakes one level less); those rows go to
results/DKT_refined.csv, beside the uniform mesh's in the speed-error plot.

    validation/validate_DKT.py [--np 1] [--end-time 0.3] [--levels L] [N ...]
                               (default N = 12 16 24)
"""

import argparse

import numpy as np

from common import (RESULTS, ROOT, RUNS, Case, foam_environment, merge_row,
                    plot_speed_error, read_csv, refinement_dict, stored_rows, timed_run)

D, TOP, CENTRE = 0.0025, 0.06, 0.01
EVENTS = {"peakVelocity_cm_s": 19.3, "peakTime_s": 0.165, "kissTime_s": 0.167,
          "overtakeTime_s": 0.28}
FIGURES = {"6a": ("position along gravity [cm]", "x_cm"),
           "6b": ("velocity along gravity [cm/s]", "u_cm_per_s"),
           "7a": ("lateral position [cm]", "y_cm"),
           "7b": ("lateral velocity [cm/s]", "v_cm_per_s"),
           "8": ("angular velocity [rad/s]", "omega_rad_per_s")}


def reference(figure, disk):
    _, data = read_csv(f"Uhlmann2005_DKT_fig{figure}_{disk}.csv")
    return data[:, 0], data[:, 1]


def curves(history):
    """Our history in the reference's units and directions."""
    t = history[:, 0]
    return t, {"6a": (TOP - history[:, 2])*100, "6b": -history[:, 5]*100,
               "7a": (history[:, 1] - CENTRE)*100, "7b": history[:, 4]*100,
               "8": history[:, 9]}


def lateral_sign(h):
    """+1 when the leading disk ends on the reference's side."""
    t_ref, y_ref = reference("7a", "leading")
    return np.sign(y_ref[-1])*np.sign(h["leading"][-1, 1] - CENTRE)


def events(h):
    T, L = h["trailing"], h["leading"]
    t = T[:, 0]
    velocity = -T[:, 5]*100
    separation = np.hypot(T[:, 1] - L[:, 1], T[:, 2] - L[:, 2])/D
    kissed = separation <= 1.1
    overtaken = T[:, 2] < L[:, 2]
    kiss = np.argmax(kissed) if kissed.any() else len(t) - 1
    peak = np.argmax(velocity[:kiss + 1])
    return {"peakVelocity_cm_s": velocity[peak], "peakTime_s": t[peak],
            "kissTime_s": t[kiss] if kissed.any() else np.nan,
            "overtakeTime_s": t[np.argmax(overtaken)] if overtaken.any() else np.nan,
            "minSeparation_d": separation.min()}


def rms_deviation(h, figure, scale, sign=1):
    deviations = []
    for disk in ("leading", "trailing"):
        t, ours = curves(h[disk])
        t_ref, y_ref = reference(figure, disk)
        inside = t_ref <= min(t[-1], 0.3)
        deviations.append(sign*np.interp(t_ref[inside], t, ours[figure]) - y_ref[inside])
    return np.sqrt(np.mean(np.concatenate(deviations)**2))/scale


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--np", type=int, default=1)
    parser.add_argument("--end-time", type=float, default=0.3)
    parser.add_argument("--levels", type=int, default=0)
    parser.add_argument("resolutions", nargs="*", type=int, default=[12, 16, 24])
    args = parser.parse_args()
    levels = args.levels
    for n in args.resolutions:
        if n % (1 << levels):
            raise SystemExit(f"{n} cells per diameter is not a base mesh's refined"
                             f" {levels} levels")

    env = foam_environment()
    RESULTS.mkdir(parents=True, exist_ok=True)
    histories = {}
    for n in args.resolutions:
        case = Case.copy(ROOT / "tutorials" / "draftingKissingTumbling",
                         RUNS / (f"DKT_{n}" + (f"_ref{levels}" if levels else "")), env)
        case.set("system/controlDict", "endTime", args.end_time)
        if levels:
            (case.path / "constant" / "dynamicMeshDict").write_text(refinement_dict(
                f"        surface {{ type particleSurface; level {levels}; }}\n"
                f"        gap     {{ type particleGap; level {levels}; walls false; }}\n"
                f"        wake    {{ type vorticity; level {max(levels - 1, 1)};"
                " threshold 0.2; }"))
        seconds = timed_run(case, "./Allrun", n >> levels, args.np)
        h = case.history()
        histories[n] = h
        e = events(h)
        sign = lateral_sign(h)
        row = [n] + [e[k] for k in EVENTS] + [e["minSeparation_d"]]
        row += [e[k]/EVENTS[k] - 1 for k in EVENTS]
        row += [rms_deviation(h, "6a", D*100), rms_deviation(h, "6b", 19.3),
                rms_deviation(h, "7a", D*100, sign), seconds]
        print(f"N={n:3d}: peak {e['peakVelocity_cm_s']:.2f} cm/s at {e['peakTime_s']:.3f} s, "
              f"kiss {e['kissTime_s']:.3f} s, overtake {e['overtakeTime_s']:.3f} s, "
              f"closest {e['minSeparation_d']:.3f} d; errors "
              + ", ".join(f"{k} {100*r:+.1f} %" for k, r in zip(EVENTS, row[6:10]))
              + f"; wall {seconds:.0f} s", flush=True)
        header = (["cellsPerDiameter"] + list(EVENTS) + ["minSeparation_d"]
                  + [f"{k}_relError" for k in EVENTS]
                  + ["rmsPosition_d", "rmsVelocity_rel", "rmsLateral_d", "wallTime_s"])
        if levels:
            merge_row(RESULTS / "DKT_refined.csv", header + ["levels"], row + [levels],
                      key_columns=1)
        else:
            merge_row(RESULTS / "DKT.csv", header, row, key_columns=1)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 5, figsize=(20, 4))
    for ax, (figure, (label, _)) in zip(axes, FIGURES.items()):
        for disk, style in (("leading", "-"), ("trailing", "--")):
            t_ref, y_ref = reference(figure, disk)
            ax.plot(t_ref, y_ref, "k" + style, lw=2, label=f"Uhlmann {disk}")
            for n, h in histories.items():
                t, ours = curves(h[disk])
                sign = lateral_sign(h) if figure in ("7a", "7b", "8") else 1
                ax.plot(t, sign*ours[figure], style, lw=1, label=f"{n} cells/d {disk}")
        ax.set_xlabel("t [s]")
        ax.set_ylabel(label)
        ax.set_xlim(0, args.end_time)
    axes[0].invert_yaxis()
    axes[-1].legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(RESULTS / "DKT.png", dpi=110)

    fig, ax = plt.subplots(figsize=(6, 4))
    rows = stored_rows(RESULTS / "DKT.csv")
    series = {k: [(r[13], abs(r[6 + j]), r[0]) for r in rows if np.isfinite(r[6 + j])]
              for j, k in enumerate(EVENTS)}
    colors = {k: f"C{j}" for j, k in enumerate(EVENTS)}
    plot_speed_error(ax, series, target=5, colors=colors)
    refined = stored_rows(RESULTS / "DKT_refined.csv")
    series = {f"{k} refined": [(r[13], abs(r[6 + j]), f"{int(r[0])}, {int(r[14])} levels")
                               for r in refined if np.isfinite(r[6 + j])]
              for j, k in enumerate(EVENTS)}
    plot_speed_error(ax, series, fmt="s--",
                     colors={f"{k} refined": c for k, c in colors.items()})
    ax.legend(fontsize=6)
    ax.set_title("DKT: event errors against wall time (labels: finest cells/d)")
    fig.tight_layout()
    fig.savefig(RESULTS / "DKT_speed_error.png", dpi=120)


if __name__ == "__main__":
    main()
