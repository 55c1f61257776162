"""C++ unit tests of the dlmParticles library (Catch2), on a 3D and a 2D mesh
and on a 3D mesh with fixed spheres across narrow gaps."""

import pathlib

import pytest

from foamcase import Case

HERE = pathlib.Path(__file__).parent


@pytest.mark.parametrize("case, tags", [
    ("box3D", "[geometry],[3D],[contact]"),
    ("box2D", "[2D]"),
    ("gap3D", "[gap]"),
])
def test_library_unit_tests(tmp_path, foam_env, case, tags):
    c = Case.copy(HERE / "unit" / case, tmp_path / case, foam_env)
    c.run("blockMesh")
    result = c.run("Test-dlmParticles", c.path, tags, check=False,
                   log="Test-dlmParticles")
    assert result.returncode == 0, result.log[-4000:]
    assert "All tests passed" in result.log
