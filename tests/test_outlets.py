"""Particle outlets: free particles whose centroid enters an outlet's region
leave the simulation, counted and recorded, without changing the others'
trajectories; the counts carry over a restart; in a fluid the removed
particle's solid leaves the mixture and the run goes on, in parallel as in
serial."""

import math
import pathlib
import re
import shutil

import numpy as np
import pytest

from foamcase import Case

HERE = pathlib.Path(__file__).parent
R = 0.002
MASS = 2500*4/3*math.pi*R**3

# Two spheres on the floor and one dropped on them: lasting contacts with
# tangential springs, in the box's x < 0 half
PILE = """
    a { shape sphere; radius 0.002; density 2500; position (-0.0061 0 0.002); }
    b { shape sphere; radius 0.002; density 2500; position (-0.0019 0 0.002); }
    c { shape sphere; radius 0.002; density 2500; position (-0.0038 0.0005 0.0058); }
"""
# Falls freely through a collecting box in the x > 0 half, listed first so
# that the pile's places in the list move when it leaves
LEAVER = """
    leaver { shape sphere; radius 0.002; density 2500; position (0.006 0.006 0.0175); }
"""
OUTLET = """
outlets
{
    bin { type box; min (0.003 0.003 0.004); max (0.009 0.009 0.008); }
}
"""


def set_particles(case, leaver, outlet):
    """The pile, with or without the leaver and the outlet, in the case's
    particleProperties."""
    props = case.path / "constant/particleProperties"
    text = props.read_text()
    start = text.index("particles\n{")
    end = text.index("contact\n{")
    tail = text[end:]
    if "outlets" in tail:
        tail = tail[:tail.index("outlets")]
    particles = "particles\n{" + (LEAVER if leaver else "") + PILE + "}\n\n"
    props.write_text(text[:start] + particles + tail + (OUTLET if outlet else ""))


def dry_scene(tmp_path, env, name, leaver=True, outlet=True, end_time=0.1):
    case = Case.copy(HERE / "cases" / "dryBox", tmp_path / name, env)
    case.run("blockMesh")
    set_particles(case, leaver, outlet)
    case.set("constant/g", "value", "(0 0 -9.81)")
    case.set("system/controlDict", "endTime", end_time)
    case.set("system/controlDict", "writeInterval", 200)
    return case


def outlet_record(case, start="0"):
    path = case.path / "postProcessing/particleOutlets" / start / "outlets.dat"
    return [line.split() for line in path.read_text().splitlines()
            if not line.startswith("#")]


def outlet_state(case, time):
    text = (case.path / time / "uniform/particles").read_text()
    block = text[text.index("outlets"):]
    block = block[block.index("bin"):]
    fields = dict(line.strip().rstrip(";").split()[:2]
                  for line in block.splitlines()[2:4])
    return int(fields["particles"]), float(fields["mass"])


def without_particle(state, name):
    """The particle state file's text without a particle: its block goes,
    the contacts' springs keyed by it go, and the particles after it move
    up a place (a key is particle, other particle or -1 - wall, feature),
    in the springs and in the list of particles near a contact."""
    names = re.findall(r"^    (\w+)\n    \{", state, re.M)
    gone = names.index(name)
    state = re.sub(rf"^    {name}\n    \{{.*?^    \}}\n", "", state, flags=re.M | re.S)

    def place(k):
        return k - 1 if k > gone else k

    springs = []
    for i, j, feature, spring in re.findall(
            r"^\(\((-?\d+) (-?\d+) (-?\d+)\) (\([^()]*\))\)$", state, re.M):
        i, j = int(i), int(j)
        if gone not in (i, j):
            springs.append(f"(({place(i)} {place(j) if j >= 0 else j} {feature}) {spring})")
    state = re.sub(r"^contacts\s+\d+\s*\(.*?^\)", "contacts\n%d\n(\n%s\n)"
                   % (len(springs), "\n".join(springs)), state, flags=re.M | re.S)

    def near(match):
        kept = [place(int(k)) for k in match.group(1).split() if int(k) != gone]
        return "nearContact %d(%s);" % (len(kept), " ".join(map(str, kept)))
    return re.sub(r"^nearContact\s+\d*\s*\(([^()]*)\)\s*;", near, state,
                  flags=re.M | re.S)


def test_outlet_removes_and_counts_without_changing_the_others(tmp_path, foam_env):
    """The leaver falls into the bin at about 0.044 s and leaves: one line in
    the record with its mass, the bin's count in the written state, no
    history after. From that step the pile (lasting contacts with tangential
    springs) moves to the bit as in a run restarted from the same step's
    state with the leaver deleted by hand, though the pile's places in the
    list, which key the springs, move up when the leaver goes."""
    with_outlet = dry_scene(tmp_path, foam_env, "withOutlet")
    with_outlet.run("dlmDEMFoam")

    record = outlet_record(with_outlet)
    assert len(record) == 1
    t_out, outlet, name, mass = record[0][:4]
    assert (outlet, name) == ("bin", "leaver")
    assert float(mass) == pytest.approx(MASS, rel=1e-12)
    assert 0.004 <= float(record[0][6]) < 0.008
    assert float(t_out) == pytest.approx(math.sqrt(2*(0.0175 - 0.008)/9.81), abs=2e-3)
    assert outlet_state(with_outlet, "0.1") == (1, pytest.approx(MASS, rel=1e-12))
    state = (with_outlet.path / "0.1/uniform/particles").read_text()
    assert "leaver" not in re.findall(r"^    (\w+)\n    \{", state, re.M)
    assert re.search(r"^\s*removed\s+1\(leaver\);", state, re.M)
    h = with_outlet.history()
    assert h["leaver"][:, 0].max() < float(t_out)

    # The same scene without the outlet to the removal's step, its state
    # then edited and run on
    t_name = f"{float(t_out):.8g}"
    by_hand = dry_scene(tmp_path, foam_env, "byHand", outlet=False, end_time=t_name)
    by_hand.run("dlmDEMFoam")
    state = by_hand.path / t_name / "uniform/particles"
    state.write_text(without_particle(state.read_text(), "leaver"))
    assert "leaver" not in state.read_text()
    set_particles(by_hand, leaver=False, outlet=False)
    by_hand.set("system/controlDict", "endTime", 0.1)
    by_hand.run("dlmDEMFoam")
    ref = by_hand.history(t_name)
    for p in "abc":
        after = h[p][h[p][:, 0] > float(t_out) + 1e-9]
        assert len(after) == len(ref[p]) >= 500
        assert np.abs(after[:, 1:] - ref[p][:, 1:]).max() == 0, p
    springs = re.findall(r"^\(\((\d+) (\d+) 0\)", state.read_text(), re.M)
    assert springs, "no spring between particles at the removal: the test would not see them"


@pytest.mark.parametrize("restart_time", ["0.02", "0.08"])
def test_restart_keeps_the_outlet_count(tmp_path, foam_env, restart_time):
    """From a time before the removal the restarted run removes the leaver at
    the same step; from one after, it carries the count over: the state at
    the end holds one particle in the bin either way."""
    full = dry_scene(tmp_path, foam_env, "full")
    full.run("dlmDEMFoam")
    restarted = dry_scene(tmp_path, foam_env, "restarted")
    shutil.copytree(full.path / restart_time, restarted.path / restart_time)
    restarted.run("dlmDEMFoam")
    assert outlet_state(restarted, "0.1") == (1, pytest.approx(MASS, rel=1e-12))
    if restart_time == "0.02":
        removed, again = outlet_record(full)[0], outlet_record(restarted, restart_time)[0]
        assert float(again[0]) == pytest.approx(float(removed[0]), abs=1e-9)
        assert again[1:] == removed[1:]
    a, b = full.history(), restarted.history(restart_time)
    tail = a["c"][a["c"][:, 0] > float(restart_time) + 1e-9]
    assert np.abs(b["c"][:, 1:10] - tail[:, 1:10]).max() < 1e-12


def test_outlet_starting_with_a_particle_inside_is_an_error(tmp_path, foam_env):
    case = dry_scene(tmp_path, foam_env, "inside")
    case.set("constant/particleProperties", "outlets/bin/min", "(0.003 0.003 0.012)")
    case.set("constant/particleProperties", "outlets/bin/max", "(0.009 0.009 0.02)")
    result = case.run("dlmDEMFoam", check=False)
    assert result.returncode != 0
    assert "Particle leaver" in result.log and "starts in outlet bin" in result.log


@pytest.mark.parametrize("edit, message", [
    (("outlets/bin/type", "sphere"), "Unknown type type sphere"),
    (("outlets/bin/radius", "0.1"), "Unknown keyword 'radius' for outlet bin"),
    (("outlets/bin/max", "(0.009 0.009 0.004)"), "is not below max"),
])
def test_bad_outlet_input_is_named(tmp_path, foam_env, edit, message):
    case = dry_scene(tmp_path, foam_env, "bad")
    case.set("constant/particleProperties", *edit)
    result = case.run("dlmDEMFoam", check=False)
    assert result.returncode != 0
    assert message in result.log and "particleProperties" in result.log


def wet_case(tmp_path, env, name):
    """A polypropylene pebble rises in water through a plane outlet at
    z = 30 mm, 15 mm below the box's lid."""
    case = Case.copy(HERE / "cases" / "sphereBox", tmp_path / name, env)
    case.run("blockMesh")
    props = case.path / "constant/particleProperties"
    props.write_text(props.read_text() + """
outlets { top { type plane; point (0 0 0.03); normal (0 0 1); } }
""")
    for (file, entry), value in {
        ("constant/particleProperties", "particles/sphere/position"): "(0.0151 0.0149 0.012)",
        ("constant/particleProperties", "particles/sphere/density"): 843,
        ("constant/transportProperties", "nu"): 1e-6,
        ("system/controlDict", "endTime"): 0.6,
        ("system/controlDict", "writeInterval"): 1000,
    }.items():
        case.set(file, entry, value)
    case.converge_linear_solvers()
    return case


def test_particle_leaves_a_fluid_in_parallel_as_in_serial(tmp_path, foam_env):
    """The pebble crosses the outlet plane; its solid leaves the mixture
    (alpha.solid zero everywhere at the end, rho the fluid's) and the run
    goes on to its end with no particle; on 2 processes it leaves at the
    same step, on the same path."""
    serial = wet_case(tmp_path, foam_env, "serial")
    serial.run("pimpleDLMFoam")
    parallel = wet_case(tmp_path, foam_env, "parallel")
    parallel.run("decomposePar")
    parallel.run("pimpleDLMFoam", np=2)
    parallel.run("reconstructPar", "-latestTime")

    record = outlet_record(serial)
    assert len(record) == 1 and record[0][1:3] == ["top", "sphere"]
    assert 0.03 < float(record[0][6]) < 0.03 + 0.5*0.005
    again = outlet_record(parallel)
    assert len(again) == 1 and again[0][:4] == record[0][:4]
    a, b = serial.history()["sphere"], parallel.history()["sphere"]
    assert len(a) == len(b) >= 10
    rise = a[-1, 3] - a[0, 3]
    assert np.abs(a[:, 1:4] - b[:, 1:4]).max() < 1e-6*rise
    assert np.abs(a[:, 4:7] - b[:, 4:7]).max() < 1e-6*np.abs(a[:, 4:7]).max()
    for case in (serial, parallel):
        last = case.times()[-1]
        assert float(last) == pytest.approx(0.6)
        assert np.abs(case.internal_field(f"{last}/alpha.solid")).max() == 0
        assert np.allclose(case.internal_field(f"{last}/rho"), 1000)


def test_particle_leaving_a_fluid_mesh_without_an_outlet_stops_the_run(tmp_path, foam_env):
    """With contacts but no contact wall at the lid (meshWalls false) the
    pebble rises through it: once its centre is out of the mesh, out of the
    flow, the run stops with an error naming it and suggesting an outlet,
    after writing the state of that time."""
    case = wet_case(tmp_path, foam_env, "noOutlet")
    props = case.path / "constant/particleProperties"
    text = props.read_text()
    props.write_text(text[:text.index("outlets")] + """
contact
{
    meshWalls false;
    pairs { pebbleWall { materials (particle wall); law overlapVolume;
                         stiffness 1e9; restitution 0.5; friction 0.3; } }
}
""")
    case.set("constant/particleProperties", "particles/sphere/position",
             "(0.0151 0.0149 0.035)")
    result = case.run("pimpleDLMFoam", check=False)
    assert result.returncode != 0
    assert "Particle sphere left the mesh" in result.log
    assert "outlets" in result.log
    last = case.times()[-1]
    assert float(last) < 0.6
    state = (case.path / last / "uniform/particles").read_text()
    z = float(re.search(r"position\s+\(\S+ \S+ (\S+)\)", state).group(1))
    assert z > 0.045


def test_particle_leaving_a_dry_mesh_without_an_outlet_stops_the_run(tmp_path, foam_env):
    """Dry (dlmDEMFoam) the mesh bounds the scene: with meshWalls false
    nothing holds the pile at the floor, and once a sphere's centre is
    below it the run stops with an error naming the sphere and suggesting
    an outlet, after writing the state of that time (LIGGGHTS, too, stops on
    lost atoms unless told to ignore them). It used to fall on silently."""
    case = dry_scene(tmp_path, foam_env, "dryNoOutlet", leaver=False, outlet=False)
    case.set("constant/particleProperties", "contact/meshWalls", "false")
    result = case.run("dlmDEMFoam", check=False)
    assert result.returncode != 0
    named = re.search(r"Particle (\w+) left the mesh", result.log)
    assert named and named.group(1) in ("a", "b", "c")
    assert "outlets" in result.log
    last = case.times()[-1]
    assert 0 < float(last) < 0.1
    state = (case.path / last / "uniform/particles").read_text()
    heights = [float(z) for z in re.findall(r"position\s+\(\S+ \S+ (\S+)\)", state)]
    assert min(heights) < 0
