#!/usr/bin/env python3
"""ten Cate's settling sphere in an endless duct of the box's cross-section:
the drag of the sphere moving steadily along the axis, body-fitted against
the DLM, and the terminal velocity that the box's walls allow.

The sphere (d = 15 mm, 1120 kg/m3) moves at u along the axis of a square
duct 100 mm wide (ten Cate's box without its floor and lid) through the
fluid of case E1 to E4 (E1: rho 970 kg/m3, mu 0.373 Pa s; the reference
README). In the sphere's frame this is a steady flow: inflow
and walls at u, the outlet open, the duct 2 L long with the sphere in the
middle. Two codes solve it:

- body-fitted: OpenFOAM alone (snappyHexMesh around the analytic sphere,
  2.5 mm cells across the duct near the sphere, surface level l giving
  3 x 2^l cells per diameter at the sphere; simpleFoam to residuals 1e-8);
- pimpleDLMFoam with the sphere held, on the ten Cate tutorial's graded
  cross-section at N cells per diameter, to a steady state.

The body-fitted drags at two speeds give the terminal velocity in the duct
(drag = net weight (rho_s - rho_f) V g, the drag linear between them). A
sphere released in the closed box, which also has a floor and a lid and
must first accelerate, falls slower than that: it bounds ten Cate's u_max
for these parameters from above. The DLM's drag at the same speed gives its
error at N with the walls as near as in the box. Writes
results/ductSphere.csv.

    validation/validate_ductSphere.py [--case E1] [--speeds 0.034,0.036]
        [--levels 3,4] [--dlm 8,12] [--half-length 0.15]
"""

import argparse
import collections
import math
import re
import shutil

from common import Case, RESULTS, ROOT, RUNS, foam_environment, merge_row, timed_run

TABLE = RESULTS / "ductSphere.csv"
HEADER = ["case", "method", "cellsPerDiameter", "halfLength", "speed", "drag", "cells",
          "wallTime_s"]
D, WIDTH, RHO_S, G = 0.015, 0.1, 1120.0, 9.81
# ten Cate et al. (2002): fluid density [kg/m3], kinematic viscosity (mu/rho)
# [m2/s] and the sphere's largest speed in the box [m/s] (reference README)
Fluid = collections.namedtuple("Fluid", "case rho nu u_max")
CASES = {"E1": Fluid("E1", 970.0, 0.373/970, 0.035986),
         "E2": Fluid("E2", 965.0, 0.212/965, 0.05718),
         "E3": Fluid("E3", 962.0, 0.113/962, 0.087269),
         "E4": Fluid("E4", 960.0, 0.058/960, 0.12224)}
FOAM_HEADER = "FoamFile {{ version 2.0; format ascii; class {cls}; object {obj}; }}\n"


def header(cls, obj):
    return FOAM_HEADER.format(cls=cls, obj=obj)


def duct_vertices(half_length):
    w, z = WIDTH/2, half_length
    return (f"vertices ( (-{w} -{w} -{z}) ({w} -{w} -{z}) ({w} {w} -{z}) (-{w} {w} -{z})\n"
            f"           (-{w} -{w} {z}) ({w} -{w} {z}) ({w} {w} {z}) (-{w} {w} {z}) );\n")


DUCT_BOUNDARY = """boundary
(
    inlet  { type patch; faces ((0 3 2 1)); }
    outlet { type patch; faces ((4 5 6 7)); }
    walls  { type wall;  faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)); }
);
"""


def body_fitted_case(fluid, level, speed, half_length, env):
    """The body-fitted case: a 5 mm background, 2.5 mm over 120 mm of the
    duct about the sphere, the surface at level `level`."""
    case = Case(RUNS / (f"ductSphere_{fluid.case}_bodyFitted_l{level}_u{speed:g}"
                        f"_L{half_length:g}"), env)
    if case.path.exists():
        shutil.rmtree(case.path)
    for folder in ("0", "constant", "system"):
        (case.path / folder).mkdir(parents=True)
    files = {
        "system/blockMeshDict": header("dictionary", "blockMeshDict") + duct_vertices(half_length)
        + f"blocks ( hex (0 1 2 3 4 5 6 7) (20 20 {round(2*half_length/0.005)})"
        " simpleGrading (1 1 1) );\n" + DUCT_BOUNDARY,
        "system/snappyHexMeshDict": header("dictionary", "snappyHexMeshDict") + f"""\
castellatedMesh true; snap true; addLayers false;
geometry
{{
    sphere {{ type searchableSphere; centre (0 0 0); radius {D/2}; }}
    near   {{ type searchableSphere; centre (0 0 0); radius {D}; }}
    duct   {{ type searchableBox; min (-0.06 -0.06 -0.06); max (0.06 0.06 0.06); }}
}}
castellatedMeshControls
{{
    maxLocalCells 4000000; maxGlobalCells 8000000; minRefinementCells 0;
    nCellsBetweenLevels 3; maxLoadUnbalance 0.1; features ();
    refinementSurfaces {{ sphere {{ level ({level} {level}); patchInfo {{ type wall; }} }} }}
    resolveFeatureAngle 30;
    refinementRegions
    {{
        duct {{ mode inside; levels ((1 1)); }}
        near {{ mode inside; levels ((1 {level - 1})); }}
    }}
    locationInMesh (0.031 0.032 0.0503);
    allowFreeStandingZoneFaces true;
}}
snapControls {{ nSmoothPatch 3; tolerance 2.0; nSolveIter 50; nRelaxIter 5; nFeatureSnapIter 10; }}
addLayersControls {{ layers {{}} relativeSizes true; expansionRatio 1; finalLayerThickness 0.3;
    minThickness 0.1; nGrow 0; featureAngle 60; nRelaxIter 3; nSmoothSurfaceNormals 1;
    nSmoothNormals 3; nSmoothThickness 10; maxFaceThicknessRatio 0.5;
    maxThicknessToMedialRatio 0.3; minMedianAxisAngle 90; nBufferCellsNoExtrude 0;
    nLayerIter 50; }}
meshQualityControls {{ #includeEtc "caseDicts/mesh/generation/meshQualityDict.cfg" }}
mergeTolerance 1e-6;
""",
        "system/controlDict": header("dictionary", "controlDict") + f"""\
application simpleFoam; startFrom latestTime; startTime 0; stopAt endTime; endTime 5000;
deltaT 1; writeControl timeStep; writeInterval 5000; purgeWrite 0; writeFormat binary;
writePrecision 12; runTimeModifiable false;
functions
{{
    forces
    {{
        type forces; libs ("libforces.so"); patches (sphere); rho rhoInf; rhoInf {fluid.rho};
        CofR (0 0 0); writeControl timeStep; writeInterval 10; log false;
    }}
}}
""",
        "system/fvSchemes": header("dictionary", "fvSchemes") + """\
ddtSchemes { default steadyState; }
gradSchemes { default Gauss linear; }
divSchemes { default none; div(phi,U) bounded Gauss linear;
             div((nuEff*dev2(T(grad(U))))) Gauss linear; }
laplacianSchemes { default Gauss linear limited corrected 0.5; }
interpolationSchemes { default linear; }
snGradSchemes { default limited corrected 0.5; }
""",
        "system/fvSolution": header("dictionary", "fvSolution") + """\
solvers
{
    p { solver GAMG; smoother GaussSeidel; tolerance 1e-10; relTol 0.05; }
    U { solver smoothSolver; smoother GaussSeidel; tolerance 1e-12; relTol 0.1; }
}
SIMPLE { nNonOrthogonalCorrectors 1; consistent yes; residualControl { p 1e-8; U 1e-9; } }
relaxationFactors { equations { U 0.9; } }
""",
        "constant/transportProperties": header("dictionary", "transportProperties")
        + f"transportModel Newtonian; nu {fluid.nu!r};\n",
        "constant/turbulenceProperties": header("dictionary", "turbulenceProperties")
        + "simulationType laminar;\n",
        "0/U": header("volVectorField", "U") + f"""\
dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 {speed});
boundaryField
{{
    inlet  {{ type fixedValue; value uniform (0 0 {speed}); }}
    outlet {{ type zeroGradient; }}
    walls  {{ type fixedValue; value uniform (0 0 {speed}); }}
    sphere {{ type noSlip; }}
}}
""",
        "0/p": header("volScalarField", "p") + """\
dimensions [0 2 -2 0 0 0 0];
internalField uniform 0;
boundaryField
{
    inlet  { type zeroGradient; }
    outlet { type fixedValue; value uniform 0; }
    walls  { type zeroGradient; }
    sphere { type zeroGradient; }
}
""",
    }
    for name, text in files.items():
        (case.path / name).write_text(text)
    return case


def cell_count(case):
    return int(re.search(r"cells:\s+(\d+)", case.run("checkMesh").log).group(1))


def body_fitted_drag(fluid, level, speed, half_length, env):
    case = body_fitted_case(fluid, level, speed, half_length, env)
    seconds = timed_run(case, "blockMesh")
    seconds += timed_run(case, "snappyHexMesh", "-overwrite")
    cells = cell_count(case)
    result = case.run("simpleFoam")
    seconds += float(re.findall(r"ClockTime = ([0-9.]+)", result.log)[-1])
    if "SIMPLE solution converged" not in result.log:
        raise SystemExit(f"{case.path}: simpleFoam did not reach its residuals")
    last = (case.path / "postProcessing/forces/0/force.dat").read_text().splitlines()[-1]
    drag = float(re.findall(r"\(([^)]*)\)", last)[0].split()[2])
    return drag, cells, seconds


def dlm_case(fluid, n, speed, half_length, env):
    """The ten Cate tutorial's case with the sphere held at the duct's centre
    and no gravity; the cross-section graded as the tutorial's, along the
    duct uniform over 60 mm about the sphere and growing by 4 to the ends."""
    case = Case.copy(ROOT / "tutorials" / "tenCate",
                     RUNS / f"ductSphere_{fluid.case}_dlm_N{n}_u{speed:g}_L{half_length:g}", env)
    h = D/n
    centre, side, n_side = graded(0.04, WIDTH, h, 3)
    z_centre, z_side, n_z_side = graded(0.06, 2*half_length, h, 4)

    def blocks(n_mid, mid, s, n_s, growth, total):
        return (f"( ({s/total!r} {n_s} {1/growth!r}) ({mid/total!r} {n_mid} 1)"
                f" ({s/total!r} {n_s} {growth}) )")
    (case.path / "system/blockMeshDict").write_text(
        header("dictionary", "blockMeshDict") + duct_vertices(half_length)
        + f"blocks ( hex (0 1 2 3 4 5 6 7) ({centre + 2*n_side} {centre + 2*n_side}"
        f" {z_centre + 2*n_z_side}) simpleGrading\n  ( "
        + blocks(centre, centre*h, side, n_side, 3, WIDTH) + "\n    "
        + blocks(centre, centre*h, side, n_side, 3, WIDTH) + "\n    "
        + blocks(z_centre, z_centre*h, z_side, n_z_side, 4, 2*half_length) + " ) );\n"
        + DUCT_BOUNDARY)
    (case.path / "0/U").write_text(header("volVectorField", "U") + f"""\
dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 {speed!r});
boundaryField
{{
    inlet  {{ type fixedValue; value uniform (0 0 {speed!r}); }}
    outlet {{ type zeroGradient; }}
    walls  {{ type fixedValue; value uniform (0 0 {speed!r}); }}
}}
""")
    (case.path / "0/p_rgh").write_text(header("volScalarField", "p_rgh") + """\
dimensions [1 -1 -2 0 0 0 0];
internalField uniform 0;
boundaryField
{
    inlet  { type fixedFluxPressure; value uniform 0; }
    outlet { type fixedValue; value uniform 0; }
    walls  { type fixedFluxPressure; value uniform 0; }
}
""")
    edit(case.path / "constant/g", [(r"\(0 0 -9.81\)", "(0 0 0)")])
    edit(case.path / "constant/particleProperties",
         [(r"position\s+\([^)]*\);", "motion      fixed;\n        position    (0 0 0);")])
    edit(case.path / "constant/transportProperties",
         [(r"^rho\s+[^;]*;", f"rho     {fluid.rho};"), (r"^nu\s+[^;]*;", f"nu      {fluid.nu!r};")])
    edit(case.path / "system/fvSolution", [(r"\s*pRefPoint[^;]*;", ""), (r"\s*pRefValue[^;]*;", "")])
    # Steady by 2 s at N = 8 (the drag within 1e-6 of its value at 12 s)
    end = 3
    edit(case.path / "system/controlDict",
         [(r"^endTime\s+[^;]*;", f"endTime         {end};"),
          (r"^writeInterval\s+[^;]*;", f"writeInterval   {end};"),
          (r"^maxDeltaT\s+[^;]*;", "maxDeltaT       0.1;")])
    case.run("blockMesh")
    return case


def graded(centre_length, total, h, growth):
    """Cells over the uniform centre (to a whole number of h), the length of
    each side and the fewest side cells whose first is no larger than h
    when they grow by `growth` to the ends."""
    centre = round(centre_length/h)
    side = (total - centre*h)/2
    cells = 2
    while True:
        q = growth**(1/(cells - 1))
        if side*(q - 1)/(q**cells - 1) <= h:
            return centre, side, cells
        cells += 1


def edit(path, substitutions):
    text = path.read_text()
    for pattern, replacement in substitutions:
        text, count = re.subn(pattern, replacement, text, flags=re.M)
        if not count:
            raise SystemExit(f"{path}: no '{pattern}' to replace")
    path.write_text(text)


def dlm_drag(fluid, n, speed, half_length, env):
    case = dlm_case(fluid, n, speed, half_length, env)
    seconds = timed_run(case, "pimpleDLMFoam")
    rows = case.history()["sphere"]
    drag = rows[-1, 12]
    halfway = rows[rows[:, 0] >= 0.5*rows[-1, 0]][0]
    change = abs(drag - halfway[12])/drag
    if change > 1e-4:
        raise SystemExit(f"{case.path}: the drag still changes ({change:.1e} over the run's"
                         " second half)")
    return drag, cell_count(case), seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--case", choices=CASES, default="E1")
    parser.add_argument("--speeds", default="0.034,0.036")
    parser.add_argument("--levels", default="3,4")
    parser.add_argument("--dlm", default="8,12")
    parser.add_argument("--half-length", type=float, default=0.15)
    args = parser.parse_args()
    fluid = CASES[args.case]
    net_weight = (RHO_S - fluid.rho)*math.pi*D**3/6*G
    speeds = [float(s) for s in args.speeds.split(",")]
    levels = [int(v) for v in args.levels.split(",") if v]
    env = foam_environment()
    RESULTS.mkdir(parents=True, exist_ok=True)
    fitted = {}
    for level in levels:
        for speed in speeds:
            drag, cells, seconds = body_fitted_drag(fluid, level, speed, args.half_length, env)
            fitted[level, speed] = drag
            merge_row(TABLE, HEADER, [fluid.case, "bodyFitted", 3*2**level, args.half_length, speed,
                                      drag, cells, f"{seconds:.0f}"], key_columns=5)
            print(f"body-fitted {3*2**level:3d} cells/d  u {speed:.4f}  drag {drag:.6e} N"
                  f"  ({cells} cells, {seconds:.0f} s)", flush=True)
        if len(speeds) >= 2:
            (u0, f0), (u1, f1) = [(u, fitted[level, u]) for u in speeds[:2]]
            terminal = u0 + (net_weight - f0)*(u1 - u0)/(f1 - f0)
            print(f"  terminal velocity in the duct {terminal:.5f} m/s:"
                  f" {100*(terminal/fluid.u_max - 1):+.2f} % against ten Cate's u_max"
                  f" {fluid.u_max} (net weight {net_weight:.5e} N)", flush=True)
    reference_level = max(levels) if levels else None
    for n in [int(v) for v in args.dlm.split(",") if v]:
        speed = speeds[-1]
        drag, cells, seconds = dlm_drag(fluid, n, speed, args.half_length, env)
        merge_row(TABLE, HEADER, [fluid.case, "dlm", n, args.half_length, speed, drag, cells,
                                  f"{seconds:.0f}"], key_columns=5)
        against = ""
        if (reference_level, speed) in fitted:
            against = (f", {100*(drag/fitted[reference_level, speed] - 1):+.2f} % against the"
                       f" body-fitted {3*2**reference_level} cells/d")
        print(f"DLM {n:3d} cells/d  u {speed:.4f}  drag {drag:.6e} N ({cells} cells,"
              f" {seconds:.0f} s){against}", flush=True)


if __name__ == "__main__":
    main()
