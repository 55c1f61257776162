"""ParaView after set-up: paraFoam finds paraview, and dlmRender draws a
case headless (pvbatch with its own Xvfb server): the flow on a slice, the particle as
its true shape where it is, the solid fraction's 0.5 contour."""

import pathlib
import shutil

import numpy as np
import pytest

from foamcase import Case

HERE = pathlib.Path(__file__).parent


def test_parafoam_finds_paraview(foam_env):
    """paraFoam stopped with 'paraview: not found' before ParaView was part
    of the set-up."""
    path = foam_env["PATH"]
    for program in ("paraFoam", "paraview", "pvbatch", "Xvfb"):
        assert shutil.which(program, path=path), f"{program} not found"


def test_render_draws_the_flow_and_the_sphere_where_it_is(tmp_path, foam_env):
    """The sphere (radius 5 mm at x = 15.1 mm, z = 25 mm in the 30 x 45 mm
    section of the box) after two steps, rendered at 600 x 600: the image
    has that size, the slice shows many colours, and the sphere's flat
    magenta disk sits at its place in the slice with its diameter."""
    case = Case.copy(HERE / "cases" / "sphereBox", tmp_path / "render", foam_env)
    case.run("blockMesh")
    case.set("system/controlDict", "endTime", 0.01)
    case.set("system/controlDict", "writeInterval", 1)
    case.run("pimpleDLMFoam")
    png = case.path / "picture.png"
    log = case.run("dlmRender", ".", "--size", 600, 600, "--output", png).log
    assert f"dlmRender: {png}" in log

    import matplotlib.image
    image = matplotlib.image.imread(png)[:, :, :3]
    assert image.shape == (600, 600, 3)
    colours = {tuple(c) for c in (image.reshape(-1, 3)*255).round().astype(int)}
    assert len(colours) > 50

    magenta = (np.abs(image - [1, 0, 1]).max(axis=2) < 0.02)
    white = image.min(axis=2) > 0.98
    # The slice: the columns and rows where most pixels are coloured
    coloured = ~white
    columns = np.flatnonzero(coloured.sum(axis=0) > 0.7*coloured.sum(axis=0).max())
    rows = np.flatnonzero(coloured.sum(axis=1) > 0.7*coloured.sum(axis=1).max())
    left, right, top, bottom = columns[0], columns[-1], rows[0], rows[-1]
    width, height = right - left, bottom - top
    assert height/width == pytest.approx(0.045/0.03, rel=0.03)

    y, x = np.nonzero(magenta)
    assert len(x) > 0
    expected_x = left + 0.0151/0.03*width
    expected_y = bottom - 0.025/0.045*height
    assert abs(x.mean() - expected_x) < 0.02*width
    assert abs(y.mean() - expected_y) < 0.02*width
    assert x.max() - x.min() == pytest.approx(0.01/0.03*width, rel=0.1)
