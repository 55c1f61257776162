"""Render a pimpleDLMFoam case with ParaView (run by dlmRender through
pvbatch): a slice of the flow coloured by the velocity magnitude, the
particles as shaded 3D bodies of their true shapes coloured by their speed
(a second colour map with its own bar), the walls as light translucent
surfaces, and the solid fraction's 0.5 contour on the slice, at chosen
written times; optionally one frame per written time for an animation.

The particles: spheres of their diameter from the particle VTK series
(VTK/particles/particles_<time>.vtk, by glyphs), the shapes that are not
round from the surfaces the solvers write beside it (surfaces_<time>.vtk),
each coloured by its particle's speed (the speed of its centre) on one
scale for all the times of a run, from rest to the largest speed written;
when no particle ever moves (a fixed bed) they are drawn in the scale's
colour of rest and the bar is left out.

The walls: the mesh's wall patches, and the contact-only walls of the
'contact' dictionary of constant/particleProperties (plane, cylinder,
cone: clipped to the mesh's bounding box; surface: its file in
constant/triSurface; patches: those patches of the mesh), read through
foamDictionary -expand (macros and includes as the solvers see them).
When the contact settings say meshWalls false and give walls of their
own, those stand for the mesh's (the castellated steps of a mesh that the
particles do not see); --walls chooses otherwise. In 3D they are light
translucent glass, the more opaque where seen edge-on, so that a wall
facing the camera hides little and a curved wall shows its outline; the
walls whose faces turn away from the particles (the mesh's, the planes)
are cut away where they face the camera: a box shows its floor and far
sides, not its lid and near sides. Their profiles on the slice are dark
grey lines (in 2D, seen edge-on, the profiles only).

The slice: in 2D (a one-cell-thick mesh) the plane of the mesh, seen
along its normal with a parallel projection. In 3D, a plane containing the
vertical (the axis of gravity, z without gravity), normal to y (to x when
gravity is along y), through the centre of the particle nearest the mesh's
middle (with one particle, the plane follows it from frame to frame; with
several, the frames keep the plane of the first picture); the camera looks
at the scene from the slice's front side at an oblique angle, from above,
with a perspective projection, so that the bodies in front of the slice
show as 3D (--view normal: along the slice's normal, parallel projection,
as in 2D).

Times: --times takes written times, 'latest' (the default) and 'moving':
the written time with the most particles in motion (faster than 5 % of the
largest particle speed of the run; of equal counts the latest), so that a
run whose particles all leave (a discharge) is drawn while they flow."""

import argparse
import math
import pathlib
import re
import shutil
import subprocess
import sys

# The pictures' colours: the particles' speed from rest (a light stone
# colour) through orange to a deep red; the walls a light blue-grey
SPEED_COLOURS = [0.0, 0.93, 0.91, 0.85,
                 0.5, 0.98, 0.58, 0.22,
                 1.0, 0.62, 0.03, 0.08]
WALL_COLOUR = [0.62, 0.68, 0.76]
# The walls' opacity where they face the camera and where seen edge-on
WALL_OPACITY = [0.08, 0.6]
PROFILE_COLOUR = [0.3, 0.33, 0.38]
MOVING = 0.05


def parse():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("case", type=pathlib.Path)
    parser.add_argument("--times", nargs="*", default=["latest"],
                        help="written times to render, 'latest' (the default) or "
                             "'moving' (the written time with the most particles in motion)")
    parser.add_argument("--frames", action="store_true",
                        help="also one frame per written time, in <case>/render/frames")
    parser.add_argument("--output", type=pathlib.Path,
                        help="PNG of a single time (default <case>/render/<case>_<time>.png)")
    parser.add_argument("--size", type=int, nargs=2, default=[800, 800], metavar=("W", "H"))
    parser.add_argument("--view", choices=["auto", "oblique", "normal"], default="auto",
                        help="3D: 'oblique' (the default) or 'normal' (along the slice's "
                             "normal); 2D cases are always seen along the mesh's normal")
    parser.add_argument("--walls", choices=["auto", "all", "mesh", "contact", "none"],
                        default="auto",
                        help="walls drawn: the mesh's wall patches and the contact walls "
                             "('auto', the default: the mesh's left out when the contact "
                             "settings say meshWalls false and give walls of their own)")
    parser.add_argument("--no-walls", dest="walls", action="store_const", const="none",
                        help="leave the walls out (--walls none)")
    parser.add_argument("--print-times", action="store_true",
                        help="print the times that would be rendered, and stop")
    return parser.parse_args()


# -- The case: times, particles, walls (plain Python) ------------------------

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


def read_legacy_points(vtk_file):
    """Points and point data of an ASCII legacy VTK file of points (the
    particle series): (points, {name: values}), values a list of floats
    (scalars) or of tuples (vectors, multi-component scalars)."""
    tokens = vtk_file.read_text().split()
    points, data, i, n = [], {}, 0, 0

    def numbers(count):
        nonlocal i
        values = [float(v) for v in tokens[i:i + count]]
        i += count
        return values

    while i < len(tokens):
        word = tokens[i]
        if word == "POINTS":
            n = int(tokens[i + 1])
            i += 3
            flat = numbers(3*n)
            points = [tuple(flat[3*k:3*k + 3]) for k in range(n)]
        elif word in ("VERTICES", "LINES", "POLYGONS"):
            i += 3 + int(tokens[i + 2])
        elif word == "SCALARS":
            name = tokens[i + 1]
            components = 1
            i += 3
            if i < len(tokens) and re.fullmatch(r"[0-9]+", tokens[i]):
                components = int(tokens[i])
                i += 1
            if tokens[i] == "LOOKUP_TABLE":
                i += 2
            flat = numbers(components*n)
            data[name] = flat if components == 1 else \
                [tuple(flat[components*k:components*k + components]) for k in range(n)]
        elif word in ("VECTORS", "NORMALS"):
            name = tokens[i + 1]
            i += 3
            flat = numbers(3*n)
            data[name] = [tuple(flat[3*k:3*k + 3]) for k in range(n)]
        else:
            i += 1
    return points, data


class Particles:
    """The particles written at one time (none when no file was written)."""

    def __init__(self, case, time_name):
        self.file = case / "VTK" / "particles" / f"particles_{time_name}.vtk"
        self.surfaces = self.file.with_name(f"surfaces_{time_name}.vtk")
        self.centres, self.diameters, self.speeds = [], [], []
        if self.file.exists():
            self.centres, data = read_legacy_points(self.file)
            self.diameters = data.get("diameter", [0.0]*len(self.centres))
            self.speeds = [math.sqrt(sum(c*c for c in v))
                           for v in data.get("velocity", [(0, 0, 0)]*len(self.centres))]

    def __len__(self):
        return len(self.centres)


def choose_times(case, times, requested):
    """The written times asked for: names or values, 'latest', 'moving'."""
    chosen, missing = [], []
    for request in requested:
        if request == "latest":
            found = [times[-1]]
        elif request == "moving":
            found = [most_moving(case, times)]
        else:
            found = [t for t in times if request in (t[1], str(t[0]))]
            if not found:
                try:
                    found = [t for t in times if t[0] == float(request)]
                except ValueError:
                    pass
        if not found:
            missing.append(request)
        chosen += [t for t in found if t not in chosen]
    if missing:
        raise SystemExit(f"dlmRender: no written time {' '.join(missing)} in {case}")
    return chosen


def most_moving(case, times):
    """The written time with the most particles faster than MOVING of the
    largest particle speed of all written times (of equal counts the
    latest; the latest time when no particle ever moves)."""
    speeds = {t: Particles(case, t[1]).speeds for t in times}
    fastest = max((max(s) for s in speeds.values() if s), default=0.0)
    if fastest <= 0:
        return times[-1]
    return max(times, key=lambda t: (sum(s > MOVING*fastest for s in speeds[t]), t[0]))


def largest_speed(case, times):
    return max((max(p.speeds) for p in (Particles(case, t[1]) for t in times) if len(p)),
               default=0.0)


def up_axis(case, two_d):
    """The axis of gravity (the largest component of constant/g), z without
    gravity (y in 2D)."""
    g = case / "constant" / "g"
    if g.exists():
        match = re.search(r"value\s*\(\s*([^)]*)\)", strip_comments(g.read_text()))
        if match:
            values = [abs(float(v)) for v in match.group(1).split()]
            if len(values) == 3 and max(values) > 0:
                return values.index(max(values))
    return 1 if two_d else 2


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def tokenise(text):
    return re.findall(r'"[^"]*"|[{}();\[\]]|[^\s{}();"\[\]]+', strip_comments(text))


def parse_dictionary(tokens, i=0, scopes=(), directory=None):
    """An OpenFOAM dictionary from tokens[i:] up to its closing brace: a
    dict of keyword to value (a number, a word or string, a list, a dict).
    Later dictionaries of the same name merge into earlier ones. Without
    foamDictionary: #include(IfPresent) relative to directory, #remove and
    $name of an enclosing scope are followed too."""
    d = {}
    scopes = (d,) + tuple(scopes)
    while i < len(tokens) and tokens[i] != "}":
        key = tokens[i]
        i += 1
        if key in ("#include", "#includeIfPresent", "#sinclude", "#includeEtc"):
            name = tokens[i].strip('"')
            i += 1
            path = pathlib.Path(name) if directory is None else directory / name
            if key != "#includeEtc" and path.exists():
                merge(d, parse_dictionary(tokenise(path.read_text()), 0, scopes,
                                          path.parent)[0])
            continue
        if key == "#remove":
            value, i = parse_value(tokens, i, scopes)
            for name in value if isinstance(value, list) else [value]:
                d.pop(name, None)
            continue
        if key.startswith("#"):
            # other directives (#inputMode ...): their word
            i += 1 if i < len(tokens) and tokens[i] not in ("{", "}", ";") else 0
            continue
        if i < len(tokens) and tokens[i] == "{":
            sub, i = parse_dictionary(tokens, i + 1, scopes, directory)
            i += 1
            if isinstance(d.get(key), dict):
                merge(d[key], sub)
            else:
                d[key] = sub
            continue
        if key.startswith("$") and i < len(tokens) and tokens[i] == ";":
            # $dictionary; the entries of another dictionary
            found = lookup(key[1:], scopes)
            if isinstance(found, dict):
                merge(d, found)
            i += 1
            continue
        values = []
        while i < len(tokens) and tokens[i] not in (";", "}"):
            value, i = parse_value(tokens, i, scopes)
            values.append(value)
        if i < len(tokens) and tokens[i] == ";":
            i += 1
        d[key] = values[0] if len(values) == 1 else values
    return d, i


def parse_value(tokens, i, scopes):
    token = tokens[i]
    if token in ("(", "["):
        close = ")" if token == "(" else "]"
        values, i = [], i + 1
        while i < len(tokens) and tokens[i] != close:
            value, i = parse_value(tokens, i, scopes)
            values.append(value)
        return values, i + 1
    if token.startswith("$"):
        found = lookup(token[1:].strip("{}"), scopes)
        if found is not None:
            return found, i + 1
    try:
        return float(token), i + 1
    except ValueError:
        return token.strip('"'), i + 1


def lookup(name, scopes):
    for scope in scopes:
        if name in scope:
            return scope[name]
    return None


def merge(into, other):
    for key, value in other.items():
        if isinstance(value, dict) and isinstance(into.get(key), dict):
            merge(into[key], value)
        else:
            into[key] = value


def read_dictionary(path):
    """The dictionary of a file as the solvers read it: by foamDictionary
    -expand where OpenFOAM is set up, else by parse_dictionary."""
    if not path.exists():
        return {}
    text = None
    if shutil.which("foamDictionary"):
        result = subprocess.run(["foamDictionary", "-expand", str(path)],
                                capture_output=True, text=True)
        if result.returncode == 0 and "FOAM FATAL" not in result.stdout:
            text = result.stdout
    if text is None:
        return parse_dictionary(tokenise(path.read_text()), 0, (), path.parent)[0]
    return parse_dictionary(tokenise(text))[0]


def patches(case):
    """(name, type) of the mesh's patches (constant/polyMesh/boundary, of
    processor0 in a decomposed case)."""
    for root in (case, case / "processor0"):
        boundary = root / "constant" / "polyMesh" / "boundary"
        if boundary.exists():
            text = strip_comments(boundary.read_text(errors="replace"))
            text = text[text.index("}") + 1:] if "FoamFile" in text else text
            return re.findall(r'"?([^\s{}()";]+)"?\s*\{[^{}]*?\btype\s+(\w+)\s*;', text)
    return []


# -- Wall geometry (VTK) ------------------------------------------------------

def vector(value):
    return [float(v) for v in value]


def unit(v):
    n = math.sqrt(sum(c*c for c in v))
    return [c/n for c in v] if n > 0 else list(v)


def dot(a, b):
    return sum(x*y for x, y in zip(a, b))


def cross(a, b):
    return [a[1]*b[2] - a[2]*b[1], a[2]*b[0] - a[0]*b[2], a[0]*b[1] - a[1]*b[0]]


def add(a, b, s=1.0):
    return [x + s*y for x, y in zip(a, b)]


def box_corners(bounds):
    return [[bounds[0 + i], bounds[2 + j], bounds[4 + k]]
            for i in (0, 1) for j in (0, 1) for k in (0, 1)]


def polydata(points, polygons):
    """A vtkPolyData of points and polygons (lists of point indices)."""
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    pts = vtkPoints()
    for p in points:
        pts.InsertNextPoint(*p)
    cells = vtkCellArray()
    for polygon in polygons:
        cells.InsertNextCell(len(polygon))
        for k in polygon:
            cells.InsertCellPoint(k)
    data = vtkPolyData()
    data.SetPoints(pts)
    data.SetPolys(cells)
    return data


def plane_polygon(point, normal, bounds):
    """The plane's part inside the box bounds, a polygon facing along
    -normal (away from the particles, as a wall of the mesh faces)."""
    n = unit(normal)
    corners = box_corners(bounds)
    edges = [(a, b) for a in range(8) for b in range(a + 1, 8)
             if sum(x != y for x, y in zip(corners[a], corners[b])) == 1]
    found = []
    for a, b in edges:
        da = dot(add(corners[a], point, -1), n)
        db = dot(add(corners[b], point, -1), n)
        if (da <= 0 <= db or db <= 0 <= da) and da != db:
            s = da/(da - db)
            p = add(corners[a], add(corners[b], corners[a], -1), s)
            if all(math.dist(p, q) > 1e-9*math.dist(bounds[0::2], bounds[1::2])
                   for q in found):
                found.append(p)
    if len(found) < 3:
        return None
    centre = [sum(p[i] for p in found)/len(found) for i in range(3)]
    e1 = unit(add(found[0], centre, -1))
    e2 = cross(n, e1)
    found.sort(key=lambda p: -math.atan2(dot(add(p, centre, -1), e2),
                                         dot(add(p, centre, -1), e1)))
    return polydata(found, [list(range(len(found)))])


def revolution(point1, radius1, point2, radius2, resolution=96):
    """The conical (cylindrical) surface between two circles."""
    a = unit(add(point2, point1, -1))
    helper = [1, 0, 0] if abs(a[0]) < 0.9 else [0, 1, 0]
    e1 = unit(cross(a, helper))
    e2 = cross(a, e1)
    points, polygons = [], []
    for k in range(resolution):
        phi = 2*math.pi*k/resolution
        radial = add([math.cos(phi)*c for c in e1], [math.sin(phi)*c for c in e2])
        points.append(add(point1, radial, radius1))
        points.append(add(point2, radial, radius2))
    for k in range(resolution):
        j = (k + 1) % resolution
        polygons.append([2*k, 2*j, 2*j + 1, 2*k + 1])
    return polydata(points, polygons)


def clip_to_box(data, bounds):
    """The part of a surface inside the box bounds (a little enlarged)."""
    from vtkmodules.vtkCommonDataModel import vtkPlane
    from vtkmodules.vtkFiltersCore import vtkClipPolyData
    margin = 1e-6*math.dist(bounds[0::2], bounds[1::2])
    for axis in range(3):
        for side, sign in ((bounds[2*axis] - margin, 1), (bounds[2*axis + 1] + margin, -1)):
            plane = vtkPlane()
            origin = [0.0, 0.0, 0.0]
            origin[axis] = side
            normal = [0.0, 0.0, 0.0]
            normal[axis] = sign
            plane.SetOrigin(origin)
            plane.SetNormal(normal)
            clip = vtkClipPolyData()
            clip.SetInputData(data)
            clip.SetClipFunction(plane)
            clip.Update()
            data = clip.GetOutput()
    return data


def contact_settings(case):
    """The 'contact' dictionary of constant/particleProperties ({} without)."""
    properties = read_dictionary(case / "constant" / "particleProperties")
    contact = properties.get("contact")
    return contact if isinstance(contact, dict) else {}


def contact_walls(contact, case, bounds):
    """(name, vtkPolyData, whether it faces away from the particles) of
    the contact-only walls of the contact settings, and the patch names
    (regular expressions) of its 'patches' walls."""
    walls = contact.get("walls", {})
    surfaces, patch_names = [], []
    if not isinstance(walls, dict):
        return surfaces, patch_names
    corners = box_corners(bounds)
    for name, wall in walls.items():
        if not isinstance(wall, dict):
            continue
        kind = wall.get("type")
        try:
            if kind == "plane":
                data = plane_polygon(vector(wall["point"]), vector(wall["normal"]), bounds)
                if data is not None:
                    surfaces.append((name, data, True))
            elif kind == "cylinder":
                # Infinite: across the mesh's bounding box
                p, a = vector(wall["point"]), unit(vector(wall["axis"]))
                along = [dot(add(c, p, -1), a) for c in corners]
                r = float(wall["radius"])
                data = revolution(add(p, a, min(along)), r, add(p, a, max(along)), r)
                surfaces.append((name, clip_to_box(data, bounds), False))
            elif kind == "cone":
                data = revolution(vector(wall["point1"]), float(wall["radius1"]),
                                  vector(wall["point2"]), float(wall["radius2"]))
                surfaces.append((name, clip_to_box(data, bounds), False))
            elif kind == "surface":
                data = read_surface(case / "constant" / "triSurface" / str(wall["file"]),
                                    float(wall.get("scale", 1.0)))
                if data is not None:
                    surfaces.append((name, data, False))
            elif kind == "patches":
                # Without a list: the wall-type patches, drawn anyway
                listed = wall.get("patches", [])
                patch_names += [str(p) for p in listed] if isinstance(listed, list) \
                    else [str(listed)]
        except (KeyError, TypeError, ValueError) as error:
            print(f"dlmRender: contact wall {name} not drawn ({error!r})", file=sys.stderr)
    return surfaces, patch_names


def read_surface(path, scale):
    """A triangulated surface file (STL, OBJ, VTK), scaled."""
    from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
    from vtkmodules.vtkCommonTransforms import vtkTransform
    from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
    from vtkmodules.vtkIOLegacy import vtkPolyDataReader
    readers = {".stl": vtkSTLReader, ".obj": vtkOBJReader, ".vtk": vtkPolyDataReader}
    reader = readers.get(path.suffix.lower())
    if reader is None or not path.exists():
        print(f"dlmRender: surface {path} not drawn (missing, or not STL/OBJ/VTK)",
              file=sys.stderr)
        return None
    reader = reader()
    reader.SetFileName(str(path))
    transform = vtkTransform()
    transform.Scale(scale, scale, scale)
    scaled = vtkTransformPolyDataFilter()
    scaled.SetInputConnection(reader.GetOutputPort())
    scaled.SetTransform(transform)
    scaled.Update()
    return scaled.GetOutput()


def particle_surfaces(particles):
    """The particles' surfaces file with each face's particle's speed
    (the speed of its centre: the file's velocity is that of the face's
    centre, which a rotation adds to)."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray
    from vtkmodules.vtkIOLegacy import vtkPolyDataReader
    reader = vtkPolyDataReader()
    reader.SetFileName(str(particles.surfaces))
    reader.Update()
    data = reader.GetOutput()
    ids = data.GetCellData().GetArray("id")
    speed = vtkDoubleArray()
    speed.SetName("speed")
    speed.SetNumberOfTuples(data.GetNumberOfCells())
    for i in range(data.GetNumberOfCells()):
        k = int(ids.GetTuple1(i)) if ids else 0
        speed.SetValue(i, particles.speeds[k] if k < len(particles.speeds) else 0.0)
    data.GetCellData().AddArray(speed)
    return data


# -- The picture (ParaView) ---------------------------------------------------

class Scene:
    def __init__(self, case, args, fastest):
        from paraview import simple as pv
        from vtkmodules.vtkCommonCore import vtkLogger
        # Not the filters' notes (INFO), on every picture
        vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_WARNING)
        self.pv = pv
        self.case = case
        self.args = args
        self.fastest = fastest
        foam = case / f"{case.name}.foam"
        foam.touch()
        case_type = "Decomposed Case" if decomposed(case) else "Reconstructed Case"
        self.reader = pv.OpenFOAMReader(FileName=str(foam))
        self.reader.MeshRegions = ["internalMesh"]
        self.reader.CellArrays = ["U", "alpha.solid"]
        self.reader.SkipZeroTime = 0
        # A decomposed run not reconstructed has its times in processor*
        self.reader.CaseType = case_type
        self.reader.UpdatePipeline(written_times(case)[-1][0])
        b = self.reader.GetDataInformation().GetBounds()
        self.bounds = list(b)
        span = [b[1] - b[0], b[3] - b[2], b[5] - b[4]]
        self.size = math.sqrt(sum(s*s for s in span))
        self.middle = [0.5*(b[0] + b[1]), 0.5*(b[2] + b[3]), 0.5*(b[4] + b[5])]
        # A one-cell-thick mesh is 2D: look at its plane
        self.twoD = span[2] < 0.05*min(span[0], span[1])
        self.up = up_axis(case, self.twoD)
        if self.twoD:
            self.normal_axis = 2
        else:
            self.normal_axis = 0 if self.up == 1 else 1
        self.oblique = not self.twoD and args.view != "normal"
        self.slice_at = None
        normal = [0.0, 0.0, 0.0]
        normal[self.normal_axis] = 1.0
        self.normal = normal
        self.up_vector = [0.0, 0.0, 0.0]
        self.up_vector[self.up] = 1.0
        # The camera on the slice's front side: +z in 2D, -y (-x) in 3D
        self.towards_camera = normal if self.twoD else [-c for c in normal]
        if self.oblique:
            # 25 degrees above the slice's normal, turned 30 degrees about
            # the vertical: the bodies show as 3D
            side = cross(self.up_vector, self.towards_camera)
            elevation, azimuth = math.radians(25), math.radians(30)
            self.direction = [
                math.cos(elevation)*(math.cos(azimuth)*c + math.sin(azimuth)*s)
                + math.sin(elevation)*u
                for c, s, u in zip(self.towards_camera, side, self.up_vector)]
        else:
            self.direction = self.towards_camera

        self.view = pv.CreateView("RenderView")
        self.view.ViewSize = args.size
        self.view.OrientationAxesVisibility = 0
        self.view.CameraParallelProjection = 0 if self.oblique else 1
        self.view.Background = [1, 1, 1]
        try:
            self.view.UseColorPaletteForBackground = 0
        except AttributeError:
            pass
        # The proxies of one picture, deleted before the next
        self.transient = []
        self.walls = self.make_walls()

    def make_walls(self):
        """The sources of the walls drawn: the mesh's wall patches (unless
        the contact settings say meshWalls false and give walls of their
        own, which then stand for them, as a castellated mesh's steps) and
        the contact-only walls; in 3D shown once as light translucent glass
        (they do not move), the more opaque where seen edge-on. Their
        profiles on the slice are drawn with each picture."""
        pv = self.pv
        which = self.args.walls
        if which == "none":
            return []
        contact = contact_settings(self.case)
        surfaces, listed = contact_walls(contact, self.case, self.bounds) \
            if which in ("auto", "all", "contact") else ([], [])
        mesh_walls = which in ("all", "mesh") or (
            which == "auto" and not (surfaces and contact.get("meshWalls") in
                                     ("false", "no", "off", "none", 0.0)))
        all_patches = patches(self.case)
        names = [name for name, kind in all_patches if kind == "wall"] if mesh_walls else []
        names += [name for name, _ in all_patches
                  if name not in names and any(re.fullmatch(p, name) for p in listed)]
        sources = []
        if names:
            reader = pv.OpenFOAMReader(FileName=self.reader.FileName)
            available = list(reader.MeshRegions.Available)
            regions = [f"patch/{n}" if f"patch/{n}" in available else n for n in names]
            reader.MeshRegions = [r for r in regions if r in available]
            reader.CellArrays = []
            reader.SkipZeroTime = 0
            reader.CaseType = self.reader.CaseType
            if reader.MeshRegions:
                merged = pv.MergeBlocks(Input=reader)
                sources.append((pv.ExtractSurface(Input=merged), True))
        for name, data, outward in surfaces:
            source = pv.TrivialProducer(registrationName=f"wall {name}")
            source.GetClientSideObject().SetOutput(data)
            sources.append((source, outward))
        if self.twoD:
            # Seen edge-on: their profiles only
            return [source for source, _ in sources]

        # Glass: opaque in proportion to how much the wall is seen edge-on
        # (1 - |n.d|, d the viewing direction), so that a wall facing the
        # camera hides little and curved walls show their outlines. Walls
        # whose faces are turned away from the particles (the mesh's, the
        # planes) are cut away where they face the camera: a box shows its
        # floor and far sides, not its lid and near sides
        facing_lut = pv.GetColorTransferFunction("wallFacing")
        facing_lut.RGBPoints = [0.0] + WALL_COLOUR + [1.0] + WALL_COLOUR
        facing_lut.EnableOpacityMapping = 1
        facing_opacity = pv.GetOpacityTransferFunction("wallFacing")
        facing_opacity.Points = [0.0, WALL_OPACITY[1], 0.5, 0.0,
                                 1.0, WALL_OPACITY[0], 0.5, 0.0]
        facing_lut.RescaleTransferFunction(0.0, 1.0)
        facing_lut.AutomaticRescaleRangeMode = "Never"
        d = self.direction
        for source, outward in sources:
            normals = pv.GenerateSurfaceNormals(Input=pv.Triangulate(Input=source))
            normals.FeatureAngle = 60
            normals.Consistency = 0
            facing = pv.Calculator(Input=normals, ResultArrayName="facing",
                                   Function=f"abs(Normals_X*({d[0]!r}) + Normals_Y*({d[1]!r})"
                                            f" + Normals_Z*({d[2]!r}))")
            rep = pv.Show(facing, self.view)
            pv.ColorBy(rep, ("POINTS", "facing"))
            rep.LookupTable = facing_lut
            rep.SetScalarBarVisibility(self.view, False)
            rep.Ambient = 0.4
            rep.Diffuse = 0.6
            rep.Specular = 0.0
            rep.Opacity = 0.999
            if outward:
                rep.BackfaceRepresentation = "Cull Frontface"
        return [source for source, _ in sources]

    def slice_origin(self, particles):
        """The slice through the particle nearest the mesh's middle, kept
        for the next frames when there are several."""
        n = self.normal_axis
        origin = list(self.middle)
        if self.twoD:
            return origin
        if len(particles) == 1 or (self.slice_at is None and len(particles)):
            nearest = min(particles.centres, key=lambda c: abs(c[n] - self.middle[n]))
            self.slice_at = nearest[n]
        if self.slice_at is not None:
            origin[n] = self.slice_at
        return origin

    def new(self, factory, **properties):
        """A proxy of this picture (deleted before the next)."""
        proxy = factory(**properties)
        self.transient.append(proxy)
        return proxy

    def lifted(self, source, distance):
        """source moved towards the camera along the slice's normal."""
        moved = self.new(self.pv.Transform, Input=source)
        moved.Transform = "Transform"
        moved.Transform.Translate = [distance*c for c in self.towards_camera]
        return moved

    def render(self, time_name, time_value, png):
        pv = self.pv
        particles = Particles(self.case, time_name)
        origin = self.slice_origin(particles)

        # What the last picture added
        for source in reversed(self.transient):
            pv.Delete(source)
        self.transient = []
        self.view.ViewTime = time_value
        self.reader.UpdatePipeline(time_value)

        cut = self.new(pv.Slice, Input=self.reader)
        cut.SliceType = "Plane"
        cut.SliceType.Origin = origin
        cut.SliceType.Normal = self.normal
        try:
            cut.Triangulatetheslice = 0
        except AttributeError:
            pass
        flow = pv.Show(cut, self.view)
        pv.ColorBy(flow, ("CELLS", "U", "Magnitude"))
        lut = pv.GetColorTransferFunction("U")
        lut.ApplyPreset("Viridis (matplotlib)", True)
        flow.RescaleTransferFunctionToDataRange(True, False)
        # The colours as the bar shows them, unshaded
        flow.Ambient = 1.0
        flow.Diffuse = 0.0
        flow.SetScalarBarVisibility(self.view, True)
        self.style_bar(pv.GetScalarBar(lut, self.view), "fluid speed [m/s]",
                       "Lower Right Corner")

        # The walls' profiles on the slice, just in front of it
        for wall in self.walls:
            profile = self.new(pv.Slice, Input=wall)
            profile.SliceType = "Plane"
            profile.SliceType.Origin = origin
            profile.SliceType.Normal = self.normal
            line = pv.Show(self.lifted(profile, 2e-3*self.size), self.view)
            line.ColorArrayName = ["POINTS", ""]
            line.AmbientColor = line.DiffuseColor = PROFILE_COLOUR
            line.LineWidth = 3

        points = self.new(pv.CellDatatoPointData, Input=cut)
        points.CellDataArraytoprocess = ["alpha.solid"]
        surface = self.new(pv.Contour, Input=points, ContourBy=["POINTS", "alpha.solid"],
                           Isosurfaces=[0.5])
        # In front of the bodies cut by the slice when seen along its normal;
        # just off the slice when seen at an angle
        lift = 1e-3*self.size if self.oblique else \
            0.51*max(particles.diameters, default=0.0) + 1e-3*self.size
        outline = pv.Show(self.lifted(surface, lift), self.view)
        outline.ColorArrayName = ["POINTS", ""]
        outline.AmbientColor = outline.DiffuseColor = [1, 1, 1]
        outline.LineWidth = 2

        if len(particles):
            self.show_particles(particles)
        if self.fastest > 0:
            # The speed's bar only when there are particles to read it on
            bar = pv.GetScalarBar(pv.GetColorTransferFunction("speed"), self.view)
            bar.Visibility = 1 if len(particles) else 0

        label = self.new(pv.Text, Text=f"{self.case.name}   t = {time_value:g} s")
        caption = pv.Show(label, self.view)
        caption.Color = [0, 0, 0]
        caption.FontSize = 14
        caption.WindowLocation = "Upper Left Corner"

        self.place_camera(origin)
        pv.SaveScreenshot(str(png), self.view, ImageResolution=self.view.ViewSize)
        print(f"dlmRender: {png}")

    def show_particles(self, particles):
        pv = self.pv
        if particles.surfaces.exists():
            # Shapes that are not round: their surfaces as written, each face
            # with its particle's speed
            drawn = self.new(pv.TrivialProducer)
            drawn.GetClientSideObject().SetOutput(particle_surfaces(particles))
            # Smooth shading of the curved faces, the edges kept sharp
            points = self.new(pv.CellDatatoPointData, Input=drawn)
            shown = self.new(pv.GenerateSurfaceNormals, Input=points)
            shown.FeatureAngle = 40
        else:
            reader = self.new(pv.LegacyVTKReader, FileNames=[str(particles.file)])
            speed = self.new(pv.Calculator, Input=reader, ResultArrayName="speed",
                             Function="mag(velocity)")
            shown = self.new(pv.Glyph, Input=speed, GlyphType="Sphere")
            shown.ScaleArray = ["POINTS", "diameter"]
            shown.ScaleFactor = 1.0
            shown.GlyphMode = "All Points"
            shown.GlyphType.ThetaResolution = 48
            shown.GlyphType.PhiResolution = 24
        association = "POINTS"
        shapes = pv.Show(shown, self.view)
        shapes.Ambient = 0.25
        shapes.Diffuse = 0.8
        shapes.Specular = 0.35
        shapes.SpecularPower = 40
        if self.fastest > 0:
            pv.ColorBy(shapes, (association, "speed"))
            lut = pv.GetColorTransferFunction("speed")
            lut.RGBPoints = [v*self.fastest if k % 4 == 0 else v
                             for k, v in enumerate(SPEED_COLOURS)]
            lut.ColorSpace = "Lab"
            lut.AutomaticRescaleRangeMode = "Never"
            lut.RescaleTransferFunction(0.0, self.fastest)
            shapes.SetScalarBarVisibility(self.view, True)
            self.style_bar(pv.GetScalarBar(lut, self.view), "particle speed [m/s]",
                           "Upper Right Corner")
        else:
            shapes.ColorArrayName = [association, ""]
            shapes.AmbientColor = shapes.DiffuseColor = SPEED_COLOURS[1:4]

    @staticmethod
    def style_bar(bar, title, corner):
        bar.Title = title
        bar.ComponentTitle = ""
        bar.TitleColor = bar.LabelColor = [0, 0, 0]
        bar.WindowLocation = corner
        bar.ScalarBarLength = 0.3
        bar.AutomaticLabelFormat = 0
        bar.LabelFormat = bar.RangeLabelFormat = "%.3g"
        bar.HorizontalTitle = 1

    def place_camera(self, origin):
        """Along the viewing direction, towards the mesh's middle (in 3D
        at an angle, in perspective) or the slice's origin (along its
        normal, parallel projection), near enough for the mesh's bounding
        box to fill the picture left of the colour bars."""
        view = self.view
        focal = list(self.middle) if self.oblique else list(origin)
        d = unit(self.direction)
        up = unit(add(self.up_vector, d, -dot(self.up_vector, d)))
        right = cross(up, d)
        aspect = self.args.size[0]/self.args.size[1]
        # The bars take the right fifth: the box within [-1, 0.64] of the
        # picture's half-width, a margin of 6 % around
        width, shift, margin = 0.82, 0.18, 0.94
        corners = [add(corner, focal, -1) for corner in box_corners(self.bounds)]
        if self.oblique:
            angle = 20
            tangent = math.tan(math.radians(angle/2))
            distance = max(max(dot(c, d) + abs(dot(c, up))/(margin*tangent),
                               dot(c, d) + abs(dot(c, right))/(margin*width*tangent*aspect))
                           for c in corners)
            offset = shift*distance*tangent*aspect
            view.CameraViewAngle = angle
        else:
            scale = max(max(abs(dot(c, up))/margin,
                            abs(dot(c, right))/(margin*width*aspect)) for c in corners)
            distance = self.size
            offset = shift*scale*aspect
            view.CameraParallelScale = scale
        focal = add(focal, right, offset)
        view.CameraFocalPoint = focal
        view.CameraPosition = add(focal, d, distance)
        view.CameraViewUp = up


def main():
    args = parse()
    case = args.case.resolve()
    times = written_times(case)
    if not times:
        raise SystemExit(f"dlmRender: no written time in {case}")
    chosen = choose_times(case, times, args.times)
    if args.print_times:
        print(" ".join(name for _, name in chosen))
        return
    scene = Scene(case, args, largest_speed(case, times))
    out = case / "render"
    for value, name in chosen:
        png = args.output if args.output and len(chosen) == 1 else out / f"{case.name}_{name}.png"
        png.parent.mkdir(parents=True, exist_ok=True)
        scene.render(name, value, png)
    if args.frames:
        (out / "frames").mkdir(parents=True, exist_ok=True)
        for k, (value, name) in enumerate(times):
            scene.render(name, value, out / "frames" / f"{case.name}_{k:04d}.png")


main()
