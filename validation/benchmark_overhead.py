#!/usr/bin/env python3
"""Cost of the particle work: time per step of pimpleDLMFoam against stock
pimpleFoam on the same mesh (48^3 cells) and PIMPLE settings, with 0, 10 and
100 free spheres of 6 cells per diameter, and 100 fixed ones (a fixed bed:
no fractions, momentum integrals or forced-cell search after the first
step). Reports the ratio of the times per
step, and the share of the particle work (fractions, projection, motion,
output) that pimpleDLMFoam measures itself, so the pressure solver's extra
work in a flow disturbed by particles is not counted as particle work.
Times are CPU times. A benchmark, not a test: it prints the ratios and
writes results/benchmark_overhead.csv.

    validation/benchmark_overhead.py [steps]        (default 20)
"""

import re
import shutil
import sys

import numpy as np

from common import Case, RESULTS, ROOT, RUNS, foam_environment, write_table

N_CELLS, L = 48, 0.048           # 1 mm cells
RADIUS = 0.003                   # 6 cells per diameter

HEADER = "FoamFile {{ version 2.0; format ascii; class {cls}; object {obj}; }}\n"


def write(path, cls, obj, body):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(HEADER.format(cls=cls, obj=obj) + body)


def make_case(name, solver, n_particles, steps, env, motion="free", n_cells=N_CELLS):
    """The lid-driven cavity of n_cells^3 cells (the particles' size is
    set for the default, 48^3) for the given solver, meshed."""
    case = Case.copy(ROOT / "tests" / "cases" / "sphereBox", RUNS / name, env)
    p = case.path
    write(p / "system/blockMeshDict", "dictionary", "blockMeshDict", f"""
vertices ((0 0 0) ({L} 0 0) ({L} {L} 0) (0 {L} 0) (0 0 {L}) ({L} 0 {L}) ({L} {L} {L}) (0 {L} {L}));
blocks (hex (0 1 2 3 4 5 6 7) ({n_cells} {n_cells} {n_cells}) simpleGrading (1 1 1));
boundary
(
    walls {{ type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1)); }}
    lid {{ type wall; faces ((4 5 6 7)); }}
);
""")
    # The same flow in both solvers: a lid-driven cavity (Re 480)
    text = (p / "0/U").read_text().replace(
        "boundaryField\n{", "boundaryField\n{\n    lid { type fixedValue; value uniform (0.01 0 0); }")
    (p / "0/U").write_text(text)
    text = (p / "0/p_rgh").read_text().replace("    walls", '    "(walls|lid)"')
    (p / "0/p_rgh").write_text(text)
    case.set("system/controlDict", "endTime", 0.001*steps)
    case.set("system/controlDict", "deltaT", 0.001)
    case.set("system/controlDict", "writeInterval", 10*steps)
    case.set("system/controlDict", "application", solver)
    case.set("system/fvSolution", "PIMPLE/pRefPoint", f"({L/2} {L/2} {0.99*L})")
    if solver == "pimpleFoam":
        text = (p / "system/fvSolution").read_text().replace("p_rgh", "p")
        (p / "system/fvSolution").write_text(text)
        shutil.move(p / "0/p_rgh", p / "0/p")
        text = (p / "0/p").read_text().replace("p_rgh", "p").replace(
            "fixedFluxPressure", "zeroGradient").replace(
            "[1 -1 -2 0 0 0 0]", "[0 2 -2 0 0 0 0]")
        (p / "0/p").write_text(text)
        write(p / "constant/transportProperties", "dictionary",
              "transportProperties", "transportModel Newtonian;\nrho 1000;\nnu 1e-6;\n")
        write(p / "constant/turbulenceProperties", "dictionary",
              "turbulenceProperties", "simulationType laminar;\n")
        text = (p / "system/fvSchemes").read_text().replace(
            "div(phi,U)", "div((nuEff*dev2(T(grad(U))))) Gauss linear;\n    div(phi,U)")
        (p / "system/fvSchemes").write_text(text)
        (p / "system/fvOptions").unlink()
        (p / "constant/particleProperties").unlink()
    else:
        per_side = int(np.ceil(n_particles**(1/3))) if n_particles else 0
        spacing = L/(per_side + 1) if per_side else L
        body = "particles\n{\n"
        count = 0
        for i in range(per_side):
            for j in range(per_side):
                for k in range(per_side):
                    if count == n_particles:
                        break
                    x, y, z = ((i + 1)*spacing, (j + 1)*spacing, (k + 1)*spacing)
                    body += (f"    p{count} {{ shape sphere; radius {RADIUS}; "
                             f"density 1000; position ({x} {y} {z}); "
                             f"motion {motion}; }}\n")
                    count += 1
        write(p / "constant/particleProperties", "dictionary",
              "particleProperties", body + "}\n")
    case.set("constant/transportProperties", "nu", 1e-6)
    case.run("blockMesh")
    return case


def time_per_step(log):
    times = [float(t) for t in re.findall(r"^ExecutionTime = ([0-9.eE+-]+)", log, re.M)]
    # Skip the first steps (set-up, caches)
    return (times[-1] - times[2])/(len(times) - 3)


def particle_share(log):
    """Share of the execution time pimpleDLMFoam spent on the particles."""
    return float(re.search(r"^Particle work .*, ([0-9.eE+-]+) % of the execution time",
                           log, re.M).group(1))/100


def main():
    steps = int(sys.argv[1]) if len(sys.argv) > 1 else 20
    env = foam_environment()
    RESULTS.mkdir(parents=True, exist_ok=True)
    base = make_case("bench_pimpleFoam", "pimpleFoam", 0, steps, env)
    reference = time_per_step(base.run("pimpleFoam").log)
    print(f"pimpleFoam: {reference:.4f} s/step")
    rows = [["pimpleFoam", 0, "", reference, 1.0, 0.0]]
    for n, motion in ((0, "free"), (10, "free"), (100, "free"), (100, "fixed")):
        case = make_case(f"bench_dlm_{n}_{motion}", "pimpleDLMFoam", n, steps, env,
                         motion)
        log = case.run("pimpleDLMFoam").log
        t = time_per_step(log)
        share = particle_share(log)
        rows.append(["pimpleDLMFoam", n, motion, t, t/reference, share])
        print(f"pimpleDLMFoam, {n:3d} {motion} particles: {t:.4f} s/step, "
              f"ratio {t/reference:.3f}, particle work {100*share:.1f} % of the run "
              f"({share*t:.4f} s/step)")
    write_table(RESULTS / "benchmark_overhead.csv",
                ["solver", "particles", "motion", "secondsPerStep", "ratioToPimpleFoam",
                 "particleWorkShare"], rows)


if __name__ == "__main__":
    main()
