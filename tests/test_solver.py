"""Case-level tests of pimpleDLMFoam on small meshes: stability and physics
of settling and rising particles, restart, serial against parallel."""

import pathlib
import shutil

import numpy as np
import pytest

from foamcase import assert_same_trajectory, Case

HERE = pathlib.Path(__file__).parent
SPHERE_BOX = HERE / "cases" / "sphereBox"
DISK = HERE.parent / "tutorials" / "fallingDisk"


def sphere_case(tmp_path, env, name, density=2000, settings=None):
    case = Case.copy(SPHERE_BOX, tmp_path / name, env)
    case.run("blockMesh")
    case.set("constant/particleProperties", "particles/sphere/density", density)
    for (file, entry), value in (settings or {}).items():
        case.set(file, entry, value)
    return case


def test_neutrally_buoyant_sphere_stays_still(tmp_path, foam_env):
    case = sphere_case(tmp_path, foam_env, "neutral", density=1000,
                       settings={("system/controlDict", "endTime"): 0.05})
    case.run("pimpleDLMFoam")
    h = case.history()["sphere"]
    assert len(h) == 10
    # Position unchanged and velocity zero to round-off
    assert np.abs(h[:, 1:4] - h[0, 1:4]).max() < 1e-15
    assert np.abs(h[:, 4:10]).max() < 1e-14


def test_rising_and_settling_speeds_agree(tmp_path, foam_env):
    """Stokes flow (Re ~ 0.15): a sphere of density 500 rises as fast as one of
    1500 settles in water of 1000, midway between the box's top and bottom."""
    speeds = {}
    for density in (500, 1500):
        case = sphere_case(tmp_path, foam_env, f"rho{density}", density,
                           {("constant/particleProperties",
                             "particles/sphere/position"): "(0.0151 0.0149 0.0225)"})
        case.run("pimpleDLMFoam")
        h = case.history()["sphere"]
        assert np.isfinite(h).all()
        speeds[density] = h[-1, 6]
        # Terminal: the last 20 % of the run changes by under 1 %
        late = h[h[:, 0] > 0.08, 6]
        assert np.ptp(late) < 0.01*abs(late[-1])
    assert speeds[500] > 0 > speeds[1500]
    # Equal within 3 % (mixed-cell error at 6 cells per diameter: about 2 %)
    assert abs(speeds[500] + speeds[1500]) < 0.03*speeds[500]


def test_heavy_sphere_starts_with_the_added_mass_acceleration(tmp_path, foam_env):
    """rho_s/rho_f = 100 from rest: dv/dt = (rho_s - rho_f) g/(rho_s + rho_f/2)
    while viscous (Basset) forces are still negligible (0.3 % at 0.5 ms)."""
    case = sphere_case(tmp_path, foam_env, "heavy", 100000,
                       {("system/controlDict", "deltaT"): 1e-4,
                        ("system/controlDict", "endTime"): 5e-4})
    case.run("pimpleDLMFoam")
    h = case.history()["sphere"]
    expected = -99/100.5*9.81
    acceleration = h[:, 6]/h[:, 0]
    assert acceleration == pytest.approx(expected, rel=0.02)


def test_heavy_sphere_is_stable_with_adjustable_time_step(tmp_path, foam_env):
    case = sphere_case(tmp_path, foam_env, "heavyLong", 100000,
                       {("system/controlDict", "adjustTimeStep"): "yes",
                        ("system/controlDict", "endTime"): 0.05})
    case.run("pimpleDLMFoam")
    h = case.history()["sphere"]
    assert np.isfinite(h).all()
    Uz = h[:, 6]
    assert (np.diff(Uz) < 0).all()
    assert np.abs(h[:, 4:6]).max() < 0.01*abs(Uz[-1])


@pytest.mark.parametrize("ddt, adjust, fluid", [("Euler", "no", "viscous"),
                                               ("backward", "yes", "viscous"),
                                               ("backward", "yes", "water"),
                                               ("backward", "yes", "waterSlip")])
def test_restart_continues_the_trajectory(tmp_path, foam_env, ddt, adjust, fluid):
    """In water the sphere's own Courant number sets the step, from its
    last change of speed, which the state written with each time keeps (a
    restart without it took another step). waterSlip: with
    boundaryLayerSlip, whose targets depend on the flow beyond the
    sphere's profile cells and on the time since the start (so the time
    directories are named to full precision: a restart's clock starts
    from the name)."""
    settings = {("system/fvSchemes", "ddtSchemes/default"): ddt,
                ("system/controlDict", "adjustTimeStep"): adjust,
                ("system/controlDict", "maxCo"): 0.1}
    if fluid.startswith("water"):
        settings[("constant/transportProperties", "nu")] = 1e-6
    if fluid == "waterSlip":
        settings[("system/fvOptions", "rigidProjection/boundaryLayerSlip")] = "true"
        settings[("system/controlDict", "timePrecision")] = 17
    full = sphere_case(tmp_path, foam_env, "full", settings=settings)
    full.run("pimpleDLMFoam")
    first_write = full.times()[1]

    restarted = sphere_case(tmp_path, foam_env, "restarted", settings=settings)
    shutil.copytree(full.path / first_write, restarted.path / first_write)
    restarted.run("pimpleDLMFoam")

    a = full.history()["sphere"]
    b = restarted.history(first_write)["sphere"]
    tail = a[a[:, 0] > float(first_write) + 1e-9]
    assert len(b) == len(tail) >= 5
    # Same trajectory to round-off (the time step too, when adjusted). The
    # clock restarts from the time directory's name (OpenFOAM), which
    # timePrecision 8 rounds: times agree to that precision
    assert np.abs(b[:, 1:10] - tail[:, 1:10]).max() < 1e-12
    assert np.abs(b[:, 0] - tail[:, 0]).max() < 1e-8*tail[-1, 0]


@pytest.mark.parametrize("source", ["sphereBox", "fallingDisk", "sphereBoxSlip"])
def test_parallel_matches_serial(tmp_path, foam_env, source):
    """sphereBoxSlip: the sphere in water, where its viscous layer is
    thinner than a cell, with boundaryLayerSlip: the profile cells' targets
    then depend on the flow beyond them, across the processor boundary."""
    def make(name):
        if source.startswith("sphereBox"):
            case = Case.copy(SPHERE_BOX, tmp_path / name, foam_env)
            case.run("blockMesh")
            case.set("system/controlDict", "endTime", 0.05)
            if source == "sphereBoxSlip":
                case.set("constant/transportProperties", "nu", 1e-6)
                case.set("system/fvOptions", "rigidProjection/boundaryLayerSlip", "true")
        else:
            case = Case.copy(DISK, tmp_path / name, foam_env)
            case.run("blockMesh")
            case.set("system/controlDict", "endTime", 0.05)
            case.set("system/controlDict", "adjustTimeStep", "no")
            case.set("system/controlDict", "deltaT", 0.005)
            case.set("system/controlDict", "writeInterval", 0.05)
            # METIS cuts the channel across its middle: start the disk there
            case.set("constant/particleProperties", "particles/disk/position",
                     "(0.1 0.2 0)")
        case.converge_linear_solvers()
        return case

    serial = make("serial")
    serial.run("pimpleDLMFoam")

    parallel = make("parallel")
    parallel.set("system/controlDict", "writeFormat", "ascii")
    decompose = parallel.run("decomposePar")
    assert "metis" in decompose.log
    parallel.run("pimpleDLMFoam", np=2)
    parallel.run("reconstructPar")

    # The particle spans both processors
    for processor in ["processor0", "processor1"]:
        alpha = parallel.internal_field(f"{processor}/0.05/alpha.solid")
        assert alpha.max() > 0.5

    name, = serial.history()
    s = serial.history()[name]
    p = parallel.history()[name]
    assert s.shape == p.shape
    assert_same_trajectory(s, p)
    assert (parallel.path / "0.05" / "U").exists()


def test_disk_at_reynolds_2000_runs_without_blow_up(tmp_path, foam_env):
    """The paper's mu = 0.002 Pa s disk on a coarse mesh (4 cells per
    diameter): it accelerates to its terminal speed, about 0.2 m/s
    (Re = U d/nu = 4000), sheds a wake that turns it, and stays bounded."""
    case = Case.copy(DISK, tmp_path / "disk2000", foam_env)
    (case.path / "system/blockMeshDict").write_text(
        (case.path / "system/blockMeshDict").read_text()
        .replace("nx  80;", "nx  40;").replace("ny  160;", "ny  80;"))
    case.run("blockMesh")
    case.set("constant/transportProperties", "nu", 0.002/2000)
    case.set("system/controlDict", "endTime", 1.2)
    case.run("pimpleDLMFoam")

    h = case.history()["disk"]
    assert h[-1, 0] == pytest.approx(1.2)
    assert np.isfinite(h).all()
    speed = np.linalg.norm(h[:, 4:6], axis=1)
    assert 0.15 < speed[-1] < 0.25
    assert speed.max() < 0.25
    U = case.internal_field("1.2/U")
    assert np.isfinite(U).all()
    assert np.linalg.norm(U, axis=1).max() < 0.5


def test_fixed_sphere_in_a_periodic_array_holds_the_driving_force(tmp_path, foam_env):
    """tutorials/periodicArray at 8 cells per diameter: in the steady Stokes
    flow the fluid force on the fixed sphere balances the mean pressure
    gradient over the periodic cell, G L^3 (1e-6 N), and the drag coefficient
    is within 15 % of Zick & Homsy's 4.292 (the convergence is in
    validation/validate_zickHomsy.py)."""
    case = Case.copy(HERE.parent / "tutorials" / "periodicArray",
                     tmp_path / "array", foam_env)
    result = case.run("./Allrun", 0.125, 8)
    F = case.history()["sphere"][-1, 10:13]
    assert F[0] == pytest.approx(1e-6, rel=1e-4)
    assert np.abs(F[1:]).max() < 1e-6*F[0]
    K = float(result.log.split("K = F/(6 pi mu a U) = ")[1].split()[0])
    assert K == pytest.approx(4.292, rel=0.15)


def test_parallel_restart_continues_the_trajectory(tmp_path, foam_env):
    """A decomposed run stopped at a written time and restarted from the
    processor directories continues as the uninterrupted parallel run."""
    def make(name, end_time):
        case = sphere_case(tmp_path, foam_env, name)
        case.set("system/controlDict", "endTime", end_time)
        case.run("decomposePar")
        return case

    full = make("full", 0.1)
    full.run("pimpleDLMFoam", np=2)

    stopped = make("stopped", 0.05)
    stopped.run("pimpleDLMFoam", np=2)
    stopped.set("system/controlDict", "endTime", 0.1)
    stopped.run("pimpleDLMFoam", np=2, log="pimpleDLMFoam.restart")

    a = full.history()["sphere"]
    b = stopped.history("0.05")["sphere"]
    tail = a[a[:, 0] > 0.05 + 1e-9]
    assert len(b) == len(tail) == 10
    assert np.abs(b[:, 1:10] - tail[:, 1:10]).max() < 1e-12


def launched_case(tmp_path, env, name, end_time, settings=None):
    """The sphere in water without gravity, at a fixed step of 1 ms."""
    return sphere_case(tmp_path, env, name, settings={
        ("constant/g", "value"): "(0 0 0)",
        ("constant/transportProperties", "nu"): 1e-6,
        ("system/controlDict", "deltaT"): 1e-3,
        ("system/controlDict", "endTime"): end_time,
        ("system/controlDict", "writeInterval"): 1000,
        **(settings or {}),
    })


def test_sphere_launched_through_still_fluid_keeps_its_velocity(tmp_path, foam_env):
    """A sphere launched at 1 cm/s spinning at 2 rad/s in water at rest: the
    fluid starts with it (rigid inside, an impulsive start's flow around),
    so the first step keeps its velocity and spin but for the drag of a
    millisecond (Basset's impulse, about 1.6 % here for an unconfined
    sphere, an upper bound), and both then decay slowly. (Before, the fluid
    inside it was at rest and the first projection stopped it.)"""
    case = launched_case(tmp_path, foam_env, "launch", 0.005, {
        ("constant/particleProperties", "particles/sphere/velocity"): "(0.01 0 0)",
        ("constant/particleProperties", "particles/sphere/angularVelocity"): "(0 0 2)",
    })
    log = case.run("pimpleDLMFoam").log
    assert "Starting the flow with the particles' initial velocities" in log
    h = case.history()["sphere"]
    assert 0.984*0.01 < h[0, 4] < 0.01
    assert 0.984*2 < h[0, 9] < 2
    assert np.all(np.diff(h[:, 4]) < 0) and np.all(np.diff(h[:, 9]) < 0)
    assert h[-1, 4] > 0.95*0.01


def test_wet_head_on_collision_is_symmetric_and_rebounds(tmp_path, foam_env):
    """Two spheres launched at each other along z at 0.1 m/s, placed
    symmetrically in the box: they keep their speed at the start, collide
    through the lubrication film and part again, mirror images of each
    other (to round-off, which the collision amplifies to about 1e-6 of the
    speed: 0.9e-6 with the carried force left on the cells, 1.2e-6 with it
    following the particles)."""
    def edit(case):
        props = case.path / "constant" / "particleProperties"
        props.write_text(props.read_text().replace(
            "particles\n{", "particles\n{\n    upper { shape sphere; radius 0.005;"
            " density 2000; position (0.0151 0.0149 0.0325);"
            " velocity (0 0 -0.1); }") + """
contact
{
    pairs
    {
        pair { materials (particle particle); law overlapVolume;
               contactTime 2e-3; impactVelocity 0.1; restitution 0.9;
               friction 0.3; }
        wall { materials (particle wall); law overlapVolume;
               contactTime 2e-3; impactVelocity 0.1; restitution 0.9;
               friction 0.3; }
    }
}
""")
    case = launched_case(tmp_path, foam_env, "headOn", 0.1)
    case.set("constant/particleProperties", "particles/sphere/position",
             "(0.0151 0.0149 0.0125)")
    case.set("constant/particleProperties", "particles/sphere/velocity", "(0 0 0.1)")
    edit(case)
    case.run("pimpleDLMFoam")
    h = case.history()
    lower, upper = h["sphere"], h["upper"]
    assert lower[0, 6] > 0.99*0.1 and upper[0, 6] < -0.99*0.1
    # Mirror images about the box's mid-height
    assert np.abs(lower[:, 6] + upper[:, 6]).max() < 3e-6*0.1
    assert np.abs(lower[:, 3] + upper[:, 3] - 0.045).max() < 1e-8
    # They touched and parted
    assert np.abs(lower[:, 18]).max() > 0
    assert lower[-1, 6] < 0 < upper[-1, 6]


def test_last_state_and_start_are_written_and_the_log_is_readable(tmp_path, foam_env):
    """endTime 0.02 is not a write time (every 3 steps of 5 ms): the last
    state is written anyway, with the particles' VTK, as is the VTK of the
    start. The log holds a particle line per step, the progress and numbers
    at 6 significant digits although the case writes 17."""
    case = sphere_case(tmp_path, foam_env, "written", settings={
        ("system/controlDict", "endTime"): 0.02,
        ("system/controlDict", "writeInterval"): 3,
        ("system/controlDict", "progressInterval"): 1e-9,
    })
    log = case.run("pimpleDLMFoam").log
    assert case.times() == ["0", "0.015", "0.02"]
    assert (case.path / "0.02" / "uniform" / "particles").exists()
    vtk = case.path / "VTK" / "particles"
    assert sorted(f.name for f in vtk.glob("*.vtk")) == [
        "particles_0.015.vtk", "particles_0.02.vtk", "particles_0.vtk"]
    start = (vtk / "particles_0.vtk").read_text()
    assert "SCALARS id int 1\nLOOKUP_TABLE default\n0\n" in start
    assert "SCALARS orientation double 4\nLOOKUP_TABLE default\n1 0 0 0\n" in start
    assert '"particles_0.vtk", "time" : 0 }' in (vtk / "particles.vtk.series").read_text()

    summaries = [line for line in log.splitlines() if line.startswith("Particles: 1, largest speed")]
    assert len(summaries) == 4
    assert "Progress: t = 0.02 of 0.02 (100 %)" in log
    courant = [line for line in log.splitlines() if line.startswith("Courant Number mean")]
    numbers = [n for line in courant for n in line.split()[3::2]]
    assert numbers and all(len(n.replace(".", "").replace("-", "").split("e")[0].lstrip("0")) <= 6
                           for n in numbers)


def test_a_free_particle_reaching_a_wall_without_contacts_stops_with_an_error(tmp_path, foam_env):
    """Without contacts it cannot go on: the run writes its state and ends
    with an error naming the particle and pointing to 'contact' (it ended
    with exit code 0 before). In water (nu 1e-5) it falls onto the floor; in
    the box's viscous liquid it would slow down on its way."""
    case = sphere_case(tmp_path, foam_env, "wall", settings={
        ("constant/transportProperties", "nu"): 1e-5,
        ("constant/particleProperties", "particles/sphere/position"): "(0.0151 0.0149 0.0085)",
        ("constant/particleProperties", "particles/sphere/velocity"): "(0 0 -0.05)",
    })
    result = case.run("pimpleDLMFoam", check=False)
    assert result.returncode != 0 and result.returncode > 0
    assert "Particle sphere reached the cells next to a wall" in result.log
    assert "'contact' dictionary" in result.log
    last = case.times()[-1]
    assert last != "0" and (case.path / last / "uniform" / "particles").exists()


def test_a_zero_time_step_set_while_running_stops_with_an_error(tmp_path, foam_env):
    """system/controlDict changed to deltaT 0 while the solver runs
    (runTimeModifiable): it stops naming the entry (the check ran at the
    start only, and the next time derivative divided by zero)."""
    import subprocess
    import time
    case = sphere_case(tmp_path, foam_env, "modified", settings={
        ("system/controlDict", "endTime"): 50,
        ("system/controlDict", "writeInterval"): 100000,
        ("system/controlDict", "runTimeModifiable"): "true",
    })
    control = case.path / "system" / "controlDict"
    control.write_text(control.read_text()
                       + "OptimisationSwitches { fileModificationSkew 0; }\n")
    log = case.path / "log.pimpleDLMFoam"
    with open(log, "w") as out:
        solver = subprocess.Popen(["pimpleDLMFoam"], cwd=case.path, stdout=out,
                                  stderr=subprocess.STDOUT,
                                  env=dict(foam_env, PWD=str(case.path)))
        try:
            deadline = time.time() + 60
            while log.read_text().count("\nTime = ") < 5 and time.time() < deadline:
                time.sleep(0.2)
            assert solver.poll() is None
            case.set("system/controlDict", "deltaT", 0)
            returncode = solver.wait(timeout=60)
        finally:
            if solver.poll() is None:
                solver.kill()
    text = log.read_text()
    assert returncode > 0
    assert "deltaT 0 must be positive" in text and "controlDict" in text
    assert "sigHandler" not in text


def test_a_rank_one_cell_thick_between_two_others_leaves_the_serial_trajectory_unchanged(
        tmp_path, foam_env):
    """The settling sphere (6 cells per diameter) on 3 ranks decomposed by
    hand: the middle rank one cell thick along x, beside the sphere's
    surface, so that the profiles of forced cells on the first rank take
    their second sample on the third. Relayed through the middle rank,
    the trajectory is the serial one to round-off (8e-15 m measured); the
    sample lost, the profile there fell back to linear and the sphere was
    2e-5 m and 8e-4 m/s off after 20 steps."""
    def make(name):
        case = sphere_case(tmp_path, foam_env, name, settings={
            ("constant/transportProperties", "nu"): 1e-5,
            ("constant/particleProperties", "particles/sphere/position"):
                "(0.0082 0.0149 0.025)",
            ("system/controlDict", "endTime"): 0.05,
            ("system/controlDict", "deltaT"): 0.0025})
        case.converge_linear_solvers()
        return case

    serial = make("serial")
    serial.run("pimpleDLMFoam")
    slab = make("slab")
    # blockMesh numbers the 18 x 18 x 27 cells x first
    owner = [0 if c % 18 < 8 else 1 if c % 18 == 8 else 2 for c in range(18*18*27)]
    (slab.path / "constant" / "cellDecomposition").write_text(
        "FoamFile { version 2.0; format ascii; class labelList;"
        " object cellDecomposition; }\n"
        f"{len(owner)}\n(\n" + "\n".join(map(str, owner)) + "\n)\n")
    (slab.path / "system" / "decomposeParDict").write_text(
        "FoamFile { version 2.0; format ascii; class dictionary;"
        " object decomposeParDict; }\n"
        "numberOfSubdomains 3;\nmethod manual;\n"
        "manualCoeffs { dataFile \"cellDecomposition\"; }\n")
    slab.run("decomposePar")
    slab.run("pimpleDLMFoam", np=3)

    a, b = serial.history()["sphere"], slab.history()["sphere"]
    assert len(a) == len(b) == 20
    assert a[-1, 6] < -0.1
    assert np.abs(b[:, 1:4] - a[:, 1:4]).max() < 1e-12
    assert np.abs(b[:, 4:7] - a[:, 4:7]).max() < 1e-10
