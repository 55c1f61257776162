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
        [--medium wet|dry|both] [--liggghts] [--law overlapVolume|linear]
        [--end-time T] [--np 1] [--restitution e] [--stiffness-factor f]
        [--chute castellated|immersed] [--chute-length L]
        [--boundary-layer-slip] [--resume] [N ...]
        (default reduced, wet, overlapVolume, 6 s, N = 4, e 0.8, f 0.01,
         castellated, 4 pebble diameters, no-slip profiles)

--medium dry runs the same bed without water (the tutorial's Allrun.dry:
dlmDEMFoam under buoyancy-reduced gravity; its rows have cellsPerDiameter
0, as no fluid is resolved); both runs the wet case, then the dry one from
its bed, plotted together in results/pebbleDischarge_<...>_wetDry.png.
--liggghts adds the dry discharge of the same bed in LIGGGHTS (validation/
liggghts, the linear spring-dashpot with tangential history; rows of
medium dryLIGGGHTS, plotted with the dry run). --law linear sets our
contacts to the same linear spring-dashpot (linearSpringDashpot, with
LIGGGHTS' conventions, as the silo's cross-check), its stiffness per pair
the overlap-volume law's force at an overlap of 1 % of d over that overlap,
so that the two codes run the same physics.

The paper's studies: its damping coefficients 0, 0.07 and 0.7 (of the
critical damping; restitution exp(-pi z/sqrt(1 - z^2)) of a linear spring:
1, 0.80 and 0.046) and stiffness factors from 1e-4 to 1e-1 (the stiffness
over 2.85e11 N/m3, the Hertzian value at an overlap of 1 % of d).

The chute's wall for the water: castellated (the tutorial's: baffles on
the faces of box cells, half a cell outside the pebbles' contact surface
on average) or --chute immersed: a fixed particle, a tube of the same mean
inner radius and two cells thick given as a closed surface
(constant/triSurface/chuteTube.stl), held at rest by the projection like
any fixed particle, which the pebbles pass through for contacts (law none:
the contact-only chute keeps them off it).

--chute-length L: the chute from the opening to the particle outlet, in
pebble diameters (the tutorial's 4; the lid a diameter above its end). The
paper does not give it, and in water it sets the rate: 47.6 / 59.6 / 72.4
kg/(m2 s) at 4 / 8 / 12 d in the reduced scene at N = 4 (the stream in the
tube, lighter than the water around it, likely drives water up it and back
through the cone, an air-lift; validation/cases/pebbleDischarge.md).

--boundary-layer-slip sets the rigid projection's boundaryLayerSlip: a
pebble's viscous layer (about d/100 at its Reynolds number of several
thousand) is far thinner than a cell, and the profile cells' tangential
velocity then follows the flow beyond them (validate_risingPebble.py; a
coarse-mesh correction: it overshoots as the mesh refines).

The full scene's discharge lasts about 35 s: at N = 4 (370 000 cells) a
few hours on 2 cores; --end-time gives its early rate sooner. --resume
continues the wet run of an earlier call (same scene, N and parameters,
serial or on the ranks it was decomposed for) from its latest written time
to --end-time, so that a long discharge can run in parts (stop a part with
`stopAt writeNow;` in the case's system/controlDict: it writes and ends);
the wall time reported is then the solver's clock over all parts.
"""

import argparse
import math
import re
import shutil
import subprocess
import sys
import time

import numpy as np

from common import RESULTS, ROOT, RUNS, foam_environment, merge_row
import pebbleDischarge

sys.path.insert(0, str(ROOT / "validation" / "liggghts"))
import run_liggghts  # noqa: E402

# The full scene: the paper's reservoir (406 mm) with the same opening and
# cone; the reservoir's cylinder tall enough for the fill's lattice of 2500
FULL = {"R": 0.203, "coneBase": 0.39, "coneTop": 0.542, "outletZ": 0.642,
        "lidZ": 0.667}
PEBBLES = {"reduced": 250, "full": 2500}
# The overlap-volume stiffness at stiffness factor 1 (constant/particleProperties)
HERTZ_STIFFNESS = 2.85e11
# The chute's wall for the water, the column 'chute' of the results: the
# tutorial's castellated tube (system/topoSetDict.chute) "tube", an
# immersed one "immersed"; rows of "open" are runs whose chute was a
# contact-only surface, which the water passed
CHUTE = {"castellated": "tube", "immersed": "immersed"}
# Sides of the immersed tube's polygons (its radius within 3e-4 of a
# circle's)
TUBE_SIDES = 128
# The tutorial's chute, from the opening to the outlet, in pebble diameters
CHUTE_LENGTH = 4
HEADER = ["scene", "medium", "law", "chute", "chuteLength", "boundaryLayerSlip", "cellsPerDiameter", "restitution", "stiffnessFactor", "pebbles",
          "endTime", "left", "chuteFlux", "bedFlux", "balance", "wallTime"]


def linear_stiffness(factor, d, wall):
    """The linear spring's stiffness [N/m] that gives the overlap-volume
    law's force at an overlap of 1 % of d: k V(delta)/delta, with V the
    lens of two spheres or the cap a plane cuts off one."""
    a, delta = d/2, 0.01*d
    volume = (math.pi*delta**2*(3*a - delta)/3 if wall
              else math.pi*(6*a - delta)*delta**2/12)
    return factor*HERTZ_STIFFNESS*volume/delta


def tube_stl(inner, outer, length, sides):
    """A closed, outward-oriented triangulated tube (ASCII STL) about the
    z axis from z = 0 to length."""
    angles = 2*np.pi*np.arange(sides + 1)/sides
    ring = np.stack([np.cos(angles), np.sin(angles)], axis=1)

    def point(radius, k, z):
        return (radius*ring[k, 0], radius*ring[k, 1], z)

    triangles = []
    for k in range(sides):
        for radius, outward in ((outer, True), (inner, False)):
            a, b = point(radius, k, 0), point(radius, k + 1, 0)
            c, e = point(radius, k + 1, length), point(radius, k, length)
            quad = [(a, b, c), (a, c, e)]
            triangles += quad if outward else [(p, r, q) for p, q, r in quad]
        for z, up in ((0, False), (length, True)):
            a, b = point(inner, k, z), point(outer, k, z)
            c, e = point(outer, k + 1, z), point(inner, k + 1, z)
            quad = [(a, b, c), (a, c, e)]
            triangles += quad if up else [(p, r, q) for p, q, r in quad]
    lines = ["solid tube"]
    for tri in triangles:
        lines.append("facet normal 0 0 0\nouter loop")
        lines += [f"vertex {x:.12g} {y:.12g} {z:.12g}" for x, y, z in tri]
        lines.append("endloop\nendfacet")
    lines.append("endsolid tube")
    return "\n".join(lines) + "\n"


def immerse_chute(case, n):
    """The case's chute a fixed immersed tube instead of castellated
    baffles: the same mean inner radius (r and half a cell), two cells
    thick, from the cone's top to the outlet."""
    g = pebbleDischarge.geometry(case)
    h = g["d"]/n
    inner = g["r"] + 0.5*h
    length = g["outletZ"] - g["coneTop"]
    surfaces = case / "constant/triSurface"
    surfaces.mkdir(exist_ok=True)
    (surfaces / "chuteTube.stl").write_text(tube_stl(inner, inner + 2*h, length, TUBE_SIDES))
    # The fill (which includes the case's particles) stays the castellated
    # case's: the same bed
    fill = case / "fill/constant/particleProperties"
    text, count = re.subn(r'^(#include "\.\./\.\./constant/particleProperties"\n)',
                          r"\g<1>#remove particles\n", fill.read_text(), flags=re.M)
    if count != 1:
        raise SystemExit(f"{fill}: the include of the case's particles not found once")
    fill.write_text(text)
    pre = case / "Allrun.pre"
    text = pre.read_text()
    for line in (r"dlmSetEntries system/topoSetDict\.chute chuteRadius \\\n[^\n]*\n",
                 r"topoSet -dict system/topoSetDict\.chute[^\n]*\n",
                 r"createBaffles -overwrite[^\n]*\n"):
        text, count = re.subn(line, "", text)
        if count != 1:
            raise SystemExit(f"{pre}: the chute's castellation ({line}) not found once")
    pre.write_text(text)
    props = case / "constant/particleProperties"
    text = props.read_text()
    tube = (
        "// The chute's wall for the water: an immersed tube, fixed, which the\n"
        "// pebbles pass through (the contact-only chute keeps them off it)\n"
        "particles\n{\n    chuteTube\n    {\n"
        "        shape       triSurface;\n        file        \"chuteTube.stl\";\n"
        "        density     1000;\n        motion      fixed;\n"
        "        material    chuteTube;\n"
        f"        position    (0 0 {g['coneTop'] + 0.5*length:.12g});\n    }}\n}}\n\n")
    text = text.replace("particleFile ", tube + "particleFile ", 1)
    pairs = ("        pebbleTube\n        {\n            materials   (pebble chuteTube);\n"
             "            law         none;\n        }\n")
    text = re.sub(r"^(    pairs\n    \{\n)", rf"\g<1>{pairs}", text, count=1, flags=re.M)
    props.write_text(text)


def set_geometry(case, values):
    """Entries of the case's constant/geometry (lengths in m) set to values."""
    geometry = case / "constant/geometry"
    text = geometry.read_text()
    for key, value in values.items():
        text, count = re.subn(rf"^({key}\s+)[^;]*;", rf"\g<1>{value:.12g};", text, flags=re.M)
        if count != 1:
            raise SystemExit(f"{geometry}: {key} not found once")
    geometry.write_text(text)


def set_chute_length(case, length):
    """The case's chute from the cone's top to the particle outlet length
    pebble diameters long, the lid a diameter above its end."""
    g = pebbleDischarge.geometry(case)
    outlet = g["coneTop"] + length*g["d"]
    set_geometry(case, {"outletZ": outlet, "lidZ": outlet + g["d"]})


def make_case(scene, n, restitution, factor, law, medium, chute="castellated", slip=False,
              chute_length=CHUTE_LENGTH):
    case = RUNS / case_name(scene, n, restitution, factor, law, medium, chute, slip,
                            chute_length)
    if case.exists():
        shutil.rmtree(case)
    shutil.copytree(ROOT / "tutorials" / "pebbleDischarge", case,
                    ignore=shutil.ignore_patterns("log.*", "processor*", "postProcessing",
                                                  "VTK", "polyMesh", "[1-9]*", "0.[0-9]*",
                                                  "*.Allrun", "pebbleBed.dat",
                                                  "lattice.dat", "render"))
    if scene == "full":
        set_geometry(case, FULL)
    if chute_length != CHUTE_LENGTH:
        set_chute_length(case, chute_length)
    props = case / "constant/particleProperties"
    text = props.read_text()
    text = re.sub(r"^(\s+restitution\s+)[^;]*;", rf"\g<1>{restitution};", text, flags=re.M)
    text = re.sub(r"^(\s+stiffness\s+)[^;]*;", rf"\g<1>{factor*HERTZ_STIFFNESS:.6g};",
                  text, flags=re.M)
    if law == "linear":
        d = pebbleDischarge.geometry(case)["d"]
        for pair, wall in (("pebbles", False), ("pebbleWall", True)):
            block = re.search(rf"^        {pair}\n        \{{.*?^        \}}", text,
                              re.M | re.S).group(0)
            linear = re.sub(r"law\s+overlapVolume;", "law         linearSpringDashpot;", block)
            linear = re.sub(r"stiffness\s+[^;]*;",
                            f"stiffness   {linear_stiffness(factor, d, wall):.6g};\n"
                            "            tangential  spring;\n"
                            "            frictionLimit spring;\n"
                            f"            tangentialStiffnessRatio {2/7!r};\n"
                            "            tangentialDampingRatio 1;\n"
                            f"            clipNormalForce {'true' if run_liggghts.LIMIT_FORCE else 'false'};",
                            linear)
            text = text.replace(block, linear)
    props.write_text(text)
    if chute == "immersed":
        immerse_chute(case, n)
    if slip:
        options = case / "system/fvOptions"
        options.write_text(re.sub(r"^(\s+mixedCells\s+[^;]*;.*)$",
                                  "\\g<1>\n    boundaryLayerSlip true;",
                                  options.read_text(), count=1, flags=re.M))
    return case


def case_name(scene, n, restitution, factor, law, medium, chute="castellated", slip=False,
              chute_length=CHUTE_LENGTH):
    return (f"pebbleDischarge_{scene}_{n}_e{restitution:g}_k{factor:g}"
            + ("_linear" if law == "linear" else "") + ("_dry" if medium == "dry" else "")
            + ("_immersed" if chute == "immersed" else "")
            + (f"_chute{chute_length:g}d" if chute_length != CHUTE_LENGTH else "")
            + ("_slip" if slip else ""))


def written_times(case):
    """The times a run wrote (on its first rank if decomposed), ascending."""
    parallel = (case / "processor0").is_dir()
    return sorted(float(p.name) for p in (case / ("processor0" if parallel else ".")).iterdir()
                  if re.fullmatch(r"[0-9.eE+-]+", p.name) and p.is_dir())


def resume_command(case, end_time, n_procs):
    """The solver's command that continues a wet run from its latest
    written time to end_time (the endTime entry in controlDict.Allrun)."""
    parallel = (case / "processor0").is_dir()
    written = written_times(case)
    if not written or written[-1] <= 0:
        raise SystemExit(f"{case}: nothing to resume (no written time after 0)")
    ranks = len(list(case.glob("processor[0-9]*")))
    if parallel and n_procs != ranks:
        raise SystemExit(f"{case}: decomposed for {ranks} ranks, not --np {n_procs}")
    allrun = case / "system/controlDict.Allrun"
    allrun.write_text(re.sub(r"^endTime\s+[^;]*;", f"endTime         {end_time:g};",
                             allrun.read_text(), flags=re.M))
    # A part stopped by stopAt writeNow
    control = case / "system/controlDict"
    control.write_text(re.sub(r"^stopAt\s+[^;]*;", "stopAt          endTime;",
                              control.read_text(), flags=re.M))
    print(f"{case.name}: resuming from {written[-1]:g} s to {end_time:g} s")
    solver = ["pimpleDLMFoam", "-case", str(case)]
    if parallel:
        return (["mpirun", "--allow-run-as-root", "-np", str(n_procs)] + solver
                + ["-parallel"], ["reconstructPar", "-case", str(case), "-newTimes"])
    return solver, None


def run_label(args, n):
    return (f"{args.scene}, N = {n}, e = {args.restitution:g}, "
            f"factor {args.stiffness_factor:g}, {args.law}"
            + (", immersed chute" if args.chute == "immersed" else "")
            + (f", chute {args.chute_length:g} d" if args.chute_length != CHUTE_LENGTH else "")
            + (", boundary-layer slip" if args.boundary_layer_slip else ""))


def record_row(args, medium, law, cells, s, wall, end_time=None):
    """The run's row in results/pebbleDischarge.csv (its end time that of
    the arguments unless given: a run stopped early)."""
    merge_row(RESULTS / "pebbleDischarge.csv", HEADER,
              [args.scene, medium, law, CHUTE[args.chute] if medium == "wet" else "-",
               args.chute_length,
               int(args.boundary_layer_slip) if medium == "wet" else "-", cells,
               args.restitution, args.stiffness_factor, PEBBLES[args.scene],
               args.end_time if end_time is None else end_time,
               s["left"], f"{s['chute_flux']:.2f}", f"{s['bed_flux']:.2f}",
               f"{s['balance']:.4f}", f"{wall:.0f}"], key_columns=9)


def entry(path, keyword):
    """The first value of keyword in a dictionary file, as text."""
    return re.search(rf"^\s*{keyword}\s+([^;]+);", path.read_text(), re.M).group(1)


def liggghts_discharge(case, end_time, restitution, factor):
    """LIGGGHTS on the case's bed and geometry, dry (the gravity of its
    dry/constant/g, the pebbles' friction of constant/particleProperties),
    with the linear spring-dashpot of --law linear: the summary and the
    loop time."""
    g = pebbleDischarge.geometry(case)
    d = g["d"]
    bed = np.loadtxt(case / "constant/pebbleBed.dat", ndmin=2)
    kn = {"particleParticle": linear_stiffness(factor, d, False),
          "particleWall": linear_stiffness(factor, d, True)}
    gravity = float(entry(case / "dry/constant/g", "value").strip("()").split()[2])
    friction = float(entry(case / "constant/particleProperties", "friction"))
    times, ids, rows, loop = run_liggghts.pebble_run(
        case / "liggghts", g, bed, pebbleDischarge.PEBBLE_DENSITY, kn, restitution,
        friction, gravity, end_time)
    mass = pebbleDischarge.PEBBLE_DENSITY*math.pi*d**3/6
    names = ids.astype(str)
    outlet = pebbleDischarge.departures(times, names, mass)
    return pebbleDischarge.summary_of(g, outlet, (times, names, rows)), loop


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--scene", choices=PEBBLES, default="reduced")
    parser.add_argument("--medium", choices=("wet", "dry", "both"), default="wet")
    parser.add_argument("--liggghts", action="store_true")
    parser.add_argument("--law", choices=("overlapVolume", "linear"), default="overlapVolume")
    parser.add_argument("--end-time", type=float, default=6)
    parser.add_argument("--np", type=int, default=1)
    parser.add_argument("--restitution", type=float, default=0.8)
    parser.add_argument("--stiffness-factor", type=float, default=0.01)
    parser.add_argument("--chute", choices=tuple(CHUTE), default="castellated")
    parser.add_argument("--chute-length", type=float, default=CHUTE_LENGTH)
    parser.add_argument("--boundary-layer-slip", action="store_true")
    parser.add_argument("--resume", action="store_true")
    parser.add_argument("resolutions", nargs="*", type=int, default=[4])
    args = parser.parse_args()
    if args.chute_length < 1:
        parser.error(f"--chute-length {args.chute_length:g}: the chute must be at least a"
                     " pebble diameter long (the outlet beyond the opening)")
    if args.resume and (args.medium != "wet" or args.liggghts):
        parser.error("--resume continues a wet run only")
    if args.chute == "immersed" and args.medium != "wet":
        parser.error("--chute immersed: a wall for the water, in a wet run only")
    if args.boundary_layer_slip and args.medium != "wet":
        parser.error("--boundary-layer-slip: the profile cells' flow, in a wet run only")
    env = foam_environment()
    for n in args.resolutions:
        if args.resume:
            case = RUNS / case_name(args.scene, n, args.restitution, args.stiffness_factor,
                                    args.law, "wet", args.chute, args.boundary_layer_slip,
                                    args.chute_length)
            resume(case, n, args, env)
            continue
        case = make_case(args.scene, n, args.restitution, args.stiffness_factor, args.law,
                         args.medium, args.chute, args.boundary_layer_slip,
                         args.chute_length)
        label = run_label(args, n)
        runs = []
        if args.medium in ("wet", "both"):
            runs.append(("wet", case, n, [str(case / "Allrun"), str(n), str(args.np),
                                          str(args.end_time), str(PEBBLES[args.scene])]))
        if args.medium in ("dry", "both"):
            runs.append(("dry", case / "dry", 0, [str(case / "Allrun.dry"), str(args.end_time),
                                                  str(PEBBLES[args.scene])]))
        summaries = []

        def record(medium, law, cells, s, wall):
            summaries.append((f"{label if medium != 'dryLIGGGHTS' else 'LIGGGHTS'}, {medium}", s))
            record_row(args, medium, law, cells, s, wall)

        for medium, run_dir, cells, command in runs:
            start = time.perf_counter()
            result = subprocess.run(command, env=env, capture_output=True, text=True)
            wall = time.perf_counter() - start
            if result.returncode != 0:
                raise SystemExit(f"{case}: {command[0]} failed\n{result.stdout}{result.stderr}")
            s = pebbleDischarge.summary(run_dir)
            print("\n".join(pebbleDischarge.report(run_dir, s)))
            print(f"  wall time  {wall:.0f} s ({command[0].split('/')[-1]}, with the set-up"
                  " where it made it)")
            record(medium, args.law, cells, s, wall)
        if args.liggghts:
            if not (case / "constant/pebbleBed.dat").exists():
                raise SystemExit("--liggghts needs the bed: with --medium dry or both")
            s, loop = liggghts_discharge(case, args.end_time, args.restitution,
                                         args.stiffness_factor)
            print("\n".join(pebbleDischarge.report(case / "liggghts", s)))
            print(f"  wall time  {loop:.0f} s (LIGGGHTS' loop)")
            record("dryLIGGGHTS", "linear", 0, s, loop)
        suffix = "_wetDry" if args.medium == "both" else ""
        pebbleDischarge.plot([s for _, s in summaries], RESULTS / f"{case.name}{suffix}.png",
                             [lab for lab, _ in summaries])


def solver_clock_times(case):
    """The solver's clock time of each part of a run (its log and the
    resumed parts' log, in which each part's clock starts again from 0);
    steps after a part's last write that the next part repeated count
    twice, the set-up not at all."""
    parts = []
    for log in ("log.pimpleDLMFoam", "log.pimpleDLMFoam.resumed"):
        path = case / log
        if not path.exists():
            continue
        last = None
        for clock in re.findall(r"ClockTime = ([0-9.eE+-]+) s", path.read_text()):
            clock = float(clock)
            if last is not None and clock < last:
                parts.append(last)
            last = clock
        if last is not None:
            parts.append(last)
    return parts


def resume(case, n, args, env):
    """Continue the wet run of case to --end-time, then report and record
    it as a whole (its wall time the sum over its parts)."""
    if not case.is_dir():
        raise SystemExit(f"{case}: no such run to resume")
    solver, reconstruct = resume_command(case, args.end_time, args.np)
    with open(case / "log.pimpleDLMFoam.resumed", "a") as log:
        result = subprocess.run(solver, env=env, stdout=log, stderr=subprocess.STDOUT)
        if result.returncode == 0 and reconstruct:
            result = subprocess.run(reconstruct, env=env, stdout=log, stderr=subprocess.STDOUT)
    if result.returncode != 0:
        raise SystemExit(f"{case}: {solver[0]} failed (log.pimpleDLMFoam.resumed)")
    parts = solver_clock_times(case)
    wall = sum(parts)
    s = pebbleDischarge.summary(case)
    print("\n".join(pebbleDischarge.report(case, s)))
    print(f"  wall time  {wall:.0f} s: the solver's clock over {len(parts)} parts"
          f" ({', '.join(f'{p:.0f}' for p in parts)} s; without the set-up)")
    # A part stopped by stopAt writeNow ends before --end-time
    reached = written_times(case)[-1]
    print(f"  reached    {reached:g} s of {args.end_time:g}")
    record_row(args, "wet", args.law, n, s, wall, end_time=round(reached, 3))
    pebbleDischarge.plot([s], RESULTS / f"{case.name}.png", [f"{run_label(args, n)}, wet"])


if __name__ == "__main__":
    main()
