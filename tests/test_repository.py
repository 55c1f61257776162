"""The repository stands alone: no tracked file points outside it, the
reference data the validation scripts read is in validation/reference, and
the tutorials run from a copy anywhere, keep their tracked files as they
are and refuse to run over an earlier run's results."""

import os
import pathlib
import re
import shutil
import subprocess
import sys

import pytest

from foamcase import ROOT

sys.path.insert(0, str(ROOT / "validation"))

TEXT_SUFFIXES = {"", ".py", ".md", ".txt", ".sh", ".C", ".H", ".cfg", ".toml",
                 ".ini", ".yml", ".yaml", ".json", ".csv", ".dat", ".in", ".pre"}

# Absolute paths of the machines the project was written on, and the
# reference set that used to lie beside the repository (its directory's name
# kept apart, so that this file does not name the path it forbids)
OLD_SET = "shared"
FORBIDDEN = ["/work/", "/home/", f"{OLD_SET}/reference", f"../{OLD_SET}"]


def tracked_files():
    out = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True,
                         check=True).stdout.decode()
    return [pathlib.Path(p) for p in out.split("\0") if p]


def tracked_text():
    """(relative path, text) of every tracked text file."""
    for relative in tracked_files():
        path = ROOT / relative
        if path.is_symlink() or not path.is_file():
            continue
        if relative.suffix not in TEXT_SUFFIXES and relative.parts[0] not in ("tutorials", "etc"):
            continue
        raw = path.read_bytes()
        if b"\0" in raw[:8192]:
            continue
        yield relative, raw.decode("utf-8", "replace")


def escapes(relative, target):
    """Whether a relative path written in the file at relative, read
    against the file's own directory, leaves the repository."""
    depth = len(relative.parts) - 1
    for part in pathlib.PurePosixPath(target).parts:
        if part == "..":
            depth -= 1
            if depth < 0:
                return True
        elif part != ".":
            depth += 1
    return False


def outside_references(relative, text):
    """The places where the file at relative refers outside the repository."""
    found = []
    for line_number, line in enumerate(text.splitlines(), 1):
        where = f"{relative}:{line_number}: {line.strip()}"
        for string in FORBIDDEN:
            if string in line:
                found.append(f"{where}  ({string!r})")
        # ../ chains, read against the file's directory
        for chain in re.findall(r"(?:\.\./)+[\w.$-]*", line):
            if escapes(relative, chain):
                found.append(f"{where}  ({chain!r} leaves the repository)")
        if relative.suffix == ".py":
            # pathlib: parents[k] of the file, or the root's parent
            for k in re.findall(r"__file__\)\.resolve\(\)\.parents\[(\d+)\]", line):
                if int(k) >= len(relative.parts):
                    found.append(f"{where}  (parents[{k}] of a file {len(relative.parts) - 1}"
                                 " directories deep)")
            if re.search(r"\bROOT\.parent\b|\bROOT\s*/\s*['\"]\.\.['\"]", line):
                found.append(f"{where}  (the repository's parent)")
    return found


def test_the_outside_reference_check_finds_what_it_should():
    """The check itself, on made-up lines."""
    assert outside_references(pathlib.Path("validation/common.py"),
                              f'REFERENCE = ROOT.parent / "{OLD_SET}" / "reference"')
    assert outside_references(pathlib.Path("validation/README.md"),
                              f"reference data in `../../{OLD_SET}/reference/`")
    assert outside_references(pathlib.Path("tests/x.py"),
                              "ROOT = pathlib.Path(__file__).resolve().parents[2]")
    assert outside_references(pathlib.Path("a/b/Allrun"), "source ../../../etc/bashrc")
    assert not outside_references(pathlib.Path("tutorials/tenCate/Allrun"),
                                  "../../validation/plotTenCate.py")
    assert not outside_references(pathlib.Path("tests/x.py"),
                                  "ROOT = pathlib.Path(__file__).resolve().parents[1]")
    assert not outside_references(pathlib.Path("a/b/c.H"), '#include "../d/e.H"')


def test_no_tracked_file_refers_outside_the_repository():
    """A fresh clone with nothing beside it has all it reads: no tracked
    text file names an absolute path of the project's machines, the old
    reference set beside the repository, a ../ chain that climbs out of the
    repository from the file's directory, or (Python) a parent of the
    repository's root."""
    found = []
    for relative, text in tracked_text():
        if relative == pathlib.Path("tests/test_repository.py"):
            continue    # the strings it looks for
        found += outside_references(relative, text)
    assert not found, "tracked files refer outside the repository:\n" + "\n".join(found)


def named_reference_files():
    """The reference files the validation scripts read: every read_csv
    name, with the f-strings' fields taken from the scripts' own tables."""
    import tenCate
    import validate_DKT
    names = set()
    for script in sorted((ROOT / "validation").glob("*.py")):
        for name in re.findall(r"read_csv\(f?[\"']([^\"']+)[\"']\)", script.read_text()):
            if "{" not in name:
                names.add(name)
    for case in tenCate.CASES.values():
        names.add(f"tenCate2002_fig5b_velocity_{case[3]}.csv")
        names.add(f"tenCate2002_fig5a_gap_{case[3]}.csv")
    for figure in validate_DKT.FIGURES:
        for disk in ("leading", "trailing"):
            names.add(f"Uhlmann2005_DKT_fig{figure}_{disk}.csv")
    return names


def test_the_reference_data_is_in_the_repository():
    """validation/common.py reads validation/reference, which holds every
    file the scripts read (each with its '#' provenance lines before the
    header, and named in its README); the scripts' readers return them."""
    import common
    import tenCate
    import validate_DKT
    reference = ROOT / "validation" / "reference"
    assert common.REFERENCE.resolve() == reference
    names = named_reference_files()
    assert len(names) >= 19
    readme = (reference / "README.md").read_text()
    missing = sorted(n for n in names if not (reference / n).is_file())
    assert not missing, f"not in validation/reference: {missing}"
    tracked = {str(p) for p in tracked_files()}
    for csv in sorted(reference.glob("*.csv")):
        lines = csv.read_text().splitlines()
        assert lines[0].startswith("#") and lines[1].startswith("#"), csv.name
        # the figures' files are named together: name_fig{6a,...}
        stem = csv.name.split("_fig")[0] if "_fig" in csv.name else csv.name
        assert f"`{stem}" in readme, f"{csv.name} not described in reference/README.md"
        assert f"validation/reference/{csv.name}" in tracked, f"{csv.name} is not tracked"
    for case in tenCate.CASES:
        assert len(tenCate.reference_velocity(case)[0]) > 20
        assert len(tenCate.reference_gap(case)[0]) > 20
    for figure in validate_DKT.FIGURES:
        for disk in ("leading", "trailing"):
            assert len(validate_DKT.reference(figure, disk)[0]) > 20
    assert common.read_csv("ZickHomsy1982_SC_drag.csv")[1].shape == (7, 5)


def test_the_demo_prints_what_it_computed(tmp_path):
    """The top-level Allrun's last step, validation/plotTenCate.py, on a
    made-up E2 run (the sphere at 0.05 m/s, the solver's log ending at
    ClockTime = 42 s): it prints u_max, its error against the experiment's
    0.05718 m/s, the wall time and the path of the plot it wrote."""
    history = tmp_path / "postProcessing" / "particles" / "0"
    history.mkdir(parents=True)
    rows = ["# time particle x y z Ux Uy Uz ..."]
    for i in range(11):
        t = 0.1*i
        rows.append(" ".join(["%g" % t, "sphere", "0.05", "0.05", "%g" % (0.1275 - 0.05*t),
                              "0", "0", "%g" % (-0.05*min(1, 2*t))] + ["0"]*15))
    (history / "particles.dat").write_text("\n".join(rows) + "\n")
    (tmp_path / "log.pimpleDLMFoam").write_text(
        "ExecutionTime = 40.1 s  ClockTime = 41 s\n\nExecutionTime = 41.2 s  ClockTime = 42 s\n\nEnd\n")
    result = subprocess.run([sys.executable, str(ROOT / "validation" / "plotTenCate.py"),
                             str(tmp_path), "E2"], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    out = result.stdout
    assert re.search(r"u_max\s+0\.05000 m/s", out), out
    assert re.search(r"experiment\s+0\.05718 m/s: error -12\.6 %", out), out
    assert re.search(r"wall time\s+42 s", out), out
    png = tmp_path / "tenCate_E2.png"
    assert png.stat().st_size > 1000
    assert f"plot       {png}" in out, out
