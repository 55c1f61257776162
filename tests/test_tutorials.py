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

import pytest

from foamcase import ROOT

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
    """Every Allrun (and randomBed's Allrun.pre): no sed -i on the case's
    files and no etc/bashrc two levels up; it finds the project (DLM_PROJECT_DIR,
    else a directory above it), refuses a case holding results, and each
    dictionary it sets entries of includes the generated file after its
    defaults; Allclean removes the generated files, and git ignores them."""
    assert len(TUTORIALS) == 6 and len(SCRIPTS) == 7
    for script in SCRIPTS:
        text = script.read_text()
        name = script.relative_to(ROOT)
        assert "sed -i" not in text, name
        assert TWO_UP not in text, name
        assert 'source "$DLM_PROJECT_DIR/etc/tutorialFunctions"' in text, name
        assert "dlmRefuseEarlierResults" in text, name
        for dictionary in re.findall(r"dlmSetEntries (\S+)", text):
            path = script.parent / dictionary
            assert f'#includeIfPresent "{path.name}.Allrun"' in path.read_text(), \
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
           "0.[0-9]*", "*.Allrun", "packing.dat", "alpha.solid", "rho", "p", "phi")
