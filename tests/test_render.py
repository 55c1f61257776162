"""ParaView after set-up: paraFoam finds paraview, and dlmRender draws a
case headless (pvbatch with its own Xvfb server): the flow on a slice, the
particles as shaded bodies where they are (on the slice or off it)
coloured by their speed, the walls (the mesh's and the contact walls), and
the solid fraction's 0.5 contour; 'moving' picks the written time with the
most particles in motion."""

import pathlib
import shutil

import numpy as np
import pytest

from foamcase import Case

HERE = pathlib.Path(__file__).parent

# The ends of dlmRender's particle speed colour map (bin/dlmRender.py,
# SPEED_COLOURS): at rest a light stone colour, at the largest speed a
# deep red
AT_REST = np.array([0.93, 0.91, 0.85])
FASTEST = np.array([0.62, 0.03, 0.08])


def test_parafoam_finds_paraview(foam_env):
    """paraFoam stopped with 'paraview: not found' before ParaView was part
    of the set-up."""
    path = foam_env["PATH"]
    for program in ("paraFoam", "paraview", "pvbatch", "Xvfb"):
        assert shutil.which(program, path=path), f"{program} not found"


def run_box(tmp_path, foam_env, name, particles=None):
    """The sphereBox case (its sphere, or the particles dictionary given)
    after two steps of 5 ms, written at each."""
    case = Case.copy(HERE / "cases" / "sphereBox", tmp_path / name, foam_env)
    if particles:
        (case.path / "constant" / "particleProperties").write_text(
            "FoamFile { version 2.0; format ascii; class dictionary; "
            "object particleProperties; }\n" + particles)
    case.run("blockMesh")
    case.set("system/controlDict", "endTime", 0.01)
    case.set("system/controlDict", "writeInterval", 1)
    case.run("pimpleDLMFoam")
    return case


def render(case, name, *options, size=600):
    png = case.path / f"{name}.png"
    log = case.run("dlmRender", ".", "--size", size, size, "--output", png, *options,
                   log=f"dlmRender.{name}").log
    assert f"dlmRender: {png}" in log
    import matplotlib.image
    image = matplotlib.image.imread(png)[:, :, :3]
    assert image.shape == (size, size, 3)
    return image


def slice_frame(image):
    """left, right, top, bottom pixel of the slice seen along its normal:
    the longest runs of columns and of rows where most pixels are coloured
    (not those of the colour bars beside it)."""
    coloured = ~(image.min(axis=2) > 0.98)

    def run(counts):
        full = np.flatnonzero(counts > 0.7*counts.max())
        runs = np.split(full, np.flatnonzero(np.diff(full) > 1) + 1)
        longest = max(runs, key=len)
        return longest[0], longest[-1]

    return (*run(coloured.sum(axis=0)), *run(coloured.sum(axis=1)))


def place(frame, x, z, size=(0.03, 0.045)):
    """Pixel column and row of the box's point (x, z) on the slice seen
    along y (x to the right, z up)."""
    left, right, top, bottom = frame
    return left + x/size[0]*(right - left), bottom - z/size[1]*(bottom - top)


def red(image, frame=None):
    """Pixels of the speed map's fast end: red, shaded or lit (the flow's
    Viridis map, the walls and the texts are never this red), within the
    frame (left, right, top, bottom) if given, else left of the colour
    bars (the right fifth of the picture)."""
    found = image[:, :, 0] - image[:, :, 1:].max(axis=2) > 0.12
    inside = np.zeros_like(found)
    if frame is None:
        inside[:, :int(0.8*image.shape[1])] = True
    else:
        inside[frame[2]:frame[3] + 1, frame[0]:frame[1] + 1] = True
    return found & inside


def chromaticity(colour):
    colour = np.asarray(colour, dtype=float)
    return colour/colour.sum(axis=-1, keepdims=True)


def ring(image, column, row, radius):
    """The pixels between 0.3 and 0.6 of radius around (column, row): the
    body's lit face, clear of its highlight and of its rim."""
    y, x = np.mgrid[:image.shape[0], :image.shape[1]]
    r = np.hypot(x - column, y - row)
    return image[(r > 0.3*radius) & (r < 0.6*radius)]


def wall_like(image):
    """Light blue-grey pixels: the translucent walls over the white
    background (not the yellowish grey of the particles at rest)."""
    return ((image[:, :, 2] >= image[:, :, 0])
            & (image.max(axis=2) - image.min(axis=2) < 0.15)
            & (image.mean(axis=2) > 0.55) & (image.mean(axis=2) < 0.97))


def test_render_draws_the_flow_and_the_sphere_where_it_is(tmp_path, foam_env):
    """The sphere (radius 5 mm at x = 15.1 mm, z = 25 mm in the 30 x 45 mm
    section of the box) after two steps, rendered at 600 x 600 along the
    slice's normal: the image has that size, the slice shows many colours,
    and the sphere, the only particle and so the fastest, sits at its place
    in the slice with its diameter, in the fast end's red."""
    case = run_box(tmp_path, foam_env, "render")
    image = render(case, "picture", "--view", "normal")
    colours = {tuple(c) for c in (image.reshape(-1, 3)*255).round().astype(int)}
    assert len(colours) > 50

    frame = slice_frame(image)
    left, right, top, bottom = frame
    width, height = right - left, bottom - top
    assert height/width == pytest.approx(0.045/0.03, rel=0.03)

    y, x = np.nonzero(red(image, frame))
    assert len(x) > 0
    expected_x, expected_y = place(frame, 0.0151, 0.025)
    assert abs(x.mean() - expected_x) < 0.02*width
    assert abs(y.mean() - expected_y) < 0.02*width
    assert x.max() - x.min() == pytest.approx(0.01/0.03*width, rel=0.1)


@pytest.fixture(scope="module")
def two_spheres(tmp_path_factory, foam_env):
    """A sphere held on the slice (radius 5 mm, centre y = 14.9 mm, the
    nearest to the box's middle, so the slice is through it), and a
    smaller one wholly in front of it (radius 4 mm, centre y = 6 mm)
    moving up at 5 cm/s; then the contact settings give a funnel (a cone
    between radius 14 mm at the lid and 4 mm at z = 32 mm about the box's
    axis), added after the run: dlmRender only reads them."""
    case = run_box(tmp_path_factory.mktemp("render"), foam_env, "twoSpheres", """
particles
{
    onSlice
    {
        shape sphere; radius 0.005; density 2000; motion fixed;
        position (0.0151 0.0149 0.025);
    }
    offSlice
    {
        shape sphere; radius 0.004; density 2000; motion prescribed;
        position (0.008 0.006 0.012); velocity (0 0 0.05);
    }
}
""")
    with open(case.path / "constant" / "particleProperties", "a") as dictionary:
        dictionary.write("""
contact
{
    walls
    {
        funnel
        {
            type cone;
            point1 (0.015 0.015 0.045); radius1 0.014;
            point2 (0.015 0.015 0.032); radius2 0.004;
        }
    }
}
""")
    return case


@pytest.fixture(scope="module")
def normal_view(two_spheres):
    return render(two_spheres, "normal", "--view", "normal")


def test_a_particle_off_the_slice_is_drawn_in_its_speed_colour(normal_view):
    """Seen along the slice's normal: the sphere in front of the slice is
    drawn at its place (x = 8 mm, z = 12.5 mm after 10 ms at 5 cm/s) with
    its diameter, in the colour of the fastest speed (it is the faster);
    the sphere held at rest on the slice in the colour of rest."""
    image = normal_view
    frame = slice_frame(image)
    width = frame[1] - frame[0]

    fast = red(image, frame)
    y, x = np.nonzero(fast)
    column, row = place(frame, 0.008, 0.0125)
    assert abs(x.mean() - column) < 0.02*width
    assert abs(y.mean() - row) < 0.02*width
    assert x.max() - x.min() == pytest.approx(0.008/0.03*width, rel=0.1)
    # Nothing red where the resting sphere is
    column, row = place(frame, 0.0151, 0.025)
    assert not fast[int(row), int(column)]

    pixels_per_metre = width/0.03
    moving = np.median(ring(image, *place(frame, 0.008, 0.0125), 0.004*pixels_per_metre),
                       axis=0)
    resting = np.median(ring(image, *place(frame, 0.0151, 0.025), 0.005*pixels_per_metre),
                        axis=0)
    # Shading scales a colour; its chromaticity stays
    assert np.abs(chromaticity(moving) - chromaticity(FASTEST)).max() < 0.06
    assert np.abs(chromaticity(resting) - chromaticity(AT_REST)).max() < 0.03
    assert resting.min() > 0.5


def test_the_contact_walls_profile_is_drawn_on_the_slice(normal_view):
    """Seen along the slice's normal, the funnel's profile on the slice
    (dark grey lines from x = 15 -+ 4 mm at z = 32 mm to 15 -+ 14 mm at
    the lid) crosses the row z = 38.5 mm at x = 15 -+ 9 mm, and no such
    line lies between them."""
    image = normal_view
    frame = slice_frame(image)
    width = frame[1] - frame[0]
    dark_grey = ((image.max(axis=2) - image.min(axis=2) < 0.12)
                 & (image.mean(axis=2) > 0.2) & (image.mean(axis=2) < 0.5))
    _, row = place(frame, 0, 0.0385)
    found = np.flatnonzero(dark_grey[int(round(row))])
    for x in (0.006, 0.024):
        column, _ = place(frame, x, 0.0385)
        assert np.abs(found - column).min() < 0.03*width, (x, found, column)
    inner = [place(frame, x, 0)[0] for x in (0.008, 0.022)]
    assert not ((found > inner[0]) & (found < inner[1])).any()


def test_the_oblique_view_shows_the_walls_and_the_bodies(two_spheres):
    """The default view of a 3D case, from above at an angle: the walls
    (light translucent grey) cover a good part of the picture, which they
    do not with --walls none, and the sphere off the slice is still drawn
    in red."""
    image = render(two_spheres, "oblique")
    bare = render(two_spheres, "bare", "--walls", "none")
    pixels = image.shape[0]*image.shape[1]
    assert wall_like(image).sum() - wall_like(bare).sum() > 0.05*pixels
    assert wall_like(bare).sum() < 0.01*pixels
    assert red(image).sum() > 0.002*pixels
    assert red(bare).sum() > 0.002*pixels


def write_particles(path, speeds):
    """A particle VTK file of particles 25 mm apart in x, with those speeds
    along z."""
    n = len(speeds)
    lines = ["# vtk DataFile Version 3.0", "particles", "ASCII", "DATASET POLYDATA",
             f"POINTS {n} double"]
    lines += [f"{0.025*i} 0 0" for i in range(n)]
    lines += [f"VERTICES {n} {2*n}"] + [f"1 {i}" for i in range(n)]
    lines += [f"POINT_DATA {n}", "SCALARS diameter double 1", "LOOKUP_TABLE default"]
    lines += ["0.01"]*n
    lines += ["VECTORS velocity double"] + [f"0 0 {s}" for s in speeds]
    path.write_text("\n".join(lines) + "\n")


def test_moving_picks_the_time_with_most_particles_in_motion(tmp_path, foam_env):
    """Written times of a discharge: all at rest at 0, then 2, 3 and 1 of
    them moving faster than 5 % of the largest speed (1 m/s; 0.01 m/s is
    at rest), and none left at the end: 'moving' picks 1; 'latest' the
    end."""
    case = Case(tmp_path / "discharge", foam_env)
    particles = case.path / "VTK" / "particles"
    particles.mkdir(parents=True)
    for time, speeds in [("0", [0, 0, 0]), ("0.5", [0.01, 0.3, 1.0]),
                         ("1", [0.2, 0.3, 0.4]), ("1.5", [0.01, 0.5]), ("2", [])]:
        (case.path / time).mkdir()
        write_particles(particles / f"particles_{time}.vtk", speeds)
    log = case.run("dlmRender", ".", "--times", "moving", "latest", "0.5",
                   "--print-times").log
    assert log.split() == ["1", "2", "0.5"]
