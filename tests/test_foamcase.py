"""The test helpers read the fields OpenFOAM writes, in either format."""

import os
import re

import numpy as np

from foamcase import ROOT, Case, packed_bed_rows


def test_binary_and_ascii_fields_read_alike(tmp_path, foam_env):
    """writeCellCentres on a 4^3 mesh, written in ascii and in binary: the
    scalar Cx and the vector C read the same, and match the cell centres
    of the uniform mesh."""
    values = {}
    for form in ("ascii", "binary"):
        case = Case.copy(ROOT / "tutorials" / "randomBed", tmp_path / form, foam_env)
        mesh = case.path / "system" / "blockMeshDict"
        mesh.write_text(re.sub(r"^n .*$", "n   4;", mesh.read_text(), flags=re.M))
        controls = case.path / "system" / "controlDict"
        controls.write_text(re.sub(r"^writeFormat .*$", f"writeFormat     {form};",
                                   controls.read_text(), flags=re.M))
        case.run("blockMesh")
        case.run("postProcess", "-func", "writeCellCentres", "-time", "0")
        assert (f"format      {form};" in (case.path / "0" / "C").read_bytes().decode("latin-1"))
        values[form] = (case.internal_field("0/Cx"), case.internal_field("0/C"))
    cx, c = values["binary"]
    assert cx.shape == (64,) and c.shape == (64, 3)
    assert np.array_equal(cx, values["ascii"][0])
    assert np.allclose(c, values["ascii"][1], rtol=0, atol=1e-15)
    side = float(re.search(r"^L\s+([^;]+);",
                           (ROOT / "tutorials" / "randomBed" / "system" / "blockMeshDict")
                           .read_text(), re.M).group(1))
    centres = (np.arange(4) + 0.5)*side/4
    assert np.allclose(np.sort(np.unique(np.round(cx, 12))), centres, atol=1e-12)


def test_packed_bed_rows_of_runs_restarted_from_the_same_time(tmp_path):
    """A run from 0 written at 1 and 2, restarted from 1 and stopped, then
    restarted from 1 again: OpenFOAM writes the second restart's rows to
    packedBed_1.dat beside the first restart's packedBed.dat. The series
    is the first run to 1, then the latest restart, whatever the files'
    names."""
    def write(start, name, times, value):
        folder = tmp_path / "postProcessing" / "bed" / start
        folder.mkdir(parents=True, exist_ok=True)
        (folder / name).write_text("# t u\n" + "".join(f"{t} {value}\n" for t in times))

    write("0", "packedBed.dat", [0.5, 1, 1.5, 2], 0)
    write("1", "packedBed.dat", [1.5], 1)
    write("1", "packedBed_1.dat", [1.5, 2, 2.5], 2)
    old = tmp_path / "postProcessing" / "bed" / "1" / "packedBed.dat"
    os.utime(old, (0, 0))
    np.testing.assert_array_equal(packed_bed_rows(tmp_path),
                                  [[0.5, 0], [1, 0], [1.5, 2], [2, 2], [2.5, 2]])
