"""In-plane refinement of 2D (one-cell-thick) cases: dlmRefineFvMesh splits
a cell into 4 in the plane and merges them back, serial and parallel."""
import math
import pathlib
import re
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

from foamcase import assert_same_trajectory, Case

HERE = pathlib.Path(__file__).resolve().parent
DISK = HERE.parent / "tutorials" / "fallingDisk"

RADIUS, DEPTH = 0.01, 0.01
SPEED = 0.01

REFINE_IN_PLANE = """\
FoamFile { version 2.0; format ascii; class dictionary; object dynamicMeshDict; }
dynamicFvMesh   dlmRefineFvMesh;
dynamicRefineFvMeshCoeffs
{
    refineInterval  1;
    nBufferLayers   1;
    maxCells        100000;
    correctFluxes
    (
        (phi none) (phi_0 none) (phi_0_0 none) (ghf none) (UBlendingFactor none)
    );
    dumpLevel       true;
    targets
    {
        surface { type particleSurface; level 2; }
    }
}
"""


def falling_case(tmp_path, foam_env, name, end_time=0.15):
    """tutorials/fallingDisk (mu 0.1 Pa s, Re about 100) on a coarse base mesh
    of 3 cells per diameter, refined to 12 at the disk's surface, the disk
    off the channel's axis (by 0.05 d) so that its path is not on a
    symmetry line."""
    case = Case.copy(DISK, tmp_path / name, foam_env)
    mesh = case.path / "system" / "blockMeshDict"
    mesh.write_text(mesh.read_text().replace("nx  80;", "nx  30;")
                    .replace("ny  160;", "ny  60;"))
    properties = case.path / "constant" / "particleProperties"
    properties.write_text(properties.read_text().replace(
        "position    (0.1 0.3 0);", "position    (0.099 0.3 0);"))
    (case.path / "constant" / "dynamicMeshDict").write_text(REFINE_IN_PLANE)
    solution = case.path / "system" / "fvSolution"
    solution.write_text(solution.read_text().replace(
        "    U\n    {", "    pcorr\n    {\n        $p_rgh;\n        tolerance 1e-13;\n"
        "        relTol 0;\n    }\n\n    U\n    {", 1))
    for entry, value in {"endTime": end_time, "writeInterval": 0.05,
                         "writePrecision": 17}.items():
        case.set("system/controlDict", entry, value)
    case.run("blockMesh")
    return case


def cell_counts(case, log="log.pimpleDLMFoam"):
    return [int(line.split()[2]) for line in (case.path / log).read_text().splitlines()
            if line.startswith("Mesh changed:")]


def plane_faces(case, time):
    """Number of faces on the front and back (empty) patch at a written time."""
    boundary = (case.path / time / "polyMesh" / "boundary").read_text()
    block = boundary[boundary.index("frontAndBack"):]
    return int(re.search(r"nFaces\s+(\d+);", block).group(1))


def test_a_falling_disk_is_refined_in_the_plane_and_its_mesh_stays_one_cell_thick(
        tmp_path, foam_env):
    """The disk falls through its refined band: the cells are split in the
    plane only (faces on the empty patches twice the cells, checkMesh finds
    a valid 2D mesh at every written time), each cell its surface cuts is at
    the finest level, the band is unrefined behind the disk, and every change
    keeps the mixture's momentum and the flux's continuity to round-off and
    the disk's solid area exact (its fractions computed, not mapped)."""
    case = falling_case(tmp_path, foam_env, "falling")
    case.run("pimpleDLMFoam")
    log = (case.path / "log.pimpleDLMFoam").read_text()
    assert log.index("Mesh changed:") < log.index("Starting time loop")

    counts = cell_counts(case)
    assert counts[0] > 1800 and len(counts) >= 10
    assert any(later < earlier for earlier, later in zip(counts, counts[1:]))

    lines = log.splitlines()
    for k, line in enumerate(lines):
        if line.startswith("Mesh changed:"):
            words = line.split()
            assert float(words[-5]) <= 1e-12*float(words[-1])
            continuity = lines[k - 1]
            assert continuity.startswith("time step continuity errors")
            assert float(continuity.split()[8].rstrip(",")) < 1e-15

    case.run("postProcess", "-func", "writeCellVolumes")
    times = [t for t in case.times() if float(t) > 0]
    assert times[-1] == "0.15"
    for time in times:
        alpha = case.internal_field(f"{time}/alpha.solid")
        volumes = case.internal_field(f"{time}/V")
        level = case.internal_field(f"{time}/cellLevel")
        assert plane_faces(case, time) == 2*alpha.size
        assert np.dot(alpha, volumes) == pytest.approx(math.pi*RADIUS**2*DEPTH, rel=1e-12)
        cut = (alpha > 1e-9) & (alpha < 1 - 1e-9)
        assert cut.sum() > 30 and (level[cut] == 2).all()
        check = case.run("checkMesh", "-time", time, log=f"checkMesh.{time}")
        assert "Mesh OK." in check.log
        assert "Mesh has 2 solution (non-empty) directions" in check.log


def test_a_refined_2d_run_restarts_exactly_and_runs_on_two_and_three_ranks_as_in_serial(
        tmp_path, foam_env):
    """Restarted from a written time (its refined mesh and cell and point
    levels read back: no refinement history is needed to merge the cells
    again), the run continues as if never stopped, to 1e-12. Decomposed
    (METIS) on 2 and 3 ranks (oversubscribed), the mesh follows the disk
    with the cells of the serial run and, with converged linear solvers,
    the same trajectory to 1e-6; so does a decomposition whose processor
    boundary runs through the disk."""
    serial = falling_case(tmp_path, foam_env, "serial", end_time=0.1)
    serial.run("pimpleDLMFoam")
    track = serial.history()["disk"]

    restarted = falling_case(tmp_path, foam_env, "restarted", end_time=0.05)
    restarted.run("pimpleDLMFoam")
    restarted.set("system/controlDict", "endTime", 0.1)
    restarted.run("pimpleDLMFoam", log="pimpleDLMFoam.restart")
    again = restarted.history("0.05")["disk"]
    tail = track[track[:, 0] > 0.05 + 1e-9]
    assert len(again) == len(tail) >= 5
    assert np.abs(again[:, 1:10] - tail[:, 1:10]).max() < 1e-12
    assert cell_counts(restarted, "log.pimpleDLMFoam.restart") == \
        cell_counts(serial)[-len(cell_counts(restarted, "log.pimpleDLMFoam.restart")):]

    converged = falling_case(tmp_path, foam_env, "converged", end_time=0.1)
    converged.converge_linear_solvers()
    converged.run("pimpleDLMFoam")
    for ranks, method in [(2, "metis"), (3, "metis"), (2, "simple")]:
        parallel = falling_case(tmp_path, foam_env, f"parallel{ranks}{method}",
                                end_time=0.1)
        parallel.converge_linear_solvers()
        parallel.set("system/decomposeParDict", "numberOfSubdomains", ranks)
        parallel.set("system/decomposeParDict", "method", method)
        # simple: the processors' boundary at x = 0.1, through the disk
        parallel.set("system/decomposeParDict", "coeffs", "{ n (2 1 1); }")
        parallel.run("decomposePar")
        parallel.run("pimpleDLMFoam", np=ranks)
        assert cell_counts(parallel) == cell_counts(converged)
        assert_same_trajectory(converged.history()["disk"], parallel.history()["disk"])
        if method == "simple":
            solid = [parallel.internal_field(f"processor{k}/0.1/alpha.solid").max()
                     for k in range(ranks)]
            assert min(solid) > 0.1


def test_a_refined_2d_time_decomposes_continues_on_two_ranks_and_reconstructs(
        tmp_path, foam_env):
    """A serial run's refined time decomposed (decomposePar -latestTime takes
    the cell and point levels along), continued on 2 ranks, where cells are
    refined and merged again, then reconstructed (reconstructParMesh,
    reconstructPar): one valid 2D mesh with its levels."""
    case = falling_case(tmp_path, foam_env, "decomposed", end_time=0.05)
    case.run("pimpleDLMFoam")
    case.set("system/controlDict", "endTime", 0.1)
    case.run("decomposePar", "-latestTime")
    case.run("pimpleDLMFoam", np=2, log="pimpleDLMFoam.parallel")
    assert len(cell_counts(case, "log.pimpleDLMFoam.parallel")) >= 3
    case.run("reconstructParMesh", "-latestTime", "-mergeTol", "1e-6")
    case.run("reconstructPar", "-latestTime")
    cells = case.internal_field("0.1/alpha.solid").size
    assert cells == case.internal_field("0.1/cellLevel").size
    assert plane_faces(case, "0.1") == 2*cells
    check = case.run("checkMesh", "-time", "0.1")
    assert "Mesh OK." in check.log


def disk_box_case(tmp_path, foam_env, name, periodic_sides):
    """tutorials/fallingDisk turned into a 4 cm square box of 16 x 16 cells,
    periodic along y, along x too or between walls at x = 0 and 4 cm,
    without gravity, refined in the plane (REFINE_IN_PLANE)."""
    case = Case.copy(DISK, tmp_path / name, foam_env)
    sides = ("left   { type cyclic; neighbourPatch right; faces ((0 4 7 3)); }\n"
             "    right  { type cyclic; neighbourPatch left;  faces ((1 2 6 5)); }"
             if periodic_sides else
             "left   { type wall; faces ((0 4 7 3)); }\n"
             "    right  { type wall; faces ((1 2 6 5)); }")
    (case.path / "system" / "blockMeshDict").write_text(f"""\
FoamFile {{ version 2.0; format ascii; class dictionary; object blockMeshDict; }}
vertices ((0 0 0) (0.04 0 0) (0.04 0.04 0) (0 0.04 0)
          (0 0 0.01) (0.04 0 0.01) (0.04 0.04 0.01) (0 0.04 0.01));
blocks (hex (0 1 2 3 4 5 6 7) (16 16 1) simpleGrading (1 1 1));
boundary
(
    {sides}
    bottom {{ type cyclic; neighbourPatch top;   faces ((0 1 5 4)); }}
    top    {{ type cyclic; neighbourPatch bottom; faces ((3 7 6 2)); }}
    frontAndBack {{ type empty; faces ((0 3 2 1) (4 5 6 7)); }}
);
""")
    (case.path / "constant" / "g").write_text(
        "FoamFile { version 2.0; format ascii; class uniformDimensionedVectorField; object g; }\n"
        "dimensions [0 1 -2 0 0 0 0];\nvalue (0 0 0);\n")
    (case.path / "constant" / "dynamicMeshDict").write_text(REFINE_IN_PLANE)
    case.set("system/fvSolution", "PIMPLE/pRefPoint", "(0.001 0.001 0.005)")
    return case


def translating_disk_case(tmp_path, foam_env, name="translating"):
    """A 2D periodic box (4 cm square, 16 x 16 cells) holding a disk of 1 cm
    radius across its periodic sides x = 0 and 4 cm, prescribed to move at
    (1, 0.5) cm/s through water moving with it: the exact solution is the
    uniform flow."""
    case = disk_box_case(tmp_path, foam_env, name, periodic_sides=True)
    velocity = f"({SPEED!r} {0.5*SPEED!r} 0)"
    (case.path / "constant" / "particleProperties").write_text(f"""\
FoamFile {{ version 2.0; format ascii; class dictionary; object particleProperties; }}
particles
{{
    disk
    {{
        shape       disk;
        radius      {RADIUS!r};
        density     1000;
        position    (0.0335 0.0207 0);
        motion      prescribed;
        velocity    {velocity};
    }}
}}
""")
    for field in ["U", "p_rgh"]:
        path = case.path / "0" / field
        text = path.read_text().replace("uniform (0 0 0)", f"uniform {velocity}")
        text = text[:text.index("boundaryField")] + """boundaryField
{
    "(left|right|bottom|top)" { type cyclic; }
    frontAndBack { type empty; }
}
"""
        path.write_text(text)
    case.set("constant/transportProperties", "nu", 1e-6)
    for entry, value in {"adjustTimeStep": "no", "deltaT": 0.02, "endTime": 0.4,
                         "writeInterval": 0.1, "writePrecision": 17}.items():
        case.set("system/controlDict", entry, value)
    return case


def test_in_plane_refinement_following_a_translating_disk_keeps_the_uniform_flow_exact(
        tmp_path, foam_env):
    """Refined and unrefined at every step about a disk that translates with
    the water through a periodic box (on both sides of its periodic
    patches: their faces split and merged as the cells beside them), the
    flow
    stays uniform to round-off: children keep their parent's velocity,
    merged cells the mean, the face velocity on new faces interpolated and
    the flux made divergence-free; the disk's solid area stays exact."""
    case = translating_disk_case(tmp_path, foam_env)
    case.run("blockMesh")
    case.run("pimpleDLMFoam")
    counts = cell_counts(case)
    assert len(counts) >= 15 and min(counts) > 16*16
    case.run("postProcess", "-func", "writeCellVolumes")
    case.run("postProcess", "-func", "writeCellCentres", "-latestTime")
    across = case.internal_field("0.4/C")[:, 0] < 0.004
    assert (case.internal_field("0.4/cellLevel")[across] == 2).sum() > 20
    times = [t for t in case.times() if float(t) > 0]
    assert times[-1] == "0.4"
    for time in times:
        alpha = case.internal_field(f"{time}/alpha.solid")
        volumes = case.internal_field(f"{time}/V")
        assert plane_faces(case, time) == 2*alpha.size
        assert np.dot(alpha, volumes) == pytest.approx(math.pi*RADIUS**2*DEPTH, rel=1e-12)
        U = case.internal_field(f"{time}/U")
        assert np.abs(U - [SPEED, 0.5*SPEED, 0]).max() < 1e-12*SPEED

    parallel = translating_disk_case(tmp_path, foam_env, "parallel")
    parallel.run("blockMesh")
    parallel.set("system/decomposeParDict", "numberOfSubdomains", 3)
    parallel.run("decomposePar")
    parallel.run("pimpleDLMFoam", np=3)
    assert cell_counts(parallel) == counts
    parallel.run("reconstructParMesh", "-mergeTol", "1e-6", "-latestTime")
    parallel.run("reconstructPar", "-latestTime")
    U = parallel.internal_field("0.4/U")
    assert np.abs(U - [SPEED, 0.5*SPEED, 0]).max() < 1e-12*SPEED


def test_2d_refinement_held_by_max_cells_is_reported_once_and_the_mesh_stays_valid(
        tmp_path, foam_env):
    """With maxCells below what the disk's band needs, the 2D mesh is not
    refined past it: the log says so once, the run goes on, and the mesh
    stays a valid one-cell-thick mesh within maxCells."""
    case = falling_case(tmp_path, foam_env, "capped", end_time=0.05)
    (case.path / "constant" / "dynamicMeshDict").write_text(
        REFINE_IN_PLANE.replace("maxCells        100000;", "maxCells        2000;"))
    log = case.run("pimpleDLMFoam").log
    assert log.count("above maxCells 2000: nothing is refined") == 1
    counts = cell_counts(case)
    assert counts and max(counts) <= 2000
    assert plane_faces(case, "0.05") == 2*case.internal_field("0.05/alpha.solid").size


def test_split_cells_take_their_parents_linear_variation(tmp_path, foam_env):
    """A shear flow v = S (x - x0) between slip walls (periodic along y),
    refined at the start to 2 levels in a band of 8 fine cells about a
    fixed disk, then one step of 1e-8 s, which leaves the flow as the
    refinement made it. A split cell's children take its value corrected
    by its gradient at their centres: in the band's level-2 cells beyond the
    disk's forced cells (2 fine cells) and within 6, whose level-1 parents
    lay among level-1 cells, the velocity is the linear field's to 1e-5 of
    S h (1e-6 measured); a child given its parent's value (injection)
    would be off by h/8 to 3h/8."""
    h, x0, shear = 0.04/16, 0.02, 1.0
    centre, radius = np.array([0.0201, 0.0198]), 0.005
    case = disk_box_case(tmp_path, foam_env, "shear", periodic_sides=False)
    (case.path / "constant" / "particleProperties").write_text(f"""\
FoamFile {{ version 2.0; format ascii; class dictionary; object particleProperties; }}
particles
{{
    disk
    {{
        shape disk; radius {radius!r}; density 1000; motion fixed;
        position ({float(centre[0])!r} {float(centre[1])!r} 0);
    }}
}}
""")
    centres = (np.arange(16) + 0.5)*h
    values = "\n".join(f"(0 {float(shear*(x - x0))!r} 0)" for _ in centres for x in centres)
    for field, walls in [("U", "slip"), ("p_rgh", "fixedFluxPressure")]:
        path = case.path / "0" / field
        text = path.read_text()
        text = text.replace("uniform (0 0 0)", f"nonuniform List<vector> 256\n(\n{values}\n)")
        path.write_text(text[:text.index("boundaryField")] + f"""boundaryField
{{
    "(left|right)" {{ type {walls}; }}
    "(bottom|top)" {{ type cyclic; }}
    frontAndBack {{ type empty; }}
}}
""")
    case.set("constant/dynamicMeshDict", "dynamicRefineFvMeshCoeffs/targets/surface/cells", 8)
    for entry, value in {"adjustTimeStep": "no", "deltaT": 1e-8, "endTime": 1e-8,
                         "writeControl": "timeStep", "writeInterval": 1,
                         "writePrecision": 17}.items():
        case.set("system/controlDict", entry, value)
    case.run("blockMesh")
    case.run("pimpleDLMFoam")
    time = case.times()[-1]
    case.run("postProcess", "-func", "writeCellCentres", "-time", time)
    C = case.internal_field(f"{time}/C")[:, :2]
    U = case.internal_field(f"{time}/U")
    level = case.internal_field(f"{time}/cellLevel")
    distance = np.linalg.norm(C - centre, axis=1) - radius
    band = (level == 2) & (distance > 2*h/4) & (distance < 6*h/4)
    assert band.sum() > 300
    error = np.abs(U[band] - np.column_stack([0*C[band, 0], shear*(C[band, 0] - x0), 0*C[band, 0]]))
    assert error.max() < 1e-5*shear*h


def test_how_often_the_mesh_changes_leaves_a_disk_settling_at_re_2000_as_it_was(
        tmp_path, foam_env):
    """tutorials/fallingDisk at Re about 2000 (nu 1e-6) on a base of 4 cells
    per diameter refined to 16 at the disk's surface, 8 in its wake, the
    mesh changed every step and every 10 steps: the settling speeds at 0.3 s
    agree within 1 %. A change keeps the flow's last increment for the
    flux's extrapolation (updateMesh.H); dropping it, the step after each
    change convected with the last step's flux, and the disk changed every
    step settled 1.7 % slower than every 3 steps (0.4 % now; 0.63 %
    between every step and every 10th)."""
    def settle(interval):
        case = Case.copy(DISK, tmp_path / f"interval{interval}", foam_env)
        mesh = case.path / "system" / "blockMeshDict"
        mesh.write_text(mesh.read_text().replace("nx  80;", "nx  40;")
                        .replace("ny  160;", "ny  80;"))
        case.set("constant/transportProperties", "nu", 1e-6)
        refine = (case.path / "constant" / "dynamicMeshDict.refine").read_text()
        (case.path / "constant" / "dynamicMeshDict").write_text(
            refine.replace("refineInterval  3;", f"refineInterval  {interval};"))
        case.set("system/controlDict", "endTime", 0.3)
        case.run("blockMesh")
        case.run("pimpleDLMFoam")
        history = case.history()["disk"]
        return -np.interp(0.3, history[:, 0], history[:, 5]), cell_counts(case)

    with ThreadPoolExecutor(2) as pool:
        (every, every_counts), (tenth, tenth_counts) = pool.map(settle, [1, 10])
    assert len(every_counts) > 5*len(tenth_counts) > 25
    assert 0.2 < tenth < 0.24
    assert every == pytest.approx(tenth, rel=0.01)
