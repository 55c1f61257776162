#!/usr/bin/env python3
"""Restitution of dry collisions: two 4 mm spheres head on at 1 m/s and a
sphere on the floor at 1 m/s (tests/cases/dryBox, dlmDEMFoam), for the
requested e from 0.1 to 0.95, both contact laws and several numbers of
sub-steps per collision. Reports the measured e, its error, the contact
duration, the sub-steps taken and the wall time; writes
results/restitution.csv and results/restitution.png (error against sub-steps
per collision).

    validation/validate_restitution.py [--steps 20,50,100]
"""

import argparse

from common import RESULTS, ROOT, RUNS, Case, foam_environment, timed_run, write_table

DRY_BOX = ROOT / "tests" / "cases" / "dryBox"
RESTITUTIONS = [0.1, 0.3, 0.5, 0.7, 0.9, 0.95]
LAWS = ["overlapVolume", "linearSpringDashpot"]
PAIRS = ("particleParticle", "particleWall")


def run(env, scene, law, e, steps):
    case = Case.copy(DRY_BOX, RUNS / f"restitution_{scene}_{law}_{e}_{steps}", env)
    case.run("blockMesh")
    props = "constant/particleProperties"
    for pair in PAIRS:
        case.set(props, f"contact/pairs/{pair}/restitution", e)
        case.set(props, f"contact/pairs/{pair}/law", law)
        if law == "linearSpringDashpot":
            case.run("foamDictionary", props, "-entry",
                     f"contact/pairs/{pair}/impactVelocity", "-remove",
                     log="foamDictionary")
    case.set(props, "contact/stepsPerContact", steps)
    if scene == "wall":
        case.run("foamDictionary", props, "-entry", "particles/right", "-remove",
                 log="foamDictionary")
        case.set(props, "particles/left/position", "(0 0 0.0025)")
        case.set(props, "particles/left/velocity", "(0 0 -1)")
    seconds = timed_run(case, "dlmDEMFoam")
    h = case.history()
    if scene == "wall":
        v = h["left"][:, 6]
        measured = v[-1]/-v[0]
    else:
        rel = h["right"][:, 4] - h["left"][:, 4]
        measured = -rel[-1]/rel[0]
    log = (case.path / "log.dlmDEMFoam").read_text()
    sub_steps = sum(int(line.split(";")[1].split()[0])
                    for line in log.splitlines() if line.startswith("Contacts:"))
    return measured, sub_steps, seconds


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--steps", default="20,50,100")
    args = parser.parse_args()
    steps_list = [int(s) for s in args.steps.split(",")]

    env = foam_environment()
    RESULTS.mkdir(parents=True, exist_ok=True)
    rows = []
    for scene in ("headOn", "wall"):
        for law in LAWS:
            for steps in steps_list:
                for e in RESTITUTIONS:
                    measured, sub_steps, seconds = run(env, scene, law, e, steps)
                    error = measured/e - 1
                    rows.append([scene, law, steps, e, measured, error, sub_steps,
                                 seconds])
                    print(f"{scene:6s} {law:19s} steps/contact {steps:3d} e {e:4.2f}"
                          f" measured {measured:.5f} ({100*error:+.3f} %)"
                          f" sub-steps {sub_steps} wall {seconds:.1f} s", flush=True)
    write_table(RESULTS / "restitution.csv",
                ["scene", "law", "stepsPerContact", "e", "e_measured", "relError",
                 "subSteps", "wallTime_s"], rows)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(10, 4), sharey=True)
    for ax, scene in zip(axes, ("headOn", "wall")):
        for law in LAWS:
            for steps in steps_list:
                sel = [r for r in rows if r[0] == scene and r[1] == law and r[2] == steps]
                ax.plot([r[3] for r in sel], [100*abs(r[5]) + 1e-4 for r in sel], "o-",
                        label=f"{law}, {steps} steps/contact")
        ax.axhline(1, color="k", ls="--", lw=0.8, label="target 1 %")
        ax.set_yscale("log")
        ax.set_xlabel("requested restitution e")
        ax.set_title("two spheres head on" if scene == "headOn" else "sphere on a wall")
    axes[0].set_ylabel("|measured/requested - 1| [%]")
    axes[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(RESULTS / "restitution.png", dpi=120)


if __name__ == "__main__":
    main()
