"""Case-level tests of particles given by a closed triangulated surface
(shape triSurface): a box's surface moves as the box primitive, dry and in a
liquid, also when the file's axes are not the box's (a full inertia tensor);
a non-convex surface is refused by the exact pair overlap and runs with the
grid overlap; particles pass through a fixed obstacle of 'law none'."""

import pathlib

import numpy as np
import pytest

from foamcase import Case
from test_shapes import DRY_BOX, SPHERE_BOX, rotation, set_particles

PAIRS = "contact/pairs"

HERE = pathlib.Path(__file__).parent


def quaternion_product(p, q):
    w1, x1, y1, z1 = p
    w2, x2, y2, z2 = q
    return np.array([w1*w2 - x1*x2 - y1*y2 - z1*z2, w1*x2 + x1*w2 + y1*z2 - z1*y2,
                     w1*y2 - x1*z2 + y1*w2 + z1*x2, w1*z2 + x1*y2 - y1*x2 + z1*w2])


def quaternion_text(q):
    return "({!r} ({!r} {!r} {!r}))".format(*map(float, q))


def write_stl(path, points, triangles):
    """An ascii STL of the triangles (point indices, outward by the right
    hand rule)."""
    lines = ["solid body"]
    for tri in triangles:
        a, b, c = (np.asarray(points[i], float) for i in tri)
        n = np.cross(b - a, c - a)
        n /= np.linalg.norm(n)
        lines += ["facet normal {!r} {!r} {!r}".format(*map(float, n)), "outer loop"]
        lines += ["vertex {!r} {!r} {!r}".format(*map(float, p)) for p in (a, b, c)]
        lines += ["endloop", "endfacet"]
    lines.append("endsolid body")
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines) + "\n")


def box_surface(half_extents):
    """Corners and outward triangles of a box centred at the origin."""
    points = [np.array(half_extents)*[1 if i & 1 else -1, 1 if i & 2 else -1, 1 if i & 4 else -1]
              for i in range(8)]
    quads = [(0, 4, 6, 2), (1, 3, 7, 5), (0, 1, 5, 4), (2, 6, 7, 3), (0, 2, 3, 1), (4, 5, 7, 6)]
    triangles = [t for q in quads for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]
    return points, triangles


# Half extents exact in the STL reader's single precision (2^-8, 3 2^-10,
# 2^-9 m), a turn of the file's axes and the box's tilt in space
HALF = (0.00390625, 0.0029296875, 0.001953125)
FILE_TURN = np.array([np.cos(0.35), *(np.sin(0.35)*np.array([1, 2, 3])/np.sqrt(14))])
TILT = np.array([np.cos(0.2), np.sin(0.2)*0.6, np.sin(0.2)*0.8, 0])


def surface_and_box(case, position, extra):
    """The box twice in separate runs' particle entries: as the primitive
    tilted by TILT, and as a surface whose file holds the box turned by
    FILE_TURN, given the orientation that places it where the primitive is
    (TILT after the inverse of FILE_TURN)."""
    points, triangles = box_surface(HALF)
    R = rotation(FILE_TURN[None, :])[0]
    write_stl(case.path / "constant" / "triSurface" / "box.stl",
              [R @ p for p in points], triangles)
    inverse = FILE_TURN*[1, -1, -1, -1]
    common = {"density": 2500, "position": position, **extra}
    primitive = {"shape": "box", "halfExtents": "({} {} {})".format(*HALF),
                 "orientation": quaternion_text(TILT), **common}
    surface = {"shape": "triSurface", "file": '"box.stl"',
               "orientation": quaternion_text(quaternion_product(TILT, inverse)), **common}
    return primitive, surface


def test_box_surface_lands_as_the_box(tmp_path, foam_env):
    """A box dropped tilted and spinning onto the floor under gravity
    (restitution 0.5, friction 0.3): given as a surface whose file's axes
    are turned from the box's (its inertia a full tensor in them), it
    follows the primitive's trajectory, landing, tipping over and sliding,
    to within 1e-6 of the box's size (the STL holds single precision)."""
    histories = {}
    for name in ("primitive", "surface"):
        case = Case.copy(DRY_BOX, tmp_path / name, foam_env)
        case.run("blockMesh")
        bodies = surface_and_box(case, "(0 0 0.006)", {"velocity": "(0.2 0 -0.5)",
                                                        "angularVelocity": "(30 -20 10)"})
        set_particles(case, {"body": bodies[0 if name == "primitive" else 1]})
        case.set("constant/g", "value", "(0 0 -9.81)")
        case.set("system/controlDict", "endTime", 0.03)
        case.set("system/controlDict", "writeInterval", 100000)
        case.run("dlmDEMFoam")
        histories[name] = case.history()["body"]
    box, surface = histories["primitive"], histories["surface"]
    assert box.shape == surface.shape

    # The surface's VTK at the end: the file's 8 corners, placed and turned
    # where the primitive's corners are
    lines = (case.path / "VTK" / "particles" / "surfaces_0.03.vtk").read_text().splitlines()
    n = int(lines[4].split()[1])
    drawn = np.array([[float(v) for v in line.split()] for line in lines[5:5 + n]])
    R = rotation(box[-1:, -4:])[0]
    corners = np.array([box[-1, 1:4] + R @ (np.array(HALF)*[sx, sy, sz])
                        for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)])
    assert n == 8
    assert np.abs(np.sort(drawn, axis=0) - np.sort(corners, axis=0)).max() < 1e-6*0.008

    # It landed: the floor's force acted (mean contact force of a step)
    assert box[:, 18].max() > 0
    assert np.abs(surface[:, 1:4] - box[:, 1:4]).max() < 1e-6*0.008
    assert np.abs(surface[:, 4:7] - box[:, 4:7]).max() < 1e-5
    assert np.abs(surface[:, 7:10] - box[:, 7:10]).max() < 1e-3
    # The same attitude: the surface's body axes are the file's
    R_box = rotation(box[:, -4:])
    R_surface = rotation(surface[:, -4:]) @ rotation(FILE_TURN[None, :])[0]
    assert np.abs(R_surface - R_box).max() < 1e-6


def test_box_surface_settles_in_a_liquid_as_the_box(tmp_path, foam_env):
    """The tilted box settling in a viscous liquid (the coupling's test
    box, 6 cells across its thickness): its surface, from a turned file,
    settles and turns as the primitive, whose tilted fractions come from
    the same subdivision: velocity within 1e-6 of the fall speed."""
    histories = {}
    for name in ("primitive", "surface"):
        case = Case.copy(SPHERE_BOX, tmp_path / name, foam_env)
        case.run("blockMesh")
        bodies = surface_and_box(case, "(0.015 0.015 0.025)", {})
        set_particles(case, {"body": bodies[0 if name == "primitive" else 1]})
        case.set("system/controlDict", "endTime", 0.05)
        case.run("pimpleDLMFoam")
        histories[name] = case.history()["body"]
    box, surface = histories["primitive"], histories["surface"]
    fall = np.abs(box[:, 6]).max()
    assert fall > 0
    assert np.abs(surface[:, 4:7] - box[:, 4:7]).max() < 1e-6*fall
    assert np.abs(surface[:, 7:10] - box[:, 7:10]).max() < 1e-6*fall/HALF[2]


def l_prism(size):
    """An L-shaped prism (not convex): section (0 0) (2 0) (2 1) (1 1)
    (1 2) (0 2) times size, height size."""
    section = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    points = [np.array([x, y, z])*size for z in (0, 1) for x, y in section]
    triangles = [(0, 2, 1), (0, 3, 2), (0, 5, 3), (3, 5, 4),
                 (6, 7, 8), (6, 8, 9), (6, 9, 11), (9, 10, 11)]
    for k in range(6):
        n = (k + 1) % 6
        triangles += [(k, n, n + 6), (k, n + 6, k + 6)]
    return points, triangles


def test_non_convex_surfaces_need_the_grid_overlap(tmp_path, foam_env):
    """Two L-shaped particles: the exact pair overlap (convex shapes) is
    refused with the particle named and the grid method pointed to; with
    'overlap grid' the pair runs and keeps its momentum."""
    case = Case.copy(DRY_BOX, tmp_path / "ell", foam_env)
    # Cells of 0.5 mm: three across the L's thickness, for the grid sums
    case.set("system/blockMeshDict", "blocks", "( hex (0 1 2 3 4 5 6 7) (40 40 40) simpleGrading (1 1 1) )")
    case.run("blockMesh")
    write_stl(case.path / "constant" / "triSurface" / "ell.stl", *l_prism(0.0015))
    ell = {"shape": "triSurface", "file": '"ell.stl"', "density": 2500}
    # The L spans -1.25 to 1.75 mm in x about its centroid: 0.1 mm apart
    set_particles(case, {
        "left": {**ell, "position": "(-0.0018 0 0.01)", "velocity": "(0.5 0 0)"},
        "right": {**ell, "position": "(0.0013 0 0.01)", "velocity": "(-0.5 0 0)"},
    })
    case.set("constant/g", "value", "(0 0 0)")
    case.set("system/controlDict", "endTime", 0.0003)
    result = case.run("dlmDEMFoam", check=False)
    assert result.returncode != 0
    assert "Particle left (triSurface) is not convex" in result.log
    assert "overlap grid" in result.log

    case.set("constant/particleProperties", "contact/overlap", "grid")
    case.run("dlmDEMFoam")
    h = case.history()
    left, right = h["left"], h["right"]
    # They met: each was turned back or slowed
    assert left[-1, 4] < 0.5*0.99
    momentum = left[:, 4:7] + right[:, 4:7]
    assert np.abs(momentum).max() < 1e-12


def test_particles_pass_through_an_obstacle_of_law_none(tmp_path, foam_env):
    """An L-shaped fixed obstacle (not convex, of material 'obstacle') in
    the path of the dry box's head-on pair: with 'law none' towards the
    particles it needs no contact formulas (exact overlap), no law with the
    walls, and the spheres pass through it: their collision is the same to
    the bit as without it. Without the entry the run stops, naming the two
    materials and 'law none'."""
    def head_on(name, obstacle):
        case = Case.copy(DRY_BOX, tmp_path / name, foam_env)
        case.run("blockMesh")
        case.set("constant/g", "value", "(0 0 0)")
        case.set("system/controlDict", "endTime", 0.004)
        if obstacle:
            write_stl(case.path / "constant" / "triSurface" / "ell.stl", *l_prism(0.0015))
            case.set("constant/particleProperties", "particles/obstacle",
                     '{ shape triSurface; file "ell.stl"; density 2500; motion fixed;'
                     ' material obstacle; position (-0.003 0 0.01); }')
        return case

    alone = head_on("alone", obstacle=False)
    alone.run("dlmDEMFoam")

    refused = head_on("refused", obstacle=True)
    result = refused.run("dlmDEMFoam", check=False)
    assert result.returncode != 0
    assert "No contact law for materials (particle obstacle)" in result.log
    assert "law none" in result.log

    passed = head_on("passed", obstacle=True)
    passed.set("constant/particleProperties", f"{PAIRS}/particleObstacle",
               "{ materials (particle obstacle); law none; }")
    passed.run("dlmDEMFoam")
    h, h0 = passed.history(), alone.history()
    assert np.all(h["obstacle"][:, 1:10] == h["obstacle"][0, 1:10])
    for name in ("left", "right"):
        assert np.array_equal(h[name], h0[name])
    # They met with the case's restitution 0.5
    assert abs(h["left"][-1, 4] + 0.25) < 0.01


def test_surface_particle_restarts_in_parallel_as_never_stopped(tmp_path, foam_env):
    """The box's surface settling in the liquid on 2 ranks (each reads the
    surface from the case's constant/triSurface), stopped at a written
    time and restarted from the processor directories: it continues as the
    uninterrupted run, to round-off."""
    def make(name, end_time):
        case = Case.copy(SPHERE_BOX, tmp_path / name, foam_env)
        case.run("blockMesh")
        surface = surface_and_box(case, "(0.015 0.015 0.025)", {})[1]
        set_particles(case, {"body": surface})
        case.set("system/controlDict", "endTime", end_time)
        case.set("system/controlDict", "writeInterval", 5)
        case.run("decomposePar")
        return case

    full = make("full", 0.05)
    full.run("pimpleDLMFoam", np=2)
    stopped = make("stopped", 0.025)
    stopped.run("pimpleDLMFoam", np=2)
    stopped.set("system/controlDict", "endTime", 0.05)
    stopped.run("pimpleDLMFoam", np=2, log="pimpleDLMFoam.restart")

    a = full.history()["body"]
    b = stopped.history("0.025")["body"]
    tail = a[a[:, 0] > 0.025 + 1e-9]
    assert len(b) == len(tail) == 5
    assert np.abs(b[:, 1:10] - tail[:, 1:10]).max() < 1e-12
    assert np.abs(b[:, -4:] - tail[:, -4:]).max() < 1e-12
