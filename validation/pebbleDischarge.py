"""Analysis of a pebble discharge (tutorials/pebbleDischarge, the paper's
section 3.4): the pebble mass flux through the chute (from the outlet's
record) and through a section of the bed (pebbles crossing it, from the
history), their mass balance, the bed bottom (the lowest pebble in the
central cylinder of the opening's radius, as the paper), and the pebbles'
vertical velocity across the bed early in the discharge."""

import pathlib
import re

import numpy as np

# The paper's full scene (figure 18): about 4 kg/(m2 s) in the bed and 60
# in the chute
PAPER_BED_FLUX = 4.0
PAPER_CHUTE_FLUX = 60.0
# The paper's reservoir: 406 mm across
PAPER_BED_AREA = np.pi*0.203**2
PEBBLE_DENSITY = 843.0
# The pebbles' names: those of the particles of constant/pebbleBed.dat
PEBBLE_NAME = "pebbleBed_"


def geometry(case_dir):
    """The entries of the case's constant/geometry, or of its parent's for
    a subcase (the tutorial's dry/)."""
    case_dir = pathlib.Path(case_dir)
    path = case_dir / "constant/geometry"
    if not path.exists():
        path = case_dir.parent / "constant/geometry"
    text = path.read_text()
    return {k: float(v) for k, v in re.findall(r"^(\w+)\s+([-0-9.eE]+);", text, re.M)}


def restarted_rows(record_dir, file_name):
    """The rows (split into fields) of a record written by every run of a
    case, one directory per start time: a run's rows after the next run's
    start are dropped, since that run wrote them again from its restart."""
    starts = sorted((float(path.parent.name), path)
                    for path in pathlib.Path(record_dir).glob(f"*/{file_name}"))
    rows = []
    for i, (start, path) in enumerate(starts):
        end = starts[i + 1][0] if i + 1 < len(starts) else np.inf
        for line in path.read_text().splitlines():
            if line.startswith("#"):
                continue
            fields = line.split()
            if (i == 0 or float(fields[0]) > start) and float(fields[0]) <= end:
                rows.append(fields)
    return rows


def outlet_record(case_dir):
    """Times and cumulative mass of the pebbles that left, over every run
    of the case (restarts append a directory per start time)."""
    rows = [(float(fields[0]), float(fields[3])) for fields in
            restarted_rows(pathlib.Path(case_dir) / "postProcessing/particleOutlets",
                           "outlets.dat")]
    rows.sort()
    t = np.array([r[0] for r in rows])
    return t, np.cumsum([r[1] for r in rows])


def history(case_dir):
    """Pebble history (every historyInterval steps): times, names and
    positions (time, pebble, xyz) and velocities, from every start time;
    the pebbles are the particles of the bed's file (an immersed wall is a
    particle too)."""
    times, names, rows = [], [], []
    for fields in restarted_rows(pathlib.Path(case_dir) / "postProcessing/particles",
                                 "particles.dat"):
        if not fields[1].startswith(PEBBLE_NAME):
            continue
        times.append(float(fields[0]))
        names.append(fields[1])
        rows.append([float(v) for v in fields[2:8]])
    return np.array(times), np.array(names), np.array(rows)


def steady_rate(t, mass, low=0.2, high=0.8):
    """Mass rate [kg/s] from a linear fit of the cumulative mass between
    the given fractions of its final value (the steady part)."""
    if len(t) < 5:
        return float("nan")
    keep = (mass >= low*mass[-1]) & (mass <= high*mass[-1])
    if keep.sum() < 3:
        return float("nan")
    return float(np.polyfit(t[keep], mass[keep], 1)[0])


def window_rate(t, mass, start, end):
    """Mass rate [kg/s] from a linear fit of the cumulative mass within
    [start, end]."""
    keep = (t >= start) & (t <= end)
    if keep.sum() < 3:
        return float("nan")
    return float(np.polyfit(t[keep], mass[keep], 1)[0])


def bed_crossings(times, names, rows, z_section, mass):
    """Times at which pebbles first cross the section z_section upward, and
    the cumulative mass through it."""
    above = rows[:, 2] > z_section
    above_names, index = np.unique(names[above], return_inverse=True)
    first_above = np.full(len(above_names), np.inf)
    np.minimum.at(first_above, index, times[above])
    start = np.isin(above_names, names[(times == times.min()) & above])
    crossed = np.sort(first_above[~start])
    return crossed, mass*np.arange(1, len(crossed) + 1)


def bed_bottom(times, names, rows, radius):
    """The lowest pebble centre in the central cylinder of the given radius
    at each history time."""
    central = rows[:, 0]**2 + rows[:, 1]**2 < radius**2
    out_t, index = np.unique(times[central], return_inverse=True)
    out_z = np.full(len(out_t), np.inf)
    np.minimum.at(out_z, index, rows[central, 2])
    return out_t, out_z


def velocity_profile(times, rows, time, z_low, z_high, edges):
    """Mean vertical velocity of the pebbles in radial bins of a slab of the
    bed at the history time nearest the given one."""
    nearest = times[np.argmin(np.abs(times - time))]
    at = (times == nearest) & (rows[:, 2] > z_low) & (rows[:, 2] < z_high)
    radius = np.hypot(rows[at, 0], rows[at, 1])
    uz = rows[at, 5]
    means = [uz[(radius >= a) & (radius < b)].mean() if ((radius >= a) & (radius < b)).any()
             else np.nan for a, b in zip(edges[:-1], edges[1:])]
    return nearest, 0.5*(edges[:-1] + edges[1:]), np.array(means)


def summary(case_dir):
    """The discharge's figures of a case (pimpleDLMFoam or dlmDEMFoam): a
    dict of the fluxes, their balance, the bed bottom's rise and the series
    for the plots."""
    pebble_history = history(case_dir)
    if not len(pebble_history[0]):
        raise SystemExit(f"{case_dir}: no pebble history (postProcessing/particles/"
                         "*/particles.dat): has the case run?")
    return summary_of(geometry(case_dir), outlet_record(case_dir), pebble_history)


def departures(times, names, mass):
    """The outlet record of a history in which a pebble that left is no
    longer listed: the first history time without it, and the cumulative
    mass (LIGGGHTS' lost atoms)."""
    sampled = np.unique(times)
    _, index = np.unique(names, return_inverse=True)
    last = np.full(index.max() + 1, -np.inf)
    np.maximum.at(last, index, times)
    left = np.sort(sampled[np.searchsorted(sampled, last[last < sampled[-1]]) + 1])
    return left, mass*np.arange(1, len(left) + 1)


def summary_of(g, outlet, pebble_history):
    """The discharge's figures from the geometry, the outlet record (times,
    cumulative mass) and the pebble history (times, names, rows x y z u v
    w)."""
    d, R, r = g["d"], g["R"], g["r"]
    mass = PEBBLE_DENSITY*np.pi*d**3/6
    t_out, m_out = outlet
    times, names, rows = pebble_history
    # The bed section: two diameters below the cone, in the reservoir
    z_section = g["coneBase"] - 2*d
    t_bed, m_bed = bed_crossings(times, names, rows, z_section, mass)
    chute_rate = steady_rate(t_out, m_out)
    bed_rate = steady_rate(t_bed, m_bed)
    # The balance over the time both flow: from the first pebble out of
    # the chute to the last through the bed section (the bed's bottom
    # passes it), as the rate changes over the discharge
    # and the pebbles counted: in through the section, out of the chute and
    # held between them at both ends (the region between need not be
    # steady: it empties as the bed above the section dilates)
    counts = None
    if len(t_out) and len(t_bed):
        start, end = t_out[0], t_bed[-1]
        balance = window_rate(t_bed, m_bed, start, end)/window_rate(t_out, m_out, start, end) - 1

        def between(time):
            at = times == times[np.argmin(np.abs(times - time))]
            z = rows[at, 2]
            return int(((z > z_section) & (z < g["outletZ"])).sum())

        counts = (int(((t_bed > start) & (t_bed <= end)).sum()),
                  int(((t_out > start) & (t_out <= end)).sum()),
                  between(start), between(end))
    else:
        start = end = balance = float("nan")
    bottom_t, bottom_z = bed_bottom(times, names, rows, r)
    profile = velocity_profile(times, rows, 0.5, z_section - 2*d, z_section,
                               np.linspace(0, R, 6))
    return {
        "chute_area": np.pi*r**2, "bed_area": np.pi*R**2,
        "chute_flux": chute_rate/(np.pi*r**2), "bed_flux": bed_rate/(np.pi*R**2),
        "chute_rate": chute_rate, "bed_rate": bed_rate, "z_section": z_section,
        "balance": balance, "balance_window": (start, end), "counts": counts,
        "left": len(t_out), "t_out": t_out, "m_out": m_out, "t_bed": t_bed, "m_bed": m_bed,
        "bottom_t": bottom_t, "bottom_z": bottom_z, "profile": profile,
    }


def plot(results, output, labels=None):
    """Discharged mass, bed bottom and early velocity profile of one or more
    runs (results: a list of summary dicts)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    labels = labels or [""]*len(results)
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.5))
    for s, label in zip(results, labels):
        line, = axes[0].plot(s["t_out"], s["m_out"], label=f"chute {label}".strip())
        axes[0].plot(s["t_bed"], s["m_bed"], "--", color=line.get_color(),
                     label=f"bed section {label}".strip())
        axes[1].plot(s["bottom_t"], s["bottom_z"], color=line.get_color(),
                     label=label or "pimpleDLMFoam")
        t, centres, means = s["profile"]
        axes[2].plot(centres, means, "o-", color=line.get_color(),
                     label=f"t = {t:.2f} s {label}".strip())
    axes[0].set(xlabel="t [s]", ylabel="pebble mass through [kg]",
                title="Pebble mass through the chute's end and a bed section")
    axes[1].set(xlabel="t [s]", ylabel="z [m]",
                title="Bed bottom (lowest pebble, central cylinder r = 51 mm)")
    axes[2].axhline(0, color="0.6", lw=0.8)
    axes[2].set(xlabel="radius [m]", ylabel="mean u_z [m/s]",
                title="Pebble velocity across the bed, early")
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(output, dpi=120)
    plt.close(fig)


def report(case_dir, s):
    """The lines printed about a run."""
    start, end = s["balance_window"]
    area_ratio = PAPER_BED_AREA/s["bed_area"]
    paper_bed = (f" with {area_ratio:.1f} times this bed's area"
                 if abs(area_ratio - 1) > 0.01 else "")
    return [
        f"Pebble discharge ({case_dir}): {s['left']} pebbles left",
        f"  chute flux {s['chute_flux']:.1f} kg/(m2 s) (paper, full scene: "
        f"{PAPER_CHUTE_FLUX:.0f}), rate {s['chute_rate']:.3f} kg/s",
        f"  bed flux   {s['bed_flux']:.1f} kg/(m2 s) through z = {s['z_section']:.3f} m"
        f" (paper, full scene{paper_bed}: {PAPER_BED_FLUX:.0f}), rate {s['bed_rate']:.3f} kg/s",
        f"  mass balance: bed rate {100*s['balance']:+.1f} % of the chute's over"
        f" {start:.2f} to {end:.2f} s, when both flow",
    ] + ([
        f"  pebbles over that time: {s['counts'][0]} in through the section,"
        f" {s['counts'][1]} out of the chute, {s['counts'][2]} -> {s['counts'][3]}"
        f" between them (residual {s['counts'][0] - s['counts'][1] - s['counts'][3] + s['counts'][2]:+d},"
        f" from the history's sampling)",
    ] if s["counts"] else [])
