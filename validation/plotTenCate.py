#!/usr/bin/env python3
"""Plot a ten Cate run against the experiment and print what it computed:
u_max, its error against the experiment's, the solver's wall time (from
the case's log.pimpleDLMFoam) and the path of the plot.

    validation/plotTenCate.py <caseDir> <E1|E2|E3|E4> [output.png]
"""

import pathlib
import re
import sys

from common import Case
import tenCate


def solver_wall_time(case_dir):
    """The solver's wall time [s]: the last ClockTime of log.pimpleDLMFoam
    (None without a log)."""
    log = pathlib.Path(case_dir) / "log.pimpleDLMFoam"
    if not log.is_file():
        return None
    times = re.findall(r"ClockTime = (\S+) s", log.read_text(errors="replace"))
    return float(times[-1]) if times else None


def report(case, case_dir, history, output):
    """The lines printed about a run."""
    u_max, error = tenCate.summary(case, history)
    wall = solver_wall_time(case_dir)
    log = pathlib.Path(case_dir) / "log.pimpleDLMFoam"
    return [
        f"ten Cate {case} ({case_dir}):",
        f"  u_max      {u_max:.5f} m/s",
        f"  experiment {tenCate.CASES[case][2]:.5f} m/s: error {100*error:+.1f} %",
        f"  wall time  {wall:.0f} s (pimpleDLMFoam, {log})" if wall is not None
        else f"  wall time  unknown (no ClockTime in {log})",
        f"  plot       {pathlib.Path(output).resolve()}",
    ]


def main():
    if len(sys.argv) not in (3, 4) or sys.argv[2] not in tenCate.CASES:
        sys.exit(__doc__)
    case_dir, case = pathlib.Path(sys.argv[1]), sys.argv[2]
    output = pathlib.Path(sys.argv[3]) if len(sys.argv) > 3 \
        else case_dir / f"tenCate_{case}.png"
    history = Case(case_dir, env={}).history()["sphere"]
    tenCate.plot(case, {"pimpleDLMFoam": history}, output)
    print("\n".join(report(case, case_dir, history, output)))


if __name__ == "__main__":
    main()
