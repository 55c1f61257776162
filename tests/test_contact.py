"""Case-level tests of the contacts: restitution of dry collisions between
spheres, with walls and between disks, friction that makes a spinning sphere
roll and a sphere roll down a slope without slipping, restart in the middle
of a contact, and the same contact forces on 1 and 2 processors."""

import math
import re
import pathlib
import shutil

import numpy as np
import pytest

from foamcase import Case

HERE = pathlib.Path(__file__).parent
DRY_BOX = HERE / "cases" / "dryBox"
PAIRS = "contact/pairs"

# The dry box as a one-cell-thick 2D mesh
DISK_BOX = """FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
vertices
(
    (-0.01 -0.01 0) (0.01 -0.01 0) (0.01 0.01 0) (-0.01 0.01 0)
    (-0.01 -0.01 0.001) (0.01 -0.01 0.001) (0.01 0.01 0.001) (-0.01 0.01 0.001)
);
blocks ( hex (0 1 2 3 4 5 6 7) (4 4 1) simpleGrading (1 1 1) );
boundary
(
    walls { type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }
);
"""


def dry_case(tmp_path, env, name, settings=None, remove=()):
    case = Case.copy(DRY_BOX, tmp_path / name, env)
    case.run("blockMesh")
    for entry in remove:
        case.run("foamDictionary", "constant/particleProperties", "-entry",
                 entry, "-remove", log="foamDictionary")
    for (file, entry), value in (settings or {}).items():
        case.set(file, entry, value)
    return case


def lone_sphere(tmp_path, env, name, position, velocity="(0 0 0)", settings=None):
    """The dry box with its left sphere alone, at the given position and
    velocity (settings as dry_case's)."""
    return dry_case(tmp_path, env, name, {
        ("constant/particleProperties", "particles/left/position"): position,
        ("constant/particleProperties", "particles/left/velocity"): velocity,
        **(settings or {}),
    }, remove=["particles/right"])


def both_pairs(entry, value):
    return {("constant/particleProperties", f"{PAIRS}/{pair}/{entry}"): value
            for pair in ("particleParticle", "particleWall")}


@pytest.mark.parametrize("law", ["overlapVolume", "linearSpringDashpot",
                                 "linearSpringDashpot unclipped"])
@pytest.mark.parametrize("e", [0.1, 0.5, 0.9])
def test_head_on_collision_has_the_requested_restitution(tmp_path, foam_env, law, e):
    """Unclipped: the normal force may pull at the end (as LIGGGHTS'
    limitForce off), with the textbook damping."""
    settings = {**both_pairs("restitution", e), **both_pairs("law", law.split()[0])}
    if law.endswith("unclipped"):
        settings.update(both_pairs("clipNormalForce", "false"))
    case = dry_case(tmp_path, foam_env, "headOn", settings)
    if law.startswith("linearSpringDashpot"):
        for pair in ("particleParticle", "particleWall"):
            case.run("foamDictionary", "constant/particleProperties", "-entry",
                     f"{PAIRS}/{pair}/impactVelocity", "-remove",
                     log="foamDictionary")
    case.run("dlmDEMFoam")
    h = case.history()
    left, right = h["left"], h["right"]
    approach = right[0, 4] - left[0, 4]
    separation = right[-1, 4] - left[-1, 4]
    assert -separation/approach == pytest.approx(e, rel=0.01)
    # Momentum conserved to round-off, no motion off the line of centres
    assert np.abs(left[:, 4:7] + right[:, 4:7]).max() < 1e-12
    assert np.abs(left[:, 5:10]).max() < 1e-12


@pytest.mark.parametrize("e", [0.3, 0.9])
def test_sphere_bounces_off_a_wall_with_the_requested_restitution(tmp_path, foam_env, e):
    case = lone_sphere(tmp_path, foam_env, "wall", "(0 0 0.0025)", "(0 0 -1)",
                       both_pairs("restitution", e))
    case.run("dlmDEMFoam")
    h = case.history()["left"]
    assert h[-1, 6] == pytest.approx(e, rel=0.01)
    # It never went through the floor: deepest overlap under 5 % of R
    assert h[:, 3].min() > 0.002*0.95


def test_sphere_rests_as_deep_wherever_it_sits_on_the_wall_faces(tmp_path, foam_env):
    """The floor is 4 x 4 mesh faces, each cut into triangles. A sphere at
    rest on it sinks to the overlap where the one contact carries its
    weight, the same over a face's interior as within round-off of a corner
    where eight triangles meet (which must not each add a contact)."""
    R = 0.002
    rest = {}
    for name, xy in (("interior", "0.0021 -0.0013"), ("corner", "1e-6 3e-7")):
        case = lone_sphere(tmp_path, foam_env, name, f"({xy} {R})", settings={
            ("constant/g", "value"): "(0 0 -9.81)",
            ("system/controlDict", "endTime"): 0.01,
            ("system/controlDict", "writeInterval"): 1000,
        })
        case.run("dlmDEMFoam")
        h = case.history()["left"]
        assert np.abs(h[-1, 4:7]).max() < 1e-6
        rest[name] = R - h[-1, 3]
    assert rest["interior"] > 0
    assert rest["corner"] == pytest.approx(rest["interior"], rel=1e-3)


def tilted_gravity(angle_deg):
    a = math.radians(angle_deg)
    return f"({9.81*math.sin(a)} 0 {-9.81*math.cos(a)})"


@pytest.mark.parametrize("tangential, limit", [("spring", "total"), ("spring", "spring"),
                                               ("coulomb", "total")])
def test_spinning_sphere_ends_up_rolling(tmp_path, foam_env, tangential, limit):
    """A sphere spinning at omega0 about y set on the floor: friction turns it
    into rolling at v = 2/7 omega0 R (angular momentum about the contact
    point is conserved), whatever the friction model and whatever the
    Coulomb limit bounds."""
    R, omega0 = 0.002, 50.0
    case = lone_sphere(tmp_path, foam_env, "spin", f"(-0.005 0 {R*(1 - 1e-4)})", settings={
        **both_pairs("tangential", tangential),
        **both_pairs("frictionLimit", limit),
        ("constant/g", "value"): "(0 0 -9.81)",
        ("system/controlDict", "endTime"): 0.1,
        ("system/controlDict", "deltaT"): 5e-4,
        ("system/controlDict", "writeInterval"): 1000,
        ("constant/particleProperties", "particles/left/angularVelocity"):
            f"(0 {omega0} 0)",
    })
    case.run("dlmDEMFoam")
    h = case.history()["left"]
    assert h[-1, 4] == pytest.approx(2/7*omega0*R, rel=0.01)
    # Rolling: the contact point is at rest
    assert h[-1, 4] - h[-1, 8]*R == pytest.approx(0, abs=1e-3*h[-1, 4])


def test_sphere_rolls_down_a_slope_without_slipping(tmp_path, foam_env):
    """On a 20 degree slope with friction 0.3 (> 2/7 tan 20) the static
    friction spring holds the contact point: acceleration 5/7 g sin 20."""
    R = 0.002
    case = lone_sphere(tmp_path, foam_env, "slope", f"(-0.008 0 {R*(1 - 1e-4)})", settings={
        ("constant/g", "value"): tilted_gravity(20),
        ("system/controlDict", "endTime"): 0.02,
        ("system/controlDict", "deltaT"): 5e-4,
        ("system/controlDict", "writeInterval"): 1000,
    })
    case.run("dlmDEMFoam")
    h = case.history()["left"]
    late = h[h[:, 0] > 0.01]
    a = np.polyfit(late[:, 0], late[:, 4], 1)[0]
    assert a == pytest.approx(5/7*9.81*math.sin(math.radians(20)), rel=0.01)
    assert np.abs(late[:, 4] - late[:, 8]*R).max() < 1e-3*late[-1, 4]


def test_disks_collide_with_the_requested_restitution(tmp_path, foam_env):
    """2D: disks on a one-cell-thick mesh, head on (disk lens) and against
    the side wall (segment)."""
    case = Case.copy(DRY_BOX, tmp_path / "disks", foam_env)
    (case.path / "system/blockMeshDict").write_text(DISK_BOX)
    case.run("blockMesh")
    for (file, entry), value in both_pairs("restitution", 0.7).items():
        case.set(file, entry, value)
    for name in ("left", "right"):
        case.set("constant/particleProperties", f"particles/{name}/shape", "disk")
    case.set("system/controlDict", "endTime", 0.025)
    case.run("dlmDEMFoam")
    h = case.history()
    left, right = h["left"], h["right"]
    # After the pair collision the disks part at 0.7 m/s; each then meets a
    # side wall and comes back at 0.7 times its 0.35 m/s
    rel = right[:, 4] - left[:, 4]
    assert rel[left[:, 0] < 0.01][-1] == pytest.approx(0.7, rel=0.01)
    assert left[-1, 4] == pytest.approx(0.7*0.35, rel=0.01)
    assert right[-1, 4] == pytest.approx(-0.7*0.35, rel=0.01)


def disk_collision(tmp_path, env, name, cells, overlap):
    """Soft head-on collision of the disks (overlap up to 0.3 R) on a 2D mesh
    of the given cells per side (R/4 at 40): restitution and deepest
    overlap over R."""
    case = Case.copy(DRY_BOX, tmp_path / name, env)
    (case.path / "system/blockMeshDict").write_text(
        DISK_BOX.replace("(4 4 1)", f"({cells} {cells} 1)"))
    case.run("blockMesh")
    props = "constant/particleProperties"
    for disk in ("left", "right"):
        case.set(props, f"particles/{disk}/shape", "disk")
    case.set(props, "contact/overlap", overlap)
    case.set(props, f"{PAIRS}/particleParticle/contactTime", 2e-3)
    case.set("system/controlDict", "endTime", 0.006)
    case.run("dlmDEMFoam")
    h = case.history()
    left, right = h["left"], h["right"]
    rel = right[:, 4] - left[:, 4]
    gap = right[:, 1] - left[:, 1] - 0.004
    return -rel[-1]/rel[0], -gap.min()/0.002


def test_grid_overlap_agrees_with_the_exact_one_as_the_mesh_is_refined(tmp_path, foam_env):
    """The paper's overlap summed over the cells against the exact lens:
    within 3 % at R/4 cells, 1 % at R/8 and R/16."""
    e_exact, depth_exact = disk_collision(tmp_path, foam_env, "exact", 40, "exact")
    for cells, tolerance in ((40, 0.03), (80, 0.01), (160, 0.01)):
        e, depth = disk_collision(tmp_path, foam_env, f"grid{cells}", cells, "grid")
        assert e == pytest.approx(e_exact, rel=tolerance)
        assert depth == pytest.approx(depth_exact, rel=tolerance)


@pytest.mark.parametrize("write_format", ["ascii", "binary"])
def test_restart_within_a_contact_continues_the_trajectory(tmp_path, foam_env, write_format):
    """Stop and restart while the sphere is pressed on the floor by a
    spinning start: the tangential spring is saved and read back, whatever
    the case's writeFormat (a binary stream wrote the springs raw inside the
    state's dictionary, which could not be read back)."""
    settings = {
        ("constant/g", "value"): "(0 0 -9.81)",
        ("system/controlDict", "endTime"): 0.01,
        ("system/controlDict", "deltaT"): 5e-4,
        ("system/controlDict", "writeInterval"): 10,
        ("system/controlDict", "writeFormat"): write_format,
        ("constant/particleProperties", "particles/left/angularVelocity"): "(0 50 0)",
    }
    position = "(-0.005 0 0.0019998)"
    full = lone_sphere(tmp_path, foam_env, "full", position, settings=settings)
    full.run("dlmDEMFoam")
    state = (full.path / "0.005" / "uniform" / "particles").read_text()
    assert "contacts" in state and "(0 -1 " in state

    restarted = lone_sphere(tmp_path, foam_env, "restarted", position, settings=settings)
    shutil.copytree(full.path / "0.005", restarted.path / "0.005")
    restarted.run("dlmDEMFoam")
    a = full.history()["left"]
    b = restarted.history("0.005")["left"]
    tail = a[a[:, 0] > 0.005 + 1e-9]
    assert len(b) == len(tail) == 10
    assert np.abs(b[:, 1:] - tail[:, 1:]).max() < 1e-12*np.abs(tail[:, 1:]).max()


@pytest.mark.parametrize("write_format", ["ascii", "binary"])
def test_restart_as_an_unclipped_contact_ends_continues_exactly(
        tmp_path, foam_env, write_format):
    """The head-on collision with a linear spring that may pull, in steps
    of 1.5 contact sub-steps, restarted from 1.2e-4 s, when the contact
    ends within the first sub-step: that sub-step's correction for the
    contact's end takes the length of the last sub-step before the restart,
    which the state keeps (without it the velocities after the restart
    were 3.4e-3 m/s off the full run's, of 0.5)."""
    settings = {
        **both_pairs("law", "linearSpringDashpot"),
        **both_pairs("clipNormalForce", "false"),
        ("constant/particleProperties", "particles/left/position"): "(-0.00201 0 0.01)",
        ("constant/particleProperties", "particles/right/position"): "(0.00201 0 0.01)",
        ("system/controlDict", "deltaT"): 3e-6,
        ("system/controlDict", "endTime"): 1.5e-4,
        ("system/controlDict", "writeInterval"): 40,
        ("system/controlDict", "writeFormat"): write_format,
    }
    remove = [f"{PAIRS}/{pair}/impactVelocity" for pair in ("particleParticle", "particleWall")]
    full = dry_case(tmp_path, foam_env, "full", settings, remove)
    full.run("dlmDEMFoam")
    restarted = dry_case(tmp_path, foam_env, "restarted", settings, remove)
    shutil.copytree(full.path / "0.00012", restarted.path / "0.00012")
    restarted.run("dlmDEMFoam")
    a, b = full.history(), restarted.history("0.00012")
    for name in ("left", "right"):
        tail = a[name][a[name][:, 0] > 1.2e-4 + 1e-12]
        assert len(b[name]) == len(tail) == 10
        assert np.abs(b[name][:, 1:10] - tail[:, 1:10]).max() < 1e-12*np.abs(tail[:, 1:10]).max()


WET_CONTACT = """
contact
{
    pairs
    {
        sphereWall
        {
            materials       (particle wall);
            law             overlapVolume;
            contactTime     2e-3;
            impactVelocity  0.05;
            restitution     0.5;
            friction        0.3;
        }
    }
}
"""


def landing_case(tmp_path, env, name):
    """The 10 mm sphere of density 2000 in the 30 x 30 x 45 mm box of a
    fluid 100 times as viscous as water, 2 mm above the floor, with
    contacts."""
    case = Case.copy(HERE / "cases" / "sphereBox", tmp_path / name, env)
    case.run("blockMesh")
    props = case.path / "constant/particleProperties"
    props.write_text(props.read_text() + WET_CONTACT)
    case.set("constant/particleProperties", "particles/sphere/position",
             "(0.0151 0.0149 0.007)")
    case.set("constant/transportProperties", "nu", 1e-4)
    case.set("system/controlDict", "endTime", 0.3)
    case.set("system/controlDict", "writeInterval", 30)
    return case


def test_settling_sphere_lands_and_comes_to_rest(tmp_path, foam_env):
    """It reaches the floor, slowed by the lubrication film, does not bounce
    (Stokes number far below 10: it moves up at most 1 % of its impact
    speed, 0.5 % here, where the dry restitution is 50 %) and comes to rest
    on it with an overlap of
    a small fraction of the radius. At rest the fluid is at rest too, so
    the floor carries the weight less the buoyancy, and the hydrodynamic
    force is the buoyancy."""
    case = landing_case(tmp_path, foam_env, "landing")
    case.run("pimpleDLMFoam")
    h = case.history()["sphere"]
    R = 0.005
    V = 4/3*math.pi*R**3
    gap = h[:, 3] - R
    assert gap.min() > -0.01*R
    speed = np.abs(h[:, 6]).max()
    assert h[:, 6].max() < 0.01*speed
    late = h[h[:, 0] > 0.2]
    assert np.abs(late[:, 6]).max() < 1e-4*speed
    # Off centre in the box it may roll slowly, held back by the fluid only
    assert np.abs(late[:, 4:6]).max() < 0.01*speed
    assert late[-1, 18] == pytest.approx(1000*V*9.81, rel=0.01)
    assert late[-1, 12] == pytest.approx(1000*V*9.81, rel=0.01)


@pytest.mark.parametrize("nu", [1e-6, 1e-4])
def test_buoyant_pebble_rests_under_a_plate_the_fluid_passes(tmp_path, foam_env, nu):
    """A polypropylene pebble (density 843) rises in water, and in a liquid
    100 times as viscous, against a contact-only plate (as the perforated
    cone of the paper's pebble discharge) and comes to rest under it: the
    plate carries its buoyancy less its weight to 1 % (0.3 % here) and the
    fluid force is the buoyancy. In the viscous liquid it bounced every
    step (u_z +0.012 / -0.008 m/s) while the contact sub-steps moved the
    particle's own mass and the follow step gave their change to the fluid
    of its cells as well."""
    case = Case.copy(HERE / "cases" / "sphereBox", tmp_path / "pebble", foam_env)
    case.run("blockMesh")
    props = case.path / "constant/particleProperties"
    props.write_text(props.read_text() + WET_CONTACT.replace(
        "    pairs", "    walls { plate { type plane; point (0 0 0.03); normal (0 0 -1); } }\n"
        "    pairs", 1))
    for (file, entry), value in {
        ("constant/particleProperties", "particles/sphere/position"): "(0.0151 0.0149 0.0235)",
        ("constant/particleProperties", "particles/sphere/density"): 843,
        ("constant/transportProperties", "nu"): nu,
        ("system/controlDict", "endTime"): 0.3,
        ("system/controlDict", "writeInterval"): 1000,
    }.items():
        case.set(file, entry, value)
    case.run("pimpleDLMFoam")
    h = case.history()["sphere"]
    R = 0.005
    V = 4/3*math.pi*R**3
    speed = np.abs(h[:, 6]).max()
    late = h[h[:, 0] > 0.25]
    assert np.abs(late[:, 6]).max() < 1e-4*speed
    assert late[:, 3].max() + R < 0.03 + 0.01*R
    assert -late[-1, 18] == pytest.approx((1000 - 843)*V*9.81, rel=0.01)
    assert late[-1, 12] == pytest.approx(1000*V*9.81, rel=0.01)


def test_restart_during_a_landing_continues_the_trajectory(tmp_path, foam_env):
    """Restarted from 0.06 s, while the sphere lands on the floor through
    lubrication and contact: the written velocity and flux already hold the
    contact's change of the particle's motion, the particle the prediction
    of the next step, so the run continues as if never stopped."""
    def make(name):
        case = landing_case(tmp_path, foam_env, name)
        case.set("system/controlDict", "endTime", 0.1)
        case.set("system/controlDict", "writeInterval", 12)
        return case

    full = make("full")
    full.run("pimpleDLMFoam")
    a = full.history()["sphere"]
    contact = a[(a[:, 0] > 0.055) & (a[:, 0] < 0.065), 18]
    assert np.abs(contact).min() > 0
    restarted = make("restarted")
    shutil.copytree(full.path / "0.06", restarted.path / "0.06")
    restarted.run("pimpleDLMFoam")
    b = restarted.history("0.06")["sphere"]
    tail = a[a[:, 0] > 0.06 + 1e-9]
    assert len(b) == len(tail) >= 5
    assert np.abs(b[:, 1:10] - tail[:, 1:10]).max() < 1e-12
    assert np.abs(b[:, 16:19] - tail[:, 16:19]).max() < 1e-9*np.abs(tail[:, 18]).max()


def test_sphere_rests_on_a_sieve_the_fluid_passes(tmp_path, foam_env):
    """A contact-only plane across the box at z = 15 mm (a sieve: the fluid
    passes through, no lubrication): the sphere lands on it and, at rest,
    the sieve carries its weight less buoyancy alone. (It carried 0.90 of
    it while the flow saw the particle's velocity from before each step's
    contact, a steady sinking of dt F/m whose drag took the rest.)"""
    case = landing_case(tmp_path, foam_env, "sieve")
    props = case.path / "constant/particleProperties"
    props.write_text(props.read_text().replace(
        "contact\n{\n",
        "contact\n{\n    walls { sieve { type plane; point (0 0 0.015);"
        " normal (0 0 1); } }\n", 1))
    case.set("constant/particleProperties", "particles/sphere/position",
             "(0.0151 0.0149 0.0215)")
    case.run("pimpleDLMFoam")
    h = case.history()["sphere"]
    R = 0.005
    V = 4/3*math.pi*R**3
    assert h[:, 3].min() > 0.015 + 0.99*R
    late = h[h[:, 0] > 0.25]
    assert np.abs(late[:, 6]).max() < 1e-4*np.abs(h[:, 6]).max()
    assert late[-1, 18] == pytest.approx(1000*V*9.81, rel=0.01)


def test_contact_forces_are_the_same_on_one_and_two_processors(tmp_path, foam_env):
    """The landing decomposed on 2 ranks: same trajectory and the same contact
    force (not twice it, a bug of some codes that sum forces over ranks)."""
    def make(name):
        case = landing_case(tmp_path, foam_env, name)
        case.converge_linear_solvers()
        case.set("system/controlDict", "endTime", 0.1)
        return case

    serial = make("serial")
    serial.run("pimpleDLMFoam")
    parallel = make("parallel")
    parallel.run("decomposePar")
    parallel.run("pimpleDLMFoam", np=2)

    s = serial.history()["sphere"]
    p = parallel.history()["sphere"]
    assert s.shape == p.shape
    assert np.abs(s[:, 18]).max() > 0
    for columns in [slice(1, 4), slice(4, 7), slice(16, 19)]:
        scale = np.abs(s[:, columns] - s[0, columns]).max()
        assert np.abs(p[:, columns] - s[:, columns]).max() < 1e-6*scale


def test_parallel_binary_restart_within_a_wet_contact(tmp_path, foam_env):
    """The landing on 2 ranks, binary fields, with a spinning start so that
    the contact holds a tangential spring at the restart time (0.075 s): the
    restarted run continues as the uninterrupted one."""
    def make(name):
        case = landing_case(tmp_path, foam_env, name)
        case.set("constant/particleProperties",
                 "particles/sphere/angularVelocity", "(0 20 0)")
        case.set("system/controlDict", "endTime", 0.1)
        case.set("system/controlDict", "writeInterval", 15)
        case.run("decomposePar")
        return case

    full = make("full")
    full.run("pimpleDLMFoam", np=2)
    state = (full.path / "processor0" / "0.075" / "uniform" / "particles").read_text()
    springs = state[state.index("contacts"):]
    assert "(0 -1 " in springs

    stopped = make("stopped")
    stopped.set("system/controlDict", "endTime", 0.075)
    stopped.run("pimpleDLMFoam", np=2)
    stopped.set("system/controlDict", "endTime", 0.1)
    stopped.run("pimpleDLMFoam", np=2, log="pimpleDLMFoam.restart")

    a = full.history()["sphere"]
    b = stopped.history("0.075")["sphere"]
    tail = a[a[:, 0] > 0.075 + 1e-9]
    assert len(b) == len(tail) >= 5
    assert np.abs(b[:, 1:10] - tail[:, 1:10]).max() < 1e-12
    assert np.abs(b[:, 16:] - tail[:, 16:]).max() < 1e-9*np.abs(tail[:, 16:]).max()


def test_restart_in_water_with_an_adjustable_step_takes_the_steps_of_the_uninterrupted_run(
        tmp_path, foam_env):
    """The landing in water (nu 1e-6) with adjustTimeStep, the step set by
    the particle's Courant number, which counts the surface speed of a
    particle near a contact twice: restarted from 0.04 s, the sphere
    pressed on the floor after its bounce, the run takes the same steps and trajectory to the next
    written time as the uninterrupted one. The written state holds which
    particles were near a contact (nearContact); without it the restart's
    first step was 0.005 s where the uninterrupted run took 0.0033 s."""
    def make(name):
        case = landing_case(tmp_path, foam_env, name)
        case.set("constant/transportProperties", "nu", 1e-6)
        for entry, value in {"endTime": 0.05, "adjustTimeStep": "yes",
                             "deltaT": 0.001, "maxDeltaT": 0.005,
                             "writeControl": "adjustableRunTime",
                             "writeInterval": 0.01}.items():
            case.set("system/controlDict", entry, value)
        return case

    full = make("full")
    full.run("pimpleDLMFoam")
    a = full.history()["sphere"]
    state = (full.path / "0.04" / "uniform" / "particles").read_text()
    assert re.search(r"nearContact\s+1\(0\);", state)
    restarted = make("restarted")
    shutil.copytree(full.path / "0.04", restarted.path / "0.04")
    restarted.run("pimpleDLMFoam")
    b = restarted.history("0.04")["sphere"]
    tail = a[a[:, 0] > 0.04 + 1e-9]
    assert len(b) == len(tail) == 3
    assert np.abs(b[:, 0] - tail[:, 0]).max() < 1e-12
    assert np.abs(b[:, 1:10] - tail[:, 1:10]).max() < 1e-12
    # In contact with the floor throughout the restarted part
    assert np.abs(tail[:, 18]).min() > 0


def test_wet_pile_restarted_in_binary_with_an_adjustable_step_continues_as_never_stopped(
        tmp_path, foam_env):
    """27 spheres (6 cells per diameter, density 2500) settle in water onto
    the floor of the 30 x 30 x 45 mm box with wet contacts, the step
    adjusted, fields in binary; stopped at 0.2 s, the pile in lasting
    contact, and continued to 0.4 s: the same steps, and positions within
    1e-11 m of the uninterrupted run's (they part by 1e-17 m at the first
    step, round-off, which the lasting contacts grow to 3e-12 m by 0.4 s).
    Before the written state held the particles near a contact, the first
    step after the restart was 0.0029 s where the run took 0.0022 s, and
    the pile ended 1.1 mm away."""
    spheres = "\n".join(
        f"    s{9*i + 3*j + k} {{ shape sphere; radius 0.003; density 2500; "
        f"material particle; position ({0.015 + (i - 1)*0.0075 + 0.0002*(j - 1)!r} "
        f"{0.015 + (j - 1)*0.0075 - 0.0001*(k - 1)!r} {0.012 + k*0.0075!r}); }}"
        for i in range(3) for j in range(3) for k in range(3))
    pair = WET_CONTACT[WET_CONTACT.index("{", WET_CONTACT.index("sphereWall")):
                       WET_CONTACT.index("}") + 1]

    def make(name):
        case = Case.copy(HERE / "cases" / "sphereBox", tmp_path / name, foam_env)
        case.run("blockMesh")
        (case.path / "constant" / "particleProperties").write_text(
            "FoamFile { version 2.0; format ascii; class dictionary;"
            " object particleProperties; }\n"
            f"particles\n{{\n{spheres}\n}}\n"
            "contact\n{\n    pairs\n    {\n"
            f"        spheres {pair.replace('(particle wall)', '(particle particle)')}\n"
            f"        sphereWall {pair}\n    }}\n}}\n")
        case.set("constant/transportProperties", "nu", 1e-6)
        for entry, value in {"endTime": 0.4, "adjustTimeStep": "yes",
                             "deltaT": 0.0005, "maxDeltaT": 0.005,
                             "writeControl": "adjustableRunTime",
                             "writeInterval": 0.1, "writeFormat": "binary"}.items():
            case.set("system/controlDict", entry, value)
        return case

    full = make("full")
    log = full.run("pimpleDLMFoam").log
    touching = [int(m) for m in re.findall(r"largest overlap \S+ % of d, (\d+) contacts", log)]
    assert min(touching[-20:]) >= 30
    restarted = make("restarted")
    shutil.copytree(full.path / "0.2", restarted.path / "0.2")
    restarted.run("pimpleDLMFoam")
    a, b = full.history(), restarted.history("0.2")
    assert len(a) == len(b) == 27
    for name, track in a.items():
        tail = track[track[:, 0] > 0.2 + 1e-9]
        assert len(b[name]) == len(tail) >= 50
        assert np.abs(b[name][:, 0] - tail[:, 0]).max() < 1e-12
        assert np.abs(b[name][:, 1:4] - tail[:, 1:4]).max() < 1e-11


@pytest.mark.parametrize("interval", [0, 5])
def test_history_interval_thins_the_history(tmp_path, foam_env, interval):
    """historyInterval N writes every N-th step (30 steps here), 0 none."""
    case = dry_case(tmp_path, foam_env, f"history{interval}",
                    {("constant/particleProperties", "historyInterval"): interval})
    case.run("dlmDEMFoam")
    path = case.path / "postProcessing/particles/0/particles.dat"
    if interval == 0:
        assert not path.exists()
    else:
        h = case.history()["left"]
        assert len(h) == 30//interval
        assert np.allclose(np.diff(h[:, 0]), interval*1e-4)


@pytest.mark.parametrize("tangential", ["spring", "coulomb"])
def test_sphere_pyramid_stands_only_with_static_friction(
        tmp_path, foam_env, tangential):
    """Three spheres on the floor, 0.1 R apart at the corners of a
    triangle, and a fourth resting on them, friction 0.5 everywhere:
    standing needs friction 0.34 at the upper contacts (tan of half the 37
    degree angle of the lines of centres to the vertical), so the
    static-friction spring holds the pyramid, the top sphere settling by
    less than 1 % of R in 1 s; the paper's sliding damping has no force at
    rest, and the bottom spheres creep apart until the top one has dropped
    by more than a fifth of R (the reason a heap needs the spring). (Two
    spheres under a third are no test: the top one rolls off sideways, a
    physical instability growing twentyfold every 50 ms.)"""
    R, gap = 0.002, 0.0002
    d = (2*R + gap)/math.sqrt(3)
    corners = [(d*math.cos(a), d*math.sin(a))
               for a in (0, 2*math.pi/3, 4*math.pi/3)]
    top = R + math.sqrt((2*R)**2 - d**2)*(1 + 1e-4)
    case = dry_case(tmp_path, foam_env, "pyramid", {
        **both_pairs("tangential", tangential),
        **both_pairs("friction", 0.5),
        ("constant/g", "value"): "(0 0 -9.81)",
        ("system/controlDict", "endTime"): 1,
        ("system/controlDict", "deltaT"): 5e-4,
        ("system/controlDict", "writeInterval"): 1000,
    }, remove=["particles/left", "particles/right"])
    spheres = [(f"bottom{k}", x, y, R*(1 - 1e-4)) for k, (x, y) in enumerate(corners)]
    spheres.append(("top", 0.0, 0.0, top))
    entries = "".join(
        f"    {name} {{ shape sphere; radius {R}; density 2500;"
        f" position ({x!r} {y!r} {z!r}); velocity (0 0 0); }}\n"
        for name, x, y, z in spheres)
    props = case.path / "constant" / "particleProperties"
    props.write_text(props.read_text().replace("particles\n{\n",
                                               "particles\n{\n" + entries, 1))
    case.run("dlmDEMFoam")
    drop = top - case.history()["top"][:, 3]
    if tangential == "spring":
        assert drop.max() < 0.01*R
    else:
        assert drop[-1] > 0.2*R


def test_adaptive_step_holds_the_courant_number_through_a_bounce(tmp_path, foam_env):
    """A steel sphere (density 8000) falls in water onto the floor and
    bounces (restitution 0.9), with an adjustable step at maxCo 0.5. The
    step also holds the particle's Courant number: its surface speed,
    doubled near a contact, plus its change over the last step (the fluid
    meets a bounced sphere at that speed). With the flow's Courant number
    alone the bounce took it to 0.69."""
    case = landing_case(tmp_path, foam_env, "bounce")
    case.set("constant/particleProperties", "particles/sphere/density", 8000)
    case.set("constant/particleProperties", "particles/sphere/position",
             "(0.0151 0.0149 0.025)")
    case.set("constant/particleProperties", "contact/pairs/sphereWall/restitution", 0.9)
    case.set("constant/particleProperties", "contact/pairs/sphereWall/impactVelocity", 0.3)
    case.set("constant/transportProperties", "nu", 1e-6)
    case.set("system/controlDict", "adjustTimeStep", "yes")
    case.set("system/controlDict", "deltaT", 1e-3)
    case.set("system/controlDict", "maxDeltaT", 0.01)
    case.set("system/controlDict", "endTime", 0.12)
    log = case.run("pimpleDLMFoam").log
    h = case.history()["sphere"]
    # It fell at over 0.4 m/s and bounced up at over 0.1 m/s
    fall = np.argmin(h[:, 6])
    assert h[fall, 6] < -0.4 and h[fall:, 6].max() > 0.1
    courant = [float(line.split()[5]) for line in log.splitlines()
               if line.startswith("Courant Number mean")]
    assert max(courant) < 0.53


def test_rolling_resistance_slows_a_rolling_sphere_at_five_sevenths_mu_r_g(
        tmp_path, foam_env):
    """A sphere rolling on the floor at 0.1 m/s with rolling friction
    mu_r = 0.05 (a torque mu_r R Fn against its spin) slows down at
    5/7 mu_r g (rolling without slipping: the contact's friction turns the
    torque into the deceleration of the sphere and its spin), to 2 %, and
    then rests without rocking."""
    mu_r = 0.05
    case = lone_sphere(tmp_path, foam_env, "rolling", "(-0.008 0 0.002)", "(0.1 0 0)", {
        ("constant/g", "value"): "(0 0 -9.81)",
        ("constant/particleProperties", "particles/left/angularVelocity"): "(0 50 0)",
        ("constant/particleProperties", f"{PAIRS}/particleWall/rollingFriction"): mu_r,
        ("system/controlDict", "endTime"): 0.4,
        ("system/controlDict", "writeInterval"): 100000,
    })
    case.run("dlmDEMFoam")
    h = case.history()["left"]
    t, ux = h[:, 0], h[:, 4]
    rolling = (t > 0.05) & (t < 0.2)
    slope = np.polyfit(t[rolling], ux[rolling], 1)[0]
    assert slope == pytest.approx(-5/7*mu_r*9.81, rel=0.02)
    rest = t > 0.35
    assert np.abs(h[rest, 4:10]).max() < 1e-6
    assert np.ptp(h[rest, 1]) < 1e-9
