"""The tutorials' Allrun scripts run from a copy anywhere, keep the tracked
dictionaries as they are (their parameters go to git-ignored *.Allrun files
the dictionaries include), refuse to run over an earlier run's results,
and Allclean removes what they made and nothing else."""

import hashlib
import os
import pathlib
import re
import shutil
import subprocess

import numpy as np
import pytest

from foamcase import Case, ROOT

TUTORIALS = sorted(p.parent for p in (ROOT / "tutorials").glob("*/Allrun"))
SCRIPTS = sorted(p for t in TUTORIALS for p in t.glob("Allrun*"))
# What the scripts sourced before: the project two levels up
TWO_UP = "/".join(["..", "..", "etc", "bashrc"])


def snapshot(directory):
    """Relative path -> content hash of every file below directory."""
    return {str(p.relative_to(directory)): hashlib.sha1(p.read_bytes()).hexdigest()
            for p in sorted(pathlib.Path(directory).rglob("*")) if p.is_file()}


def bare_environment():
    """No OpenFOAM, no project: what a new shell has."""
    env = {k: v for k, v in os.environ.items()
           if k in ("HOME", "USER", "LANG", "LC_ALL", "TMPDIR")}
    env["PATH"] = "/usr/local/bin:/usr/bin:/bin"
    return env


def run(script, *args, env):
    return subprocess.run([str(script)] + [str(a) for a in args], env=env,
                          capture_output=True, text=True, timeout=300)


def test_tutorial_scripts_find_the_project_and_edit_no_tracked_file():
    """Every Allrun (and the Allrun.pre and Allrun.dry beside some): no sed -i on the case's
    files and no etc/bashrc two levels up; it finds the project (DLM_PROJECT_DIR,
    else a directory above it), refuses a case holding results, and each
    dictionary it sets entries of includes the generated file after its
    defaults; Allclean removes the generated files, and git ignores them."""
    assert len(TUTORIALS) == 10 and len(SCRIPTS) == 13
    for script in SCRIPTS:
        text = script.read_text()
        name = script.relative_to(ROOT)
        assert "sed -i" not in text, name
        assert TWO_UP not in text, name
        assert 'source "$DLM_PROJECT_DIR/etc/tutorialFunctions"' in text, name
        assert "dlmRefuseEarlierResults" in text, name
        for dictionary in re.findall(r"dlmSetEntries (\S+)", text):
            path = script.parent / dictionary
            # A dictionary the Allrun makes (switching an option on) is a
            # copy of a tracked one
            copied = re.search(rf"cp (\S+) {re.escape(dictionary)}\n", text)
            source = script.parent / copied.group(1) if copied else path
            assert f'#includeIfPresent "{path.name}.Allrun"' in source.read_text(), \
                f"{name}: {dictionary} does not include {path.name}.Allrun"
    for tutorial in TUTORIALS:
        assert "constant/*.Allrun system/*.Allrun" in (tutorial / "Allclean").read_text()
    ignored = subprocess.run(
        ["git", "check-ignore", "tutorials/tenCate/system/controlDict.Allrun",
         "tutorials/periodicArray/constant/particleProperties.Allrun"],
        cwd=ROOT, capture_output=True, text=True).stdout.split()
    assert len(ignored) == 2


def check_run_then_refused_then_cleaned(case, args, env):
    """Allrun works in case, leaves its tracked files as they were, refuses
    a second run, and Allclean brings the case back to its files."""
    before = snapshot(case)
    first = run(case / "Allrun", *args, env=env)
    assert first.returncode == 0, first.stdout + first.stderr
    after = snapshot(case)
    changed = [f for f, digest in before.items() if after.get(f) != digest]
    assert not changed, f"Allrun changed the case's files {changed}"
    assert any(f.endswith(".Allrun") for f in after)
    second = run(case / "Allrun", *args, env=env)
    assert second.returncode != 0
    assert "holds the results of an earlier run" in second.stderr
    assert "run ./Allclean first" in second.stderr
    assert snapshot(case) == after, "the refused run changed the case"
    clean = run(case / "Allclean", env=env)
    assert clean.returncode == 0, clean.stderr
    assert snapshot(case) == before, "Allclean left or removed files"
    return first


def test_a_tutorial_in_a_copy_of_the_project_finds_it_without_the_environment(tmp_path):
    """tutorials/periodicArray (6^3 cells) copied two levels below a copy of
    the project (its top-level entries linked), where no etc/bashrc is two
    levels up, run from a shell without OpenFOAM or DLM_PROJECT_DIR: the
    Allrun finds the project above it and runs; a second Allrun refuses
    with a clear message; Allclean restores the case."""
    project = tmp_path / "project"
    project.mkdir()
    for entry in ROOT.iterdir():
        if entry.name not in (".git", "tutorials"):
            (project / entry.name).symlink_to(entry)
    case = project / "runs" / "mine" / "periodicArray"
    shutil.copytree(ROOT / "tutorials" / "periodicArray", case,
                    ignore=shutil.ignore_patterns(*IGNORED))
    assert not (case / TWO_UP).exists()
    result = check_run_then_refused_then_cleaned(case, (0.125, 4), bare_environment())
    assert "K = F/(6 pi mu a U) = " in result.stdout


def test_a_tutorial_copied_anywhere_runs_with_the_environment(tmp_path, foam_env):
    """tutorials/cubicBed at 4 cells per diameter on 2 ranks, copied outside
    any project, with etc/bashrc's environment (DLM_PROJECT_DIR set): it
    runs (decomposeParDict, controlDict, transportProperties and
    blockMeshDict set through *.Allrun files), keeps every tracked file,
    refuses a second run, and Allclean restores the case."""
    case = tmp_path / "cubicBed"
    shutil.copytree(ROOT / "tutorials" / "cubicBed", case,
                    ignore=shutil.ignore_patterns(*IGNORED))
    result = check_run_then_refused_then_cleaned(case, (18, 4, 2), foam_env)
    assert "Lambda = " in result.stdout
    assert "nu = 0.000212207" in result.stdout


def test_ten_cate_refined_on_two_ranks_runs_reconstructs_and_cleans(tmp_path, foam_env):
    """tutorials/tenCate E4 at 4 cells per diameter refined once (Allrun's
    5th argument) on 2 ranks for 0.05 s: the mesh follows the sphere,
    reconstructParMesh and reconstructPar give each written time its
    refined mesh with cellLevel (for paraFoam), the tracked files stay, and
    Allclean removes the dynamicMeshDict it switched on."""
    case = tmp_path / "tenCate"
    shutil.copytree(ROOT / "tutorials" / "tenCate", case,
                    ignore=shutil.ignore_patterns(*IGNORED))
    before = snapshot(case)
    result = run(case / "Allrun", "E4", 4, 2, 0.05, 1, env=foam_env)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "refined at the sphere's surface to 8 cells per diameter" in result.stdout
    changes = re.findall(r"^Mesh changed: (\d+) cells",
                         (case / "log.pimpleDLMFoam").read_text(), re.M)
    last = Case(case, foam_env).times()[-1]
    assert float(last) > 0.04
    level = Case(case, foam_env).internal_field(f"{last}/cellLevel")
    assert level.size == int(changes[-1]) > 21*21*43
    assert level.max() == 1
    after = snapshot(case)
    assert not [f for f, digest in before.items() if after.get(f) != digest]
    assert run(case / "Allclean", env=foam_env).returncode == 0
    assert snapshot(case) == before


def test_falling_disk_refined_in_the_plane_on_two_ranks_runs_reconstructs_and_cleans(
        tmp_path, foam_env):
    """tutorials/fallingDisk at 4 cells per diameter refined twice in the
    plane (Allrun's 4th argument) on 2 ranks for 0.2 s: the mesh follows
    the disk and stays one cell thick, reconstructParMesh and reconstructPar
    give each written time its refined mesh with cellLevel, the tracked
    files stay, and Allclean removes the dynamicMeshDict it switched on."""
    case = tmp_path / "fallingDisk"
    shutil.copytree(ROOT / "tutorials" / "fallingDisk", case,
                    ignore=shutil.ignore_patterns(*IGNORED))
    control = case / "system" / "controlDict"
    control.write_text(control.read_text().replace("endTime         1;",
                                                   "endTime         0.2;"))
    before = snapshot(case)
    result = run(case / "Allrun", 0.1, 4, 2, 2, env=foam_env)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "refined at the disk's surface to 16 cells per diameter" in result.stdout
    changes = re.findall(r"^Mesh changed: (\d+) cells",
                         (case / "log.pimpleDLMFoam").read_text(), re.M)
    assert len(changes) >= 5
    assert Case(case, foam_env).times()[-1] == "0.2"
    level = Case(case, foam_env).internal_field("0.2/cellLevel")
    assert level.size == int(changes[-1]) > 40*80
    assert level.max() == 2
    boundary = (case / "0.2" / "polyMesh" / "boundary").read_text()
    plane = boundary[boundary.index("frontAndBack"):]
    assert int(re.search(r"nFaces\s+(\d+);", plane).group(1)) == 2*level.size
    after = snapshot(case)
    assert not [f for f, digest in before.items() if after.get(f) != digest]
    assert run(case / "Allclean", env=foam_env).returncode == 0
    assert snapshot(case) == before


def test_settling_sphere_oblique_start_on_two_ranks_runs_reports_and_cleans(tmp_path, foam_env):
    """tutorials/settlingSphere at Ga 200 (an oblique path), 4 cells per
    diameter refined once, on 2 ranks for 0.03 s: the viscosity makes Ga
    200, the sphere starts a quarter of the 6 d box off the axis moving
    sideways at 0.1 u_g and down at 0.95 of the published speed
    interpolated between Ga 190 and 250 (1.390 u_g), the mesh follows it,
    the run is reported against Uhlmann & Dusek, the tracked files stay,
    and Allclean restores the case. A Galileo number that is not a positive
    number is refused by name before anything is written."""
    case = tmp_path / "settlingSphere"
    shutil.copytree(ROOT / "tutorials" / "settlingSphere", case,
                    ignore=shutil.ignore_patterns(*IGNORED))
    before = snapshot(case)
    refused = run(case / "Allrun", "-144", env=foam_env)
    assert refused.returncode != 0
    assert "Ga '-144'" in refused.stderr and "must be positive numbers" in refused.stderr
    assert snapshot(case) == before
    result = run(case / "Allrun", 200, 4, 1, 2, 6, 0.03, env=foam_env)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "refined at the sphere's surface to 8 cells per diameter" in result.stdout
    assert "Ga=200: u_V/u_g=" in result.stdout
    ug = (0.5*9.81*0.01)**0.5
    nu = float(re.search(r"nu\s+([0-9.e+-]+);",
                         (case / "constant" / "transportProperties.Allrun").read_text()).group(1))
    assert nu == pytest.approx(ug*0.01/200, rel=1e-5)
    history = Case(case, foam_env).history()["sphere"]
    assert history[0, 1] == pytest.approx(-0.015, abs=1e-4)
    assert history[0, 4] > 0 and history[-1, 1] > history[0, 1]
    assert -history[0, 6] == pytest.approx(0.95*1.39007*ug, rel=2e-3)
    assert history[-1, 0] > 0.029
    last = Case(case, foam_env).times()[-1]
    assert Case(case, foam_env).internal_field(f"{last}/cellLevel").max() == 1
    assert (case / "freeSphere.png").exists()
    after = snapshot(case)
    assert not [f for f, digest in before.items() if after.get(f) != digest]
    assert run(case / "Allclean", env=foam_env).returncode == 0
    assert snapshot(case) == before


def test_a_tutorial_outside_any_project_without_the_environment_says_what_to_source(
        tmp_path):
    """No DLM_PROJECT_DIR and no project above the case: the Allrun stops at
    once, saying to source the project's etc/bashrc, and changes nothing."""
    case = tmp_path / "tenCate"
    shutil.copytree(ROOT / "tutorials" / "tenCate", case,
                    ignore=shutil.ignore_patterns(*IGNORED))
    before = snapshot(case)
    result = run(case / "Allrun", env=bare_environment())
    assert result.returncode != 0
    assert "source <project>/etc/bashrc first" in result.stderr
    assert snapshot(case) == before


# What a tutorial directory in the working tree may hold besides its
# tracked files (an earlier run's output)
IGNORED = ("log.*", "processor*", "postProcessing", "VTK", "polyMesh", "[1-9]*",
           "0.[0-9]*", "*.Allrun", "packing.dat", "alpha.solid", "rho", "p", "phi",
           "pebbleBed.dat", "lattice.dat", "render", "*.foam")


def particle_state(path):
    """Positions and velocities of the particles of a written state
    (uniform/particles), by name."""
    text = pathlib.Path(path).read_text()
    state = {}
    for name, body in re.findall(r"^    (\w+)\n    \{(.*?)^    \}", text, re.M | re.S):
        values = dict(re.findall(r"^\s+(position|velocity)\s+\(([^)]*)\);", body, re.M))
        if not values:
            continue    # an outlet's counts
        state[name] = [float(v) for v in values["position"].split() + values["velocity"].split()]
    return state


@pytest.fixture(scope="module")
def pebble_runs(tmp_path_factory, foam_env):
    """tutorials/pebbleDischarge for 0.1 s serially, then on 2 ranks from the
    same bed (reused: no second fill), with converged linear solvers so
    that the two could differ by round-off only."""
    tmp_path = tmp_path_factory.mktemp("pebbleDischarge")
    runs = {}
    for name, ranks in (("serial", 1), ("parallel", 2)):
        case = tmp_path / name
        shutil.copytree(ROOT / "tutorials" / "pebbleDischarge", case,
                        ignore=shutil.ignore_patterns(*IGNORED))
        fv_solution = case / "system/fvSolution"
        fv_solution.write_text(fv_solution.read_text()
                               .replace("tolerance       1e-7;", "tolerance       1e-13;")
                               .replace("relTol          0.01;", "relTol          0;")
                               .replace("tolerance       1e-8;", "tolerance       1e-14;"))
        if ranks > 1:
            shutil.copy(tmp_path / "serial/constant/pebbleBed.dat", case / "constant/pebbleBed.dat")
        result = run(case / "Allrun", 4, ranks, 0.1, env=foam_env)
        assert result.returncode == 0, result.stdout + result.stderr
        runs[name] = (case, result.stdout)
    return runs


def last_state(case):
    last = max((t for t in os.listdir(case) if re.fullmatch(r"0\.\d+", t)), key=float)
    return particle_state(case / last / "uniform/particles")


def test_pebble_discharge_fills_its_bed_and_runs_serial_and_parallel(pebble_runs):
    """The fill packs 250 pebbles at rest under the cone and the barrier,
    without overlaps beyond 1 % of d; the chute is a tube of walls for the
    water (baffles); the discharge starts (the pebbles in the opening rise)
    in serial and on 2 ranks, the latter reusing the bed."""
    (serial, serial_out), (parallel, parallel_out) = pebble_runs["serial"], pebble_runs["parallel"]
    assert "Bed: filled" in serial_out and "Bed: filled" not in parallel_out
    bed = np.loadtxt(serial / "constant/pebbleBed.dat")
    assert bed.shape == (250, 4)
    d = 0.025
    centres = bed[:, :3]
    gaps = np.linalg.norm(centres[:, None] - centres[None], axis=2) - d
    np.fill_diagonal(gaps, d)
    assert gaps.min() > -0.01*d
    assert bed[:, 2].max() < 0.2106 - 0.49*d
    fill_speed = float(re.findall(r"largest speed (\S+) m/s", (serial / "log.fill").read_text())[-1])
    assert fill_speed < 0.01
    boundary = (serial / "constant/polyMesh/boundary").read_text()
    for side in ("chuteWall_master", "chuteWall_slave"):
        faces = re.search(side + r"\s*\{[^}]*nFaces\s+(\d+);", boundary)
        assert faces and int(faces.group(1)) > 0, f"the chute's tube ({side}) is missing"
    for case in (serial, parallel):
        state = last_state(case)
        assert len(state) == 250
        top = max(state, key=lambda name: state[name][2])
        assert state[top][5] > 0.05, "the pebbles in the opening do not rise"


def test_pebble_discharge_on_2_ranks_equals_serial(pebble_runs):
    """Every pebble's position and velocity after 0.1 s agree with the
    serial run's to round-off amplified by the contacts. (They differed by
    2e-4 of the fluid force in the first step for pebbles near the
    castellated wall and the processor boundary: whether a wall half a cell
    beyond a profile's first sample gave a quadratic profile was left to the
    round-off of the cell centres, which differs between a mesh and its
    decomposition.)"""
    a = last_state(pebble_runs["serial"][0])
    b = last_state(pebble_runs["parallel"][0])
    speed = max(np.linalg.norm(v[3:]) for v in a.values())
    for name in a:
        assert np.abs(np.subtract(a[name][:3], b[name][:3])).max() < 1e-9, name
        assert np.abs(np.subtract(a[name][3:], b[name][3:])).max() < 1e-6*speed, name


def test_pebble_discharge_dry_rises_freely_where_the_water_holds_back(pebble_runs, foam_env):
    """Allrun.dry runs the serial case's bed without water (dlmDEMFoam under
    buoyancy-reduced gravity, reusing the mesh and the bed): the fastest
    pebble in the opening rises at least at the free rise g (rho_f/rho_s -
    1) t by 0.1 s, less 3 % (1.45 times it measured: the bed's elastic
    release kicks the upper pebbles, 1.12 to 1.45 times, while three still
    in contact rise at 0.45 to 0.66 times; their mean, which this test
    once took, met the free rise by chance), while in the water they rise
    at less than half of it; a second Allrun.dry is refused."""
    import sys
    sys.path.insert(0, str(ROOT / "validation"))
    import pebbleDischarge

    case, _ = pebble_runs["serial"]
    result = run(case / "Allrun.dry", 0.1, env=foam_env)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "Dry discharge: 0 of 250 pebbles left by 0.1 s" in result.stdout
    free_rise = 9.81*(1000/843 - 1)*0.1
    opening = 0.2106 - 0.5*0.025

    times, _, rows = pebbleDischarge.history(case / "dry")
    at = np.isclose(times, 0.1) & (rows[:, 2] > opening)
    assert at.sum() >= 5
    assert 0.97*free_rise <= rows[at, 5].max() < 2*free_rise

    wet = last_state(case)
    wet_rise = np.mean([v[5] for v in wet.values() if v[2] > opening])
    assert 0 < wet_rise < 0.5*free_rise

    second = run(case / "Allrun.dry", 0.1, env=foam_env)
    assert second.returncode != 0 and "run ./Allclean first" in second.stderr
