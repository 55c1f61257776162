"""One sphere (d = 10 mm, water) in a box of square section with slip side
walls, in three frames that Galilean invariance makes equivalent:

- "held": the sphere fixed, the fluid entering through the bottom at the
  speed and leaving through the top;
- "prescribed": the box closed, the fluid at rest, the sphere moving down at
  the speed;
- "free": the box closed, the sphere released under gravity (density ratio
  rho_s/rho_f), optionally started at the speed.

Slip side walls move with either frame, so the flow about the sphere is the
same in all three; the held sphere's drag at a speed is the weight less the
buoyancy that a free sphere settling at that speed must have. Used by
tests/test_freeParticles.py and validation/validate_freeSphere.py."""

import math

D = 0.01
RHO_FLUID = 1000.0
G = 9.81

HEADER = "FoamFile {{ version 2.0; format ascii; class {cls}; object {obj}; }}\n"


def gravitational_speed(density_ratio):
    """u_g = sqrt(|rho_s/rho_f - 1| g d)."""
    return math.sqrt(abs(density_ratio - 1)*G*D)


def viscosity_for_galileo(galileo, density_ratio):
    """nu for Ga = u_g d/nu."""
    return gravitational_speed(density_ratio)*D/galileo


def write(case, relative, cls, obj, body):
    path = case.path / relative
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(HEADER.format(cls=cls, obj=obj) + body)


def sphere_in_box(case, mode, n, speed, nu, density_ratio=1.5, width=4,
                  below=6, above=12, end_time=None, max_co=0.5, levels=0,
                  convection="Gauss LUST grad(U)", start_speed=None,
                  write_interval=None, refine_interval=3, offset=0.0, lateral_speed=0.0,
                  surface_cells=3, periodic_sides=False):
    """Write the case (blockMesh still to run): n cells per diameter on the
    base mesh, with levels of refinement at the sphere's surface (its wake
    one level less; the surface's band surface_cells cells of the finest
    level wide outside it, besides its look-ahead). "held": the box spans
    below and above diameters about the sphere; "prescribed" and "free": it is below + above diameters
    tall, the sphere starting 4 diameters under its lid. end_time defaults
    to the time the sphere moves, or the fluid passes it, by 3/4 of the
    box's height less 5 diameters. A free sphere may start offset diameters
    along x off the axis, moving at lateral_speed along x (an oblique path's
    start, away from the nearer wall). periodic_sides makes the side walls
    two cyclic pairs (a lateral drift without walls)."""
    assert mode in ("held", "prescribed", "free")
    speed, nu, density_ratio, max_co = (float(v) for v in (speed, nu, density_ratio, max_co))
    width, below, above = float(width), float(below), float(above)
    if start_speed is not None:
        start_speed = float(start_speed)
    height = below + above
    half = width*D/2
    if mode == "held":
        z_low, z_high, centre = -below*D, above*D, 0.0
    else:
        z_low, z_high, centre = 0.0, height*D, (height - 4)*D
    nx, nz = round(width*n), round(height*n)
    if end_time is None:
        end_time = (0.75*height - 5)*D/speed
    end_time = float(end_time)
    write_interval = end_time if write_interval is None else float(write_interval)

    sides = ("xLow { type cyclic; neighbourPatch xHigh; faces ((0 4 7 3)); }\n"
             "    xHigh { type cyclic; neighbourPatch xLow; faces ((1 2 6 5)); }\n"
             "    yLow { type cyclic; neighbourPatch yHigh; faces ((0 1 5 4)); }\n"
             "    yHigh { type cyclic; neighbourPatch yLow; faces ((3 7 6 2)); }"
             if periodic_sides else
             "sides { type patch; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)); }")
    for name in ("system", "constant", "0"):
        (case.path / name).mkdir(parents=True, exist_ok=True)
    write(case, "system/blockMeshDict", "dictionary", "blockMeshDict", f"""
vertices
(
    ({-half!r} {-half!r} {z_low!r}) ({half!r} {-half!r} {z_low!r})
    ({half!r} {half!r} {z_low!r}) ({-half!r} {half!r} {z_low!r})
    ({-half!r} {-half!r} {z_high!r}) ({half!r} {-half!r} {z_high!r})
    ({half!r} {half!r} {z_high!r}) ({-half!r} {half!r} {z_high!r})
);
blocks (hex (0 1 2 3 4 5 6 7) ({nx} {nx} {nz}) simpleGrading (1 1 1));
boundary
(
    {sides}
    bottom {{ type {"patch" if mode == "held" else "wall"}; faces ((0 3 2 1)); }}
    top {{ type {"patch" if mode == "held" else "wall"}; faces ((4 5 6 7)); }}
);
""")
    write(case, "system/controlDict", "dictionary", "controlDict", f"""
application     pimpleDLMFoam;
startFrom       latestTime;
startTime       0;
stopAt          endTime;
endTime         {end_time!r};
deltaT          1e-4;
adjustTimeStep  yes;
maxCo           {max_co!r};
maxDeltaT       0.01;
writeControl    adjustableRunTime;
writeInterval   {write_interval!r};
writeFormat     binary;
writePrecision  17;
timeFormat      general;
timePrecision   8;
runTimeModifiable false;
progressInterval 0;
""")
    write(case, "system/fvSchemes", "dictionary", "fvSchemes", f"""
ddtSchemes {{ default backward; }}
gradSchemes {{ default Gauss linear; }}
divSchemes {{ default none; div(phi,U) {convection}; }}
laplacianSchemes {{ default Gauss linear corrected; }}
interpolationSchemes {{ default linear; }}
snGradSchemes {{ default corrected; }}
""")
    reference = "" if mode == "held" else \
        f"pRefPoint ({half/2!r} {half/2!r} {z_high - 0.5*D/n!r}); pRefValue 0;"
    write(case, "system/fvSolution", "dictionary", "fvSolution", f"""
solvers
{{
    p_rgh {{ solver GAMG; smoother DIC; tolerance 1e-8; relTol 0.01; }}
    p_rghFinal
    {{
        solver PCG;
        preconditioner {{ preconditioner GAMG; smoother DIC; tolerance 0; relTol 0; }}
        tolerance 1e-7;
        relTol 0;
    }}
    "(U|UFinal)" {{ solver PBiCGStab; preconditioner DILU; tolerance 1e-8; relTol 0; }}
}}
PIMPLE
{{
    momentumPredictor yes;
    nOuterCorrectors 1;
    nCorrectors 3;
    nNonOrthogonalCorrectors 0;
    {reference}
}}
""")
    write(case, "system/fvOptions", "dictionary", "fvOptions",
          "rigidProjection { type rigidProjection; mixedCells interpolated; }\n")
    write(case, "system/decomposeParDict", "dictionary", "decomposeParDict",
          "numberOfSubdomains 2;\nmethod metis;\n")
    g = -G if mode == "free" else 0
    write(case, "constant/g", "uniformDimensionedVectorField", "g",
          f"dimensions [0 1 -2 0 0 0 0];\nvalue (0 0 {g!r});\n")
    write(case, "constant/transportProperties", "dictionary", "transportProperties",
          f"rho {RHO_FLUID!r};\nnu {nu!r};\n")
    motion = {
        "held": "motion fixed;",
        "prescribed": f"motion prescribed; velocity (0 0 {-speed!r});",
        "free": "" if start_speed is None else
                f"velocity ({float(lateral_speed)!r} 0 {-start_speed!r});",
    }[mode]
    # Off the mesh's symmetry by a hundredth of a diameter, so that an
    # unstable wake leaves the axis at once rather than from round-off
    write(case, "constant/particleProperties", "dictionary", "particleProperties", f"""
particles
{{
    sphere
    {{
        shape sphere;
        radius {D/2!r};
        density {density_ratio*RHO_FLUID!r};
        position ({(float(offset) + 0.01)*D!r} {-0.007*D!r} {centre!r});
        {motion}
    }}
}}
""")
    if levels:
        write(case, "constant/dynamicMeshDict", "dictionary", "dynamicMeshDict", f"""
dynamicFvMesh dlmRefineFvMesh;
dynamicRefineFvMeshCoeffs
{{
    refineInterval {refine_interval};
    nBufferLayers 1;
    maxCells 4000000;
    dumpLevel true;
    correctFluxes
    (
        (phi none) (phi_0 none) (phi_0_0 none) (ghf none) (UBlendingFactor none)
    );
    targets
    {{
        surface {{ type particleSurface; level {levels}; cells {surface_cells}; }}
        wake {{ type vorticity; level {max(levels - 1, 1)}; threshold 0.2; }}
    }}
}}
""")
    side_type = '"(xLow|xHigh|yLow|yHigh)" { type cyclic; }' if periodic_sides else None
    if mode == "held":
        u_sides = side_type or "sides { type slip; }"
        u_ends = (f"bottom {{ type fixedValue; value uniform (0 0 {speed!r}); }}\n"
                  f"    top {{ type inletOutlet; inletValue uniform (0 0 0);"
                  f" value uniform (0 0 {speed!r}); }}")
        p_ends = "bottom { type zeroGradient; }\n    top { type fixedValue; value uniform 0; }"
        u_internal = f"(0 0 {speed!r})"
    else:
        u_sides = side_type or "sides { type slip; }"
        u_ends = "bottom { type noSlip; }\n    top { type noSlip; }"
        p_ends = ("bottom { type fixedFluxPressure; value uniform 0; }\n"
                  "    top { type fixedFluxPressure; value uniform 0; }")
        u_internal = "(0 0 0)"
    write(case, "0/U", "volVectorField", "U", f"""
dimensions [0 1 -1 0 0 0 0];
internalField uniform {u_internal};
boundaryField
{{
    {u_sides}
    {u_ends}
}}
""")
    write(case, "0/p_rgh", "volScalarField", "p_rgh", f"""
dimensions [1 -1 -2 0 0 0 0];
internalField uniform 0;
boundaryField
{{
    {side_type or "sides { type zeroGradient; }"}
    {p_ends}
}}
""")
    return case
