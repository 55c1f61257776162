#!/usr/bin/env python3
"""The largest stable viscous number nu deltaT/h^2 of the flow solver in
cells longer in one direction, with no particle: the measurements behind
the solver's default limit (viscousNumber.H; validation/cases/viscousLimit.md).

A periodic box of uniform cells A h x h x h (8 x 24 x 24 cells, h = 0.25
mm, nu = 1e-3 m2/s) holds a random flow of 1e-5 m/s that decays; 300
fixed steps at each viscous number of the list, in increasing order until
one fails. Stable: every step runs and the flow at the end is below a
tenth of its start; otherwise it swung and grew. The linear solvers stop
after 30 iterations (the decayed flow cannot meet their tolerances). Prints
the largest stable viscous number per aspect ratio and number of pressure
correctors, and the solver's default limit for comparison.

    validation/benchmark_viscousLimit.py [--correctors 2,3,6]
        [--aspect-ratios 1,1.5,2,3,4.5,8,12] [--viscous-numbers 1,2,3,5,10,20,50]
"""

import argparse
import re

import numpy as np

from common import RUNS, ROOT, Case, foam_environment
from foamcase import long_cell_flow

H, NX, NY = 2.5e-4, 8, 24
NU = 1e-3
STEPS = 300


def default_limit(correctors, aspect):
    """The solver's default maxViscousNumber (viscousNumber.H)."""
    if correctors < 3:
        return 1
    return 50 if aspect <= 2 else 5 if aspect <= 3 else 3 if aspect <= 8 else 2


def stable(aspect, correctors, viscous_number, env):
    case = Case.copy(ROOT / "tutorials" / "periodicArray",
                     RUNS / f"viscousLimit_A{aspect:g}_p{correctors}_VN{viscous_number:g}", env)
    long_cell_flow(case, aspect, H, (NX, NY, NY))
    dt = viscous_number*H**2/NU
    for (file, entry), value in {
        ("constant/transportProperties", "nu"): NU,
        ("system/fvSolution", "PIMPLE/nCorrectors"): correctors,
        ("system/controlDict", "deltaT"): dt,
        ("system/controlDict", "adjustTimeStep"): "no",
        ("system/controlDict", "maxViscousNumber"): 1e6,
        ("system/controlDict", "endTime"): STEPS*dt,
        ("system/controlDict", "writeInterval"): STEPS*dt,
    }.items():
        case.set(file, entry, value)
    for solver in ("U", "UFinal", "p_rgh", "p_rghFinal"):
        case.run("foamDictionary", "system/fvSolution", "-entry", f"solvers/{solver}/maxIter",
                 "-add", 30, log="foamDictionary", check=False)
    case.run("foamDictionary", "system/controlDict", "-entry", "functions", "-remove",
             log="foamDictionary")
    result = case.run("pimpleDLMFoam", check=False)
    courant = [float(v) for v in re.findall(r"^Courant Number mean: \S+ max: (\S+)",
                                            result.log, re.M)]
    return (result.returncode == 0 and len(courant) > STEPS
            and np.isfinite(courant).all() and courant[-1] < 0.1*courant[1])


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--correctors", default="2,3,6")
    parser.add_argument("--aspect-ratios", default="1,1.5,2,3,4.5,8,12")
    parser.add_argument("--viscous-numbers", default="1,2,3,5,10,20,50")
    args = parser.parse_args()
    env = foam_environment()
    numbers = [float(v) for v in args.viscous_numbers.split(",")]
    for correctors in (int(c) for c in args.correctors.split(",")):
        for aspect in (float(a) for a in args.aspect_ratios.split(",")):
            largest = None
            for viscous_number in numbers:
                if not stable(aspect, correctors, viscous_number, env):
                    break
                largest = viscous_number
            print(f"{correctors} correctors, aspect ratio {aspect:g}: largest stable viscous"
                  f" number {largest} (of {args.viscous_numbers}); the solver's default limit"
                  f" {default_limit(correctors, aspect):.3g}", flush=True)


if __name__ == "__main__":
    main()
