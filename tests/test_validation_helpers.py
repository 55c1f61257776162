"""Helpers of the validation scripts that carry physics: the conversion of
drag correlations for random arrays of spheres to the DLM paper's Lambda,
and the layered Ergun estimates of the anisotropic beds; the records of a
run in parts; the immersed chute's surface and case; the rising pebble's
reference and case; and the results tables' merge."""

import argparse
import pathlib
import re
import subprocess
import sys

import numpy as np
import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "validation"))
from common import (beetstra_drag, correlation_lambda, ergun_lambda,  # noqa: E402
                    merge_row, stored_rows, tang_drag)
import pebbleDischarge  # noqa: E402
import validate_anisotropicBed as anisotropic  # noqa: E402
import validate_pebbleDischarge  # noqa: E402
import validate_risingPebble as risingPebble  # noqa: E402


@pytest.mark.parametrize("porosity", [0.36, 0.3983, 0.48])
@pytest.mark.parametrize("re_number", [0.1, 18, 900])
def test_correlations_convert_to_the_papers_lambda(porosity, re_number):
    """Carman-Kozeny's drag law gives Lambda = 180 and Ergun's gives 150 +
    1.75 Re at any porosity, as eq. 25 defines them; the two fits to fully
    resolved simulations reduce to Carman-Kozeny (plus their small Stokes
    correction) as Re goes to 0, and give the values quoted in
    validation/cases/randomBed.md for the paper's bed."""
    def carman_kozeny(phi, re_s):
        return 10*phi/(1 - phi)**2

    def ergun(phi, re_s):
        return (150*phi + 1.75*re_s)/(18*(1 - phi)**2)

    assert correlation_lambda(carman_kozeny, porosity, re_number) == pytest.approx(180)
    assert correlation_lambda(ergun, porosity, re_number) == \
        pytest.approx(ergun_lambda(re_number))
    for drag in (beetstra_drag, tang_drag):
        assert correlation_lambda(drag, porosity, 1e-6) == pytest.approx(180, rel=0.03)


def test_correlations_for_the_papers_random_bed():
    """The paper's bed (porosity 0.3983, Re 897.5 by it): Beetstra et al.
    1348 and Tang et al. 767, against Ergun's 1721."""
    assert correlation_lambda(beetstra_drag, 0.3983, 897.49) == pytest.approx(1348, abs=1)
    assert correlation_lambda(tang_drag, 0.3983, 897.49) == pytest.approx(767, abs=1)
    assert ergun_lambda(897.49) == pytest.approx(1721, abs=1)


@pytest.mark.parametrize("width", [1, 2])
def test_layered_ergun_of_a_uniform_lattice_is_ergun_at_its_porosity(width):
    """A lattice whose spacing along the band's axis (0.1) divides the band
    and the rest has the same porosity in both layers, so the parallel and
    the series estimates are Ergun's at the bed's porosity, also in a box
    twice as wide along y, where the spheres at y = 1.95 cross the periodic
    face at 2 (a period or a cross-section of the unit cube would count the
    wrong spheres)."""
    box = anisotropic.Box(width)
    volume = 4/3*np.pi*anisotropic.RADIUS**3
    for axis, series in ((1, False), (0, True)):
        spacing = [0.5, 0.5, 0.5]
        spacing[axis] = 0.1
        sites = [np.arange(h/2, extent, h) for h, extent in zip(spacing, box.extent)]
        centres = np.column_stack([c.ravel() for c in np.meshgrid(*sites)])
        eps = 1 - len(centres)*volume/(box.extent[0]*box.extent[1]*box.extent[2])
        assert 0.7 < eps < 0.8
        assert anisotropic.layered_ergun(centres, axis, series, box) == \
            pytest.approx(anisotropic.ergun_gradient(eps, anisotropic.U), rel=1e-9)


def test_merge_row_replaces_by_key_adds_columns_and_refuses_other_columns(tmp_path):
    """A row replaces the one with the same key; a header that adds columns
    at the end pads the old rows with nan; a header with a column inserted
    (a newer script) is refused, with the file unchanged, where merging
    would have shifted every column after it."""
    path = tmp_path / "results.csv"
    merge_row(path, ["case", "N", "value"], ["a", 4, 1.0])
    merge_row(path, ["case", "N", "value"], ["a", 4, 2.0])
    merge_row(path, ["case", "N", "value"], ["a", 6, 3.0])
    merge_row(path, ["case", "N", "value", "time"], ["b", 4, 4.0, 10])
    assert path.read_text().splitlines() == [
        "case,N,value,time", "a,4.0,2.0,nan", "a,6.0,3.0,nan", "b,4,4.0,10"]
    before = path.read_text()
    with pytest.raises(SystemExit, match="not this script's"):
        merge_row(path, ["case", "medium", "N", "value", "time"], ["c", "wet", 4, 5.0, 1])
    assert path.read_text() == before


def test_a_discharge_run_in_parts_counts_each_pebble_once(tmp_path):
    """A run stopped at 1.3 s after its last write at 1.0 and resumed from
    1.0 wrote the pebbles that left between 1.0 and 1.3 twice (in the
    directories 0 and 1); a second resume from 2.0 wrote its own directory.
    Each departure counts once, from the part that wrote it last, and so
    does the history at the restart time; an immersed wall's history (a
    fixed particle) is no pebble's."""
    outlets = tmp_path / "postProcessing/particleOutlets"
    departures = {"0": [0.5, 0.9, 1.1, 1.25], "1": [1.1, 1.25, 1.6, 1.95, 2.2],
                  "2": [2.3, 2.8]}
    for start, times in departures.items():
        (outlets / start).mkdir(parents=True)
        (outlets / start / "outlets.dat").write_text(
            "# time outlet particle mass x y z Ux Uy Uz outletParticles outletMass\n"
            + "".join(f"{t} chute p{t} 0.007 0 0 0.6 0 0 0.3 0 0\n" for t in times))
    t, mass = pebbleDischarge.outlet_record(tmp_path)
    assert list(t) == [0.5, 0.9, 1.1, 1.25, 1.6, 1.95, 2.3, 2.8]
    assert mass[-1] == pytest.approx(8*0.007)
    particles = tmp_path / "postProcessing/particles"
    for start, times in {"0": [0, 0.5, 1.0, 1.5], "1": [1.0, 1.5, 2.0]}.items():
        (particles / start).mkdir(parents=True)
        (particles / start / "particles.dat").write_text(
            "# time particle x y z Ux Uy Uz\n"
            + "".join(f"{t} pebbleBed_0 0 0 {t} 0 0 0.1\n{t} chuteTube 0 0 0.3 0 0 0\n"
                      for t in times))
    times, names, rows = pebbleDischarge.history(tmp_path)
    assert list(times) == [0, 0.5, 1.0, 1.5, 2.0]
    assert set(names) == {"pebbleBed_0"}
    assert list(rows[:, 2]) == [0, 0.5, 1.0, 1.5, 2.0]


def test_a_run_in_parts_takes_the_solvers_clock_of_every_part(tmp_path):
    """The first part's log and the resumed parts' log, in which each part's
    clock starts again: the wall time is the sum of each part's last clock."""
    (tmp_path / "log.pimpleDLMFoam").write_text(
        "ExecutionTime = 1 s  ClockTime = 2 s\nExecutionTime = 9 s  ClockTime = 10 s\n")
    (tmp_path / "log.pimpleDLMFoam.resumed").write_text(
        "ExecutionTime = 3 s  ClockTime = 4 s\nExecutionTime = 6 s  ClockTime = 7 s\n"
        "ExecutionTime = 1 s  ClockTime = 1 s\nExecutionTime = 20 s  ClockTime = 21 s\n")
    assert validate_pebbleDischarge.solver_clock_times(tmp_path) == [10, 7, 21]


def test_the_immersed_chute_is_a_closed_outward_tube_of_its_volume():
    """The immersed chute's surface (validate_pebbleDischarge --chute
    immersed): every edge on two triangles in opposite directions (closed,
    consistently oriented), outward (positive volume by the divergence
    theorem), the volume and centroid those of its polygonal tube."""
    inner, outer, length, sides = 0.054, 0.066, 0.1, 16
    text = validate_pebbleDischarge.tube_stl(inner, outer, length, sides)
    vertices = np.array([[float(v) for v in line.split()[1:]]
                         for line in text.splitlines() if line.startswith("vertex")])
    triangles = vertices.reshape(-1, 3, 3)
    keys = [tuple(np.round(p, 12)) for p in vertices]
    edges = {}
    for t in range(len(triangles)):
        for k in range(3):
            edge = (keys[3*t + k], keys[3*t + (k + 1) % 3])
            edges[edge] = edges.get(edge, 0) + 1
    assert all(n == 1 for n in edges.values())
    assert all((b, a) in edges for a, b in edges)
    a, b, c = triangles[:, 0], triangles[:, 1], triangles[:, 2]
    signed = np.einsum("ij,ij->i", a, np.cross(b, c))/6
    polygon_area = 0.5*sides*np.sin(2*np.pi/sides)
    assert signed.sum() == pytest.approx(polygon_area*(outer**2 - inner**2)*length, rel=1e-9)
    centroid = (signed[:, None]*(a + b + c)/4).sum(axis=0)/signed.sum()
    assert centroid == pytest.approx([0, 0, length/2], abs=1e-12)


def test_the_immersed_chute_replaces_the_castellated_one(tmp_path, monkeypatch):
    """--chute immersed: the case's set-up makes no baffles, its particles
    add the fixed tube that the pebbles pass through, and the fill (the
    same bed as the castellated case's) leaves the tube out."""
    monkeypatch.setattr(validate_pebbleDischarge, "RUNS", tmp_path)
    case = validate_pebbleDischarge.make_case("reduced", 4, 0.8, 0.01, "overlapVolume", "wet",
                                              "immersed")
    assert case.name.endswith("_immersed")
    pre = (case / "Allrun.pre").read_text()
    commands = [line for line in pre.splitlines() if not line.lstrip().startswith("#")]
    assert any(line.startswith("subsetMesh") for line in commands)
    assert not [line for line in commands if "createBaffles" in line or "topoSetDict.chute" in line]
    props = (case / "constant/particleProperties").read_text()
    assert re.search(r"chuteTube\s*\{[^}]*motion\s+fixed;[^}]*material\s+chuteTube;", props)
    assert re.search(r"materials\s+\(pebble chuteTube\);\s*law\s+none;", props)
    assert (case / "constant/triSurface/chuteTube.stl").read_text().startswith("solid")
    fill = (case / "fill/constant/particleProperties").read_text()
    assert re.search(r'#include "\.\./\.\./constant/particleProperties"\n#remove particles\n', fill)


def test_the_rising_pebbles_reference_solves_the_force_balance():
    """The unbounded terminal velocity balances the pebble's buoyancy less
    its weight with the drag of Brown & Lawler's curve, whose coefficient
    is about 0.4 at Re 9000 (Newton's regime); the wall factor of a box 10
    diameters wide is a few per cent below 1 and tends to 1 as the box
    widens."""
    u = risingPebble.terminal_velocity()
    re_number = u*risingPebble.D/risingPebble.NU
    volume = np.pi/6*risingPebble.D**3
    net = (risingPebble.RHO_F - risingPebble.RHO_S)*volume*risingPebble.G
    drag = risingPebble.drag_coefficient(re_number)*0.5*risingPebble.RHO_F*u**2 \
        * np.pi/4*risingPebble.D**2
    assert drag == pytest.approx(net, rel=1e-12)
    assert 0.39 < risingPebble.drag_coefficient(re_number) < 0.42
    assert 8000 < re_number < 10000
    assert 0.9 < risingPebble.wall_factor(u) < 0.97


def test_the_rising_pebbles_case(tmp_path, monkeypatch):
    """The case: a box of N cells per diameter with the pebble 2 diameters
    above the floor, in water, with the discharge tutorial's schemes."""
    monkeypatch.setattr(risingPebble, "RUNS", tmp_path)
    case = risingPebble.make_case(4, 1, None)
    assert (case.path / "constant/polyMesh/owner").exists()
    header = (case.path / "constant/polyMesh/owner").read_text(errors="ignore")[:2000]
    assert "nCells:" + str(40*40*96) in header.replace(" ", "")
    props = (case.path / "constant/particleProperties").read_text()
    assert "density     843.0;" in props
    assert re.search(r"position\s+\(0\.1251 0\.1249 0\.05\);", props)
    pebble = pathlib.Path(risingPebble.ROOT) / "tutorials/pebbleDischarge/system"
    for name in ("fvSchemes", "fvSolution"):
        assert (case.path / "system" / name).read_text() == (pebble / name).read_text()


def test_boundary_layer_slip_is_set_in_the_discharge_and_the_rising_pebble(
        tmp_path, monkeypatch, foam_env):
    """--boundary-layer-slip: the runs' own folders, and the rigid
    projection's fvOptions entry as the solver reads it."""
    monkeypatch.setattr(validate_pebbleDischarge, "RUNS", tmp_path)
    case = validate_pebbleDischarge.make_case("reduced", 4, 0.8, 0.01, "overlapVolume", "wet",
                                              "castellated", True)
    assert case.name.endswith("_slip")
    monkeypatch.setattr(risingPebble, "RUNS", tmp_path)
    rising = risingPebble.make_case(4, 1, foam_env, slip=True)
    assert rising.path.name.endswith("_slip")
    for folder in (case, rising.path):
        value = subprocess.run(
            ["foamDictionary", str(folder / "system/fvOptions"), "-entry",
             "rigidProjection/boundaryLayerSlip", "-value"],
            env=foam_env, capture_output=True, text=True, check=True).stdout.strip()
        assert value == "true"


def test_the_chute_length_sets_the_outlet_and_the_lid(tmp_path, monkeypatch, foam_env):
    """--chute-length 8: the particle outlet 8 pebble diameters above the
    cone's top, the lid a diameter above it, as the mesh, the castellated
    tube and the contact walls read them (the full scene's cone)."""
    monkeypatch.setattr(validate_pebbleDischarge, "RUNS", tmp_path)
    case = validate_pebbleDischarge.make_case("full", 4, 0.8, 0.01, "overlapVolume", "wet",
                                              chute_length=8)
    assert case.name == "pebbleDischarge_full_4_e0.8_k0.01_chute8d"
    g = pebbleDischarge.geometry(case)
    assert g["coneTop"] == validate_pebbleDischarge.FULL["coneTop"]
    assert g["outletZ"] == pytest.approx(g["coneTop"] + 8*g["d"], abs=1e-12)
    assert g["lidZ"] == pytest.approx(g["outletZ"] + g["d"], abs=1e-12)

    def expanded(dictionary):
        return subprocess.run(["foamDictionary", str(case / dictionary), "-expand"], cwd=case,
                              env=foam_env, capture_output=True, text=True, check=True).stdout

    number = r"\(\s*0\s+0\s+([-0-9.eE]+)\s*\)"
    chute = re.search(r"source cylinderToCell ;.*?p2 " + number, expanded("system/topoSetDict.chute"))
    props = expanded("constant/particleProperties")
    lid = re.search(r"\blid\s*\{[^}]*point\s+" + number, props)
    outlet = re.search(r"chuteEnd\s*\{[^}]*point\s+" + number, props)
    assert float(chute.group(1)) == pytest.approx(g["outletZ"], abs=1e-12)
    assert float(outlet.group(1)) == pytest.approx(g["outletZ"], abs=1e-12)
    assert float(lid.group(1)) == pytest.approx(g["lidZ"], abs=1e-12)
    default = validate_pebbleDischarge.make_case("full", 4, 0.8, 0.01, "overlapVolume", "wet")
    assert pebbleDischarge.geometry(default)["outletZ"] == validate_pebbleDischarge.FULL["outletZ"]


def test_a_discharge_row_merges_into_the_stored_results(tmp_path, monkeypatch):
    """The script's columns are those of results/pebbleDischarge.csv, and a
    run's row (here a chute of 8 diameters) replaces a stored row of the
    same parameters and leaves the others as they were."""
    stored = pathlib.Path(validate_pebbleDischarge.RESULTS) / "pebbleDischarge.csv"
    (tmp_path / "pebbleDischarge.csv").write_text(stored.read_text())
    monkeypatch.setattr(validate_pebbleDischarge, "RESULTS", tmp_path)
    args = argparse.Namespace(scene="full", chute="castellated", chute_length=8.0,
                              boundary_layer_slip=False, restitution=0.8,
                              stiffness_factor=0.01, end_time=6.0)
    s = {"left": 313, "chute_flux": 59.1, "bed_flux": 3.6, "balance": -0.072}
    validate_pebbleDischarge.record_row(args, "wet", "overlapVolume", 4, s, 2519)
    header = ",".join(validate_pebbleDischarge.HEADER)
    assert stored.read_text().split("\n", 1)[0] == header
    assert (tmp_path / "pebbleDischarge.csv").read_text().split("\n", 1)[0] == header
    key = ["full", "wet", "overlapVolume", "tube", 8.0, 0.0, 4.0, 0.8, 0.01]
    old = [r for r in stored_rows(stored) if r[:9] != key]
    new = stored_rows(tmp_path / "pebbleDischarge.csv")
    added = [r for r in new if r[:9] == key]
    assert len(added) == 1 and added[0][9:] == [2500, 6.0, 313, 59.1, 3.6, -0.072, 2519]
    assert [r for r in new if r[:9] != key] == old


def test_a_chute_shorter_than_a_pebble_is_refused():
    """--chute-length below one diameter: a clear error before any case is
    made."""
    script = pathlib.Path(validate_pebbleDischarge.__file__)
    result = subprocess.run([sys.executable, str(script), "--chute-length", "0.5"],
                            capture_output=True, text=True)
    assert result.returncode == 2
    assert "--chute-length 0.5: the chute must be at least a pebble diameter long" in result.stderr


@pytest.mark.parametrize("option", [["--box", "8,16"], ["--duration", "20"], ["--offset", "0.01"],
                                    ["--upstream", "6"], ["--near", "8"],
                                    ["--convection", "LUST"]])
def test_sphere_drag_options_of_the_refined_table_need_levels(option):
    """The uniform table (results/sphereDrag.csv) has no column for the
    refined runs' box, inlet, near band or scheme: without --levels these
    options are refused before any case is made, so that rows of different
    set-ups are not mixed up."""
    script = pathlib.Path(__file__).parents[1] / "validation" / "validate_sphereDrag.py"
    result = subprocess.run([sys.executable, str(script), *option, "8"],
                            capture_output=True, text=True, timeout=60)
    assert result.returncode == 2
    assert f"{option[0]} go with --levels" in result.stderr


def test_ten_cate_plots_take_every_stored_run_of_the_case_and_step(tmp_path, monkeypatch):
    """validate_tenCate's plots gather the runs of a case at one step factor
    from the runs directory, by resolution, whichever call ran them; runs of
    other cases, other step factors, or without a history stay out."""
    import validate_tenCate
    monkeypatch.setattr(validate_tenCate, "RUNS", tmp_path)
    line = "0.1 sphere " + " ".join(["0.01"]*27) + "\n"
    for name in ("tenCate_E1_12", "tenCate_E1_8", "tenCate_E1_16_step0.5",
                 "tenCate_E2_8", "tenCate_E1_10"):
        history = tmp_path / name / "postProcessing/particles/0"
        history.mkdir(parents=True)
        if name != "tenCate_E1_10":
            (history / "particles.dat").write_text("# header\n" + line)
    assert list(validate_tenCate.stored_histories("E1", "", {})) == \
        ["8 cells/d", "12 cells/d"]
    assert list(validate_tenCate.stored_histories("E1", "_step0.5", {})) == \
        ["16 cells/d, step0.5"]
