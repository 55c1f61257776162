"""dlmPackSpheres: random packings of equal spheres without overlaps at a
requested solid fraction, reproducible from the seed, and clear errors on bad
input."""

import math

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
