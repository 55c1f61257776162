#!/usr/bin/env python3
"""Cost of the contacts: dry simple-cubic stacks of 10^3, 10^4 and 10^5
spheres (d = 4 mm, 2500 kg/m^3) pressed slightly together in a walled box
without gravity, run by
dlmDEMFoam for a few fluid steps with the overlap-volume law and static
friction. The walls press on the outer layers as hard as neighbours press on
each other, so the stack stays at rest in the same state at every size:
every sphere keeps its 6 contacts (neighbours or walls). Reports the CPU time per particle per contact sub-step (search,
forces and motion), which should stay within 1.5 times across the range
(O(N) search), and the particle-sub-steps per second. A benchmark, not a
test: prints and writes results/benchmark_contact.csv.

With --liggghts, the same stacks also run in LIGGGHTS (liggghts/, linear
spring-dashpot with tangential history, the constants of liggghts/scenes.py)
and, for a like-for-like comparison, in dlmDEMFoam with the same law:
particle-steps per second of both codes in one run, written to
results/benchmark_contact_liggghts.csv.

    validation/benchmark_contact.py [--sizes 10,22,46] [--steps 10] [--liggghts]
                                    (spheres per box side)
"""

import argparse
import re
import sys
from pathlib import Path

import numpy as np

from common import Case, RESULTS, ROOT, RUNS, foam_environment, write_table

sys.path.insert(0, str(Path(__file__).resolve().parent / "liggghts"))
from run_liggghts import header, liggghts, loop_times, wall  # noqa: E402
from scenes import KN, contact  # noqa: E402

D = 0.004
SPACING = D*(1 - 2e-3)          # every neighbour overlaps by 0.2 % of d

HEADER = "FoamFile {{ version 2.0; format ascii; class {cls}; object {obj}; }}\n"


def write(path, cls, obj, body):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(HEADER.format(cls=cls, obj=obj) + body)


def stack(n):
    """Centres of the n^3 stack and the box side. A sphere-sphere lens of
    overlap delta has the volume of a wall cap of depth delta/sqrt(2), and
    the law's stiffness from a contact time is the same for both pairs (the
    reduced mass and radius scale alike), so walls at that depth balance the
    neighbours' push."""
    delta = D - SPACING
    wall_gap = D/2 - delta/np.sqrt(2)
    L = float((n - 1)*SPACING + 2*wall_gap)
    rng = np.random.default_rng(1)
    index = np.arange(n)
    x, y, z = np.meshgrid(index, index, index, indexing="ij")
    centres = np.stack([x, y, z], axis=-1).reshape(-1, 3)*SPACING + wall_gap \
        + rng.uniform(-1e-4*D, 1e-4*D, (n**3, 3))
    return centres, L


def make_case(n, steps, env, law=None):
    suffix = "_lsd" if law else ""
    case = Case.copy(ROOT / "tests" / "cases" / "dryBox",
                     RUNS / f"benchmarkContact_{n}{suffix}", env)
    centres, L = stack(n)
    write(case.path / "system/blockMeshDict", "dictionary", "blockMeshDict", f"""
vertices ((0 0 0) ({L} 0 0) ({L} {L} 0) (0 {L} 0) (0 0 {L}) ({L} 0 {L}) ({L} {L} {L}) (0 {L} {L}));
blocks (hex (0 1 2 3 4 5 6 7) (4 4 4) simpleGrading (1 1 1));
boundary ( walls {{ type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); }} );
""")
    np.savetxt(case.path / "constant/packing.dat",
               np.column_stack([centres, np.full(n**3, D/2)]), fmt="%.9e")
    contact_law = law or ("law overlapVolume; contactTime 1e-4; impactVelocity 1;"
                          " restitution 0.5; friction 0.3;")
    write(case.path / "constant/particleProperties", "dictionary", "particleProperties", f"""
historyInterval 0;
particleFile "constant/packing.dat";
particleFileDefaults {{ shape sphere; density 2500; }}
contact
{{
    pairs
    {{
        particles {{ materials (particle particle); {contact_law} }}
        walls     {{ materials (particle wall); {contact_law} }}
    }}
}}
""")
    write(case.path / "constant/g", "uniformDimensionedVectorField", "g",
          "dimensions [0 1 -2 0 0 0 0];\nvalue (0 0 0);\n")
    case.run("blockMesh")
    case.set("system/controlDict", "deltaT", 1e-4)
    case.set("system/controlDict", "endTime", steps*1e-4)
    case.set("system/controlDict", "writeInterval", 100000)
    return case


def run_ours(n, steps, env, law=None):
    """dlmDEMFoam on the n^3 stack: candidate pairs, contacts, sub-steps,
    CPU time and CPU seconds per sub-step (the first fluid step, with the
    set-up, left out)."""
    case = make_case(n, steps, env, law)
    case.run("dlmDEMFoam")
    log = (case.path / "log.dlmDEMFoam").read_text()
    contacts = [line for line in log.splitlines() if line.startswith("Contacts:")]
    sub_steps = sum(int(re.search(r"; (\d+) sub-steps", c).group(1)) for c in contacts)
    pairs = int(re.search(r"Contacts: (\d+) particle pairs", contacts[-1]).group(1))
    touching = int(re.search(r"up to (\d+) touching", contacts[-1]).group(1))
    cpu = float(re.findall(r"ExecutionTime = ([0-9.e+-]+) s", log)[-1])
    start = float(re.findall(r"ExecutionTime = ([0-9.e+-]+) s", log)[0])
    per_step = (cpu - start)/max(sub_steps - sub_steps/len(contacts), 1)
    return pairs, touching, sub_steps, cpu, per_step


def run_liggghts(n, steps):
    """LIGGGHTS on the n^3 stack (walls as planes, no gravity, the linear
    spring-dashpot of scenes.py, its time step): seconds per step (loop
    time, without start-up)."""
    centres, L = stack(n)
    case = RUNS / f"benchmarkContact_{n}_liggghts"
    case.mkdir(parents=True, exist_ok=True)
    lo, hi = -0.01*L, 1.01*L
    script = header((lo, lo, lo), (hi, hi, hi), contact(0.5), gravity=False)
    script += "".join(f"create_atoms    1 single {x:.9e} {y:.9e} {z:.9e} units box\n"
                      for x, y, z in centres)
    script += f"set             atom * diameter {D!r} density 2500\n"
    for name, plane, position in (("x0", "xplane", 0.0), ("x1", "xplane", L),
                                  ("y0", "yplane", 0.0), ("y1", "yplane", L),
                                  ("z0", "zplane", 0.0), ("z1", "zplane", L)):
        script += wall(name, plane, position)
    script += f"""fix             integr all nve/sphere
thermo          {steps}
run             {steps}
"""
    log = liggghts(case, script)
    seconds = sum(t for _, t, _ in loop_times(log))
    return seconds/steps


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--sizes", default="10,22,46")
    parser.add_argument("--steps", type=int, default=10)
    parser.add_argument("--liggghts", action="store_true")
    args = parser.parse_args()

    env = foam_environment()
    RESULTS.mkdir(parents=True, exist_ok=True)
    sizes = [int(s) for s in args.sizes.split(",")]
    rows = []
    for n in sizes:
        pairs, touching, sub_steps, cpu, per_step = run_ours(n, args.steps, env)
        N = n**3
        rows.append([N, pairs, touching, sub_steps, cpu, per_step/N*1e6, N/per_step])
        print(f"{N:7d} spheres: {pairs} candidate pairs, {touching} contacts, "
              f"{sub_steps} sub-steps, CPU {cpu:.1f} s; "
              f"{per_step/N*1e6:.3f} us per particle-sub-step "
              f"({N/per_step:.3g} particle-sub-steps/s)", flush=True)
    base = rows[0][5]
    for r in rows:
        print(f"{r[0]:7d}: cost per particle {r[5]/base:.2f} x that of {rows[0][0]}")
    write_table(RESULTS / "benchmark_contact.csv",
                ["particles", "candidatePairs", "contacts", "subSteps", "cpuTime_s",
                 "us_per_particle_subStep", "particleSubSteps_per_s"], rows)

    if not args.liggghts:
        return
    # The same law in both codes: LIGGGHTS' hooke/stiffness with history
    law = (f"law linearSpringDashpot; stiffness {KN}; restitution 0.5; friction 0.5;"
           f" tangential spring; frictionLimit spring; clipNormalForce false;")
    rows = []
    for n in sizes:
        N = n**3
        ours = run_ours(n, args.steps, env, law)[4]
        theirs = run_liggghts(n, 20*args.steps*10)
        rows.append([N, ours/N*1e6, theirs/N*1e6, ours/theirs])
        print(f"{N:7d} spheres, linear spring-dashpot: dlmDEMFoam {N/ours:.3g},"
              f" LIGGGHTS {N/theirs:.3g} particle-steps/s (ours {ours/theirs:.2f} x"
              f" LIGGGHTS' time per step)", flush=True)
    write_table(RESULTS / "benchmark_contact_liggghts.csv",
                ["particles", "dlmDEMFoam_us_per_particle_step",
                 "LIGGGHTS_us_per_particle_step", "time_ratio"], rows)


if __name__ == "__main__":
    main()
