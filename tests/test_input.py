"""Bad input stops the solver with a clear error naming the file, the keyword
and the particle: never a signal, never a silent run.

BAD_INPUT is the table of cases. Each row is one line: an id, the edits of a
meshed copy of a test case (functions of the Case, from the helpers below),
and the texts the log must hold; options choose the case (source), the
solver and the number of processes (np). Every row must exit non-zero
without a signal."""

import pathlib
import re
import shutil
from dataclasses import dataclass

import pytest

from foamcase import Case

HERE = pathlib.Path(__file__).parent
SOURCES = {
    "sphereBox": HERE / "cases" / "sphereBox",           # 3D, 18x18x27 cells of 1.67 mm
    "fallingDisk": HERE.parent / "tutorials" / "fallingDisk",   # 2D
}

HEADER = "FoamFile {{ version 2.0; format ascii; class dictionary; object {}; }}\n"
GOOD = "shape sphere; radius 0.005; density 2000; position (0.015 0.015 0.025);"
PAIR = ("materials (particle wall); law overlapVolume; stiffness 1e9;"
        " restitution 0.5; friction 0.3;")
PAIRS = "pairs { pw { " + PAIR + " } }"
BOTH_PAIRS = ("pairs { pw { " + PAIR + " } pp { "
              + PAIR.replace("wall", "particle") + " } }")
CONTROL = "system/controlDict"
SIGNALS = ("sigFpe", "Floating point exception", "Segmentation")


# Edits of a case

def particles(body, extra=""):
    """constant/particleProperties with these particles (and extra
    top-level entries)."""
    return write("constant/particleProperties",
                 HEADER.format("particleProperties")
                 + "particles\n{\n" + body + "\n}\n" + extra)


def contact(body):
    """One good sphere with these contact settings."""
    return particles("sphere { " + GOOD + " }", "contact\n{\n" + body + "\n}\n")


def write(file, text):
    def edit(case):
        path = case.path / file
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return edit


def append(file, text):
    def edit(case):
        path = case.path / file
        path.write_text(path.read_text() + text)
    return edit


def setting(file, entry, value):
    """Set (or add) a dictionary entry with foamDictionary."""
    return lambda case: case.set(file, entry, value)


def remove(file):
    return lambda case: (case.path / file).unlink()


def start_at(time):
    """The initial fields moved from 0 to the given time, started from."""
    def edit(case):
        (case.path / "0").rename(case.path / time)
        case.set(CONTROL, "startFrom", "startTime")
        case.set(CONTROL, "startTime", time)
    return edit


def replace(file, old, new):
    def edit(case):
        path = case.path / file
        assert old in path.read_text(), f"'{old}' not in {file}"
        path.write_text(path.read_text().replace(old, new))
    return edit


def blocks(cells):
    """Mesh the case again with these cells in blockMeshDict's block."""
    def edit(case):
        replace("system/blockMeshDict", "(18 18 27)", cells)(case)
        case.run("blockMesh")
    return edit


def decompose(n):
    """decomposeParDict for n processors stacked along z."""
    return write("system/decomposeParDict", HEADER.format("decomposeParDict")
                 + f"numberOfSubdomains {n};\nmethod simple;\ncoeffs {{ n (1 1 {n}); }}\n")


def particle_file(lines):
    return (write("constant/packing.dat", "# x y z radius\n" + lines),
            write("constant/particleProperties", HEADER.format("particleProperties")
                  + 'particleFile "constant/packing.dat";\n'
                  "particleFileDefaults { shape sphere; density 2000; }\n"))


def surface_wall(stl, extra=""):
    """A good sphere with a contact-only STL wall 'funnel' of this text."""
    return (write("constant/triSurface/funnel.stl", stl),
            contact(PAIRS + ' walls { funnel { type surface; file "funnel.stl";'
                    + extra + ' } }'))


TRIANGLE = ("solid funnel\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n"
            "   vertex 1 0 0\n   vertex 0 1 0\n  endloop\n endfacet\nendsolid funnel\n")


@dataclass
class Bad:
    edits: tuple
    expected: tuple
    source: str = "sphereBox"
    solver: str = "pimpleDLMFoam"
    np: int = 1


def bad(id, edits, *expected, **options):
    """A row of the table: edits is an edit or a tuple of them."""
    edits = edits if isinstance(edits, tuple) else (edits,)
    return pytest.param(Bad(edits, expected, **options), id=id)


BAD_INPUT = [
    # Particles
    bad("radius missing", particles("sphere { shape sphere; density 2000; position (0.015 0.015 0.025); }"),
        "'radius'", "particleProperties.particles.sphere"),
    bad("radius negative", particles("sphere { shape sphere; radius -0.005; density 2000; position (0.015 0.015 0.025); }"),
        "radius -0.005", "of particle sphere must be positive", "particleProperties"),
    bad("density zero", particles("sphere { shape sphere; radius 0.005; density 0; position (0.015 0.015 0.025); }"),
        "density 0 of particle sphere must be positive", "particleProperties"),
    bad("particle keyword misspelt", particles("sphere { " + GOOD + " raduis 0.005; }"),
        "Unknown keyword 'raduis' for particle sphere", "particleProperties"),
    bad("shape unknown", particles("sphere { " + GOOD.replace("sphere;", "cube;") + " }"),
        "cube", "sphere", "disk", "particleProperties"),
    bad("particle outside the mesh", particles("sphere { " + GOOD.replace("(0.015 ", "(0.1 ") + " }"),
        "Particle sphere", "outside the mesh", "particleProperties"),
    bad("particles overlap", particles("a { " + GOOD + " } b { " + GOOD.replace("0.025)", "0.033)") + " }"),
        "Particles a and b", "overlap", "particleProperties"),
    bad("motion unknown", particles("sphere { " + GOOD + " motion floating; }"),
        "floating", "free", "fixed", "prescribed"),
    bad("motion prescribed without velocity", particles("sphere { " + GOOD + " motion prescribed; }"),
        "Particle sphere has motion prescribed but neither 'velocity' nor 'angularVelocity'",
        "motion fixed", "particleProperties.particles.sphere"),
    bad("orientation zero", particles("sphere { " + GOOD + " orientation (0 (0 0 0)); }"),
        "orientation (0 (0 0 0)) of particle sphere is the zero quaternion", "(1 (0 0 0))",
        "particleProperties.particles.sphere"),
    bad("sphere on a 2D mesh", particles("ball { shape sphere; radius 0.01; density 2500; position (0.1 0.3 0); }"),
        "Particle ball", "3D but the mesh is 2D", source="fallingDisk"),
    bad("disk velocity out of the plane",
        particles("coin { shape disk; radius 0.01; density 2500; position (0.1 0.3 0); velocity (0 0 0.5); }"),
        "Particle coin", "velocity (0 0 0.5) and angularVelocity (0 0 0) must lie in the 2D mesh's plane",
        source="fallingDisk"),
    bad("gravity out of the 2D plane", setting("constant/g", "value", "(0 -9.81 1)"),
        "constant/g", "value (0 -9.81 1) has a component along z, the 2D mesh's empty direction",
        source="fallingDisk"),
    bad("ellipse semi-axis negative", particles("egg { shape ellipse; semiAxes (0.01 -0.005); density 2500; position (0.1 0.3 0); }"),
        "semiAxes (0.01 -0.005) of particle egg must both be positive", "particleProperties", source="fallingDisk"),
    bad("polygon crossing itself", particles("tie { shape polygon; vertices ((0 0) (0.02 0.02) (0.02 0) (0 0.01));"
                                             " density 2500; position (0.1 0.3 0); }"),
        "vertices of particle tie", "intersects itself: edge 0-1 meets edge 2-3", "particleProperties",
        source="fallingDisk"),
    bad("polygon of two vertices", particles("stick { shape polygon; vertices ((0 0) (0.02 0));"
                                             " density 2500; position (0.1 0.3 0); }"),
        "vertices of particle stick", "at least 3 vertices, 2 given", source="fallingDisk"),
    bad("non-convex polygon in exact pair contacts",
        particles("ell { shape polygon; vertices ((0 0) (0.02 0) (0.02 0.01) (0.01 0.01) (0.01 0.02) (0 0.02));"
                  " density 2500; position (0.05 0.3 0); }"
                  " egg { shape ellipse; semiAxes (0.01 0.005); density 2500; position (0.15 0.3 0); }",
                  "contact { " + BOTH_PAIRS + " }"),
        "Particle ell (polygon) is not convex", "exact overlap between particles needs convex shapes",
        "overlap grid", source="fallingDisk"),
    bad("disk on a 3D mesh", particles("coin { " + GOOD.replace("sphere;", "disk;") + " }"),
        "Particle coin", "2D but the mesh is 3D"),
    bad("sphere under-resolved", particles("sphere { " + GOOD.replace("0.005;", "0.000667;") + " }"),
        "Particle sphere", "has a diameter of 0.8004 cells", "needs at least 2",
        "refine the mesh"),
    bad("sphere leaves the mesh", (setting("constant/g", "value", "(0 0 -1000)"),
                                   contact("meshWalls false; pairs { pp { " + PAIR.replace("wall", "particle") + " } }")),
        "Particle sphere left the mesh", "meshWalls false", "outlets",
        "The state of this time has been written"),
    bad("particle name repeated", particles("a { " + GOOD + " } a { " + GOOD.replace("0.025)", "0.04)") + " }"),
        "Particle a is listed twice in 'particles'", "particleProperties"),
    bad("particles overlap beyond the contact laws",
        particles("a { " + GOOD + " } b { " + GOOD.replace("0.025)", "0.032)") + " }",
                  "contact { " + BOTH_PAIRS + " }"),
        "Particles a and b", "overlap by 0.003 (30 % of the smaller diameter)",
        "contact.maxStartOverlap 0.05", "particleProperties"),
    bad("boxes overlap beyond the contact laws",
        particles("a { shape box; halfExtents (0.005 0.005 0.002); density 2000; position (0.015 0.015 0.025); }"
                  " b { shape box; halfExtents (0.005 0.005 0.002); density 2000; position (0.015 0.015 0.0286); }",
                  "contact { " + BOTH_PAIRS + " }"),
        "Particles a and b", "overlap by 0.0004 (10 % of the smaller thickness across it)",
        "contact.maxStartOverlap 0.05", "particleProperties"),
    bad("sphere centred on the floor, with contacts",
        particles("a { " + GOOD.replace("0.025)", "0)") + " }", "contact { " + PAIRS + " }"),
        "Particle a", "overlaps wall meshWalls by 0.005 (50 % of its thickness)", "maxStartOverlap 0.05"),
    bad("sphere in the floor, with contacts",
        particles("a { " + GOOD.replace("0.025)", "0.003)") + " }", "contact { " + PAIRS + " }"),
        "Particle a", "overlaps wall meshWalls by 0.002 (20 % of its thickness)", "maxStartOverlap 0.05"),
    bad("sphere beyond a contact-only wall",
        particles("a { " + GOOD.replace("0.025)", "0.035)") + " }", "contact { " + PAIRS
                  + " walls { lid { type plane; point (0 0 0.03); normal (0 0 -1); } } }"),
        "Particle a", "has its centre beyond wall lid"),
    bad("sphere on the cells next to a wall, no contacts",
        particles("a { " + GOOD.replace("0.025)", "0.006)") + " }"),
        "Particle a", "covers cells next to a wall at the start", "'contact' dictionary"),
    bad("prescribed particle leaves the mesh",
        particles("a { " + GOOD + " motion prescribed; velocity (0 0 0.5); }"),
        "Particle a", "is prescribed to move at (0 0 0.5)", "reaches the mesh's bounds",
        "at t = 0.03", "before endTime 0.1", "particleProperties"),
    bad("sphere reaches a wall, no contacts",
        (particles("sphere { " + GOOD.replace("0.025)", "0.0085)") + " velocity (0 0 -0.05); }"),
         setting("constant/transportProperties", "nu", 1e-5)),
        "Particle sphere reached the cells next to a wall", "'contact' dictionary",
        "The state of this time has been written"),
    bad("particles meet, no contacts",
        particles("sphere { " + GOOD + " } upper { shape sphere; radius 0.004; density 8000;"
                  " position (0.015 0.015 0.036); }"),
        "Particles sphere and upper overlap by", "at t = 0.055",
        "Particle-particle contact is not modelled without a 'contact' dictionary",
        "The state of this time has been written"),
    bad("particles meet, no contacts, dry",
        particles("sphere { " + GOOD + " } upper { shape sphere; radius 0.004; density 8000;"
                  " position (0.015 0.015 0.036); velocity (0 0 -0.5); }"),
        "Particles sphere and upper overlap by", "at t = 0.005",
        "Particle-particle contact is not modelled without a 'contact' dictionary",
        "The state of this time has been written", solver="dlmDEMFoam"),
    bad("unknown top-level keyword", append("constant/particleProperties", "surfaceResolutoin 16;\n"),
        "Unknown keyword 'surfaceResolutoin'"),
    # A value that is not a number (here Python's repr of a numpy float)
    bad("particle file not a number", particle_file("np.float64(0.015) 0.015 0.025 0.005\n"),
        "packing.dat\", line 2", "expected 'x y z radius'", "np.float64"),
    bad("particle file short line", particle_file("0.015 0.015 0.025\n"),
        "packing.dat\", line 2", "expected 'x y z radius'"),
    bad("particle file empty", particle_file("# comments and blank lines only\n\n"),
        "packing.dat", "holds no particles"),

    # Fluid, time step and rigid projection
    bad("viscosity negative", setting("constant/transportProperties", "nu", -1),
        "nu -1 must be positive", "transportProperties"),
    bad("rigid projection missing", remove("system/fvOptions"),
        "Particle sphere is free but no rigid projection ran"),
    bad("forceRelaxation out of range", setting("system/fvOptions", "rigidProjection/forceRelaxation", 1.5),
        "forceRelaxation 1.5", "outside [0, 1]", "fvOptions"),
    bad("gapBlending out of range", setting("system/fvOptions", "rigidProjection/gapBlending", -0.5),
        "gapBlending -0.5", "outside [0, 1]", "fvOptions"),
    bad("rigidProjection keyword misspelt", replace("system/fvOptions", "mixedCells ", "mixedCell "),
        "Unknown keyword 'mixedCell' for fvOption rigidProjection", "mixedCells", "system/fvOptions"),
    bad("rigidProjection keyword of another fvOption", replace("system/fvOptions", "mixedCells ", "selectionMode all; mixedCells "),
        "Unknown keyword 'selectionMode' for fvOption rigidProjection", "system/fvOptions"),
    bad("rigidProjectionCoeffs keyword misspelt",
        replace("system/fvOptions", "mixedCells ", "rigidProjectionCoeffs { gapBlend 1; } mixedCells "),
        "Unknown keyword 'gapBlend'", "rigidProjectionCoeffs", "gapBlending"),
    # h = 1.67 mm in sphereBox: nu 1e-2 makes nu dt/h^2 = 18 at dt = 5 ms
    bad("time step above the viscous limit", setting("constant/transportProperties", "nu", 1e-2),
        "viscous number", "maxViscousNumber 2", "controlDict", "Reduce deltaT to at most"),
    bad("deltaT zero", setting(CONTROL, "deltaT", 0),
        "deltaT 0 must be positive", "controlDict"),
    bad("deltaT negative, adjustable", (setting(CONTROL, "deltaT", -0.001), setting(CONTROL, "adjustTimeStep", "yes")),
        "deltaT -0.001 must be positive", "controlDict"),
    bad("maxCo zero", (setting(CONTROL, "maxCo", 0), setting(CONTROL, "adjustTimeStep", "yes")),
        "maxCo 0 must be positive with adjustTimeStep yes", "controlDict"),
    bad("deltaT zero, dry", setting(CONTROL, "deltaT", 0),
        "deltaT 0 must be positive", "controlDict", solver="dlmDEMFoam"),
    bad("deltaT below the time's round-off",
        (start_at("1000"), setting(CONTROL, "endTime", 1001), setting(CONTROL, "deltaT", 1e-14),
         setting(CONTROL, "adjustTimeStep", "no")),
        "The time step 1e-14 s at time 1000 s is below the time's round-off", "cannot advance",
        "controlDict"),
    bad("deltaT below the time's round-off, dry",
        (start_at("1000"), setting(CONTROL, "endTime", 1001), setting(CONTROL, "deltaT", 1e-14),
         setting(CONTROL, "adjustTimeStep", "no")),
        "is below the time's round-off", "cannot advance", "controlDict", solver="dlmDEMFoam"),

    # Contacts
    bad("contact pairs empty", contact("pairs { }"),
        "No contact law for materials (particle wall)", "'pairs'"),
    bad("restitution out of range", contact("pairs { pw { " + PAIR.replace("0.5", "1.5") + " } }"),
        "restitution 1.5 of contact pair pw must be in (0, 1]"),
    bad("contact pair keyword misspelt", contact("pairs { pw { " + PAIR + " stifness 3; } }"),
        "Unknown keyword 'stifness' for contact pair pw"),
    bad("contact law none with a stiffness",
        contact("pairs { pw { materials (particle wall); law none; stiffness 1e9; } }"),
        "Unknown keyword 'stiffness' for contact pair pw"),
    bad("contact law unknown", contact("pairs { pw { " + PAIR.replace("overlapVolume", "hertz") + " } }"),
        "hertz", "overlapVolume", "linearSpringDashpot"),
    bad("contact stiffness missing", contact("pairs { pw { " + PAIR.replace(" stiffness 1e9;", "") + " } }"),
        "Contact pair pw", "needs either 'stiffness' or 'contactTime'"),
    bad("stepsPerContact too small", contact("stepsPerContact 2; " + PAIRS),
        "stepsPerContact 2 must be at least 4"),
    bad("maxStartOverlap out of range", contact("maxStartOverlap 1.5; " + PAIRS),
        "maxStartOverlap 1.5 must be in [0, 1)"),
    bad("contact keyword misspelt", contact("overlaps exact; " + PAIRS),
        "Unknown keyword 'overlaps' in the contact settings"),
    bad("lubrication keyword misspelt", contact("lubrication { rnage 0.001; } " + PAIRS),
        "Unknown keyword 'rnage' in the contact settings' lubrication", "range"),
    bad("plane wall normal missing", contact(PAIRS + " walls { lid { type plane; point (0 0 1); } }"),
        "'normal'", "walls.lid"),
    bad("plane wall keyword unknown",
        contact(PAIRS + " walls { lid { type plane; point (0 0 1); normal (0 0 1); radius 3; } }"),
        "Unknown keyword 'radius' for wall lid (type plane)"),
    bad("surface wall file missing", contact(PAIRS + ' walls { funnel { type surface; file "none.stl"; } }'),
        "Wall funnel: cannot find the surface file", "none.stl"),
    bad("surface wall empty", surface_wall("solid funnel\nendsolid funnel\n"),
        "Wall funnel: the surface file", "funnel.stl", "holds no faces", "walls.funnel"),
    bad("surface wall corrupt", surface_wall(TRIANGLE.replace("1 0 0", "1 0 zero")),
        "Wall funnel: cannot read the surface file", "funnel.stl", "while reading vertex on line 5",
        "walls.funnel"),
    bad("surface wall scale zero", surface_wall(TRIANGLE, " scale 0;"),
        "Wall funnel: scale 0 must be positive"),
    # One cell per processor: no internal face anywhere. The default
    # lubrication range (the largest distance between neighbouring centres)
    # must come from the faces between processors, not stop the run
    bad("one cell per processor",
        (blocks("(1 1 2)"), decompose(2), setting("system/fvSolution", "solvers/p_rgh/solver", "PCG"),
         setting("system/fvSolution", "solvers/p_rgh/preconditioner", "DIC"), contact(PAIRS)),
        "Lubrication below gaps of 0.0225", "Particle sphere", "has a diameter of 0.444444 cells",
        np=2),
]


@pytest.fixture(scope="module")
def meshed(tmp_path_factory, foam_env):
    """One meshed copy of each case, copied again per test."""
    root = tmp_path_factory.mktemp("input")
    cases = {}
    for name, source in SOURCES.items():
        case = Case.copy(source, root / name, foam_env)
        case.run("blockMesh")
        cases[name] = case
    return cases


def copy(meshed, tmp_path, source="sphereBox"):
    case = Case(tmp_path / "case", meshed[source].env)
    shutil.copytree(meshed[source].path, case.path)
    return case


@pytest.mark.parametrize("bad", BAD_INPUT)
def test_bad_input(meshed, tmp_path, bad):
    case = copy(meshed, tmp_path, bad.source)
    for edit in bad.edits:
        edit(case)
    if bad.np > 1:
        case.run("decomposePar")
    # A run that never ends (deltaT 0 did in dlmDEMFoam) fails too
    result = case.run(bad.solver, check=False, np=bad.np, timeout=120)
    log = result.log
    assert result.returncode > 0, \
        f"exit code {result.returncode} (bad input accepted or a signal):\n{log[-2000:]}"
    # Without the banner's "trapFpe: Floating point exception trapping enabled"
    body = "\n".join(line for line in log.splitlines() if not line.startswith("trapFpe:"))
    for signal in SIGNALS:
        assert signal not in body, f"'{signal}' in:\n{log[-2000:]}"
    for text in bad.expected:
        assert text in log, f"'{text}' missing from:\n{log[-2000:]}"


def test_plain_flow_at_rest(meshed, tmp_path):
    """No particles (legal: plain flow) in a fluid at rest: the fluid stays
    exactly at rest and every solve converges at once, as in pimpleFoam
    (the round-off of the hydrostatic pressure once left in p_rgh made
    every pressure solve run to GAMG's 1000 iterations)."""
    case = copy(meshed, tmp_path)
    particles("")(case)
    case.set(CONTROL, "endTime", 0.015)
    log = case.run("pimpleDLMFoam").log
    iterations = [int(n) for n in re.findall(r"Solving for \w+,.* No Iterations (\d+)", log)]
    assert len(iterations) == 3*(3 + 2), log[-2000:]
    assert max(iterations) == 0, log[-2000:]


@pytest.mark.parametrize("position", ["0.015 0.015 0.025", "0.0155 0.0145 0.0212"])
def test_a_sphere_of_exactly_two_cells_per_diameter_is_accepted(meshed, tmp_path, position):
    """The smallest diameter the projection takes, 2 cells (of 1/600 m),
    in cells whose span differs from 1/600 m by round-off: both were
    refused as "a diameter of 2 cells; needs at least 2"."""
    case = copy(meshed, tmp_path)
    particles(f"sphere {{ shape sphere; radius {0.03/18!r}; density 2000;"
              f" position ({position}); }}")(case)
    case.set(CONTROL, "endTime", 0.005)
    assert case.run("pimpleDLMFoam").log.rstrip().endswith("End")


SECOND = "second { shape sphere; radius 0.004; density 2000; position (0.015 0.015 0.04); }"


@pytest.mark.parametrize("edit, expected", [
    (particles("sphere { " + GOOD.replace("2000;", "2500;") + " }"),
     "Particle sphere has other properties in constant/particleProperties than at time 0.01:"
     " density 2500; there, density 2000; at time 0.01."),
    (particles("sphere { " + GOOD + " motion fixed; }"),
     "Particle sphere has other properties in constant/particleProperties than at time 0.01:"
     " motion fixed; there, motion free; at time 0.01."),
    (particles("sphere { " + GOOD + " } " + SECOND),
     "Particle second is in constant/particleProperties but not among the particles of time 0.01."),
    (particles(SECOND),
     "Particle second is in constant/particleProperties but not among the particles of time 0.01."),
    (particles(""),
     "Particle sphere is among the particles of time 0.01 but not in constant/particleProperties."),
], ids=["density changed", "motion changed", "particle added", "particle renamed", "particle dropped"])
def test_restart_refuses_particles_changed_since_the_written_time(meshed, tmp_path, edit, expected):
    """A restart continues the particles written with its start time, which
    replace those of particleProperties: a particle added, dropped or changed
    there between the runs would be ignored, so the run stops and says so.
    The same input unchanged restarts."""
    case = copy(meshed, tmp_path)
    particles("sphere { " + GOOD + " }")(case)
    case.set(CONTROL, "endTime", 0.01)
    case.set(CONTROL, "writeInterval", 2)
    case.run("pimpleDLMFoam")
    case.set(CONTROL, "startFrom", "latestTime")
    case.set(CONTROL, "endTime", 0.015)
    unchanged = case.run("pimpleDLMFoam", check=False)
    assert unchanged.returncode == 0, unchanged.log[-2000:]
    shutil.rmtree(case.path / "0.015")

    edit(case)
    result = case.run("pimpleDLMFoam", check=False)
    assert result.returncode > 0, result.log[-2000:]
    assert expected in result.log, result.log[-2000:]
    assert "start from time 0, or edit both files alike" in result.log
