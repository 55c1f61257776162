"""Bad input stops the solver with a clear error naming the file, the keyword
and the particle."""

import pathlib

import pytest

from foamcase import Case

HERE = pathlib.Path(__file__).parent
SPHERE_BOX = HERE / "cases" / "sphereBox"
DISK = HERE.parent / "tutorials" / "fallingDisk"

HEADER = "FoamFile { version 2.0; format ascii; class dictionary; object particleProperties; }\n"
GOOD = "shape sphere; radius 0.005; density 2000; position (0.015 0.015 0.025);"


@pytest.fixture(scope="module")
def meshed(tmp_path_factory, foam_env):
    """One meshed copy of each case, copied again per test."""
    root = tmp_path_factory.mktemp("input")
    cases = {}
    for name, source in [("sphereBox", SPHERE_BOX), ("fallingDisk", DISK)]:
        case = Case.copy(source, root / name, foam_env)
        case.run("blockMesh")
        cases[name] = case
    return cases


def run_with(meshed, tmp_path, particles, source="sphereBox", edit=None):
    case = Case(tmp_path / "case", meshed[source].env)
    import shutil
    shutil.copytree(meshed[source].path, case.path)
    if particles is not None:
        (case.path / "constant" / "particleProperties").write_text(
            HEADER + "particles\n{\n" + particles + "\n}\n")
    if edit:
        edit(case)
    result = case.run("pimpleDLMFoam", check=False)
    assert result.returncode != 0, "the solver accepted bad input"
    return result.log


@pytest.mark.parametrize("particles, expected", [
    ("sphere { shape sphere; density 2000; position (0.015 0.015 0.025); }",
     ["'radius'", "particleProperties.particles.sphere"]),
    ("sphere { shape sphere; radius -0.005; density 2000; position (0.015 0.015 0.025); }",
     ["radius -0.005", "of particle sphere must be positive", "particleProperties"]),
    ("sphere { shape sphere; radius 0.005; density 0; position (0.015 0.015 0.025); }",
     ["density 0 of particle sphere must be positive", "particleProperties"]),
    ("sphere { shape sphere; raduis 0.005; radius 0.005; density 2000; position (0.015 0.015 0.025); }",
     ["Unknown keyword 'raduis' for particle sphere", "particleProperties"]),
    ("sphere { shape cube; radius 0.005; density 2000; position (0.015 0.015 0.025); }",
     ["cube", "sphere", "disk", "particleProperties"]),
    ("sphere { shape sphere; radius 0.005; density 2000; position (0.1 0.015 0.025); }",
     ["Particle sphere", "outside the mesh", "particleProperties"]),
    ("a { " + GOOD + " } b { shape sphere; radius 0.005; density 2000; position (0.015 0.015 0.033); }",
     ["Particles a and b", "overlap", "particleProperties"]),
    ("sphere { " + GOOD + " motion floating; }",
     ["floating", "free", "fixed", "prescribed"]),
])
def test_bad_particle_input(meshed, tmp_path, particles, expected):
    log = run_with(meshed, tmp_path, particles)
    for text in expected:
        assert text in log, f"'{text}' missing from:\n{log[-2000:]}"


def test_sphere_on_a_2d_mesh(meshed, tmp_path):
    log = run_with(meshed, tmp_path,
                   "ball { shape sphere; radius 0.01; density 2500; position (0.1 0.3 0); }",
                   source="fallingDisk")
    assert "Particle ball" in log and "3D but the mesh is 2D" in log


def test_disk_on_a_3d_mesh(meshed, tmp_path):
    log = run_with(meshed, tmp_path,
                   "coin { shape disk; radius 0.005; density 2500; position (0.015 0.015 0.025); }")
    assert "Particle coin" in log and "2D but the mesh is 3D" in log


@pytest.mark.parametrize("lines, expected", [
    # A value that is not a number (here Python's repr of a numpy float)
    ("np.float64(0.015) 0.015 0.025 0.005\n",
     ["packing.dat\", line 2", "expected 'x y z radius'", "np.float64"]),
    ("0.015 0.015 0.025\n", ["packing.dat\", line 2", "expected 'x y z radius'"]),
    ("# comments and blank lines only\n\n", ["packing.dat", "holds no particles"]),
])
def test_bad_particle_file(meshed, tmp_path, lines, expected):
    """A particle file line that does not read as 'x y z radius' is an
    error naming the file and the line, not skipped; a file without any
    particle is an error too."""
    def edit(case):
        (case.path / "constant" / "packing.dat").write_text("# x y z radius\n" + lines)
        (case.path / "constant" / "particleProperties").write_text(
            HEADER + 'particleFile "constant/packing.dat";\n'
            "particleFileDefaults { shape sphere; density 2000; }\n")
    log = run_with(meshed, tmp_path, None, edit=edit)
    for text in expected:
        assert text in log, f"'{text}' missing from:\n{log[-2000:]}"


def test_unknown_top_level_keyword(meshed, tmp_path):
    def edit(case):
        path = case.path / "constant" / "particleProperties"
        path.write_text(path.read_text() + "surfaceResolutoin 16;\n")
    log = run_with(meshed, tmp_path, None, edit=edit)
    assert "Unknown keyword 'surfaceResolutoin'" in log


def test_non_positive_viscosity(meshed, tmp_path):
    def edit(case):
        case.set("constant/transportProperties", "nu", -1)
    log = run_with(meshed, tmp_path, None, edit=edit)
    assert "nu -1 must be positive" in log and "transportProperties" in log


def test_missing_rigid_projection(meshed, tmp_path):
    def edit(case):
        (case.path / "system" / "fvOptions").unlink()
    log = run_with(meshed, tmp_path, None, edit=edit)
    assert "Particle sphere is free but no rigid projection ran" in log


def test_force_relaxation_out_of_range(meshed, tmp_path):
    def edit(case):
        case.set("system/fvOptions", "rigidProjection/forceRelaxation", 1.5)
    log = run_with(meshed, tmp_path, None, edit=edit)
    assert "forceRelaxation 1.5" in log and "outside [0, 1]" in log
    assert "fvOptions" in log


def test_gap_blending_out_of_range(meshed, tmp_path):
    def edit(case):
        case.set("system/fvOptions", "rigidProjection/gapBlending", -0.5)
    log = run_with(meshed, tmp_path, None, edit=edit)
    assert "gapBlending -0.5" in log and "outside [0, 1]" in log
    assert "fvOptions" in log


def test_time_step_above_the_viscous_limit(meshed, tmp_path):
    # h = 1.67 mm in sphereBox: nu 1e-2 makes nu dt/h^2 = 18 at dt = 5 ms
    def edit(case):
        case.set("constant/transportProperties", "nu", 1e-2)
    log = run_with(meshed, tmp_path, None, edit=edit)
    assert "viscous number" in log and "maxViscousNumber 2" in log
    assert "controlDict" in log and "Reduce deltaT to at most" in log


PAIR = ("materials (particle wall); law overlapVolume; stiffness 1e9;"
        " restitution 0.5; friction 0.3;")


@pytest.mark.parametrize("contact, expected", [
    ("pairs { }",
     ["No contact law for materials (particle wall)", "'pairs'"]),
    ("pairs { pw { " + PAIR.replace("0.5", "1.5") + " } }",
     ["restitution 1.5 of contact pair pw must be in (0, 1]"]),
    ("pairs { pw { " + PAIR + " stifness 3; } }",
     ["Unknown keyword 'stifness' for contact pair pw"]),
    ("pairs { pw { " + PAIR.replace("overlapVolume", "hertz") + " } }",
     ["hertz", "overlapVolume", "linearSpringDashpot"]),
    ("pairs { pw { " + PAIR.replace(" stiffness 1e9;", "") + " } }",
     ["Contact pair pw", "needs either 'stiffness' or 'contactTime'"]),
    ("stepsPerContact 2; pairs { pw { " + PAIR + " } }",
     ["stepsPerContact 2 must be at least 4"]),
    ("overlaps exact; pairs { pw { " + PAIR + " } }",
     ["Unknown keyword 'overlaps' in the contact settings"]),
    ("pairs { pw { " + PAIR + " } } walls { lid { type plane; point (0 0 1); } }",
     ["'normal'", "walls.lid"]),
    ("pairs { pw { " + PAIR + " } } walls { lid { type plane; point (0 0 1);"
     " normal (0 0 1); radius 3; } }",
     ["Unknown keyword 'radius' for wall lid (type plane)"]),
    ("pairs { pw { " + PAIR + " } } walls { funnel { type surface; file \"none.stl\"; } }",
     ["Wall funnel: cannot find the surface file", "none.stl"]),
])
def test_bad_contact_input(meshed, tmp_path, contact, expected):
    def add_contact(case):
        path = case.path / "constant" / "particleProperties"
        path.write_text(path.read_text() + "contact\n{\n" + contact + "\n}\n")
    log = run_with(meshed, tmp_path, "sphere { " + GOOD + " }", edit=add_contact)
    for text in expected:
        assert text in log, f"'{text}' missing from:\n{log[-2000:]}"
