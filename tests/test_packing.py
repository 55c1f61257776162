"""dlmPackSpheres: random packings of equal spheres without overlaps at a
requested solid fraction, reproducible from the seed, and clear errors on bad
input. dlmPackParticles: spheres, ellipsoids, boxes and cylinders at random
positions and orientations, apart and inside the box by the gap (checked
here by their own closed forms, not the library's), reproducible from the
seed, and a clear error when they do not fit."""

import math
import re

import numpy as np
import pytest

from foamcase import Case

CONTROL_DICT = """FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application dlmPackSpheres;
startTime 0; endTime 1; deltaT 1; writeControl timeStep; writeInterval 1;
"""

PACK_HEADER = "FoamFile { version 2.0; format ascii; class dictionary; object packSpheresDict; }\n"


def pack_case(path, env, settings):
    """A case with system/packSpheresDict holding the given entries."""
    case = Case(path, env)
    (case.path / "system").mkdir(parents=True)
    (case.path / "system" / "controlDict").write_text(CONTROL_DICT)
    (case.path / "system" / "packSpheresDict").write_text(PACK_HEADER + settings + "\n")
    return case


def box_entry(lower, upper):
    """The box entry of packSpheresDict for the corners lower and upper."""
    return f"box ({' '.join(map(str, lower))}) ({' '.join(map(str, upper))});"


def read_packing(path):
    """Centres (n, 3) and the radius of a particle file."""
    rows = np.loadtxt(path, comments="#", ndmin=2)
    assert rows.shape[1] == 4
    assert np.all(rows[:, 3] == rows[0, 3]), "spheres of different radii"
    return rows[:, :3], rows[0, 3]


def smallest_distance(centres, lower, upper, periodic):
    """Smallest distance between two centres, minimum image in the periodic
    directions."""
    length = np.asarray(upper) - np.asarray(lower)
    d = centres[:, None, :] - centres[None, :, :]
    for i in range(3):
        if periodic[i]:
            d[..., i] -= length[i] * np.round(d[..., i] / length[i])
    distance = np.sqrt((d**2).sum(axis=-1))
    np.fill_diagonal(distance, np.inf)
    return distance.min()


def test_overlap_check_uses_minimum_image():
    # Two spheres of radius 0.5 mm touching across the periodic x faces
    centres = np.array([[0.0002, 0.005, 0.005], [0.0098, 0.005, 0.005]])
    lower, upper = (0, 0, 0), (0.01, 0.01, 0.01)
    assert smallest_distance(centres, lower, upper, (True, True, True)) \
        == pytest.approx(0.0004)
    assert smallest_distance(centres, lower, upper, (False, True, True)) \
        == pytest.approx(0.0096)


def test_periodic_packing_at_060(tmp_path, foam_env):
    lower, upper, radius, fraction = (0, 0, 0), (0.01, 0.01, 0.01), 0.0007, 0.6
    case = pack_case(tmp_path / "case", foam_env, f"""
{box_entry(lower, upper)}
periodic (yes yes yes);
radius {radius};
solidFraction {fraction};
""")
    case.run("dlmPackSpheres")
    path = case.path / "constant" / "packing.dat"
    centres, r = read_packing(path)
    assert r == radius

    n = len(centres)
    box_volume = np.prod(np.subtract(upper, lower))
    sphere_volume = 4 / 3 * math.pi * radius**3
    achieved = n * sphere_volume / box_volume
    assert n == round(fraction * box_volume / sphere_volume) == 418
    # Rounding to whole spheres: off by half a sphere's share of the box at
    # most, which is below 1/n (and unlike 1/n fails for one sphere too many)
    assert abs(achieved - fraction) <= 0.5 * sphere_volume / box_volume < 1 / n

    assert smallest_distance(centres, lower, upper, (True,) * 3) \
        >= 2 * radius * (1 - 1e-12)
    assert np.all(centres >= lower) and np.all(centres < upper)

    header = [line for line in path.read_text().splitlines() if line.startswith("#")]
    assert "# periodic (yes yes yes)" in header
    assert "# nParticles 418" in header
    assert "# seed 1" in header
    assert any(line.startswith("# smallest gap / diameter") for line in header)


def test_periodic_packing_at_064_near_random_close_packing(tmp_path, foam_env):
    """The anisotropic beds start from porosity 36 %: 106 spheres at 0.638,
    above the 0.62 that relaxing random centres reaches, through the Monte
    Carlo compression; no two spheres overlap."""
    lower, upper, radius = (0, 0, 0), (1, 1, 1), 0.11283
    case = pack_case(tmp_path / "case", foam_env, f"""
{box_entry(lower, upper)}
periodic (yes yes yes);
radius {radius};
solidFraction 0.64;
""")
    case.run("dlmPackSpheres")
    centres, _ = read_packing(case.path / "constant" / "packing.dat")
    assert len(centres) == 106
    assert len(centres)*4/3*math.pi*radius**3 == pytest.approx(0.6378, abs=1e-4)
    assert smallest_distance(centres, lower, upper, (True,) * 3) \
        >= 2 * radius * (1 - 1e-12)
    assert np.all(centres >= lower) and np.all(centres < upper)


def test_walls_in_z_at_050(tmp_path, foam_env):
    # A box off the origin: wrapping and wall distances are relative to it
    lower, upper, radius = (-0.004, 0.002, 0.001), (0.004, 0.010, 0.009), 0.0006
    case = pack_case(tmp_path / "case", foam_env, f"""
{box_entry(lower, upper)}
periodic (yes yes no);
radius {radius};
solidFraction 0.5;
""")
    case.run("dlmPackSpheres")
    centres, r = read_packing(case.path / "constant" / "packing.dat")
    assert len(centres) == 283

    wall_distance = np.minimum(centres[:, 2] - lower[2], upper[2] - centres[:, 2])
    assert wall_distance.min() >= radius
    # Spheres pushed onto the walls touch them: the walls are at one radius
    assert wall_distance.min() < 1.01 * radius
    assert np.all(centres[:, :2] >= lower[:2]) and np.all(centres[:, :2] < upper[:2])
    assert smallest_distance(centres, lower, upper, (True, True, False)) \
        >= 2 * radius * (1 - 1e-12)


SMALL = """box (0 0 0) (0.01 0.01 0.01);
periodic (yes yes yes);
radius 0.001;
solidFraction 0.5;
"""


def test_seed_reproducibility(tmp_path, foam_env):
    case = pack_case(tmp_path / "case", foam_env, SMALL + 'output "constant/first.dat";')
    case.run("dlmPackSpheres")
    dictionary = case.path / "system" / "packSpheresDict"
    dictionary.write_text(PACK_HEADER + SMALL + 'output "constant/second.dat";')
    case.run("dlmPackSpheres")
    dictionary.write_text(PACK_HEADER + SMALL + 'seed 2; output "constant/third.dat";')
    case.run("dlmPackSpheres")

    constant = case.path / "constant"
    assert (constant / "first.dat").read_bytes() == (constant / "second.dat").read_bytes()
    first, _ = read_packing(constant / "first.dat")
    third, _ = read_packing(constant / "third.dat")
    assert first.shape == third.shape
    # Not merely the same spheres in another order
    assert not np.allclose(np.sort(first, axis=0), np.sort(third, axis=0))


@pytest.mark.parametrize("settings, expected", [
    ("radius 0.001; solidFraction 0.8;",
     ["solidFraction 0.8", "densest packing", "system/packSpheresDict"]),
    ("radius -1; solidFraction 0.5;",
     ["radius -1 must be positive", "system/packSpheresDict"]),
    ("radius 0.001; solidFraction 0.5; nParticles 100;",
     ["exactly one of solidFraction and nParticles", "system/packSpheresDict"]),
    ("radius 0.001; solidFraction 0.5; maxIterations 5;",
     ["Could not reach solid fraction", "Lower solidFraction"]),
])
def test_bad_input(tmp_path, foam_env, settings, expected):
    case = pack_case(tmp_path / "case", foam_env,
                     "box (0 0 0) (0.01 0.01 0.01);\nperiodic (yes yes yes);\n" + settings)
    result = case.run("dlmPackSpheres", check=False)
    assert result.returncode != 0, "dlmPackSpheres accepted bad input"
    for text in expected:
        assert text in result.log, f"'{text}' missing from:\n{result.log[-2000:]}"
    assert not (case.path / "constant" / "packing.dat").exists()


PARTICLES_HEADER = "FoamFile { version 2.0; format ascii; class dictionary; object packParticlesDict; }\n"

MIXED = """box (0 0 0.002) (0.016 0.016 0.034);
periodic (no no no);
gap 0.0003;
particles
{
    ball { number 8; shape sphere; radius 0.002; density 2500; }
    egg { number 8; shape ellipsoid; semiAxes (0.003 0.002 0.0015); density 2500; }
    brick { number 8; shape box; halfExtents (0.0025 0.002 0.0015); density 2500; }
    can { number 8; shape cylinder; radius 0.0015; length 0.004; density 2500; }
}
"""


def particles_case(path, env, settings):
    """A case with system/packParticlesDict holding the given entries."""
    case = Case(path, env)
    (case.path / "system").mkdir(parents=True)
    (case.path / "system" / "controlDict").write_text(CONTROL_DICT)
    (case.path / "system" / "packParticlesDict").write_text(PARTICLES_HEADER + settings)
    return case


def read_particles(path):
    """name -> dict of the entries of each particle written by
    dlmPackParticles (numbers and vectors as float arrays)."""
    particles = {}
    for name, body in re.findall(r"^(\w+)\s*\{(.*?)\}", path.read_text(), flags=re.S | re.M):
        entries = {}
        for key, value in re.findall(r"(\w+)\s+([^;]+);", body):
            numbers = re.findall(r"[-+0-9.eE]+", value)
            entries[key] = value.strip() if key == "shape" else np.array(numbers, dtype=float)
        particles[name] = entries
    return particles


def rotation(q):
    """Rotation matrix, body to global, of the quaternion (w, x, y, z)."""
    w, x, y, z = q
    return np.array([
        [1 - 2*(y*y + z*z), 2*(x*y - w*z), 2*(x*z + w*y)],
        [2*(x*y + w*z), 1 - 2*(x*x + z*z), 2*(y*z - w*x)],
        [2*(x*z - w*y), 2*(y*z + w*x), 1 - 2*(x*x + y*y)],
    ])


def inside(p, r):
    """Whether the body-frame points r (n, 3) are inside particle p."""
    if p["shape"] == "sphere":
        return (r**2).sum(axis=1) < p["radius"][0]**2
    if p["shape"] == "ellipsoid":
        return ((r/p["semiAxes"])**2).sum(axis=1) < 1
    if p["shape"] == "box":
        return np.all(np.abs(r) < p["halfExtents"], axis=1)
    radius, length = p["radius"][0], p["length"][0]
    return (r[:, 0]**2 + r[:, 1]**2 < radius**2) & (np.abs(r[:, 2]) < length/2)


def support(p, u):
    """Largest extent of particle p along the body-frame unit vector u."""
    if p["shape"] == "sphere":
        return p["radius"][0]
    if p["shape"] == "ellipsoid":
        return np.linalg.norm(p["semiAxes"]*u)
    if p["shape"] == "box":
        return np.abs(p["halfExtents"]*u).sum()
    return p["radius"][0]*np.hypot(u[0], u[1]) + p["length"][0]/2*abs(u[2])


def bounding_radius(p):
    """Radius of the smallest sphere about the centroid holding particle p."""
    if p["shape"] == "sphere":
        return p["radius"][0]
    if p["shape"] == "ellipsoid":
        return p["semiAxes"].max()
    if p["shape"] == "box":
        return np.linalg.norm(p["halfExtents"])
    return np.hypot(p["radius"][0], p["length"][0]/2)


def test_mixed_shapes_are_placed_apart_and_inside_the_box(tmp_path, foam_env):
    """32 shapes of four kinds at a solid fraction of 0.16: each at least
    the gap (0.3 mm) inside the walls by its support function, at random
    orientations; no two overlap, tested on a grid of 0.05 mm (every pair
    whose bounding spheres meet: a grid of 50^3 points over their common
    box, none inside both)."""
    case = particles_case(tmp_path / "case", foam_env, MIXED)
    case.run("dlmPackParticles")
    particles = read_particles(case.path / "constant" / "packedParticles")
    assert sorted(particles) == sorted(f"{g}_{i}" for g in ("ball", "egg", "brick", "can")
                                       for i in range(8))
    lower, upper, gap = np.array([0, 0, 0.002]), np.array([0.016, 0.016, 0.034]), 0.0003

    turned = 0
    for name, p in particles.items():
        q = p["orientation"]
        assert abs(np.dot(q, q) - 1) < 1e-12, name
        turned += abs(q[0]) < 0.99
        R = rotation(q)
        for axis in range(3):
            e = np.eye(3)[axis]
            assert p["position"][axis] + support(p, R.T @ e) <= upper[axis] - gap*(1 - 1e-9), name
            assert p["position"][axis] - support(p, -R.T @ e) >= lower[axis] + gap*(1 - 1e-9), name
        assert p["density"][0] == 2500
    assert turned > 20

    names = sorted(particles)
    close = 0
    grid = (np.arange(50) + 0.5)/50
    unit = np.stack(np.meshgrid(grid, grid, grid, indexing="ij"), -1).reshape(-1, 3)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            pa, pb = particles[a], particles[b]
            ra, rb = bounding_radius(pa), bounding_radius(pb)
            xa, xb = pa["position"], pb["position"]
            if np.linalg.norm(xb - xa) >= ra + rb:
                continue
            close += 1
            if pa["shape"] == pb["shape"] == "sphere":
                assert np.linalg.norm(xb - xa) >= ra + rb + gap*(1 - 1e-9)
                continue
            low = np.maximum(xa - ra, xb - rb)
            high = np.minimum(xa + ra, xb + rb)
            points = low + unit*(high - low)
            both = inside(pa, (points - xa) @ rotation(pa["orientation"])) \
                & inside(pb, (points - xb) @ rotation(pb["orientation"]))
            assert not both.any(), (a, b)
    assert close > 10


def test_mixed_shapes_repeat_with_their_seed(tmp_path, foam_env):
    case = particles_case(tmp_path / "case", foam_env, MIXED + 'output "constant/first";')
    case.run("dlmPackParticles")
    dictionary = case.path / "system" / "packParticlesDict"
    dictionary.write_text(PARTICLES_HEADER + MIXED + 'output "constant/second";')
    case.run("dlmPackParticles")
    dictionary.write_text(PARTICLES_HEADER + MIXED + 'seed 2; output "constant/third";')
    case.run("dlmPackParticles")
    constant = case.path / "constant"
    assert (constant / "first").read_bytes() == (constant / "second").read_bytes()
    first, third = read_particles(constant / "first"), read_particles(constant / "third")
    assert sorted(first) == sorted(third)
    assert not np.allclose([first[n]["position"] for n in sorted(first)],
                           [third[n]["position"] for n in sorted(third)])


@pytest.mark.parametrize("settings, expected", [
    (MIXED.replace("number 8; shape sphere", "number 200; shape sphere"),
     ["Could place only", "particle ball_", "found no free place in maxAttempts 10000",
      "Random insertion jams"]),
    (MIXED.replace("number 8; shape sphere", "number 8; position (0 0 0); shape sphere"),
     ["Group ball gives a position", "packParticlesDict"]),
    (MIXED.replace("number 8; shape box", "number 8; orientation upright; shape box"),
     ["orientation upright of group brick", "'random' or a quaternion"]),
    (MIXED.replace("semiAxes", "semiAxis"),
     ["Entry 'semiAxes' not found", "packParticlesDict.particles.egg"]),
    (MIXED.replace("gap 0.0003", "gap -1"), ["gap -1 must not be negative"]),
])
def test_mixed_shapes_bad_input(tmp_path, foam_env, settings, expected):
    case = particles_case(tmp_path / "case", foam_env, settings)
    result = case.run("dlmPackParticles", check=False)
    assert result.returncode != 0, "dlmPackParticles accepted bad input"
    for text in expected:
        assert text in result.log, f"'{text}' missing from:\n{result.log[-2000:]}"
    assert not (case.path / "constant" / "packedParticles").exists()
