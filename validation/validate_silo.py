#!/usr/bin/env python3
"""Dry silo discharge, cross-checked with LIGGGHTS: the scene of
validation/liggghts/scenes.py (2500 spheres d = 4 mm in a 60 x 60 mm square
silo, circular orifice D0 = 7 d in the flat floor, linear spring-dashpot
with tangential history, e = 0.5, mu = 0.5), from the packing LIGGGHTS
settled (validation/liggghts/silo_packing.dat), run by dlmDEMFoam with the
same contact constants (law linearSpringDashpot, kt/kn = 2/7, gamma_t =
gamma_n, the normal force clipped or not as LIGGGHTS' limitForce, and by
default the Coulomb limit on the spring alone as LIGGGHTS' history model:
frictionLimit spring; walls: four planes and the STL floor with the hole). Discharge rate
from a linear fit of the discharged mass between the same fractions of the
charge as the LIGGGHTS script, against LIGGGHTS and Beverloo. Writes
results/silo.csv (discharged mass against time), results/silo_summary.csv
and results/silo.png.

    validation/liggghts/run_liggghts.py silo       # first: LIGGGHTS side
    validation/validate_silo.py [--friction-limit spring|total] [endTime]   (0.8 s)
    validation/validate_silo.py --ensemble K [--friction-limit ...] [endTime]

One discharge is one realisation of a chaotic flow, so --ensemble compares
the codes' mean rates over K packings: the committed one and K - 1 fresh
LIGGGHTS fills with other insertion seeds, each discharged by both codes
(LIGGGHTS for endTime only), into results/silo_ensemble_<limit>Limit.csv.
"""

import argparse
import csv
import sys

import numpy as np

from common import RESULTS, ROOT, RUNS, Case, foam_environment, timed_run, write_table

sys.path.insert(0, str(ROOT / "validation" / "liggghts"))
from floor_stl import plate_with_hole, write_stl   # noqa: E402
from scenes import (DENSITY, FRICTION, KN, KT, LIMIT_FORCE, MASS, SILO,  # noqa: E402
                    TANGENTIAL_DAMPING_RATIO, beverloo)
from run_liggghts import RUNS as LIGGGHTS_RUNS  # noqa: E402
from run_liggghts import prime_seeds, silo_rate, silo_run  # noqa: E402

HEADER = "FoamFile {{ version 2.0; format ascii; class {cls}; object {obj}; }}\n"
DT = 1e-4                   # fluid step; the contacts sub-cycle within it
HISTORY_EVERY = 20          # steps between history lines (2 ms)


def write(path, cls, obj, body):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(HEADER.format(cls=cls, obj=obj) + body)


def make_case(env, end_time, packing, name, friction_limit):
    case = Case.copy(ROOT / "tests" / "cases" / "dryBox", RUNS / name, env)
    w = SILO["width"]/2
    write(case.path / "system/blockMeshDict", "dictionary", "blockMeshDict", f"""
vertices ((-{w} -{w} -0.5) ({w} -{w} -0.5) ({w} {w} -0.5) (-{w} {w} -0.5)
          (-{w} -{w} 0.2) ({w} -{w} 0.2) ({w} {w} 0.2) (-{w} {w} 0.2));
blocks (hex (0 1 2 3 4 5 6 7) (2 2 4) simpleGrading (1 1 1));
boundary ( sides {{ type patch; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); }} );
""")
    (case.path / "constant/triSurface").mkdir(parents=True, exist_ok=True)
    write_stl(case.path / "constant/triSurface/floor.stl",
              plate_with_hole(SILO["width"], SILO["orifice"], SILO["orifice_segments"]))
    np.savetxt(case.path / "constant/packing.dat", packing, fmt="%.9e")
    law = f"""law linearSpringDashpot; stiffness {KN}; restitution {SILO['e']};
            friction {FRICTION}; tangential spring; frictionLimit {friction_limit};
            tangentialStiffnessRatio {KT/KN!r}; tangentialDampingRatio {TANGENTIAL_DAMPING_RATIO};
            clipNormalForce {'true' if LIMIT_FORCE else 'false'};"""
    walls = "\n".join(
        f"        {name} {{ type plane; point ({px} {py} 0); normal ({nx} {ny} 0); }}"
        for name, px, py, nx, ny in (("xMin", -w, 0, 1, 0), ("xMax", w, 0, -1, 0),
                                     ("yMin", 0, -w, 0, 1), ("yMax", 0, w, 0, -1)))
    write(case.path / "constant/particleProperties", "dictionary", "particleProperties", f"""
historyInterval {HISTORY_EVERY};
particleFile "constant/packing.dat";
particleFileDefaults {{ shape sphere; density {DENSITY}; }}
contact
{{
    meshWalls false;
    pairs
    {{
        particles {{ materials (particle particle); {law} }}
        walls     {{ materials (particle wall); {law} }}
    }}
    walls
    {{
{walls}
        floor {{ type surface; file "floor.stl"; }}
    }}
}}
// The spheres that fell out leave before the mesh's bottom (z = -0.5)
outlets
{{
    below {{ type plane; point (0 0 -0.4); normal (0 0 -1); }}
}}
""")
    write(case.path / "constant/g", "uniformDimensionedVectorField", "g",
          "dimensions [0 1 -2 0 0 0 0];\nvalue (0 0 -9.81);\n")
    case.run("blockMesh")
    case.set("system/controlDict", "deltaT", DT)
    case.set("system/controlDict", "endTime", end_time)
    case.set("system/controlDict", "writeInterval", 100000)
    return case, len(packing)


def fit_rate(t, mass, m0, m1):
    sel = (mass >= m0) & (mass <= m1)
    return np.polyfit(t[sel], mass[sel], 1)[0]


def discharge(env, end_time, packing, name="silo", friction_limit="spring"):
    """dlmDEMFoam on the packing: discharged mass against time, the rate,
    the wall time and the case. friction_limit: what the Coulomb limit
    bounds, the spring alone as LIGGGHTS' history model (sticking contacts
    add their damping on top), or the total force (our default)."""
    case, n = make_case(env, end_time, packing, name, friction_limit)
    seconds = timed_run(case, "dlmDEMFoam")
    history = case.history()
    # A sphere is out from its first history time below the floor (it
    # falls on, through the outlet at z = -0.4 m, which ends its history)
    times = max((h[:, 0] for h in history.values()), key=len)
    first_below = [h[h[:, 3] < 0, 0].min() for h in history.values() if (h[:, 3] < 0).any()]
    below = np.searchsorted(np.sort(first_below), times, side="right")
    t = np.concatenate([[0.0], times])
    mass = np.concatenate([[0.0], below*MASS])
    charge = n*MASS
    lo, hi = SILO["fit_window"]
    return t, mass, fit_rate(t, mass, lo*charge, hi*charge), seconds, case


def ensemble(env, end_time, members, friction_limit):
    """Member 0 is the committed packing (LIGGGHTS' rate from its summary);
    members 1.. are fresh LIGGGHTS fills with other insertion seeds, each
    discharged by both codes. A single discharge is one realisation of a
    chaotic flow: the codes are compared by their mean rates."""
    summary = dict(zip(*csv.reader(open(RESULTS / "liggghts_silo_summary.csv"))))
    rows = []
    for k in range(members):
        if k == 0:
            packing = np.loadtxt(ROOT / "validation/liggghts/silo_packing.dat")
            theirs = float(summary["discharge_rate_kg_s"])
        else:
            xyzr, tl, ml, _ = silo_run(LIGGGHTS_RUNS / f"silo_{k}", prime_seeds(k), end_time)
            packing, theirs = xyzr, silo_rate(tl, ml, len(xyzr))
        ours = discharge(env, end_time, packing, f"silo_{k}", friction_limit)[2]
        rows.append([k, theirs, ours, ours/theirs - 1])
        print(f"member {k}: LIGGGHTS {theirs:.4f}, dlmDEMFoam {ours:.4f} kg/s "
              f"({100*(ours/theirs - 1):+.1f} %)", flush=True)
    write_table(RESULTS / f"silo_ensemble_{friction_limit}Limit.csv",
                ["member", "LIGGGHTS_rate_kg_s", "dlmDEMFoam_rate_kg_s", "relative"], rows)
    rates = np.array(rows)[:, 1:3]
    mean, sem = rates.mean(axis=0), rates.std(axis=0, ddof=1)/np.sqrt(len(rows))
    difference = mean[1]/mean[0] - 1
    uncertainty = np.hypot(sem[0]/mean[0], sem[1]/mean[1])
    print(f"{len(rows)} packings: LIGGGHTS {mean[0]:.4f} +- {sem[0]:.4f}, dlmDEMFoam "
          f"{mean[1]:.4f} +- {sem[1]:.4f} kg/s (standard errors); means differ by "
          f"{100*difference:+.1f} +- {100*uncertainty:.1f} %; member-to-member scatter "
          f"{100*rates[:, 0].std(ddof=1)/mean[0]:.1f} % (LIGGGHTS), "
          f"{100*rates[:, 1].std(ddof=1)/mean[1]:.1f} % (dlmDEMFoam)")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("end_time", nargs="?", type=float, default=0.8)
    parser.add_argument("--friction-limit", choices=["spring", "total"], default="spring")
    parser.add_argument("--ensemble", type=int, default=0, metavar="K",
                        help="compare mean rates over K packings (the committed one "
                             "and K - 1 fresh LIGGGHTS fills)")
    args = parser.parse_args()
    end_time = args.end_time
    env = foam_environment()
    if args.ensemble:
        ensemble(env, end_time, args.ensemble, args.friction_limit)
        return
    t, mass, rate, seconds, case = discharge(
        env, end_time, np.loadtxt(ROOT / "validation/liggghts/silo_packing.dat"),
        friction_limit=args.friction_limit)

    summary_path = RESULTS / "liggghts_silo_summary.csv"
    liggghts = dict(zip(*csv.reader(open(summary_path)))) if summary_path.exists() else {}
    rho_bulk = float(liggghts["rho_bulk_kg_m3"]) if liggghts else float("nan")
    predicted = beverloo(rho_bulk, **SILO["beverloo"]) if liggghts else float("nan")
    rate_liggghts = float(liggghts.get("discharge_rate_kg_s", "nan"))

    log = (case.path / "log.dlmDEMFoam").read_text()
    sub_steps = sum(int(line.split(";")[1].split()[0])
                    for line in log.splitlines() if line.startswith("Contacts:"))
    write_table(RESULTS / "silo.csv", ["time_s", "discharged_mass_kg"],
                [[f"{a:.6g}", f"{b:.6e}"] for a, b in zip(t, mass)])
    write_table(RESULTS / "silo_summary.csv",
                ["code", "discharge_rate_kg_s", "relative_to_LIGGGHTS", "beverloo_kg_s",
                 "rate_over_beverloo", "wall_time_s", "steps"],
                [["pimpleDLMFoam/dlmDEMFoam", rate, rate/rate_liggghts - 1, predicted,
                  rate/predicted, seconds, sub_steps],
                 ["LIGGGHTS", rate_liggghts, 0, predicted, rate_liggghts/predicted,
                  float(liggghts.get("discharge_wall_s", "nan")),
                  float(liggghts.get("discharge_steps", "nan"))]])
    print(f"dlmDEMFoam: rate {rate:.4f} kg/s ({100*(rate/rate_liggghts - 1):+.1f} % against "
          f"LIGGGHTS {rate_liggghts:.4f}); Beverloo {predicted:.4f} kg/s; "
          f"wall {seconds:.0f} s, {sub_steps} sub-steps")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(t, 1000*mass, label="dlmDEMFoam")
    ligg = RESULTS / "liggghts_silo.csv"
    if ligg.exists():
        tl, ml = np.loadtxt(ligg, delimiter=",", skiprows=1, unpack=True)
        ax.plot(tl, 1000*ml, "--", label="LIGGGHTS")
    if liggghts:
        ax.plot(t, 1000*predicted*t, ":", label="Beverloo")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("discharged mass [g]")
    ax.set_xlim(0, end_time)
    ax.legend()
    fig.tight_layout()
    fig.savefig(RESULTS / "silo.png", dpi=120)


if __name__ == "__main__":
    main()
