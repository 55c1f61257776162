"""The coupling of particles and fluid: heavy and light particles against
their free motion, and results that do not depend on the time step."""

import pathlib

import numpy as np
import pytest

from foamcase import Case

HERE = pathlib.Path(__file__).parent
SPHERE_BOX = HERE / "cases" / "sphereBox"
G = 9.81

# A 10 mm sphere at 6 cells per diameter in a closed box 4 x 4 x 9 diameters,
# 7.5 diameters above the bottom: room for 5 diameters of fall
TALL_BOX = """FoamFile
{
    version     2.0;
    format      ascii;
    class       dictionary;
    object      blockMeshDict;
}
vertices
(
    (0 0 0) (0.04 0 0) (0.04 0.04 0) (0 0.04 0)
    (0 0 0.09) (0.04 0 0.09) (0.04 0.04 0.09) (0 0.04 0.09)
);
blocks ( hex (0 1 2 3 4 5 6 7) (24 24 54) simpleGrading (1 1 1) );
boundary
(
    walls
    {
        type wall;
        faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7));
    }
);
"""


def falling_sphere(tmp_path, env, name, density, end_time, delta_t=5e-4):
    """Water (nu 1e-5, so that the drag over the fall is below 0.5 % of a
    heavy sphere's weight) at rest, the sphere released from rest."""
    case = Case.copy(SPHERE_BOX, tmp_path / name, env)
    (case.path / "system" / "blockMeshDict").write_text(TALL_BOX)
    case.run("blockMesh")
    settings = {
        ("constant/transportProperties", "nu"): 1e-5,
        ("constant/particleProperties", "particles/sphere/density"): density,
        ("constant/particleProperties", "particles/sphere/position"):
            "(0.0201 0.0199 0.075)",
        ("system/controlDict", "deltaT"): delta_t,
        ("system/controlDict", "endTime"): end_time,
        ("system/controlDict", "maxViscousNumber"): 1000,
        ("system/controlDict", "writeInterval"): 1000,
    }
    for (file, entry), value in settings.items():
        case.set(file, entry, value)
    case.run("pimpleDLMFoam")
    return case.history()["sphere"]


def test_a_sphere_1000_times_as_heavy_as_water_falls_freely(tmp_path, foam_env):
    """Over 5 diameters of fall its velocity stays within 1 % of g t: drag
    and added mass are below 0.5 % of its weight. The solid mass a moving
    particle takes into a cell used to keep that cell's fluid velocity, and
    the mixture's convection acted on the solid: 27 % below g t after 0.1 s."""
    h = falling_sphere(tmp_path, foam_env, "rho1e6", 1e6, 0.1)
    t, z, uz = h[1:, 0], h[1:, 3], h[1:, 6]
    fall = h[0, 3] - z[-1]
    assert fall > 0.048
    assert fall == pytest.approx(G*t[-1]**2/2, rel=0.01)
    assert np.all(np.abs(uz/(-G*t) - 1) < 0.01)
    assert np.abs(h[:, 4:6]).max() < 0.01*abs(uz[-1])


def test_the_early_fluid_force_on_a_heavy_sphere_does_not_grow_with_its_density(
        tmp_path, foam_env):
    """The fluid force on spheres 100 and 1000 times as heavy as water, over
    their first 0.03 s (the same motion to 3 %), is the fluid's: the same
    for both (5 % in the mean, 30 % at each step: the crossing of cells
    differs), and below 5 % of the lighter one's weight.
    It was proportional to the solid density (0.8 N on the heavier, 160
    times its drag, after 0.03 s)."""
    forces = {}
    for density in (1e5, 1e6):
        h = falling_sphere(tmp_path, foam_env, f"rho{density:g}", density, 0.03)
        forces[density] = h[1:, 12]
    weight = 1e5*np.pi/6*0.01**3*G
    assert np.abs(forces[1e5]).max() < 0.05*weight
    assert forces[1e6].mean() == pytest.approx(forces[1e5].mean(), rel=0.05)
    assert np.abs(forces[1e6] - forces[1e5]).max() < 0.3*forces[1e5].max()
