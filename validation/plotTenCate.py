#!/usr/bin/env python3
"""Plot a ten Cate run against the experiment and print u_max.

    validation/plotTenCate.py <caseDir> <E1|E2|E3|E4> [output.png]
"""

import pathlib
import sys

from common import Case
import tenCate


def main():
    case_dir, case = pathlib.Path(sys.argv[1]), sys.argv[2]
    output = pathlib.Path(sys.argv[3]) if len(sys.argv) > 3 \
        else case_dir / f"tenCate_{case}.png"
    history = Case(case_dir, env={}).history()["sphere"]
    u_max, error = tenCate.summary(case, history)
    tenCate.plot(case, {"pimpleDLMFoam": history}, output)
    print(f"ten Cate {case}: u_max = {u_max:.5f} m/s, experiment "
          f"{tenCate.CASES[case][2]:.5f} m/s ({100*error:+.1f} %); plot {output}")


if __name__ == "__main__":
    main()
