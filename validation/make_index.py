#!/usr/bin/env python3
"""Write the table of validation/README.md (between its markers
<!-- index: begin --> and <!-- index: end -->) from validation/results/*.csv,
or with --check compare it and exit 1, printing the difference, when the
README's table is not the one the results give.

Each row below is a case: what it checks, the reference, the target, the
result at the recommended setting, the cost and the link to the case's page
(validation/cases/<case>.md). Cells computed from a results file name it in
their function (`rows("tenCate.csv", ...)`). Cells marked HAND are written
here by hand, because no results file holds them (the heavy sphere, the
mixed pile, the viscous-number limit; parts of other rows, such as a bound
from the literature): change them here when the case's page changes.

    validation/make_index.py [--check] [--readme PATH]
"""

import argparse
import csv
import difflib
import math
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
RESULTS = ROOT / "validation" / "results"
README = ROOT / "validation" / "README.md"
BEGIN = "<!-- index: begin (written by validation/make_index.py from results/*.csv) -->"
END = "<!-- index: end -->"
HEADER = ("| case | what it checks | reference | target | result at the recommended setting "
          "| cost | page |\n|---|---|---|---|---|---|---|")


def HAND(text):
    """A cell written by hand: no results file holds it."""
    return text


# * * * * * * * * * * * * * * * * * Reading * * * * * * * * * * * * * * * * * //

def number(text):
    try:
        return float(text)
    except ValueError:
        return text


def rows(name, **where):
    """The rows of results/<name> whose columns equal the given values
    (numbers compared as numbers), as dicts of numbers and strings."""
    with open(RESULTS / name, newline="") as table:
        found = [{k: number(v) for k, v in row.items()} for row in csv.DictReader(table)]
    return [row for row in found
            if all(row[k] == v or (isinstance(row[k], float) and isinstance(v, (int, float))
                                   and math.isclose(row[k], v)) for k, v in where.items())]


def one(name, **where):
    found = rows(name, **where)
    if len(found) != 1:
        raise SystemExit(f"results/{name}: {len(found)} rows where {where}, expected one")
    return found[0]


# * * * * * * * * * * * * * * * * Formatting * * * * * * * * * * * * * * * * //

def pct(x, digits=1):
    """A relative difference as a signed percentage: +1.3 %."""
    text = f"{100*x:+.{digits}f}"
    if float(text) == 0:
        text = f"{0:.{digits}f}"
    return text + " %"


def pct_abs(x, digits=2):
    return f"{100*abs(x):.{digits}f} %"


def duration(seconds):
    """Wall time as s, min or h, two significant figures or so."""
    if seconds < 300:
        return f"{seconds:.0f} s"
    if seconds < 5400:
        return f"{seconds/60:.0f} min"
    return f"{seconds/3600:.1f} h"


def sci(x):
    """1.8e-4, as the pages write it."""
    mantissa, exponent = f"{x:.1e}".split("e")
    return f"{mantissa}e{int(exponent)}"


def minutes_range(values):
    low, high = min(values)/60, max(values)/60
    return f"{low:.0f}-{high:.0f} min"


def observed_order(n, error):
    """Least-squares slope of log|error| against log h (h = 1/N), as
    validation/common.py's observed_order."""
    x = [math.log(1/v) for v in n]
    y = [math.log(abs(e)) for e in error]
    mx, my = sum(x)/len(x), sum(y)/len(y)
    return (sum((a - mx)*(b - my) for a, b in zip(x, y))
            / sum((a - mx)**2 for a in x))


# * * * * * * * * * * * * * * * * * * Rows * * * * * * * * * * * * * * * * * //

def disk_stokes():
    runs = sorted(rows("diskStokes.csv", mixedCells="interpolated", viscousNumber=20.0),
                  key=lambda r: r["cellsPerDiameter"])
    by_n = {int(r["cellsPerDiameter"]): r for r in runs}
    order = observed_order([r["cellsPerDiameter"] for r in runs], [r["relError"] for r in runs])
    return ("disk between walls, Stokes flow (2D)", "terminal velocity, order",
            "analytic (FEM)", "1 % at N = 16, order >= 1.5",
            f"{pct(by_n[16]['relError'], 2)} at N = 16, order {order:.1f} (viscous number 20)",
            f"N = 16: {duration(by_n[16]['wallTime_s'])}", "diskStokes")


def ten_cate():
    runs = {r["case"]: r for r in rows("tenCate.csv", cellsPerDiameter=12, stepFactor=1)}
    others = [runs[c]["relError"] for c in ("E2", "E3", "E4")]
    return ("ten Cate settling sphere, Re 1.5-32", "peak velocity u_max", "experiment",
            "2 %",
            f"N = 12: E2-E4 {pct(min(others), 2)} to {pct(max(others), 2)}; "
            f"E1 {pct(runs['E1']['relError'])} "
            + HAND("(bound: -3.4 %)"),
            f"N = 12: {minutes_range([r['wallTime_s'] for r in runs.values()])}, 2 ranks",
            "tenCate")


def duct_sphere():
    def drag(method, n):
        return one("ductSphere.csv", case="E1", method=method, cellsPerDiameter=n,
                   speed=0.036)
    fitted = [drag("bodyFitted", n)["drag"] for n in (24, 48, 96)]
    order = math.log((fitted[1] - fitted[0])/(fitted[2] - fitted[1]))/math.log(2)
    limit = fitted[2] + (fitted[2] - fitted[1])/(2**order - 1)
    coarse, fine = drag("dlm", 8), drag("dlm", 16)
    return ("ten Cate E1's sphere held in an endless duct", "drag with walls as near as E1's",
            "body-fitted OpenFOAM, 24-96 cells per diameter", "-",
            f"{pct(coarse['drag']/limit - 1)} / {pct(fine['drag']/limit - 1)} "
            "at N = 8 / 16",
            f"N = 16: {duration(fine['wallTime_s'])}",
            "tenCate.md#what-e1s-experiment-allows-the-sphere-in-an-endless-duct")


def ten_cate_refined():
    runs = {r["case"]: r for r in rows("tenCate_refined.csv")}
    others = [runs[c]["relError"] for c in ("E2", "E3", "E4")]
    return ("ten Cate, refined at the sphere (4 + 2 levels)", "u_max, speed-up", "experiment",
            "2 %, 5 x faster than uniform",
            f"E2-E4 {pct(min(others), 2)} to {pct(max(others), 2)}; "
            f"E1 {pct(runs['E1']['relError'])}",
            HAND("108-210 s alone; 18-23 x faster than uniform N = 16"), "refinement")


def falling_disk():
    refined = rows("fallingDisk.csv", mesh="refined")
    at16 = [r for r in refined if r["finestCellsPerDiameter"] == 16]
    at32 = one("fallingDisk.csv", mesh="refined", finestCellsPerDiameter=32)

    def speed_up(run):
        uniform = one("fallingDisk.csv", mesh="uniform", mu=run["mu"],
                      finestCellsPerDiameter=run["finestCellsPerDiameter"])
        return uniform["wallTime_s"]/run["wallTime_s"]
    ups = [speed_up(r) for r in at16]
    return ("falling disk, refined in the plane (2D)", "settling speed, Re 0.2-2000",
            "uniform mesh of the finest cells", "1 %, 3.2 x faster",
            f"within {pct_abs(max(abs(r['relDifference']) for r in at16))} at 16; "
            f"{pct(at32['relDifference'], 2)} at 32",
            f"{min(ups):.1f}-{max(ups):.1f} x faster at 16, {speed_up(at32):.0f} x at 32",
            "fallingDisk")


def dkt_refined():
    refined = one("DKT_refined.csv")
    uniform = one("DKT.csv", cellsPerDiameter=refined["cellsPerDiameter"])
    kiss = refined["kissTime_s"]/uniform["kissTime_s"] - 1
    overtake = refined["overtakeTime_s"]/uniform["overtakeTime_s"] - 1
    return ("two disks (DKT), refined in the plane (2D)", "kiss and overtake times",
            f"uniform N = {refined['cellsPerDiameter']:.0f}", "2 %, 4 x faster",
            f"kiss {pct(kiss, 2)}, overtake {pct(overtake, 2)}",
            f"{uniform['wallTime_s']/refined['wallTime_s']:.1f} x faster "
            f"({refined['wallTime_s']:.0f} s)", "DKT.md#refined-in-the-plane")


def zick_homsy():
    at16 = rows("zickHomsy.csv", cellsPerDiameter=16)
    met = [r for r in at16 if r["solidFraction"] <= 0.343]
    dense = one("zickHomsy.csv", cellsPerDiameter=16, solidFraction=0.45)
    walls = [r["wallTime_s"] for r in at16]
    return ("simple cubic array, Stokes flow, phi 0.027-0.45", "drag K",
            "Zick & Homsy (1982)", "2 % at N = 16 (phi <= 0.343)",
            f"within {pct_abs(max(abs(r['relError']) for r in met))} at N = 16; "
            f"phi 0.45: {pct(dense['relError'])}",
            f"N = 16: {min(walls):.0f}-{max(walls):.0f} s", "zickHomsy")


# Zick & Homsy's K = 42.1 for touching spheres in a simple cubic array, as
# Lambda (validate_ergun.py's LAMBDA_STOKES)
EPS_CUBIC = 1 - math.pi/6
LAMBDA_STOKES = 3*math.pi*42.1*EPS_CUBIC**3/(1 - EPS_CUBIC)**2


def cubic_packing(re_number):
    def run(n):
        return one("ergun.csv", Re=re_number, cellsPerDiameter=n)
    if re_number == 0.1:
        r = run(32)
        return ("cubic packing, Re 0.1", "Lambda", "Zick & Homsy (exact)", "-",
                f"{pct(r['Lambda']/LAMBDA_STOKES - 1)} at N = 32",
                f"N = 32: {duration(r['wallTime_s'])}", "ergun")
    if re_number == 18:
        r = run(32)
        return ("cubic packing, Re 18", "Lambda", "Ergun", "-",
                f"{pct(r['relErrorErgun'])} at N = 32",
                f"N = 32: {duration(r['wallTime_s'])}", "ergun")
    r = run(16)
    return ("cubic packing, Re 900", "Lambda", "Ergun", "-",
            f"{pct(r['relErrorErgun'], 0)} at N = 16, " + HAND("not converged (the paper: 96)"),
            f"N = 16: {duration(r['wallTime_s'])}", "ergun")


def random_bed():
    n40 = one("randomBed.csv", Re=900, cellsPerDiameter=40)
    n48 = one("randomBed_co1.csv", Re=900, cellsPerDiameter=48)
    return ("random bed (the paper's, 100 spheres), Re 900", "Lambda", "Ergun",
            "5 % (the paper: 7 %)",
            f"{pct(n40['relErrorErgun'])} at N = 40, {pct(n48['relErrorErgun'])} at 48; "
            + HAND("limit 15-30 % below"),
            f"N = 40: {duration(n40['wallTime_s'])}, 48: {duration(n48['wallTime_s'])} "
            "(2 ranks)", "randomBed")


def random_bed_stokes():
    x24 = one("randomBed.csv", Re=0.1, cellsPerDiameter=24)
    return ("random bed, Stokes flow", "Lambda", "Carman-Kozeny 180", "-",
            f"x: {x24['Lambda']:.1f} at N = 24; "
            + HAND("three directions, extrapolated: about 169 (-7 %)"),
            f"N = 24: {duration(x24['wallTime_s'])}", "randomBed.md#stokes-flow-re-01")


def anisotropic_beds():
    def drop(name, bed):
        r = one(name, bed=bed, cellsPerDiameter=16)
        return r["pressureDrop_m2s2"], r["ergun_m2s2"]

    def change(name, bed):
        (run, ergun), (run0, ergun0) = drop(name, bed), drop(name, "uniform42")
        return f"{pct(run/run0 - 1, 0)} (Ergun {pct(ergun/ergun0 - 1, 0)})"
    narrow = [r["wallTime_s"] for r in rows("anisotropicBed.csv", cellsPerDiameter=16)]
    wide = [r["wallTime_s"] for r in rows("anisotropicBed_width2.csv", cellsPerDiameter=16)]
    return ("anisotropic beds, Re 100", "pressure drop against the uniform bed",
            "layered Ergun", "-",
            f"series {change('anisotropicBed.csv', 'series')}; parallel: band 1.3 D "
            f"{change('anisotropicBed.csv', 'parallel')}, 2.7 D "
            f"{change('anisotropicBed_width2.csv', 'parallel')}",
            f"N = 16: {minutes_range(narrow)}; wide box {minutes_range(wide)}",
            "anisotropicBeds")


def heavy_particles():
    return HAND(("heavy sphere falling, rho_s/rho_f 1000", "velocity after 5 diameters",
                 "g t", "1 %", "-0.5 % at N = 6", "20 s", "heavyParticles"))


def sphere_drag():
    def run(re_number, levels):
        return one("sphereDrag_refined.csv", Re=re_number, levels=levels, widthD=12,
                   upstreamD=8, nearCells=8, convection="LUST")
    r16, r32, r300 = run(100, 3), run(100, 4), run(300, 3)
    johnson_patel = HAND(0.656)    # Johnson and Patel (1999), Re 300, mean C_D
    return ("one fixed sphere, Re 100 and 300", "C_D (and C_L)",
            "Schiller-Naumann; Johnson & Patel (1999)", "2 %",
            f"Re 100: {pct(r16['relError'])} / {pct(r32['relError'])} at 16 / 32; "
            f"Re 300: C_D {pct(r300['CD']/johnson_patel - 1)}, C_L {r300['CL']:.3f}",
            f"{duration(r16['wallTime_s'])} / {duration(r32['wallTime_s'])}", "sphereDrag")


def oberbeck():
    at16 = rows("oberbeck.csv", cellsPerMinorDiameter=16)
    spheroids = [r for r in at16 if r["case"] != "1x"]
    aspect2 = [r["wallTime_s"] for r in spheroids if r["case"].startswith("2")]
    aspect4 = [r["wallTime_s"] for r in spheroids if r["case"].startswith("4")]
    return ("held prolate spheroid, Stokes flow, aspect 2 and 4", "drag along and across",
            "Oberbeck, periodic correction", "2 % at N = 16",
            f"within {pct_abs(max(abs(r['relError']) for r in spheroids))} at N = 16",
            f"N = 16: {duration(max(aspect2))} (aspect 2), "
            f"{minutes_range(aspect4)} (aspect 4)", "oberbeck")


def settling_spheroid():
    r = one("settlingSpheroid.csv")
    return ("spheroid settling from 30 degrees tilt, Re 57", "turning broadside",
            "known behaviour", "turns without numerical trouble",
            f"broadside after {r['fallToBroadside_d']:.1f} d of fall; last swing "
            f"{r['rockingAmplitude_deg']:.1f} degrees",
            f"N = {r['cellsPerMinorDiameter']:.0f}: {duration(r['wallTime_s'])}",
            "settlingSpheroid")


def dkt():
    r = one("DKT.csv", cellsPerDiameter=32)
    return ("two disks: drafting, kissing, tumbling (2D)", "kiss and overtake times",
            "Uhlmann (2005)", "5 %",
            f"kiss {pct(r['kissTime_s_relError'])}, overtake "
            f"{pct(r['overtakeTime_s_relError'])} at N = 32",
            f"N = 32: {duration(r['wallTime_s'])}", "DKT")


def restitution():
    at50 = rows("restitution.csv", stepsPerContact=50)
    return ("dry restitution, e 0.1-0.95", "rebound over impact speed", "requested e", "1 %",
            f"within {pct_abs(max(abs(r['relError']) for r in at50))} at 50 sub-steps",
            f"under {math.ceil(max(r['wallTime_s'] for r in at50)):.0f} s a collision",
            "restitution")


def silo():
    members = rows("silo_ensemble_springLimit.csv")
    ours = [r["dlmDEMFoam_rate_kg_s"] for r in members]
    theirs = [r["LIGGGHTS_rate_kg_s"] for r in members]

    def mean_sem(values):
        mean = sum(values)/len(values)
        sd = math.sqrt(sum((v - mean)**2 for v in values)/(len(values) - 1))
        return mean, sd/math.sqrt(len(values))
    (m1, s1), (m0, s0) = mean_sem(ours), mean_sem(theirs)
    spread = math.hypot(s0/m0, s1/m1)
    return ("silo discharge, 2500 dry spheres", "discharge rate", "LIGGGHTS, same packings",
            "5 %", f"{pct(m1/m0 - 1)} +- {pct_abs(spread, 1)} ({len(members)} packings)",
            HAND("2.5 min a discharge (LIGGGHTS 1.5)"), "silo")


def pebble_discharge():
    whole = one("pebbleDischarge.csv", scene="full", medium="wet", chute="tube",
                chuteLength=4, cellsPerDiameter=4)
    longer = one("pebbleDischarge.csv", scene="full", medium="wet", chute="tube",
                 chuteLength=8, cellsPerDiameter=4)
    paper = HAND(60)    # kg/(m2 s), the paper's chute flux
    return ("pebble discharge in water, 2500 pebbles", "chute and bed fluxes",
            "the paper: about 60 and 4 kg/(m2 s)", "15 %",
            f"N = 4, chute 4 d: {whole['chuteFlux']:.1f} ({pct(whole['chuteFlux']/paper - 1, 0)}); "
            f"8 d: {longer['chuteFlux']:.1f} ({pct(longer['chuteFlux']/paper - 1)}, "
            f"first {longer['endTime']:.0f} s)",
            HAND("5.2 h on 2 ranks (whole discharge)"), "pebbleDischarge")


def rising_pebble():
    runs = sorted(rows("risingPebble.csv", boundaryLayerSlip=0),
                  key=lambda r: r["cellsPerDiameter"])
    errors = " / ".join(f"{100*r['relErrorWallCorrected']:.0f}" for r in runs)
    ns = " / ".join(f"{r['cellsPerDiameter']:.0f}" for r in runs)
    return ("one pebble rising alone, Re 9000", "rise velocity",
            "drag curve with the box's wall factor", "-",
            f"{errors} % at N = {ns}",
            f"N = {runs[-1]['cellsPerDiameter']:.0f}: {duration(runs[-1]['wallTime_s'])}",
            "risingPebble")


def mixed_pile():
    return HAND(("mixed pile in water, 24 shapes of four kinds", "coming to rest",
                 "at rest, no jitter", "rest, no energy gain",
                 "at most 0.23 mm/s over 0.4-0.5 s, no energy gain", "458 s (0.5 s)",
                 "mixedPile"))


def shape_fractions():
    runs = rows("benchmark_shapeFractions.csv", cellsPerSmallestDimension=16)
    shaped = [r for r in runs if r["shape"] not in ("sphere", "box aligned")]
    worst = max(shaped, key=lambda r: r["meanMagError"])
    best = min(shaped, key=lambda r: r["meanMagError"])
    return ("solid fractions of non-spherical shapes", "volume error, cost",
            "exact volume", "error stated and tested",
            f"bias {sci(best['meanMagError'])} ({best['shape']}) to "
            f"{sci(worst['meanMagError'])} ({worst['shape']})",
            f"{min(r['timeRatio'] for r in shaped):.1f}-{max(r['timeRatio'] for r in shaped):.0f}"
            " x a sphere's at 16 cells", "shapeFractions")


def shape_contacts():
    runs = rows("benchmark_shapeContacts.csv", method="commonPlane")
    times = [r["microseconds"] for r in runs]
    return ("contacts of non-spherical shapes", "rebound of flat drops, overlap volume",
            "requested e", "2 %", HAND("within 0.3 % (3D), 0.8 % (2D)"),
            f"{min(times):.0f}-{max(times):.0f} us a pair overlap", "shapeContacts")


def overhead():
    free = one("benchmark_overhead.csv", particles=100, motion="free")
    fixed = one("benchmark_overhead.csv", particles=100, motion="fixed")
    return ("cost of the particle work", "share of a step, 48^3 cells", "pimpleFoam",
            "15 % of a step",
            f"{pct_abs(free['particleWorkShare'], 1)} (100 free spheres), "
            f"{pct_abs(fixed['particleWorkShare'], 1)} (100 fixed)",
            f"{free['secondsPerStep']:.2f} s a step (100 free)", "overhead")


def contact_cost():
    runs = rows("benchmark_contact.csv")
    smallest = min(runs, key=lambda r: r["particles"])
    largest = max(runs, key=lambda r: r["particles"])
    liggghts = [r["time_ratio"] for r in rows("benchmark_contact_liggghts.csv")]
    return ("cost of the contacts, 10^3-10^5 spheres", "cost per particle-sub-step",
            "LIGGGHTS", "within 1.5 x over the sizes",
            f"{largest['us_per_particle_subStep']/smallest['us_per_particle_subStep']:.2f} x; "
            f"LIGGGHTS {min(liggghts):.1f}-{max(liggghts):.1f} x faster",
            f"{largest['cpuTime_s']:.0f} s of CPU at 10^5 (10 steps)", "contactCost")


def allocation():
    runs = sorted(rows("benchmark_allocation.csv"), key=lambda r: r["cells"])
    return ("memory allocation on large meshes", "time per step", "glibc's defaults", "-",
            f"{runs[-1]['speedUp']:.2f} x faster at {runs[-1]['cells']/1e6:.1f} M cells, "
            f"{runs[0]['speedUp']:.2f} x at {runs[0]['cells']/1e6:.2f} M",
            f"{runs[-1]['secondsPerStepDefault']:.1f} s a step at "
            f"{runs[-1]['cells']/1e6:.1f} M", "allocation")


def viscous_limit():
    return HAND(("viscous-number limit in long cells", "largest stable viscous number",
                 "-", "-", "3 correctors: 50 (A <= 2), 5 (A = 3), 3 (A = 4.5-8)", "-",
                 "viscousLimit"))


def free_sphere():
    recommended = one("freeSphere.csv", Ga=144, baseCellsPerDiameter=4, widthD=10,
                      refineInterval=20, surfaceBandCells=3)
    oblique = one("freeSphere.csv", Ga=178.46, baseCellsPerDiameter=4, widthD=10,
                  refineInterval=20)
    return ("free sphere, Re 185-365", "terminal speed, path",
            "Uhlmann & Dusek (2014)", "2 % (Ga 144, 178)",
            f"Ga 144: {pct(recommended['uV_error'], 1)} at 16 cells per diameter at the"
            f" surface, box 10 d wide (mesh changes {recommended['meshChangeShare']:.0f} %"
            f" of the run); Ga 178 {pct(oblique['uV_error'], 1)}, its oblique angle not"
            f" reached ({oblique['angle_deg']:.1f} against {oblique['angle_reference']:.1f}"
            " degrees in a closed box; 14.8 held in a stream, the sphere spinning)",
            duration(recommended["wallTime_s"]), "freeSphere")


ROWS = [disk_stokes, ten_cate, duct_sphere, ten_cate_refined, falling_disk, dkt_refined,
        zick_homsy, lambda: cubic_packing(0.1), lambda: cubic_packing(18),
        lambda: cubic_packing(900), random_bed, random_bed_stokes, anisotropic_beds,
        heavy_particles, sphere_drag, free_sphere, oberbeck, settling_spheroid, dkt,
        restitution, silo, pebble_discharge, rising_pebble, mixed_pile, shape_fractions,
        shape_contacts, overhead, contact_cost, allocation, viscous_limit]


def link(page):
    target = page if page.endswith(".md") or ".md#" in page else f"{page}.md"
    name = target.split(".md")[0]
    return f"[{name}](cases/{target})"


def table():
    lines = [HEADER]
    for make in ROWS:
        *cells, page = make()
        lines.append("| " + " | ".join(list(cells) + [link(page)]) + " |")
    return "\n".join(lines)


def split(text, readme=README):
    """(before, table, after) of the README around the markers."""
    try:
        start = text.index(BEGIN) + len(BEGIN)
        stop = text.index(END, start)
    except ValueError:
        raise SystemExit(f"{readme}: the markers {BEGIN!r} and {END!r} not found")
    return text[:start], text[start:stop], text[stop:]


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--check", action="store_true",
                        help="compare the README's table with the results; exit 1 if they differ")
    parser.add_argument("--readme", type=pathlib.Path, default=README,
                        help="the index to write or check (default: validation/README.md)")
    args = parser.parse_args()
    readme = args.readme
    text = readme.read_text()
    before, current, after = split(text, readme)
    wanted = "\n" + table() + "\n"
    if args.check:
        if current != wanted:
            sys.stdout.writelines(difflib.unified_diff(
                current.splitlines(True), wanted.splitlines(True),
                f"{readme} (as written)", f"{readme} (from the results)"))
            print("\nThe index does not match results/*.csv: run validation/make_index.py")
            return 1
        return 0
    if current != wanted:
        readme.write_text(before + wanted + after)
        print(f"wrote the index of {readme}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
