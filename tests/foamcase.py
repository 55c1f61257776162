"""Helpers to run OpenFOAM cases from the tests and validation scripts."""

import os
import pathlib
import re
import shutil
import subprocess

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]


def foam_environment():
    """The environment of etc/bashrc, as a dict."""
    out = subprocess.run(
        ["bash", "-c", f"source '{ROOT}/etc/bashrc' >/dev/null 2>&1 && env -0"],
        capture_output=True, check=True).stdout.decode()
    return dict(item.split("=", 1) for item in out.split("\0") if "=" in item)


def packed_bed_rows(case_path, name="bed"):
    """Rows of a packedBed function object's output: t u eps G_drag
    G_patches Re Lambda Lambda_Ergun dragPerParticle F/Fs. A restarted run
    writes a file per start time, and a second start from the same time
    writes packedBed_<time>.dat beside the first; a later start replaces
    the rows it repeats."""
    starts = sorted((pathlib.Path(case_path) / "postProcessing" / name).iterdir(),
                    key=lambda d: float(d.name))
    rows = []
    for start in starts:
        for output in sorted(start.glob("packedBed*.dat"), key=lambda f: f.stat().st_mtime):
            rows = [r for r in rows if r[0] <= float(start.name)]
            rows += [[float(v) for v in line.split()]
                     for line in output.read_text().splitlines()
                     if line.strip() and not line.startswith("#")]
    return np.array(rows)


def assert_same_trajectory(expected, actual, rel=1e-6):
    """Two particle histories (rows of Case.history) agree: displacement,
    velocity and angular velocity each to rel of its largest magnitude."""
    assert expected.shape == actual.shape
    s, p = expected, actual
    displacement = s[:, 1:4] - s[0, 1:4] + s[0, 4:7]*s[0, 0]
    for columns, scale in [(slice(1, 4), np.abs(displacement).max()),
                           (slice(4, 7), np.abs(s[:, 4:7]).max()),
                           (slice(7, 10), np.abs(s[:, 7:10]).max())]:
        assert np.abs(p[:, columns] - s[:, columns]).max() < rel*scale


class Case:
    """An OpenFOAM case directory with the project's environment."""

    def __init__(self, path, env=None):
        self.path = pathlib.Path(path)
        self.env = env if env is not None else foam_environment()

    @classmethod
    def copy(cls, source, destination, env=None, parameters=False):
        """A copy of the case without run outputs; parameters: keep the
        *.Allrun files of a tutorial's Allrun (the settings it ran with),
        else the case's own defaults."""
        destination = pathlib.Path(destination)
        if destination.exists():
            shutil.rmtree(destination)
        ignored = ["log.*", "processor*", "postProcessing", "VTK", "polyMesh",
                   "[1-9]*", "0.[0-9]*"]
        if not parameters:
            ignored.append("*.Allrun")
        shutil.copytree(source, destination, ignore=shutil.ignore_patterns(*ignored))
        return cls(destination, env)

    def run(self, *cmd, log=None, check=True, np=1, timeout=None):
        """Run a command in the case, output to log.<name>; np > 1: mpirun;
        timeout: seconds, after which it is killed (subprocess.TimeoutExpired)."""
        cmd = [str(c) for c in cmd]
        if np > 1:
            cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe",
                   "-np", str(np)] + cmd + ["-parallel"]
        name = log or pathlib.Path(cmd[0] if np == 1 else cmd[5]).name
        logfile = self.path / f"log.{name}"
        with open(logfile, "w") as out:
            result = subprocess.run(cmd, cwd=self.path,
                                    env=dict(self.env, PWD=str(self.path)),
                                    stdout=out, stderr=subprocess.STDOUT,
                                    timeout=timeout)
        if check and result.returncode != 0:
            tail = logfile.read_text()[-3000:]
            raise RuntimeError(f"{' '.join(cmd)} failed in {self.path}:\n{tail}")
        result.log = logfile.read_text()
        return result

    def set(self, file, entry, value):
        """Set a dictionary entry with foamDictionary."""
        self.run("foamDictionary", file, "-entry", entry, "-set", str(value),
                 log="foamDictionary")

    def converge_linear_solvers(self):
        """Tolerances of 1e-13 on p_rgh and 1e-14 on U, no relative one:
        runs that should agree (serial and parallel) then differ by
        round-off."""
        for field in ["p_rgh", "p_rghFinal"]:
            self.set("system/fvSolution", f"solvers/{field}/tolerance", 1e-13)
            self.set("system/fvSolution", f"solvers/{field}/relTol", 0)
        self.set("system/fvSolution", "solvers/U/tolerance", 1e-14)

    def history(self, start="0"):
        """Particle history: dict name -> array of rows
        (t, x, y, z, Ux, Uy, Uz, wx, wy, wz, Fx, Fy, Fz, Tx, Ty, Tz)."""
        path = self.path / "postProcessing" / "particles" / start / "particles.dat"
        rows = {}
        for line in path.read_text().splitlines():
            if line.startswith("#"):
                continue
            fields = line.split()
            rows.setdefault(fields[1], []).append(
                [float(fields[0])] + [float(v) for v in fields[2:]])
        return {name: np.array(values) for name, values in rows.items()}

    def internal_field(self, relative_path):
        """Values of a scalar or vector field written in ascii or binary
        (this build's binary: little-endian 64-bit scalars), uniform or
        nonuniform: shape (n,) or (n, 3)."""
        raw = (self.path / relative_path).read_bytes()
        binary = None
        if re.search(rb"^\s*format\s+binary;", raw, re.M):
            binary = re.search(
                rb"internalField\s+nonuniform\s+List<(scalar|vector)>\s*(\d+)\s*\(", raw)
        if binary:
            count = int(binary.group(2))
            if binary.group(1) == b"scalar":
                return np.frombuffer(raw, "<f8", count, binary.end())
            return np.frombuffer(raw, "<f8", 3*count, binary.end()).reshape(count, 3)
        text = raw.decode("latin-1")
        rest = text[text.index("internalField"):]
        rest = rest[:rest.index(";")]
        if rest.split()[1] == "uniform":
            values = np.array([float(v) for v in rest.split(None, 2)[2].strip("() ").split()])
            return values if values.size == 1 else values.reshape(1, -1)
        body = rest[rest.index("(") + 1:rest.rindex(")")]
        if "(" in body:
            return np.array([[float(v) for v in t.split()]
                             for t in re.findall(r"\(([^()]*)\)", body)])
        return np.array([float(v) for v in body.split()])

    def times(self):
        """Written time directories, sorted."""
        found = []
        for entry in self.path.iterdir():
            try:
                found.append((float(entry.name), entry.name))
            except ValueError:
                pass
        return [name for _, name in sorted(found)]


def write_periodic_box(case, lengths, counts, gradings=(1, 1, 1)):
    """system/blockMeshDict of one block from the origin with the given side
    lengths, cell counts and blockMesh gradings along x, y and z, its
    opposite faces cyclic pairs."""
    lx, ly, lz = (repr(float(v)) for v in lengths)
    (case.path / "system" / "blockMeshDict").write_text(f"""\
FoamFile {{ version 2.0; format ascii; class dictionary; object blockMeshDict; }}
vertices ((0 0 0) ({lx} 0 0) ({lx} {ly} 0) (0 {ly} 0)
          (0 0 {lz}) ({lx} 0 {lz}) ({lx} {ly} {lz}) (0 {ly} {lz}));
blocks (hex (0 1 2 3 4 5 6 7) ({counts[0]} {counts[1]} {counts[2]})
        simpleGrading ({gradings[0]} {gradings[1]} {gradings[2]}));
boundary
(
    left   {{ type cyclic; neighbourPatch right; faces ((0 4 7 3)); }}
    right  {{ type cyclic; neighbourPatch left;  faces ((1 2 6 5)); }}
    bottom {{ type cyclic; neighbourPatch top;   faces ((0 1 5 4)); }}
    top    {{ type cyclic; neighbourPatch bottom; faces ((3 7 6 2)); }}
    back   {{ type cyclic; neighbourPatch front; faces ((0 3 2 1)); }}
    front  {{ type cyclic; neighbourPatch back;  faces ((4 5 6 7)); }}
);
""")


def long_cell_flow(case, aspect, h, counts, speed=1e-5, seed=1):
    """The periodicArray tutorial's case turned into a periodic box of
    uniform cells aspect h x h x h with no particle and no force, holding a
    random flow of the given speed: the flow alone, to find where the
    pressure correctors lose stability in long cells."""
    write_periodic_box(case, (counts[0]*aspect*h, counts[1]*h, counts[2]*h), counts)
    (case.path / "constant" / "particleProperties").write_text(
        "FoamFile { version 2.0; format ascii; class dictionary; object particleProperties; }\n"
        "particles {}\n")
    (case.path / "system" / "fvOptions").write_text(
        "FoamFile { version 2.0; format ascii; class dictionary; object fvOptions; }\n")
    cells = int(np.prod(counts))
    rng = np.random.default_rng(seed)
    values = "\n".join("(%.9e %.9e %.9e)" % tuple(v)
                       for v in speed*rng.uniform(-1, 1, (cells, 3)))
    (case.path / "0" / "U").write_text(
        "FoamFile { version 2.0; format ascii; class volVectorField; object U; }\n"
        "dimensions [0 1 -1 0 0 0 0];\n"
        f"internalField nonuniform List<vector> {cells}\n(\n{values}\n);\n"
        'boundaryField { ".*" { type cyclic; } }\n')
    case.run("blockMesh")
