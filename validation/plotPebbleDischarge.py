#!/usr/bin/env python3
"""Plot a pebble discharge (tutorials/pebbleDischarge) and print its
figures: the pebble mass flux through the chute and a bed section against
the paper's, their mass balance, and the path of the plot (the discharged
mass, the bed bottom, the pebbles' velocity across the bed early on).

    validation/plotPebbleDischarge.py <caseDir> [output.png]
"""

import pathlib
import sys

import pebbleDischarge


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    case_dir = pathlib.Path(sys.argv[1])
    output = pathlib.Path(sys.argv[2]) if len(sys.argv) > 2 \
        else case_dir / "pebbleDischarge.png"
    s = pebbleDischarge.summary(case_dir)
    pebbleDischarge.plot([s], output)
    print("\n".join(pebbleDischarge.report(case_dir, s)))
    print(f"  plot       {output.resolve()}")


if __name__ == "__main__":
    main()
