#!/usr/bin/env python3
"""Cost of glibc's default memory allocation on large meshes. A block of
more than 32 MB (a tensor field of 0.47 M cells, a vector field of 1.4 M, a
scalar field of 4.2 M, per rank) is beyond glibc's largest threshold for
serving allocations from mmap, so each such temporary (OpenFOAM makes many
a step: gradients, interpolates, matrix coefficients) is a fresh mapping
whose pages the kernel zeroes on first touch. etc/bashrc sets
GLIBC_TUNABLES so that large blocks stay on the heap (mmap_max=0) and the
heap never gives its top back (trim_threshold at its largest).

This benchmark runs pimpleDLMFoam on the lid-driven cavity of
benchmark_overhead.py, without particles, at n^3 cells on one core, with
glibc's defaults and with etc/bashrc's setting, and reports the CPU time per
step (skipping the first three) and the share of system (kernel) time of
the whole run. A benchmark, not a test: it prints and writes
results/benchmark_allocation.csv.

    validation/benchmark_allocation.py [--steps 12] [n ...]   (default n = 64 128)
"""

import argparse
import resource

from benchmark_overhead import make_case, time_per_step
from common import RESULTS, foam_environment, write_table


def run(n, steps, env, label):
    """CPU time per step and the run's share of system time."""
    case = make_case(f"bench_allocation_{n}_{label}", "pimpleDLMFoam", 0, steps, env,
                     n_cells=n)
    # The cavity's 1e-8 is below round-off on the finer meshes (the final
    # pressure solve then stops at its 1000 iterations)
    for solver in ("p_rgh", "p_rghFinal"):
        case.set("system/fvSolution", f"solvers/{solver}/tolerance", 1e-6)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    log = case.run("pimpleDLMFoam").log
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    system = after.ru_stime - before.ru_stime
    user = after.ru_utime - before.ru_utime
    return time_per_step(log), system/(system + user)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--steps", type=int, default=12)
    parser.add_argument("cells", nargs="*", type=int, default=[64, 128],
                        help="cells per side of the cavity")
    args = parser.parse_args()
    tuned = foam_environment()
    if "mmap_max=0" not in tuned.get("GLIBC_TUNABLES", ""):
        raise SystemExit("etc/bashrc does not set glibc.malloc.mmap_max=0 in GLIBC_TUNABLES")
    default = {key: value for key, value in tuned.items() if key != "GLIBC_TUNABLES"}
    RESULTS.mkdir(parents=True, exist_ok=True)
    rows = []
    for n in args.cells:
        (t_default, sys_default), (t_tuned, sys_tuned) = \
            (run(n, args.steps, env, label)
             for env, label in ((default, "default"), (tuned, "tuned")))
        rows.append([n**3, t_default, sys_default, t_tuned, sys_tuned, t_default/t_tuned])
        print(f"{n}^3 cells: glibc's defaults {t_default:.3f} s/step "
              f"({100*sys_default:.0f} % system time), etc/bashrc's setting "
              f"{t_tuned:.3f} s/step ({100*sys_tuned:.0f} %): "
              f"{t_default/t_tuned:.2f} times faster", flush=True)
    write_table(RESULTS / "benchmark_allocation.csv",
                ["cells", "secondsPerStepDefault", "systemShareDefault",
                 "secondsPerStepTuned", "systemShareTuned", "speedUp"], rows)


if __name__ == "__main__":
    main()
