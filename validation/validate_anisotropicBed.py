#!/usr/bin/env python3
"""Anisotropic beds, the DLM paper's section 3.2 and appendix: from a
random packing of porosity 36 % (106 spheres of radius 0.11283 m in a
periodic cube of side 1 m, dlmPackSpheres), spheres are removed from a band
0.3 m wide until the bed holds as many as a uniform packing of porosity
42 % (10 of 106), which leaves the band near 56 %:

- configuration 1: the band along the flow (x), across y: the layers
  (0.7 m at 36 %, 0.3 m at 56 %) are in parallel;
- configuration 2: the band across the flow: the layers are in series.

Both are compared with uniform random packings of porosity 42 % and 36 %,
all driven to the superficial velocity u = 0.008 m/s along x by
meanVelocityForce (tutorials/randomBed), and with Ergun's estimates for
each layer structure (reference README section 5): in parallel the layers
share the pressure gradient and split the flow, u = 0.7 u1 + 0.3 u2; in
series they share the velocity and add their pressure drops. The layer
porosities are those of the packings (exact sphere-slab volumes).

The fluid is the same in every bed: rho 1000 kg/m^3 and the viscosity that
gives Re = D u/(nu (1 - eps)) = 100 in the uniform 42 % bed, where Ergun's
viscous and inertial terms are comparable. Each run reports the pressure
drop over the 1 m bed (the particles' drag per unit volume, averaged over
the last quarter of the run) divided by the density, as the paper does,
and its wall time. Rows are merged into results/anisotropicBed.csv;
results/anisotropicBed.png plots the pressure drops against resolution
beside the Ergun estimates, their ratios to the uniform 42 % bed and the
difference from Ergun against wall time. For the layered beds each layer's
flow and pressure drop from the final fields, against Ergun at the layer's
porosity, go to results/anisotropicBed_layers.csv.

    validation/validate_anisotropicBed.py [--end-time 80] [--beds a,b] [--width 1] [N ...]
        (default N = 8 12 16, all four beds; --beds runs some of them, so
        that two calls can share the cores; --width W: the box W m wide
        along y, across the parallel bed's band, which is then 0.3 W wide,
        every bed packed at the same solid fractions in that box; runs and
        tables as anisotropicBed_width<W>)
"""

import argparse
import math
import os
import re
import shutil

import numpy as np

from common import (Case, RESULTS, ROOT, RUNS, foam_environment, merge_row,
                    packed_bed_rows, plot_speed_error, richardson, stored_rows,
                    timed_run)

HEADER = ["bed", "cellsPerDiameter", "porosity", "pressureDrop_m2s2",
          "ergun_m2s2", "relDiffErgun", "drift", "wallTime_s", "steps"]
LAYERS_HEADER = ["bed", "cellsPerDiameter", "layer", "porosity",
                 "superficialVelocity", "pressureDrop_m2s2", "ergun_m2s2",
                 "relDiffErgun"]

RADIUS, D, U, L, RHO = 0.11283, 2*0.11283, 0.008, 1.0, 1000.0
NU = D*U/(100*(1 - 0.42))
BAND = (0.7, 1.0)           # the depleted band, as fractions of the box's side
BEDS = ["uniform36", "uniform42", "parallel", "series"]


class Box:
    """The periodic box: L along x and z, a whole number of metres wide
    along y (across the parallel bed's band); names its runs and tables."""

    def __init__(self, width):
        self.width = width
        self.extent = (L, width, L)
        self.volume = L*width*L
        self.name = "anisotropicBed" + ("" if width == 1 else f"_width{width}")

    def band(self, axis):
        return BAND[0]*self.extent[axis], BAND[1]*self.extent[axis]

    def cross_section(self, axis):
        """Area of the box normal to the axis."""
        return self.volume/self.extent[axis]

    def run_path(self, bed, n):
        """The run of a bed at n cells per diameter."""
        prefix = "anisotropic" if self.width == 1 else self.name
        return RUNS / f"{prefix}_{bed}_{n}"


def ergun_gradient(eps, u):
    """Ergun's pressure gradient over the density [m/s^2]."""
    return (150*NU*(1 - eps)**2*u/(eps**3*D**2)
            + 1.75*(1 - eps)*u**2/(eps**3*D))


def slab_volume(centres, axis, lower, upper, period):
    """Volume of the spheres inside lower <= x[axis] < upper, periodic with
    the period (spherical caps)."""
    def below(h):
        # Volume of a sphere below a plane at height h above its centre
        h = np.clip(h, -RADIUS, RADIUS)
        cap = math.pi*(RADIUS - h)**2*(2*RADIUS + h)/3
        return 4/3*math.pi*RADIUS**3 - cap

    total = 0.0
    for shift in (-period, 0.0, period):
        c = centres[:, axis] + shift
        total += np.sum(below(upper - c) - below(lower - c))
    return total


def pack(fraction, box, env):
    """A periodic random packing of the box at the solid fraction (seed 1):
    centres. Packed in a folder of this call's own, as calls may run
    together."""
    case = Case.copy(ROOT / "tutorials" / "randomBed",
                     RUNS / f"pack_{fraction:g}_{os.getpid()}", env)
    settings = case.path / "system" / "packSpheresDict"
    text = re.sub(r"^solidFraction .*$", f"solidFraction   {fraction};",
                  settings.read_text(), flags=re.M)
    text = re.sub(r"^box .*$", "box             (0 0 0) ({:g} {:g} {:g});".format(*box.extent),
                  text, flags=re.M)
    settings.write_text(text)
    case.run("dlmPackSpheres")
    centres = np.loadtxt(case.path / "constant" / "packing.dat", comments="#")[:, :3]
    shutil.rmtree(case.path)
    return centres


def deplete(centres, axis, count, box):
    """Remove spheres centred in the band, in a seeded random order, until
    count are left."""
    rng = np.random.default_rng(1)
    lower, upper = box.band(axis)
    in_band = np.flatnonzero((centres[:, axis] >= lower) & (centres[:, axis] < upper))
    keep = np.ones(len(centres), bool)
    keep[rng.permutation(in_band)[:len(centres) - count]] = False
    return centres[keep]


def ergun_velocity(eps, gradient):
    """The superficial velocity at which Ergun's gradient over the density
    is the given one: the positive root of a u + b u^2 = gradient."""
    a = 150*NU*(1 - eps)**2/(eps**3*D**2)
    b = 1.75*(1 - eps)/(eps**3*D)
    return 2*gradient/(a + math.sqrt(a*a + 4*b*gradient))


def layered_ergun(centres, axis, series, box):
    """Ergun's estimate for the two layers of the bed: the band and the
    rest, with their porosities from the packing (the gradient along x)."""
    lower, upper = box.band(axis)
    period, area = box.extent[axis], box.cross_section(axis)
    eps2 = 1 - slab_volume(centres, axis, lower, upper, period)/((upper - lower)*area)
    eps1 = 1 - slab_volume(centres, axis, 0, lower, period)/(lower*area)
    if series:
        return (BAND[0]*ergun_gradient(eps1, U)
                + (BAND[1] - BAND[0])*ergun_gradient(eps2, U))
    # Parallel: the same gradient in both layers, whose flows add up to U;
    # bisect on the gradient (the flow grows with it)
    lo, hi = 0.0, ergun_gradient(min(eps1, eps2), U)
    for _ in range(200):
        gradient = 0.5*(lo + hi)
        flow = BAND[0]*ergun_velocity(eps1, gradient) \
            + (BAND[1] - BAND[0])*ergun_velocity(eps2, gradient)
        lo, hi = (gradient, hi) if flow < U else (lo, gradient)
    return 0.5*(lo + hi)


def beds(box, env):
    """Particle centres and the Ergun estimate of each bed."""
    dense = pack(0.64, box, env)
    loose = pack(0.58, box, env)
    # As many spheres as the uniform 42 % bed: the same porosity
    parallel = deplete(dense, 1, len(loose), box)
    series = deplete(dense, 0, len(loose), box)
    volume = 4/3*math.pi*RADIUS**3
    return {
        "uniform36": (dense, ergun_gradient(1 - len(dense)*volume/box.volume, U)*L),
        "uniform42": (loose, ergun_gradient(1 - len(loose)*volume/box.volume, U)*L),
        "parallel": (parallel, layered_ergun(parallel, 1, False, box)*L),
        "series": (series, layered_ergun(series, 0, True, box)*L),
    }


def layer_rows(name, case, centres, end_time, box):
    """Each layer's superficial velocity and pressure drop from the final
    fields, against Ergun for that layer's porosity: in parallel the drop is
    the bed's (the layers share it) and Ergun's is the one the layer's own
    flow needs; in series the velocity is the bed's and the drop is the
    layer's own (the driving body force over the layer plus the difference
    of the mean fluid pressure at its ends)."""
    axis = 1 if name == "parallel" else 0
    time = f"{end_time:g}"
    solid = case.internal_field(f"{time}/alpha.solid")
    n = round((len(solid)/box.width) ** (1/3))
    # blockMesh numbers the cells x fastest: index [z, y, x], so the
    # coordinate axis a is the array's axis 2 - a
    shape = (n, n*box.width, n)
    fluid = 1 - solid.reshape(shape)
    ux = case.internal_field(f"{time}/U")[:, 0].reshape(shape)
    p = case.internal_field(f"{time}/p").reshape(shape)
    across = tuple(a for a in (0, 1, 2) if a != 2 - axis)
    period, area = box.extent[axis], box.cross_section(axis)
    cells_along = shape[2 - axis]
    centre = (np.arange(cells_along) + 0.5)/cells_along*period
    band = box.band(axis)
    in_band = (centre >= band[0]) & (centre < band[1])
    gradient = packed_bed_rows(case.path)[-1, 3]/RHO
    rows = []
    for layer, lower, upper, cells in (("band", *band, in_band),
                                       ("rest", 0.0, band[0], ~in_band)):
        width = upper - lower
        eps = 1 - slab_volume(centres, axis, lower, upper, period)/(width*area)
        if axis == 1:
            u = ux.mean(axis=across)[cells].mean()
            drop, ergun = gradient*L, ergun_gradient(eps, u)*L
        else:
            u = U
            mean_p = (p*fluid).sum(axis=across)/fluid.sum(axis=across)/RHO

            def pressure(x):
                periodic = np.r_[centre - period, centre, centre + period]
                return np.interp(x, periodic, np.tile(mean_p, 3))

            drop = gradient*width + pressure(lower) - pressure(upper)
            ergun = ergun_gradient(eps, u)*width
        rows.append([name, None, layer, eps, u, drop, ergun, drop/ergun - 1])
    return rows


def run(name, centres, n, end_time, box, env):
    case = Case.copy(ROOT / "tutorials" / "randomBed", box.run_path(name, n), env)
    path = case.path
    with open(path / "constant" / "packing.dat", "w") as out:
        out.write(f"# {name}: {len(centres)} spheres\n")
        for c in centres:
            out.write(" ".join(repr(float(v)) for v in (*c, RADIUS)) + "\n")

    def substitute(relative, pattern, value):
        f = path / relative
        f.write_text(re.sub(pattern, value, f.read_text(), flags=re.M))

    substitute("constant/transportProperties", r"^nu .*$", f"nu              {NU:.8g};")
    substitute("system/blockMeshDict", r"^n .*$", f"n   {round(n*L/D)};")
    if box.width != 1:
        # The box W wide along y: the vertices' y and its cell count
        substitute("system/blockMeshDict", r"^L .*$", f"L   {L:g};\nW   {box.width};")
        substitute("system/blockMeshDict", r"\(\$L \$L (0|\$L)\)", r"($L $W \1)")
        substitute("system/blockMeshDict", r"\(0 \$L (0|\$L)\)", r"(0 $W \1)")
        substitute("system/blockMeshDict", r"\(\$n \$n \$n\)",
                   f"($n {round(n*L/D)*box.width} $n)")
    substitute("system/controlDict", r"^endTime .*$", f"endTime         {end_time:g};")
    substitute("system/controlDict", r"^writeInterval .*$", f"writeInterval   {end_time:g};")
    case.run("blockMesh")
    seconds = timed_run(case, "pimpleDLMFoam")
    log = (path / "log.pimpleDLMFoam").read_text()
    steps = len(re.findall(r"^Time = ", log, re.M))
    rows = packed_bed_rows(path)
    window = rows[rows[:, 0] >= 0.75*rows[-1, 0], 3]/RHO*L
    return rows[-1, 2], window.mean(), (window.max() - window.min())/window.mean(), \
        seconds, steps


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--end-time", type=float, default=80)
    parser.add_argument("--beds", default=",".join(BEDS),
                        help="comma-separated subset of " + ", ".join(BEDS))
    parser.add_argument("--width", type=int, default=1,
                        help="the box's width along y [m], a whole number")
    parser.add_argument("resolutions", nargs="*", type=int, default=[8, 12, 16])
    args = parser.parse_args()
    chosen = args.beds.split(",")
    unknown = sorted(set(chosen) - set(BEDS))
    if unknown:
        parser.error(f"unknown bed {', '.join(unknown)}: choose from {', '.join(BEDS)}")

    env = foam_environment()
    RESULTS.mkdir(parents=True, exist_ok=True)
    box = Box(args.width)
    table, layers = RESULTS / f"{box.name}.csv", RESULTS / f"{box.name}_layers.csv"
    packings = beds(box, env)
    for name in BEDS:
        centres, estimate = packings[name]
        print(f"{name}: {len(centres)} spheres, Ergun estimate {estimate:.5f} m^2/s^2",
              flush=True)
    for n in args.resolutions:
        for name in (b for b in BEDS if b in chosen):
            centres, estimate = packings[name]
            eps, drop, drift, seconds, steps = run(name, centres, n, args.end_time,
                                                   box, env)
            merge_row(table, HEADER,
                      [name, n, eps, drop, estimate, drop/estimate - 1, drift,
                       seconds, steps],
                      sort_key=lambda r: (BEDS.index(r[0]), r[1]))
            print(f"{name:10s} N={n:3d} porosity={eps:.4f} dp/rho={drop:.5f} m^2/s^2 "
                  f"Ergun {estimate:.5f} ({100*(drop/estimate - 1):+.1f}%) "
                  f"drift={100*drift:.2f}% wall={seconds:.0f}s steps={steps}", flush=True)
            if name in ("parallel", "series"):
                for row in layer_rows(name, Case(box.run_path(name, n), env),
                                      centres, args.end_time, box):
                    row[1] = n
                    merge_row(layers, LAYERS_HEADER, row, key_columns=3,
                              sort_key=lambda r: (r[0], r[1], r[2]))
                    print(f"  {row[2]:4s} porosity={row[3]:.4f} u={row[4]:.5f} m/s "
                          f"dp/rho={row[5]:.5f} Ergun {row[6]:.5f} ({100*row[7]:+.1f}%)",
                          flush=True)
    summarise(box)


def summarise(box):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = stored_rows(RESULTS / f"{box.name}.csv")
    fig, axes = plt.subplots(1, 3, figsize=(16, 4))
    series = {}
    for k, name in enumerate(BEDS):
        sel = sorted((r for r in rows if r[0] == name), key=lambda r: r[1])
        if not sel:
            continue
        n = np.array([r[1] for r in sel])
        drop = np.array([r[3] for r in sel])
        order, extrapolate = richardson(n, drop)
        print(f"{name}: {', '.join(f'{v:.5f}' for v in drop)} at N = "
              f"{', '.join(str(int(v)) for v in n)}; observed order {order:.2f}, "
              f"extrapolate {extrapolate:.5f} (Ergun {sel[-1][4]:.5f}, "
              f"{100*(extrapolate/sel[-1][4] - 1):+.1f}%)")
        axes[0].plot(n, drop, "o-", color=f"C{k}", label=f"{name} (order {order:.2f})")
        axes[0].axhline(sel[-1][4], ls="--", lw=0.8, color=f"C{k}")
        axes[1].plot(n, [r[3]/next(q[3] for q in rows if q[0] == "uniform42"
                                     and q[1] == r[1]) for r in sel],
                     "o-", color=f"C{k}", label=name)
        series[f"{name}, against Ergun"] = [(r[7], abs(r[5]), int(r[1])) for r in sel]
    axes[0].set_xlabel("cells per diameter")
    axes[0].set_ylabel("pressure drop / density [m^2/s^2]")
    axes[0].set_title("Anisotropic beds (dashed: Ergun estimates)")
    axes[0].legend(fontsize=7)
    axes[1].set_xlabel("cells per diameter")
    axes[1].set_ylabel("pressure drop / uniform 42 %")
    axes[1].set_title("Relative to the uniform 42 % bed")
    axes[1].legend(fontsize=7)
    plot_speed_error(axes[2], series)
    axes[2].set_title("Difference from Ergun against wall time")
    fig.tight_layout()
    fig.savefig(RESULTS / f"{box.name}.png", dpi=120)


if __name__ == "__main__":
    main()
