"""Case-level tests of non-spherical particles: a dry ellipsoid tumbling free
of torque (the intermediate-axis flip, energy and angular momentum kept, the
orientation in the history and the surfaces in the VTK files), a
spheroid settling tilted in a viscous liquid (the glide of an anisotropic
body in Stokes flow), an ellipsoid and a box dropped flat on a floor (the
rebound at the requested restitution) and a tilted ellipsoid with rolling
friction settling onto its largest face."""

import pathlib
import re

import numpy as np
import pytest

from foamcase import Case
from stokesFlow import oberbeck_resistances, unbounded_resistance

HERE = pathlib.Path(__file__).parent
DRY_BOX = HERE / "cases" / "dryBox"
SPHERE_BOX = HERE / "cases" / "sphereBox"


def rotation(q):
    """Rotation matrices (n, 3, 3), body to global, of quaternions (n, 4)
    (w x y z)."""
    w, x, y, z = q.T
    return np.stack([
        np.stack([1 - 2*(y*y + z*z), 2*(x*y - w*z), 2*(x*z + w*y)], -1),
        np.stack([2*(x*y + w*z), 1 - 2*(x*x + z*z), 2*(y*z - w*x)], -1),
        np.stack([2*(x*z - w*y), 2*(y*z + w*x), 1 - 2*(x*x + y*y)], -1),
    ], -2)


def ellipsoid_inertia(semi_axes):
    """Body-frame principal inertia per unit density and unit volume factor."""
    a, b, c = semi_axes
    return np.array([b*b + c*c, a*a + c*c, a*a + b*b])/5


def set_particle(case, name, entries):
    text = (case.path / "constant" / "particleProperties").read_text()
    body = "\n".join(f"        {k} {v};" for k, v in entries.items())
    text = re.sub(r"particles\s*\{.*?\n\}\n",
                  f"particles\n{{\n    {name}\n    {{\n{body}\n    }}\n}}\n",
                  text, count=1, flags=re.S)
    (case.path / "constant" / "particleProperties").write_text(text)


def test_dry_ellipsoid_spun_about_its_intermediate_axis_flips(tmp_path, foam_env):
    """An ellipsoid (semi-axes 1, 2.5 and 4 mm) spun at 50 turns a second
    about its intermediate axis (y) with a disturbance of 1e-3, no gravity
    and no contacts: the y axis turns against the angular momentum and
    back, while the kinetic energy and the angular momentum stay to 1e-9
    (the history's 15 digits). The VTK surfaces lie on the ellipsoid as
    placed and turned at each write time."""
    semi_axes = np.array([0.001, 0.0025, 0.004])
    spin = 2*np.pi*50
    omega0 = spin*np.array([0, 1, 0]) + 1e-3*spin
    case = Case.copy(DRY_BOX, tmp_path / "tumble", foam_env)
    case.run("blockMesh")
    set_particle(case, "body", {
        "shape": "ellipsoid",
        "semiAxes": "({!r} {!r} {!r})".format(*map(float, semi_axes)),
        "density": 2500,
        "position": "(0 0 0.01)",
        "angularVelocity": "({!r} {!r} {!r})".format(*map(float, omega0)),
    })
    case.run("foamDictionary", "constant/particleProperties", "-entry",
             "contact", "-remove", log="foamDictionary")
    case.set("constant/g", "value", "(0 0 0)")
    case.set("system/controlDict", "endTime", 0.2)
    case.set("system/controlDict", "writeInterval", 500)
    case.run("dlmDEMFoam")

    h = case.history()["body"]
    omega = h[:, 7:10]
    R = rotation(h[:, -4:])
    inertia = ellipsoid_inertia(semi_axes)
    # Body-frame angular velocity, then global angular momentum and energy
    omega_body = np.einsum("nji,nj->ni", R, omega)
    L = np.einsum("nij,nj->ni", R, inertia*omega_body)
    energy = 0.5*np.sum(inertia*omega_body**2, axis=1)
    assert np.abs(L - L[0]).max() < 1e-9*np.linalg.norm(L[0])
    assert np.abs(energy/energy[0] - 1).max() < 1e-9

    alignment = R[:, :, 1] @ (L[0]/np.linalg.norm(L[0]))
    flip = np.argmax(alignment < -0.99)
    assert flip > 0, alignment.min()
    assert alignment[flip:].max() > 0.99

    # Surfaces: each point on the ellipsoid x.A.x = 1 in the body frame
    # (the history starts after the first step)
    for vtk in sorted((case.path / "VTK" / "particles").glob("surfaces_*.vtk")):
        t = float(vtk.stem.split("_")[1])
        if t == 0:
            continue
        row = np.argmin(np.abs(h[:, 0] - t))
        assert abs(h[row, 0] - t) < 1e-9
        lines = vtk.read_text().splitlines()
        n = int(lines[4].split()[1])
        points = np.array([[float(v) for v in line.split()]
                           for line in lines[5:5 + n]])
        local = (points - h[row, 1:4]) @ R[row]
        assert n == 642
        assert np.abs(np.sum((local/semi_axes)**2, axis=1) - 1).max() < 1e-6
    assert len(list((case.path / "VTK" / "particles").glob("surfaces_*.vtk"))) == 5
    assert (case.path / "VTK" / "particles" / "surfaces.vtk.series").exists()


def test_oberbeck_resistances_have_the_sphere_limit():
    along, across = oberbeck_resistances(1, 1 - 1e-6, 1)
    assert along == pytest.approx(6*np.pi, rel=1e-5)
    assert across == pytest.approx(6*np.pi, rel=1e-5)


def test_periodic_correction_leaves_the_cubic_arrays_third_order_term():
    """Zick & Homsy's drag of spheres in a simple cubic array (K = 2.008 at
    a solid fraction of 0.027, 2.81 at 0.064), corrected to unbounded
    fluid by the Stokeslet lattice's leading term, is Stokes' drag but for
    the next term of the series, 1/K = 1 - 1.7601 phi^(1/3) + phi: the
    corrected 6 pi mu a/R - 1 is phi within 10 %."""
    for phi, K in [(0.027, 2.008), (0.064, 2.81)]:
        L = (4*np.pi/(3*phi))**(1/3)
        R = unbounded_resistance(6*np.pi*K, 1, L)
        assert 6*np.pi/R - 1 == pytest.approx(phi, rel=0.1)


def test_tilted_spheroid_glides_as_it_settles_in_stokes_flow(tmp_path, foam_env):
    """A prolate spheroid (semi-axes 2, 2, 4 mm, 4.8 cells across its minor
    diameter, density 2000) tilted 45 degrees and settling in a liquid of
    viscosity 1 Pa s (Reynolds number 0.05): in Stokes flow it drifts
    sideways, towards where its lower end points, by the anisotropy of its
    drag, and does not turn. Unbounded, Oberbeck's resistances give a drift
    of 0.068 of the fall; the box (3.75 lengths wide) changes that, so the
    drift must lie within half and twice of it (0.10 here). Its tilt
    changes by less than 0.1 degree over the fall of 0.8 mm; the angular
    velocity jumps by up to 1.3 % of the fall speed over the semi-major
    axis as cells change sides of the moving surface, so it is held to
    3 %."""
    a, b = 0.004, 0.002
    case = Case.copy(SPHERE_BOX, tmp_path / "glide", foam_env)
    case.set("system/blockMeshDict", "blocks", "( hex (0 1 2 3 4 5 6 7) (36 36 54) simpleGrading (1 1 1) )")
    case.run("blockMesh")
    case.run("foamDictionary", "system/controlDict", "-entry",
             "maxViscousNumber", "-remove", log="foamDictionary")
    half = np.pi/8
    set_particle(case, "spheroid", {
        "shape": "ellipsoid",
        "semiAxes": f"({b} {b} {a})",
        "density": 2000,
        "position": "(0.015 0.015 0.025)",
        "orientation": f"({float(np.cos(half))!r} ({float(np.sin(half))!r} 0 0))",
    })
    for (file, entry), value in {
        ("system/fvSolution", "PIMPLE/nCorrectors"): 3,
        ("system/controlDict", "deltaT"): 0.004,
        ("system/controlDict", "endTime"): 0.1,
        ("system/controlDict", "writeInterval"): 1000,
    }.items():
        case.set(file, entry, value)
    case.run("pimpleDLMFoam")
    h = case.history()["spheroid"]
    late = h[:, 0] >= 0.06
    U = h[late, 4:7].mean(axis=0)
    omega = h[late, 7:10]

    # The spheroid's axis, global: (0, -sin 45, cos 45); its lower end at +y
    axis = np.array([0, -np.sin(2*half), np.cos(2*half)])
    along, across = oberbeck_resistances(a, b, 1.0)
    mobility = np.outer(axis, axis)/along + (np.eye(3) - np.outer(axis, axis))/across
    expected = mobility @ np.array([0, 0, -1.0])
    drift, expected_drift = U[1]/-U[2], expected[1]/-expected[2]
    assert U[2] < 0
    assert 0.5*expected_drift < drift < 2*expected_drift, (drift, expected_drift)
    assert abs(U[0]) < 0.01*abs(U[2])
    assert np.abs(omega).max()*a < 0.03*abs(U[2])
    tilt = 2*np.arctan2(h[:, -3], h[:, -4])
    assert np.abs(np.degrees(tilt) - 45).max() < 0.1
    assert np.abs(h[:, [-2, -1]]).max() < 1e-6


def dry_shape(tmp_path, env, name, entries, settings=None):
    """The dry box with one particle of the given entries (contacts as the
    box's: overlap volume, contact time 1e-4 s at 1 m/s)."""
    case = Case.copy(DRY_BOX, tmp_path / name, env)
    case.run("blockMesh")
    set_particle(case, "body", {"density": 2500, **entries})
    for (file, entry), value in (settings or {}).items():
        case.set(file, entry, value)
    return case


FLAT_SHAPES = {
    # Largest face down: the ellipsoid meets the floor at a smooth point
    # (overlap ~ delta^2), the box with a face (overlap ~ delta)
    "ellipsoid": {"shape": "ellipsoid", "semiAxes": "(0.004 0.003 0.0015)"},
    "box": {"shape": "box", "halfExtents": "(0.004 0.003 0.0015)"},
    # On an end face (overlap ~ delta), and on its side, axis along x: a
    # line of contact (overlap ~ delta^1.5)
    "cylinder": {"shape": "cylinder", "radius": 0.004, "length": 0.003},
    "cylinder on its side": {"shape": "cylinder", "radius": 0.0015, "length": 0.008,
                             "orientation": "(0.7071067811865476 (0 0.7071067811865476 0))"},
}


@pytest.mark.parametrize("shape", FLAT_SHAPES)
@pytest.mark.parametrize("e", [0.3, 0.8])
def test_shape_dropped_flat_bounces_with_the_requested_restitution(
        tmp_path, foam_env, shape, e):
    """Dropped flat onto the floor at 1 m/s (no gravity): the rebound speed
    is the requested restitution within 2 %, whether the overlap grows as
    the depth squared (a smooth point), linearly (a face) or as the depth
    to the power 1.5 (a line), without turning or drifting."""
    pairs = "contact/pairs/particleWall"
    case = dry_shape(tmp_path, foam_env, f"{shape.replace(' ', '_')}_{e}", {
        **FLAT_SHAPES[shape],
        "position": "(0 0 0.002)",
        "velocity": "(0 0 -1)",
    }, {
        ("constant/g", "value"): "(0 0 0)",
        ("constant/particleProperties", f"{pairs}/restitution"): e,
    })
    case.run("dlmDEMFoam")
    h = case.history()["body"]
    assert h[-1, 6] == pytest.approx(e, rel=0.02)
    assert np.abs(h[:, [4, 5, 7, 8, 9]]).max() < 1e-9
    # Never through the floor: the deepest overlap under 10 % of the
    # smallest semi-axis
    assert h[:, 3].min() > 0.0015*0.9


def test_tilted_ellipsoid_comes_to_rest_on_its_largest_face(tmp_path, foam_env):
    """An ellipsoid (semi-axes 4, 3 and 1.5 mm) dropped from 6 mm tilted
    30 degrees about x and 20 about y, under gravity, with restitution 0.5,
    friction 0.3 and rolling friction 0.02: it rocks down onto its flattest
    side and rests there: the short axis vertical within the tilt that
    rolling friction holds, mu_r R/(R - c) with R = b^2/c the curvature
    radius at the bottom (1.5 degrees; it rests at 1.2), the centroid at
    the short semi-axis within 1 %, no spin, and its centroid moving less
    than 1e-3 of its length over the last 0.2 s. Without rolling friction
    it rocks on (rolling without slip dissipates nothing)."""
    q = np.array([np.cos(np.radians(15)), np.sin(np.radians(15)), 0, 0])
    tilt_y = np.array([np.cos(np.radians(10)), 0, np.sin(np.radians(10)), 0])
    w1, x1, y1, z1 = tilt_y
    w2, x2, y2, z2 = q
    q = [w1*w2 - x1*x2 - y1*y2 - z1*z2, w1*x2 + x1*w2 + y1*z2 - z1*y2,
         w1*y2 - x1*z2 + y1*w2 + z1*x2, w1*z2 + x1*y2 - y1*x2 + z1*w2]
    case = dry_shape(tmp_path, foam_env, "rest", {
        **FLAT_SHAPES["ellipsoid"],
        "position": "(0 0 0.006)",
        "orientation": "({!r} ({!r} {!r} {!r}))".format(*map(float, q)),
    }, {
        ("constant/g", "value"): "(0 0 -9.81)",
        ("constant/particleProperties", "contact/pairs/particleWall/rollingFriction"): 0.02,
        ("system/controlDict", "endTime"): 0.6,
        ("system/controlDict", "writeInterval"): 100000,
    })
    case.run("dlmDEMFoam")
    h = case.history()["body"]
    R = rotation(h[:, -4:])
    b, c = 0.003, 0.0015
    held = 0.02*(b*b/c)/(b*b/c - c)
    assert np.arccos(min(abs(R[-1, 2, 2]), 1)) < held
    assert h[-1, 3] == pytest.approx(0.0015, rel=0.01)
    assert np.abs(h[-1, 7:10]).max() < 0.01
    last = h[:, 0] >= 0.4
    assert np.ptp(h[last, 1:3], axis=0).max() < 1e-3*0.008


def set_particles(case, bodies):
    """Replace the particles with these: dict name -> entries."""
    text = (case.path / "constant" / "particleProperties").read_text()
    body = "".join(
        f"    {name}\n    {{\n" + "".join(f"        {k} {v};\n" for k, v in entries.items())
        + "    }\n" for name, entries in bodies.items())
    text = re.sub(r"particles\s*\{.*?\n\}\n", f"particles\n{{\n{body}}}\n",
                  text, count=1, flags=re.S)
    (case.path / "constant" / "particleProperties").write_text(text)


def box_inertia(half_extents):
    """Principal moments of inertia per unit mass of a box."""
    a2 = np.asarray(half_extents)**2
    return np.array([a2[1] + a2[2], a2[0] + a2[2], a2[0] + a2[1]])/3


def test_aligned_ellipsoids_meet_head_on_with_the_requested_restitution(tmp_path, foam_env):
    """Two equal ellipsoids (semi-axes 2, 1.5 and 1 mm) meet tip to tip at
    1 m/s (no gravity): the common-plane overlap of two aligned shapes is
    their exact lens, and they part at 0.5 m/s (restitution 0.5) within
    2 %, momentum kept to round-off, without turning or moving sideways."""
    case = Case.copy(DRY_BOX, tmp_path / "eggs", foam_env)
    case.run("blockMesh")
    egg = {"shape": "ellipsoid", "semiAxes": "(0.002 0.0015 0.001)", "density": 2500}
    set_particles(case, {
        "left": {**egg, "position": "(-0.0025 0 0.01)", "velocity": "(0.5 0 0)"},
        "right": {**egg, "position": "(0.0025 0 0.01)", "velocity": "(-0.5 0 0)"},
    })
    case.set("constant/g", "value", "(0 0 0)")
    case.run("dlmDEMFoam")
    h = case.history()
    left, right = h["left"], h["right"]
    assert right[-1, 4] - left[-1, 4] == pytest.approx(0.5, rel=0.02)
    assert np.abs(left[:, 4:7] + right[:, 4:7]).max() < 1e-12
    for body in (left, right):
        assert np.abs(body[:, [5, 6, 7, 8, 9]]).max() < 1e-9


def test_box_striking_a_tilted_ellipsoid_keeps_momentum_and_angular_momentum(tmp_path, foam_env):
    """A tilted box strikes a tilted ellipsoid off centre (no gravity,
    friction 0.3): both spin off, the total momentum and angular momentum
    (about the origin, the spins' R I R^T omega included) stay to round-off
    (1e-9 of their scale), and kinetic energy is lost."""
    case = Case.copy(DRY_BOX, tmp_path / "strike", foam_env)
    case.run("blockMesh")
    half = np.array([0.002, 0.0015, 0.001])
    semi = np.array([0.002, 0.0015, 0.001])
    density = 2500
    set_particles(case, {
        "brick": {"shape": "box", "halfExtents": "({!r} {!r} {!r})".format(*map(float, half)),
                  "density": density, "position": "(-0.003 0.0005 0.01)",
                  "orientation": "(0.9 (0.3 0.2 0.1))", "velocity": "(0.8 0 0.1)"},
        "egg": {"shape": "ellipsoid", "semiAxes": "({!r} {!r} {!r})".format(*map(float, semi)),
                "density": density, "position": "(0.0025 -0.0005 0.01)",
                "orientation": "(0.8 (-0.1 0.4 0.2))", "velocity": "(-0.4 0 0)"},
    })
    case.set("constant/g", "value", "(0 0 0)")
    case.set("system/controlDict", "endTime", 0.006)
    case.run("dlmDEMFoam")
    h = case.history()
    bodies = {
        "brick": (density*8*np.prod(half), box_inertia(half)),
        "egg": (density*4/3*np.pi*np.prod(semi), ellipsoid_inertia(semi)),
    }
    P = 0
    L = 0
    E = 0
    for name, (mass, inertia) in bodies.items():
        x, v, w = h[name][:, 1:4], h[name][:, 4:7], h[name][:, 7:10]
        R = rotation(h[name][:, -4:])
        w_body = np.einsum("nji,nj->ni", R, w)
        P = P + mass*v
        L = L + mass*np.cross(x, v) + np.einsum("nij,nj->ni", R, mass*inertia*w_body)
        E = E + 0.5*mass*np.sum(v**2, axis=1) + 0.5*mass*np.sum(inertia*w_body**2, axis=1)
    spin = np.abs(h["brick"][-1, 7:10]).max()
    assert spin > 10, spin
    assert np.abs(P - P[0]).max() < 1e-12*np.abs(P[0]).max() + 1e-15
    scale = np.linalg.norm(L[0]) + 0.01*0.8*bodies["brick"][0]
    assert np.abs(L - L[0]).max() < 1e-9*scale
    assert 0 < E[-1] < 0.99*E[0]


def test_stack_of_boxes_and_a_cylinder_rests_without_jitter(tmp_path, foam_env):
    """A box on the floor, a smaller box turned 30 degrees on it and a
    cylinder standing on top, placed just touching, under gravity: the
    face-on-face contacts (the least depth at a kink of the support
    functions; a face stiff at any depth, so sub-stepped from the first
    touch) hold the stack still. Over 0.02 s every body moves slower than
    0.1 mm/s and turns slower than 0.01 rad/s, and each rests at the
    height of the ones below within 1 % of its thickness, without sliding
    or turning about the vertical. (A box resting down onto a face sank by
    a step's fall before its contact was sub-stepped and flew off; a face
    on a larger one had no section where the plane met the larger face.)"""
    case = Case.copy(DRY_BOX, tmp_path / "stack", foam_env)
    case.run("blockMesh")
    turned = "({!r} (0 0 {!r}))".format(float(np.cos(np.radians(15))), float(np.sin(np.radians(15))))
    set_particles(case, {
        "base": {"shape": "box", "halfExtents": "(0.004 0.003 0.0015)", "density": 2500,
                 "position": "(0.0005 0 0.0015)"},
        "middle": {"shape": "box", "halfExtents": "(0.003 0.0025 0.0015)", "density": 2500,
                   "position": "(0 0.0005 0.0045)", "orientation": turned},
        "top": {"shape": "cylinder", "radius": 0.002, "length": 0.004, "density": 2500,
                "position": "(0 0 0.008)"},
    })
    case.set("constant/g", "value", "(0 0 -9.81)")
    case.set("system/controlDict", "endTime", 0.02)
    case.set("system/controlDict", "writeInterval", 100000)
    case.run("dlmDEMFoam")
    h = case.history()
    heights = {"base": 0.0015, "middle": 0.0045, "top": 0.008}
    thickness = {"base": 0.003, "middle": 0.003, "top": 0.004}
    for name, body in h.items():
        assert np.abs(body[:, 4:7]).max() < 1e-4, name
        assert np.abs(body[:, 7:10]).max() < 1e-2, name
        assert abs(body[-1, 3] - heights[name]) < 0.01*thickness[name], name
        assert np.abs(body[-1, 1:3] - body[0, 1:3]).max() < 1e-5, name
        R0, R1 = rotation(body[[0, -1], -4:])
        assert np.abs(R1 - R0).max() < 1e-3, name
