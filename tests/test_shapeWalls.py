"""Shapes that are not round against contact-only walls: a box lying in a
horizontal cylinder rests on its two long edges, a box in a funnel on its
four corners, at the heights the geometry gives (the tangent plane at the
point nearest the centroid would let them sink through the curved wall),
and a box dropped flat onto a plane wall and onto an STL surface rebounds
with the requested restitution."""

import numpy as np
import pytest

from foamcase import Case
from test_shapes import DRY_BOX, rotation, set_particles
from test_surfaceShapes import write_stl

HALF = (0.004, 0.003, 0.0015)
BOX = {"shape": "box", "halfExtents": "({} {} {})".format(*HALF), "density": 2500}


def walls_case(tmp_path, env, name, walls, body, settings, surfaces=None):
    """The dry box with the body and these contact-only walls (name ->
    entries), surfaces (file name -> points, triangles) written to
    constant/triSurface; the body's history after dlmDEMFoam."""
    case = Case.copy(DRY_BOX, tmp_path / name, env)
    for file, (points, triangles) in (surfaces or {}).items():
        write_stl(case.path / "constant" / "triSurface" / file, points, triangles)
    case.run("blockMesh")
    set_particles(case, {"body": body})
    text = (case.path / "constant" / "particleProperties").read_text()
    entries = "".join(f"        {wall} {{ {spec} }}\n" for wall, spec in walls.items())
    text = text.replace("contact\n{\n", f"contact\n{{\n    walls\n    {{\n{entries}    }}\n", 1)
    (case.path / "constant" / "particleProperties").write_text(text)
    for (file, entry), value in settings.items():
        case.set(file, entry, value)
    case.run("dlmDEMFoam")
    return case.history()["body"]


RESTING = {
    ("constant/g", "value"): "(0 0 -9.81)",
    ("system/controlDict", "endTime"): 0.3,
    ("system/controlDict", "writeInterval"): 100000,
}


def resting_corners(h):
    """The box's eight corners at the end (bottom four first), after
    checking that it is at rest: its centroid moving less than 1e-7 m over
    the last 0.05 s."""
    last = h[:, 0] >= h[-1, 0] - 0.05
    assert np.ptp(h[last, 1:4], axis=0).max() < 1e-7
    R = rotation(h[-1:, -4:])[0]
    signs = [(x, y, z) for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)]
    return np.array([h[-1, 1:4] + R @ (np.array(HALF)*s) for s in signs])


def test_box_rests_on_its_edges_in_a_horizontal_cylinder(tmp_path, foam_env):
    """A box (8 x 6 x 3 mm) lying along a horizontal cylinder of radius
    6 mm falls onto its curve and rests on its two lower long edges: the
    four lower corners on the cylinder (within the contact's overlap, 1 %
    of the half-thickness), the centroid sqrt(6^2 - 3^2) - 1.5 = 3.696 mm
    from the axis (the tangent plane at the point nearest the centroid
    alone would let the edges sink 0.8 mm through the curve). Friction
    holds it at whatever small roll the landing left."""
    axis_point = np.array([0, 0, 0.01])
    h = walls_case(tmp_path, foam_env, "trough",
                   {"trough": "type cylinder; point (0 0 0.01); axis (1 0 0); radius 0.006;"},
                   {**BOX, "position": "(0 0 0.01)"}, RESTING)
    corners = resting_corners(h)
    beyond = np.hypot(*(corners[:4] - axis_point)[:, 1:].T) - 0.006
    assert beyond.min() > -1e-9
    assert beyond.max() < 0.01*HALF[2]
    depth = np.sqrt(0.006**2 - HALF[1]**2) - HALF[2]
    assert np.hypot(*(h[-1, 2:4] - axis_point[1:])) == pytest.approx(depth, abs=0.01*HALF[2])
    assert h[-1, 1] == pytest.approx(0, abs=1e-4*HALF[0])


def test_box_rests_on_its_corners_in_a_funnel(tmp_path, foam_env):
    """The box lying flat on the axis of a funnel (a cone widening upwards
    by 1 in 2, radius 1 mm at z = 2 mm) falls in and rests on its lower
    corners: none beyond the cone by more than the contact's overlap (1.7 %
    of the half-thickness; about 16 um, the corners' soft cubic overlap law
    carrying the weight), at least three bearing (beyond it by 0.3 % or
    more). Corners on a cone do not fix the pose: it may rest turned or
    tipped, on three corners or four, as round-off decides."""
    h = walls_case(tmp_path, foam_env, "funnel",
                   {"funnel": "type cone; point1 (0 0 0.002); radius1 0.001;"
                              " point2 (0 0 0.018); radius2 0.009;"},
                   {**BOX, "position": "(0 0 0.013)"}, RESTING)
    corners = resting_corners(h)[:4]
    radius = 0.001 + 0.5*(corners[:, 2] - 0.002)
    beyond = (np.hypot(corners[:, 0], corners[:, 1]) - radius)*np.cos(np.arctan(0.5))
    assert np.sort(beyond)[1] > 0.003*HALF[2]
    assert beyond.max() < 0.017*HALF[2]


@pytest.mark.parametrize("wall", ["plane", "surface"])
def test_box_dropped_flat_on_a_contact_wall_bounces_with_the_restitution(
        tmp_path, foam_env, wall):
    """Dropped flat at 1 m/s (no gravity) onto a contact-only shelf at
    z = 5 mm, a plane or a square of two STL triangles: it rebounds at the
    requested restitution 0.5 within 2 %, without turning."""
    surfaces = None
    if wall == "plane":
        spec = "type plane; point (0 0 0.005); normal (0 0 1);"
    else:
        corners = [(-0.009, -0.009, 0.005), (0.009, -0.009, 0.005),
                   (0.009, 0.009, 0.005), (-0.009, 0.009, 0.005)]
        surfaces = {"shelf.stl": (corners, [(0, 1, 2), (0, 2, 3)])}
        spec = 'type surface; file "shelf.stl";'
    h = walls_case(tmp_path, foam_env, wall, {"shelf": spec},
                   {**BOX, "position": "(0 0 0.007)", "velocity": "(0 0 -1)"},
                   {("constant/g", "value"): "(0 0 0)"}, surfaces)
    assert h[-1, 6] == pytest.approx(0.5, rel=0.02)
    assert np.abs(h[:, [4, 5, 7, 8, 9]]).max() < 1e-9
    assert h[:, 3].min() > 0.005 + 0.9*HALF[2]


def test_grid_overlap_pushes_along_the_face_touched(tmp_path, foam_env):
    """A sphere (radius 1 mm) dropped at 1 m/s onto the top face of a box
    held fixed, 4 mm off the box's centre, with the grid overlap (cells of
    0.5 mm): the face pushes it straight back up (the line through the
    centroids leans 60 degrees and would throw it sideways), at the
    requested restitution within 10 % (the grid's overlap at 4 cells per
    diameter)."""
    case = Case.copy(DRY_BOX, tmp_path / "grid", foam_env)
    case.set("system/blockMeshDict", "blocks", "( hex (0 1 2 3 4 5 6 7) (40 40 40) simpleGrading (1 1 1) )")
    case.run("blockMesh")
    set_particles(case, {
        "table": {**BOX, "halfExtents": "(0.006 0.006 0.002)", "position": "(0 0 0.005)",
                  "motion": "fixed"},
        "ball": {"shape": "sphere", "radius": 0.001, "density": 2500,
                 "position": "(0.004 0 0.0081)", "velocity": "(0 0 -1)"},
    })
    case.set("constant/particleProperties", "contact/overlap", "grid")
    case.set("constant/g", "value", "(0 0 0)")
    case.set("system/controlDict", "endTime", 0.0006)
    case.run("dlmDEMFoam")
    ball = case.history()["ball"]
    assert ball[-1, 6] == pytest.approx(0.5, rel=0.1)
    assert np.abs(ball[-1, 4:6]).max() < 0.01*ball[-1, 6]
