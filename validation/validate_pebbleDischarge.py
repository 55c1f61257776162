#!/usr/bin/env python3
"""The paper's pebble discharge in water (section 3.4) through
tutorials/pebbleDischarge: the reduced scene (250 pebbles, a reservoir of
half the paper's diameter) or the full one (2500 pebbles, 406 mm), at
chosen resolutions. Each run: the pebbles that left, the chute and bed mass
fluxes against the paper's (about 60 and 4 kg/(m2 s) in the full scene),
their mass balance and the wall time, appended to
results/pebbleDischarge.csv; the plot of each run (discharged mass, bed
bottom, velocity across the bed) in
results/pebbleDischarge_<scene>_<N>_e<e>_k<factor>.png.

    validation/validate_pebbleDischarge.py [--scene reduced|full]
        [--end-time T] [--np 1] [--restitution e] [--stiffness-factor f]
        [N ...]           (default reduced, 6 s, N = 4, e 0.8, f 0.01)

The paper's studies: its damping coefficients 0, 0.07 and 0.7 (of the
critical damping; restitution exp(-pi z/sqrt(1 - z^2)) of a linear spring:
1, 0.80 and 0.046) and stiffness factors from 1e-4 to 1e-1 (the stiffness
over 2.85e11 N/m3, the Hertzian value at an overlap of 1 % of d).

The full scene's discharge lasts about 35 s: at N = 4 (370 000 cells) a
few hours on 2 cores; --end-time gives its early rate sooner.
"""

import argparse
import re
import shutil
import subprocess
import time

from common import RESULTS, ROOT, RUNS, foam_environment, merge_row
import pebbleDischarge

# The full scene: the paper's reservoir (406 mm) with the same opening and
# cone; the reservoir's cylinder tall enough for the fill's lattice of 2500
FULL = {"R": 0.203, "coneBase": 0.39, "coneTop": 0.542, "outletZ": 0.642,
        "lidZ": 0.667}
PEBBLES = {"reduced": 250, "full": 2500}
# The overlap-volume stiffness at stiffness factor 1 (constant/particleProperties)
HERTZ_STIFFNESS = 2.85e11
HEADER = ["scene", "cellsPerDiameter", "restitution", "stiffnessFactor", "pebbles",
          "endTime", "left", "chuteFlux", "bedFlux", "balance", "wallTime"]


def make_case(scene, n, restitution, factor):
    case = RUNS / f"pebbleDischarge_{scene}_{n}_e{restitution:g}_k{factor:g}"
    if case.exists():
        shutil.rmtree(case)
    shutil.copytree(ROOT / "tutorials" / "pebbleDischarge", case,
                    ignore=shutil.ignore_patterns("log.*", "processor*", "postProcessing",
                                                  "VTK", "polyMesh", "[1-9]*", "0.[0-9]*",
                                                  "*.Allrun", "pebbleBed.dat",
                                                  "lattice.dat", "render"))
    if scene == "full":
        geometry = case / "constant/geometry"
        text = geometry.read_text()
        for key, value in FULL.items():
            text = re.sub(rf"^({key}\s+)[^;]*;", rf"\g<1>{value};", text, flags=re.M)
        geometry.write_text(text)
    props = case / "constant/particleProperties"
    text = props.read_text()
    text = re.sub(r"^(\s+restitution\s+)[^;]*;", rf"\g<1>{restitution};", text, flags=re.M)
    text = re.sub(r"^(\s+stiffness\s+)[^;]*;", rf"\g<1>{factor*HERTZ_STIFFNESS:.6g};",
                  text, flags=re.M)
    props.write_text(text)
    return case


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--scene", choices=PEBBLES, default="reduced")
    parser.add_argument("--end-time", type=float, default=6)
    parser.add_argument("--np", type=int, default=1)
    parser.add_argument("--restitution", type=float, default=0.8)
    parser.add_argument("--stiffness-factor", type=float, default=0.01)
    parser.add_argument("resolutions", nargs="*", type=int, default=[4])
    args = parser.parse_args()
    env = foam_environment()
    for n in args.resolutions:
        case = make_case(args.scene, n, args.restitution, args.stiffness_factor)
        label = f"{args.scene}, N = {n}, e = {args.restitution:g}, factor {args.stiffness_factor:g}"
        start = time.perf_counter()
        result = subprocess.run(
            [str(case / "Allrun"), str(n), str(args.np), str(args.end_time),
             str(PEBBLES[args.scene])], env=env, capture_output=True, text=True)
        wall = time.perf_counter() - start
        if result.returncode != 0:
            raise SystemExit(f"{case}: Allrun failed\n{result.stdout}{result.stderr}")
        s = pebbleDischarge.summary(case)
        pebbleDischarge.plot([s], RESULTS / f"{case.name}.png", [label])
        print("\n".join(pebbleDischarge.report(case, s)))
        print(f"  wall time  {wall:.0f} s (Allrun: mesh, fill, discharge)")
        balance = s["balance"]
        merge_row(RESULTS / "pebbleDischarge.csv", HEADER,
                  [args.scene, n, args.restitution, args.stiffness_factor,
             PEBBLES[args.scene], args.end_time, s["left"],
                   f"{s['chute_flux']:.2f}", f"{s['bed_flux']:.2f}", f"{balance:.4f}",
                   f"{wall:.0f}"], key_columns=4)


if __name__ == "__main__":
    main()
