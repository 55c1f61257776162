#!/usr/bin/env python3
"""Plot pebble discharges (tutorials/pebbleDischarge) and print their
figures: the pebble mass flux through the chute and a bed section against
the paper's, their mass balance, and the path of the plot (the discharged
mass, the bed bottom, the pebbles' velocity across the bed early on). Two
or more cases go on one plot, for example the wet run and its dry twin:

    validation/plotPebbleDischarge.py <caseDir> [<caseDir> ...] [-o output.png]
        (default output: the first case's pebbleDischarge.png)
"""

import argparse
import pathlib

import pebbleDischarge


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("cases", nargs="+", type=pathlib.Path)
    parser.add_argument("-o", "--output", type=pathlib.Path)
    args = parser.parse_args()
    output = args.output or args.cases[0] / "pebbleDischarge.png"
    summaries = []
    for case_dir in args.cases:
        s = pebbleDischarge.summary(case_dir)
        summaries.append(s)
        print("\n".join(pebbleDischarge.report(case_dir, s)))
    # Labels: the case's name, with its parent's for a subcase (dry)
    labels = None
    if len(args.cases) > 1:
        labels = ["/".join(c.resolve().parts[-2:]) if c.resolve().name == "dry"
                  else c.resolve().name for c in args.cases]
    pebbleDischarge.plot(summaries, output, labels)
    print(f"  plot       {output.resolve()}")


if __name__ == "__main__":
    main()
