"""The coupling of particles and fluid: heavy and light particles against
their free motion, and results that do not depend on the time step."""

import pathlib
import re

import numpy as np
import pytest

from foamcase import Case, long_cell_flow

HERE = pathlib.Path(__file__).parent
SPHERE_BOX = HERE / "cases" / "sphereBox"
G = 9.81

# A 10 mm sphere at 6 cells per diameter in a closed box 4 x 4 x 9 diameters,
# 7.5 diameters above the bottom: room for 5 diameters of fall
TALL_BOX = """FoamFile
{
    version     2.0;
    format      ascii;
    class       dictionary;
    object      blockMeshDict;
}
vertices
(
    (0 0 0) (0.04 0 0) (0.04 0.04 0) (0 0.04 0)
    (0 0 0.09) (0.04 0 0.09) (0.04 0.04 0.09) (0 0.04 0.09)
);
blocks ( hex (0 1 2 3 4 5 6 7) (24 24 54) simpleGrading (1 1 1) );
boundary
(
    walls
    {
        type wall;
        faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7));
    }
);
"""


def falling_sphere(tmp_path, env, name, density, end_time, delta_t=5e-4,
                   nu=1e-5, settings=None):
    """Water (nu 1e-5, so that the drag over the fall is below 0.5 % of a
    heavy sphere's weight) at rest, the sphere released from rest; further
    dictionary settings may be given."""
    case = Case.copy(SPHERE_BOX, tmp_path / name, env)
    (case.path / "system" / "blockMeshDict").write_text(TALL_BOX)
    case.run("blockMesh")
    settings = {
        **(settings or {}),
        ("constant/transportProperties", "nu"): nu,
        ("constant/particleProperties", "particles/sphere/density"): density,
        ("constant/particleProperties", "particles/sphere/position"):
            "(0.0201 0.0199 0.075)",
        ("system/controlDict", "deltaT"): delta_t,
        ("system/controlDict", "endTime"): end_time,
        ("system/controlDict", "maxViscousNumber"): 1000,
        ("system/controlDict", "writeInterval"): 1000,
    }
    for (file, entry), value in settings.items():
        case.set(file, entry, value)
    case.run("pimpleDLMFoam")
    return case.history()["sphere"]


def test_a_sphere_1000_times_as_heavy_as_water_falls_freely(tmp_path, foam_env):
    """Over 5 diameters of fall its velocity stays within 1 % of g t: drag
    and added mass are below 0.5 % of its weight. The solid mass a moving
    particle takes into a cell used to keep that cell's fluid velocity, and
    the mixture's convection acted on the solid: 27 % below g t after 0.1 s."""
    h = falling_sphere(tmp_path, foam_env, "rho1e6", 1e6, 0.1)
    t, z, uz = h[1:, 0], h[1:, 3], h[1:, 6]
    fall = h[0, 3] - z[-1]
    assert fall > 0.048
    assert fall == pytest.approx(G*t[-1]**2/2, rel=0.01)
    assert np.all(np.abs(uz/(-G*t) - 1) < 0.01)
    assert np.abs(h[:, 4:6]).max() < 0.01*abs(uz[-1])


def test_the_early_fluid_force_on_a_heavy_sphere_does_not_grow_with_its_density(
        tmp_path, foam_env):
    """The fluid force on spheres 100 and 1000 times as heavy as water, over
    their first 0.03 s, is the fluid's: the same for both within 8 % in the
    mean (5.5 % measured: the lighter one falls 2.7 % slower by 0.03 s, and
    the drag grows with the speed) and 30 % at each step (the crossing of
    cells differs), and below 5 % of the lighter one's weight.
    It was proportional to the solid density (0.8 N on the heavier, 160
    times its drag, after 0.03 s)."""
    forces = {}
    for density in (1e5, 1e6):
        h = falling_sphere(tmp_path, foam_env, f"rho{density:g}", density, 0.03)
        forces[density] = h[1:, 12]
    weight = 1e5*np.pi/6*0.01**3*G
    assert np.abs(forces[1e5]).max() < 0.05*weight
    assert forces[1e6].mean() == pytest.approx(forces[1e5].mean(), rel=0.08)
    assert np.abs(forces[1e6] - forces[1e5]).max() < 0.3*forces[1e5].max()


@pytest.mark.parametrize("ratio, water, slip", [
    (0.1, False, False), (0.3, False, False), (0.5, False, False), (2, False, False),
    (10, False, False), (100, False, False), (1000, False, False),
    (0.1, True, False), (0.1, True, True), (0.6, True, True), (1000, True, True)])
def test_particles_light_and_heavy_move_without_blow_up(tmp_path, foam_env, ratio, water, slip):
    """Density ratios from 0.1 to 1000 in a liquid of nu 1e-3, released from
    rest with an adjustable step (maxCo 0.5) for 0.06 s (light ones reach
    their terminal speed, the heaviest falls 2 diameters): each rises or
    sinks at most as fast as its buoyancy alone would take it, the fluid
    stays slower than twice the particle, and the particle does not drift
    sideways. The lightest also in water (nu 1e-6, Reynolds number up to
    2000: it blew up when its cells convected the fluid's density), and
    in water with boundaryLayerSlip, whose layer is then thinner than a
    cell: 0.6 and 1000 slip; 0.1, lighter than its added mass, keeps
    no-slip profiles with a warning (slipping, it blew up)."""
    name = f"ratio{ratio:g}{'water' if water else ''}{'slip' if slip else ''}"
    case = Case.copy(SPHERE_BOX, tmp_path / name, foam_env)
    case.run("blockMesh")
    if water:
        case.set("constant/transportProperties", "nu", 1e-6)
    if slip:
        case.set("system/fvOptions", "rigidProjection/boundaryLayerSlip", "true")
    for (file, entry), value in {
        ("constant/particleProperties", "particles/sphere/density"): 1000*ratio,
        ("system/controlDict", "adjustTimeStep"): "yes",
        ("constant/particleProperties", "particles/sphere/position"):
            "(0.0151 0.0149 0.015)" if ratio < 1 else "(0.0151 0.0149 0.03)",
        ("system/controlDict", "endTime"): 0.06,
        ("system/controlDict", "writeInterval"): 1000,
    }.items():
        case.set(file, entry, value)
    log = case.run("pimpleDLMFoam").log
    assert ("particle sphere (density 100) is lighter than 0.5 times the fluid"
            in log) == (slip and ratio < 0.5)
    h = case.history()["sphere"]
    assert np.isfinite(h).all()
    t, uz = h[1:, 0], h[1:, 6]
    # Buoyancy alone, with the added mass of a sphere (coefficient 1/2)
    free = (ratio - 1)/(ratio + 0.5)*G*t
    assert np.all(np.sign(uz) == -np.sign(ratio - 1))
    assert np.all(np.abs(uz) <= np.abs(free)*1.001)
    assert np.abs(h[:, 4:6]).max() < 0.01*np.abs(uz).max()
    U = case.internal_field(f"{case.times()[-1]}/U")
    assert np.linalg.norm(U, axis=1).max() < 2*np.abs(uz[-1])


def start_acceleration(tmp_path, env, n, mixed_cells, slip=False, end_time=0.002):
    """The mean acceleration over the first end_time (2 ms steps) of a
    light sphere (d 10 mm, 843 kg/m3, in water) released from rest at the
    centre of a closed cube 6 d wide with n cells per diameter."""
    case = Case.copy(SPHERE_BOX, tmp_path / f"{mixed_cells}{n}{'slip' if slip else ''}", env)
    cells = 6*n
    (case.path / "system" / "blockMeshDict").write_text(
        TALL_BOX.replace("0.09", "0.06").replace("0.04", "0.06")
        .replace("(24 24 54)", f"({cells} {cells} {cells})"))
    case.run("blockMesh")
    for (file, entry), value in {
        ("constant/transportProperties", "nu"): 1e-6,
        ("constant/particleProperties", "particles/sphere/density"): 843,
        ("constant/particleProperties", "particles/sphere/position"):
            "(0.0301 0.0299 0.03)",
        ("system/controlDict", "deltaT"): 0.002,
        ("system/controlDict", "endTime"): end_time,
        ("system/fvOptions", "rigidProjection/mixedCells"): mixed_cells,
    }.items():
        case.set(file, entry, value)
    if slip:
        case.set("system/fvOptions", "rigidProjection/boundaryLayerSlip", "true")
    case.run("pimpleDLMFoam")
    h = case.history()["sphere"]
    return h[-1, 6]/h[-1, 0]


def test_a_light_spheres_start_converges_to_the_added_mass_acceleration(tmp_path, foam_env):
    """Released from rest, before drag and the viscous layer act, a sphere
    lighter than the fluid accelerates at (rho_f - rho_s) g/(rho_s +
    rho_f/2) (1.147 m/s2 here; a few per cent less in the cube). The
    interpolated treatment also moves the fluid of the profile cells around
    the sphere with it, a layer about 0.8 of a cell thick: the inertia in
    excess of the sphere's and its added mass halves with the cell size
    (0.66 and 0.30 of the displaced fluid's mass at 8 and 16 cells per
    diameter; validation/cases/risingPebble.md). The paper's
    blend (massWeighted) forces only the covered cells: its first step
    comes within 6 % of the added-mass acceleration at 16 cells (-4.6 %)."""
    net_buoyancy = (1000 - 843)*G
    ideal = net_buoyancy/(843 + 500)
    excess = {n: (net_buoyancy/start_acceleration(tmp_path, foam_env, n, "interpolated")
                  - (843 + 500))/1000 for n in (8, 16)}
    assert 0.35 < excess[16]/excess[8] < 0.6
    assert 0 < excess[16] < 0.4
    assert start_acceleration(tmp_path, foam_env, 16, "massWeighted") == \
        pytest.approx(ideal, rel=0.06)


def test_boundary_layer_slip_brings_a_light_spheres_start_near_its_added_mass(
        tmp_path, foam_env):
    """At 8 cells per diameter in water the viscous layer of a sphere
    released from rest is far thinner than a cell after its first step.
    With boundaryLayerSlip the profile cells' tangential velocity follows
    the flow beyond them instead of the sphere: the mean acceleration over
    the first 20 ms comes within 15 % of the added-mass value (-13 %, of
    which a few per cent are the cube's confinement; the no-slip profiles'
    is 32 % below it)."""
    ideal = (1000 - 843)*G/(843 + 500)
    slip = start_acceleration(tmp_path, foam_env, 8, "interpolated", True, 0.02)
    no_slip = start_acceleration(tmp_path, foam_env, 8, "interpolated", False, 0.02)
    assert slip == pytest.approx(ideal, rel=0.15)
    assert no_slip < 0.75*ideal


def test_boundary_layer_slip_keeps_a_resolved_layer_no_slip(tmp_path, foam_env):
    """Where the viscous layer spans cells (a sphere settling in a liquid
    of nu 1e-3 at a Reynolds number below 0.5: the layer sqrt(nu t) is a
    cell thick after the first step, sqrt(nu d/u) 8 cells), the slip's
    share is zero and boundaryLayerSlip gives the no-slip trajectory, to
    the round-off of its other way of summing the momentum balance."""
    def settle(name, slip):
        case = Case.copy(SPHERE_BOX, tmp_path / name, foam_env)
        case.run("blockMesh")
        case.set("constant/transportProperties", "nu", 1e-3)
        case.set("system/controlDict", "endTime", 0.05)
        if slip:
            case.set("system/fvOptions", "rigidProjection/boundaryLayerSlip", "true")
        case.run("pimpleDLMFoam")
        return case.history()["sphere"]

    slip, no_slip = settle("slip", True), settle("noSlip", False)
    assert slip.shape == no_slip.shape
    assert np.abs(no_slip[-1, 6]) > 1e-4
    assert np.abs(slip[:, 4:10] - no_slip[:, 4:10]).max() < 1e-9*np.abs(no_slip[:, 6]).max()


@pytest.fixture(scope="module")
def settling_at_viscous_numbers(tmp_path_factory, foam_env):
    """The sphere of tests/cases/sphereBox (density 2000, 6 cells per
    diameter) settling in a viscous liquid (nu 1e-2: Reynolds number 0.002)
    at fixed steps giving viscous numbers nu dt/h^2 of 1, 10 and 50, with
    three pressure correctors (and the default limit), for 0.6 s (2160, 216 and 43 steps): the
    history (t, u_z) of each."""
    h = 0.03/18
    histories = {}
    for number in (1, 10, 50):
        case = Case.copy(SPHERE_BOX, tmp_path_factory.mktemp(f"vn{number}"),
                         foam_env)
        case.run("blockMesh")
        case.run("foamDictionary", "system/controlDict", "-entry",
                 "maxViscousNumber", "-remove", log="foamDictionary")
        for (file, entry), value in {
            ("constant/transportProperties", "nu"): 1e-2,
            ("system/fvSolution", "PIMPLE/nCorrectors"): 3,
            # Just below the number (foamDictionary writes 6 digits): 50 is the
            # default limit with three correctors
            ("system/controlDict", "deltaT"): repr((1 - 1e-4)*number*h**2/1e-2),
            ("system/controlDict", "endTime"): 0.6,
            ("system/controlDict", "writeInterval"): 100000,
        }.items():
            case.set(file, entry, value)
        case.run("pimpleDLMFoam")
        history = case.history()["sphere"]
        histories[number] = history[1:, [0, 6]]
    return histories


def test_settling_velocity_does_not_depend_on_the_viscous_number(
        settling_at_viscous_numbers):
    """The terminal velocity (the mean over 0.5-0.6 s) at viscous numbers
    10 and 50 equals that at 1 to 0.5 % (0.02 % here). When a correction
    changed the force the projection carries by rho/dt times the change of
    velocity, removing only about 1/(1 + 6 nu dt/h^2) of a cell-to-cell
    deficit a step, the velocity at 0.3 s was 1.7 % off at 10 and 22 % off
    at 50, swinging from step to step (with four correctors)."""
    def terminal(history):
        t, uz = history.T
        assert np.isfinite(uz).all()
        return uz[(t >= 0.5) & (t <= 0.6)].mean()

    reference = terminal(settling_at_viscous_numbers[1])
    assert reference < 0
    for number in (10, 50):
        assert terminal(settling_at_viscous_numbers[number]) == pytest.approx(
            reference, rel=0.005)


def test_settling_at_high_viscous_numbers_comes_to_a_steady_velocity(
        settling_at_viscous_numbers):
    """No swing is left at the end: over 0.5-0.6 s the velocity changes by
    less than 1 % from step to step at every viscous number (0.06, 0.14 and
    0.19 % here: the sphere's surface crosses cells). At 50 the first steps
    swing (12 % over 0.1-0.2 s), dying out by a factor of about 0.93 a
    step."""
    for number, history in settling_at_viscous_numbers.items():
        t, uz = history.T
        window = uz[(t >= 0.5) & (t <= 0.6)]
        assert np.abs(np.diff(window)).max() < 0.01*abs(window.mean()), number


def ten_cate_E4(path, env, step_factor):
    """tutorials/tenCate, case E4 (Re 32), on its own mesh (6 cells per
    diameter, graded to the side walls) with the step limits maxCo 0.5 and
    maxDeltaT 0.02 (the Courant number sets the step) scaled by
    step_factor: u_max [m/s]."""
    case = Case.copy(HERE.parent / "tutorials" / "tenCate", path, env)
    for (file, entry), value in {
        ("constant/transportProperties", "rho"): 960,
        ("constant/transportProperties", "nu"): 6.0417e-5,
        ("system/controlDict", "maxCo"): 0.5*step_factor,
        ("system/controlDict", "maxDeltaT"): 0.02*step_factor,
        ("system/controlDict", "endTime"): 1.1,
        ("system/controlDict", "writeInterval"): 1000,
    }.items():
        case.set(file, entry, value)
    case.run("blockMesh")
    case.run("pimpleDLMFoam")
    uz = case.history()["sphere"][:, 6]
    assert np.isfinite(uz).all()
    return -uz.min()


def test_settling_at_Re_32_does_not_depend_on_the_time_step(tmp_path, foam_env):
    """ten Cate's E4 (the sphere reaches u_max at about 1.05 s): u_max at
    half the tutorial's step is the same to 0.4 % (0.08 % here; 0.11620 and
    0.11629 m/s). When the momentum equation convected with the last step's
    flux, the flow the moving sphere carries lagged a step: 1.16 % (0.11431
    and 0.11565)."""
    u_max = {factor: ten_cate_E4(tmp_path / f"step{factor:g}", foam_env, factor)
             for factor in (1, 0.5)}
    assert u_max[1] > 0.1
    assert u_max[1] == pytest.approx(u_max[0.5], rel=0.004)


def settling_at_Re_half(path, env, delta_t, follow=True):
    """The 10 mm sphere of the tall box (density 1167, nu 3e-4: Re 0.5,
    terminal velocity about 0.0159 m/s, 6 cells per diameter, backward
    time derivative) settling at a fixed step from rest: its mean velocity
    over 0.4-0.5 s (the displacement, which averages the swing of crossing
    cells)."""
    h = falling_sphere(path.parent, env, path.name, 1167, 0.5, delta_t, nu=3e-4, settings={
        ("system/fvSchemes", "ddtSchemes/default"): "backward",
        ("system/fvSolution", "PIMPLE/nCorrectors"): 3,
        ("system/fvOptions", "rigidProjection/forceFollowsParticles"):
            "true" if follow else "false",
    })
    t, z = h[:, [0, 3]].T
    return (np.interp(0.5, t, z) - np.interp(0.4, t, z))/0.1


def test_settling_at_large_steps_keeps_the_small_steps_speed(tmp_path, foam_env):
    """At 40 ms (viscous number 4.3, particle Courant number 0.38) the sphere
    settles as at 4 ms to 0.5 % (0.04 % here): the force that holds it rigid
    moves with it from step to step. Left on the cells, that force lags the
    sphere by a step and the sphere runs 2.5 % fast (checked here: more than
    1.5 %)."""
    small = settling_at_Re_half(tmp_path / "dt4ms", foam_env, 0.004)
    large = settling_at_Re_half(tmp_path / "dt40ms", foam_env, 0.04)
    lagging = settling_at_Re_half(tmp_path / "dt40msLag", foam_env, 0.04, follow=False)
    assert small == pytest.approx(-0.0159, rel=0.02)
    assert large == pytest.approx(small, rel=0.005)
    assert lagging/small - 1 > 0.015


def test_long_cells_limit_the_viscous_number_so_the_flow_stays_stable(tmp_path, foam_env):
    """A periodic box of cells 4.5 times longer along x than across (no
    particle), a random flow decaying: with three pressure correctors the
    flow swings and grows from a viscous number of 4 (pimpleFoam's too;
    the cubic cells' limit is 50), so the default limit falls to 3 and the
    flow decays over 300 steps (validation/benchmark_viscousLimit.py)."""
    case = Case.copy(HERE.parent / "tutorials" / "periodicArray", tmp_path / "longCells", foam_env)
    h = 2.5e-4
    long_cell_flow(case, 4.5, h, (6, 16, 16))
    nu = 1e-3
    steps = 300
    for (file, entry), value in {
        ("constant/transportProperties", "nu"): nu,
        ("system/fvSolution", "PIMPLE/nCorrectors"): 3,
        ("system/controlDict", "deltaT"): 50*h**2/nu,
        ("system/controlDict", "adjustTimeStep"): "yes",
        ("system/controlDict", "maxCo"): 100,
        ("system/controlDict", "endTime"): steps*3*h**2/nu,
        ("system/controlDict", "writeInterval"): 1,
    }.items():
        case.set(file, entry, value)
    case.run("foamDictionary", "system/controlDict", "-entry", "maxViscousNumber",
             "-remove", log="foamDictionary")
    case.run("foamDictionary", "system/controlDict", "-entry", "functions",
             "-remove", log="foamDictionary")
    log = case.run("pimpleDLMFoam").log
    viscous = np.array([float(v) for v in re.findall(r"^Viscous number: (\S+)", log, re.M)])
    courant = np.array([float(v) for v in
                        re.findall(r"^Courant Number mean: \S+ max: (\S+)", log, re.M)])
    assert len(viscous) > steps
    assert viscous.max() == pytest.approx(3, rel=1e-3)
    assert np.isfinite(courant).all()
    # Decaying: the largest velocity at the end below a tenth of the start's
    assert courant[-1] < 0.1*courant[1]
