"""Render a pimpleDLMFoam case with ParaView (run by dlmRender through
pvbatch): a slice of the flow coloured by the velocity magnitude, the
particles as their true shapes (spheres of their diameter, disks seen from
the front in 2D, from the particle VTK series; other shapes from the
surfaces the solvers write beside it), and the solid fraction's 0.5
contour on the slice, at chosen written times; optionally one frame per
written time for an animation.

The slice is normal to y through the first particle's centre in 3D (to z in
2D, the plane of the mesh); the camera looks along its normal with a
parallel projection, framing the slice. Particles are drawn flat in one
colour (magenta by default) so that they stand out of the colour map; the
contour (white) is lifted towards the camera by the largest radius, so
that the particles in front of the slice do not hide it."""

import argparse
import pathlib
import re

from paraview import simple as pv


def parse():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("case", type=pathlib.Path)
    parser.add_argument("--times", nargs="*", default=["latest"],
                        help="written times to render (default: the latest)")
    parser.add_argument("--frames", action="store_true",
                        help="also one frame per written time, in <case>/render/frames")
    parser.add_argument("--output", type=pathlib.Path,
                        help="PNG of a single time (default <case>/render/<case>_<time>.png)")
    parser.add_argument("--size", type=int, nargs=2, default=[800, 800], metavar=("W", "H"))
    parser.add_argument("--particle-colour", type=float, nargs=3, default=[1.0, 0.0, 1.0])
    return parser.parse_args()


def decomposed(case):
    """Whether the case's results are only in its processor directories."""
    return (case / "processor0").is_dir() and \
        len(time_directories(case / "processor0")) > len(time_directories(case))


def written_times(case):
    """(value, name) of the written times, sorted."""
    return time_directories(case / "processor0" if decomposed(case) else case)


def time_directories(case):
    times = []
    for entry in case.iterdir():
        if entry.is_dir() and re.fullmatch(r"[0-9.eE+-]+", entry.name):
            try:
                times.append((float(entry.name), entry.name))
            except ValueError:
                pass
    return sorted(times)


def first_particle(vtk_file):
    """Centre and diameter of the first particle of a particle VTK file."""
    lines = vtk_file.read_text().splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("POINTS"))
    if int(lines[start].split()[1]) == 0:
        return None, None
    centre = [float(v) for v in lines[start + 1].split()]
    k = next(i for i, line in enumerate(lines) if line.startswith("SCALARS diameter"))
    return centre, float(lines[k + 2])


class Scene:
    def __init__(self, case, args):
        self.case = case
        foam = case / f"{case.name}.foam"
        foam.touch()
        self.reader = pv.OpenFOAMReader(FileName=str(foam))
        self.reader.MeshRegions = ["internalMesh"]
        self.reader.CellArrays = ["U", "alpha.solid"]
        # A decomposed run not reconstructed has its times in processor*
        self.reader.CaseType = (
            "Decomposed Case" if decomposed(case) else "Reconstructed Case")
        self.reader.UpdatePipeline(written_times(case)[-1][0])
        bounds = self.reader.GetDataInformation().GetBounds()
        self.bounds = bounds
        span = [bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]]
        # A one-cell-thick mesh is 2D: look at its plane
        self.twoD = span[2] < 0.05*min(span[0], span[1])
        self.view = pv.CreateView("RenderView")
        self.view.ViewSize = args.size
        self.view.OrientationAxesVisibility = 0
        self.view.CameraParallelProjection = 1
        self.view.Background = [1, 1, 1]
        try:
            self.view.UseColorPaletteForBackground = 0
        except AttributeError:
            pass
        self.colour = args.particle_colour

    def render(self, time_name, time_value, png):
        case = self.case
        vtk = case / "VTK" / "particles" / f"particles_{time_name}.vtk"
        centre, diameter = None, 0.0
        if vtk.exists():
            centre, diameter = first_particle(vtk)
        b = self.bounds
        mid = [0.5*(b[0] + b[1]), 0.5*(b[2] + b[3]), 0.5*(b[4] + b[5])]
        origin = list(centre) if centre else mid
        normal = [0, 0, 1] if self.twoD else [0, 1, 0]
        if self.twoD:
            origin[2] = mid[2]

        for source in list(pv.GetSources().values()):
            if source is not self.reader:
                pv.Delete(source)
        self.view.ViewTime = time_value
        self.reader.UpdatePipeline(time_value)

        cut = pv.Slice(Input=self.reader)
        cut.SliceType = "Plane"
        cut.SliceType.Origin = origin
        cut.SliceType.Normal = normal
        flow = pv.Show(cut, self.view)
        pv.ColorBy(flow, ("CELLS", "U", "Magnitude"))
        lut = pv.GetColorTransferFunction("U")
        lut.ApplyPreset("Viridis (matplotlib)", True)
        flow.RescaleTransferFunctionToDataRange(True, False)
        flow.SetScalarBarVisibility(self.view, True)
        bar = pv.GetScalarBar(lut, self.view)
        bar.Title = "|U| [m/s]"
        bar.ComponentTitle = ""
        bar.TitleColor = bar.LabelColor = [0, 0, 0]

        points = pv.CellDatatoPointData(Input=cut)
        points.CellDataArraytoprocess = ["alpha.solid"]
        surface = pv.Contour(Input=points, ContourBy=["POINTS", "alpha.solid"], Isosurfaces=[0.5])
        lifted = pv.Transform(Input=surface)
        lifted.Transform = "Transform"
        lifted.Transform.Translate = [0.51*(diameter or 0.0)*n for n in normal]
        outline = pv.Show(lifted, self.view)
        outline.ColorArrayName = ["POINTS", ""]
        outline.AmbientColor = outline.DiffuseColor = [1, 1, 1]
        outline.LineWidth = 2

        surfaces = vtk.with_name(f"surfaces_{time_name}.vtk")
        if surfaces.exists():
            # Shapes that are not round: their surfaces as written
            drawn = pv.LegacyVTKReader(FileNames=[str(surfaces)])
        elif vtk.exists():
            particles = pv.LegacyVTKReader(FileNames=[str(vtk)])
            drawn = pv.Glyph(Input=particles, GlyphType="Sphere")
            drawn.ScaleArray = ["POINTS", "diameter"]
            drawn.ScaleFactor = 1.0
            drawn.GlyphMode = "All Points"
            drawn.GlyphType.ThetaResolution = 48
            drawn.GlyphType.PhiResolution = 24
        if surfaces.exists() or vtk.exists():
            shapes = pv.Show(drawn, self.view)
            shapes.ColorArrayName = ["POINTS", ""]
            shapes.AmbientColor = shapes.DiffuseColor = self.colour
            shapes.Ambient = 1.0
            shapes.Diffuse = 0.0

        label = pv.Text(Text=f"{self.case.name}   t = {time_value:g} s")
        caption = pv.Show(label, self.view)
        caption.Color = [0, 0, 0]
        caption.FontSize = 14
        caption.WindowLocation = "Upper Left Corner"

        # Look along the slice's normal, from its positive side
        focal = origin
        self.view.CameraFocalPoint = focal
        self.view.CameraPosition = [focal[i] + normal[i] for i in range(3)]
        self.view.CameraViewUp = [0, 1, 0] if self.twoD else [0, 0, 1]
        self.view.ResetCamera(False)
        pv.SaveScreenshot(str(png), self.view, ImageResolution=self.view.ViewSize)
        print(f"dlmRender: {png}")


def main():
    args = parse()
    case = args.case.resolve()
    times = written_times(case)
    if not times:
        raise SystemExit(f"dlmRender: no written time in {case}")
    scene = Scene(case, args)
    out = case / "render"
    chosen = times[-1:] if args.times == ["latest"] else \
        [t for t in times if t[1] in args.times or str(t[0]) in args.times]
    missing = set(args.times) - {"latest"} - {t[1] for t in chosen} - {str(t[0]) for t in chosen}
    if missing:
        raise SystemExit(f"dlmRender: no written time {' '.join(sorted(missing))} in {case}")
    for value, name in chosen:
        png = args.output if args.output and len(chosen) == 1 else out / f"{case.name}_{name}.png"
        png.parent.mkdir(parents=True, exist_ok=True)
        scene.render(name, value, png)
    if args.frames:
        (out / "frames").mkdir(parents=True, exist_ok=True)
        for k, (value, name) in enumerate(times):
            scene.render(name, value, out / "frames" / f"{case.name}_{k:04d}.png")


main()
