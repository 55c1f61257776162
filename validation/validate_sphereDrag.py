#!/usr/bin/env python3
"""Drag of one fixed sphere in a uniform stream at finite Reynolds number
against the Schiller-Naumann correlation (reference README section 6): a
check of the method's inertial flow on its own, apart from packings.

The sphere (D = 4 mm) sits 4 D behind the inlet of a 12 D x 6 D x 6 D box
(tutorials/cubicBed's boundaries: fixed inflow U = 0.5 m/s, fixed pressure
at the outlet, periodic sides, so a lateral array at 6 D spacing, 2.2 %
blockage), Re = U D/nu. C_D = F/(rho U^2 pi D^2/8) from the particle
history, averaged over the last fifth of 30 D/U; its drift over that
window is reported. Writes results/sphereDrag.csv.

--levels L refines the mesh at the sphere: N is then the base
mesh's cells per diameter, the sphere's surface band (particleSurface,
3 fine cells out, 1 in) gets N 2^L, the near wake (vorticity above 0.2
U/R) N 2^(L-1) and the far wake (above 0.05 U/R) N 2^(L-2); --box W,L
sets the box's width and length in diameters (the sphere 4 D behind the
inlet), to show how far the lateral array's confinement moves C_D. Those
runs go to results/sphereDrag_refined.csv, with the lift coefficient C_L =
|F_lateral|/(rho U^2 pi D^2/8) over the same window and its range: above
Re 210 the wake leaves the axis (Johnson & Patel 1999: steady and oblique
up to about 270, then shedding; at Re 300 mean C_D 0.656, C_L 0.069).
--duration sets the run's length in D/U (30), --offset moves the sphere
off the mesh's symmetry by (0, 1, 2) times that many diameters, so that
the wake's symmetry breaks at once rather than when round-off has grown;
--upstream sets the sphere's distance behind the inlet in diameters (4);
--near K adds a band of K level-1 cells about the sphere (particleSurface at
level 1), so that the potential flow about it is not left to the base;
--convection sets the velocity's convection scheme (CONVECTION: the
tutorials' limitedLinearV 1, LUST, linear), to see what it does to a wake.

    validation/validate_sphereDrag.py [--re 20,100] [--levels L] [--box 6,12]
                                      [--duration 30] [--offset 0]
                                      [--upstream 4] [--near 0]
                                      [--convection limitedLinearV] [N ...]
                                      (default N = 8 12)
"""

import argparse
import math
import re

import numpy as np

from common import (Case, RESULTS, ROOT, RUNS, foam_environment, merge_row,
                    refinement_dict, timed_run)

TABLE = RESULTS / "sphereDrag.csv"
HEADER = ["Re", "cellsPerDiameter", "CD", "CD_SchillerNaumann", "relError", "drift",
          "wallTime_s", "steps"]
REFINED_TABLE = RESULTS / "sphereDrag_refined.csv"
REFINED_HEADER = ["Re", "baseCellsPerDiameter", "levels", "surfaceCellsPerDiameter",
                  "widthD", "lengthD", "CD", "CD_SchillerNaumann", "relError", "drift",
                  "wallTime_s", "steps", "lastCells", "CL", "CLrange", "durationDU",
                  "offsetD", "upstreamD", "nearCells", "convection"]
D, U = 0.004, 0.5
LENGTH, WIDTH, CENTRE = 12, 6, 4       # in diameters
CONVECTION = {"limitedLinearV": "Gauss limitedLinearV 1",
              "LUST": "Gauss LUST grad(U)",
              "linear": "Gauss linear"}

def schiller_naumann(re_number):
    return 24/re_number*(1 + 0.15*re_number**0.687)


def make_case(re_number, n, env, levels=0, width=WIDTH, length=LENGTH, duration=30,
              offset=0.0, upstream=CENTRE, near=0, convection="limitedLinearV"):
    name = f"sphereDrag_Re{re_number:g}_N{n}"
    if levels:
        name += f"_ref{levels}_box{width}x{length}"
    if duration != 30 or offset:
        name += f"_{duration:g}DU_offset{offset:g}"
    if upstream != CENTRE:
        name += f"_upstream{upstream:g}"
    if near:
        name += f"_near{near:g}"
    if convection != "limitedLinearV":
        name += f"_{convection}"
    case = Case.copy(ROOT / "tutorials" / "cubicBed", RUNS / name, env)
    L, W = length*D, width*D
    (case.path / "system" / "blockMeshDict").write_text(f"""\
FoamFile {{ version 2.0; format ascii; class dictionary; object blockMeshDict; }}
vertices ((0 0 0) ({L!r} 0 0) ({L!r} {W!r} 0) (0 {W!r} 0)
          (0 0 {W!r}) ({L!r} 0 {W!r}) ({L!r} {W!r} {W!r}) (0 {W!r} {W!r}));
blocks (hex (0 1 2 3 4 5 6 7) ({length*n} {width*n} {width*n}) simpleGrading (1 1 1));
boundary
(
    inlet  {{ type patch; faces ((0 4 7 3)); }}
    outlet {{ type patch; faces ((1 2 6 5)); }}
    bottom {{ type cyclic; neighbourPatch top;   faces ((0 1 5 4)); }}
    top    {{ type cyclic; neighbourPatch bottom; faces ((3 7 6 2)); }}
    back   {{ type cyclic; neighbourPatch front; faces ((0 3 2 1)); }}
    front  {{ type cyclic; neighbourPatch back;  faces ((4 5 6 7)); }}
);
""")
    (case.path / "constant" / "particleProperties").write_text(f"""\
FoamFile {{ version 2.0; format ascii; class dictionary; object particleProperties; }}
particles
{{
    sphere
    {{
        shape       sphere;
        radius      {D/2!r};
        density     2500;
        motion      fixed;
        position    ({upstream*D!r} {W/2 + offset*D!r} {W/2 + 2*offset*D!r});
    }}
}}
""")
    (case.path / "constant" / "bed.dat").unlink()
    nu = U*D/re_number
    properties = case.path / "constant" / "transportProperties"
    properties.write_text("\n".join(
        f"nu              {nu!r};" if line.startswith("nu ") else line
        for line in properties.read_text().splitlines()) + "\n")
    control = case.path / "system" / "controlDict"
    text = control.read_text()
    text = text[:text.index("functions")] + "functions {}\n"
    end = duration*D/U
    text = "\n".join(
        f"endTime         {end!r};" if line.startswith("endTime ") else
        f"writeInterval   {end!r};" if line.startswith("writeInterval ") else line
        for line in text.splitlines()) + "\n"
    control.write_text(text)
    case.run("foamDictionary", "system/fvSchemes", "-entry", "divSchemes/div(phi,U)",
             "-set", CONVECTION[convection], log="foamDictionary")
    if levels:
        (case.path / "constant" / "dynamicMeshDict").write_text(refinement_dict(
            f"        surface  {{ type particleSurface; level {levels}; }}\n"
            f"        nearWake {{ type vorticity; level {max(levels - 1, 1)};"
            " threshold 0.2; }\n"
            f"        farWake  {{ type vorticity; level {max(levels - 2, 1)};"
            " threshold 0.05; }"
            + (f"\n        nearField {{ type particleSurface; level 1; cells {near:g}; }}"
               if near else "")))
    case.run("blockMesh")
    return case


def last_cell_count(case):
    """Cells of the last mesh of a refined run (its log's last change)."""
    changes = re.findall(r"^Mesh changed: (\d+) cells",
                         (case.path / "log.pimpleDLMFoam").read_text(), re.M)
    return int(changes[-1])


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--re", default="20,100")
    parser.add_argument("--levels", type=int, default=0)
    parser.add_argument("--box", default=f"{WIDTH},{LENGTH}")
    parser.add_argument("--duration", type=float, default=30)
    parser.add_argument("--offset", type=float, default=0.0)
    parser.add_argument("--upstream", type=float, default=CENTRE)
    parser.add_argument("--near", type=float, default=0)
    parser.add_argument("--convection", choices=CONVECTION, default="limitedLinearV")
    parser.add_argument("resolutions", nargs="*", type=int, default=[8, 12])
    args = parser.parse_args()
    options = {"--box": args.box != f"{WIDTH},{LENGTH}", "--duration": args.duration != 30,
               "--offset": args.offset != 0, "--upstream": args.upstream != CENTRE,
               "--near": args.near != 0, "--convection": args.convection != "limitedLinearV"}
    if not args.levels and any(options.values()):
        parser.error(", ".join(k for k, v in options.items() if v) + " go with --levels"
                     " (results/sphereDrag.csv, of the uniform meshes, has no column for them)")
    width, length = (int(v) for v in args.box.split(","))

    env = foam_environment()
    RESULTS.mkdir(parents=True, exist_ok=True)
    for re_number in [float(r) for r in args.re.split(",")]:
        reference = schiller_naumann(re_number)
        for n in args.resolutions:
            case = make_case(re_number, n, env, args.levels, width, length,
                             args.duration, args.offset, args.upstream, args.near,
                             args.convection)
            seconds = timed_run(case, "pimpleDLMFoam")
            h = case.history()["sphere"]
            t, drag = h[:, 0], h[:, 10]
            window = t >= 0.8*t[-1]
            reference_force = 1000*U**2*math.pi*D**2/8
            cd = drag[window]/reference_force
            cl = np.hypot(h[window, 11], h[window, 12])/reference_force
            drift = (cd[-1] - cd[0])/cd.mean()
            error = cd.mean()/reference - 1
            if args.levels:
                merge_row(REFINED_TABLE, REFINED_HEADER,
                          [re_number, n, args.levels, n << args.levels, width, length,
                           cd.mean(), reference, error, drift, seconds, len(t),
                           last_cell_count(case), cl.mean(), np.ptp(cl), args.duration,
                           args.offset, args.upstream, args.near, args.convection],
                          key_columns=[0, 1, 2, 3, 4, 5, 15, 16, 17, 18, 19])
            else:
                merge_row(TABLE, HEADER, [re_number, n, cd.mean(), reference, error,
                                          drift, seconds, len(t)])
            print(f"Re={re_number:g} N={n:3d} C_D={cd.mean():.4f} Schiller-Naumann "
                  f"{reference:.4f} ({100*error:+.1f}%) drift={100*drift:+.2f}% "
                  f"C_L={cl.mean():.4f} (range {np.ptp(cl):.4f}) "
                  f"wall={seconds:.0f}s steps={len(t)}", flush=True)


if __name__ == "__main__":
    main()
