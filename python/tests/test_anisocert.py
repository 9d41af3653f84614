"""The Python module against the CLI (issue 43, docs/python.md), run by CTest (Python.Pytest) with
PYTHONPATH=build/python, ANISOCERT_BIN the CLI and ANISOCERT_SOURCE the source tree.

- Every peer and format fixture (tests/peers/fixtures, tests/formats/peers) certified by the module
  and by `anisocert certify --json`: the same report, field for field (the metric's source apart:
  a file name the module is not given), or, for a file the CLI refuses, its message as ValueError.
- The malformed-file catalogue (tests/formats/malformed): `read` and `certify` raise ValueError
  with the CLI's message, on one line.
- Exactness: decimal strings and Fractions are the rationals they spell, floats the doubles they
  are: four points exactly on the unit circle tie when given as "0.6", and do not as floats.
- meshio: a mesh written by meshio and read back is certified as the original.
- Bad arrays (shape, dtype, NaN, index out of range, a metric that is not positive definite or not
  symmetric): ValueError, one line. Progress lines reach the callback; an interrupt stops a long
  call with KeyboardInterrupt.
"""

import _thread
import fractions
import json
import os
import pathlib
import subprocess
import threading
import time

import numpy as np
import pytest

import anisocert

SOURCE = pathlib.Path(os.environ.get("ANISOCERT_SOURCE", pathlib.Path(__file__).resolve().parents[2]))
BIN = os.environ.get("ANISOCERT_BIN", str(SOURCE / "build" / "bin" / "anisocert"))

PEERS = SOURCE / "tests" / "peers" / "fixtures"
FORMATS = SOURCE / "tests" / "formats" / "peers"
FIXTURES = sorted((m, None) for pattern in ("*.msh", "*.mesh", "*.ele") for m in PEERS.glob(pattern)) + sorted(
    (m, None) for m in FORMATS.glob("*/*.msh")) + [
    (FORMATS / "freefem" / "square_hole.msh", FORMATS / "freefem" / "square_hole.mtr"),
    (FORMATS / "freefem" / "square_hole.msh", FORMATS / "freefem" / "square_hole_iso.mtr"),
]


def cli_run(mesh, metric, tmp_path, *args):
    out = tmp_path / "cli.json"
    command = [BIN, "certify", str(mesh), "--json", str(out), *args]
    if metric is not None:
        command += ["--metric", str(metric)]
    r = subprocess.run(command, capture_output=True, text=True)
    return r, (json.loads(out.read_text()) if r.returncode in (0, 1) else None)


def cli_report(mesh, metric, tmp_path, *args):
    r, report = cli_run(mesh, metric, tmp_path, *args)
    assert report is not None, r.stderr
    return report


def without_source(d):
    d = dict(d)
    d.pop("metric_source")
    return d


@pytest.mark.parametrize("mesh,metric", FIXTURES, ids=[f"{m.name}{'+' + s.name if s else ''}" for m, s in FIXTURES])
def test_same_report_as_the_cli(mesh, metric, tmp_path):
    r, expected = cli_run(mesh, metric, tmp_path)
    if expected is None:  # a file the CLI refuses: the same message, as a ValueError
        assert r.returncode == 2, r.stderr
        with pytest.raises(ValueError) as e:
            anisocert.certify(anisocert.read(mesh, metric=metric))
        assert str(e.value) in r.stderr
        return
    report = anisocert.certify(anisocert.read(mesh, metric=metric))
    assert without_source(report.to_dict()) == without_source(expected)
    assert report.holds == expected["holds"]
    assert repr(report).startswith("<anisocert.Report")


@pytest.mark.parametrize("extension", [".vtu", ".json", ".mesh"])
def test_written_formats_read_as_the_cli(extension, tmp_path):
    # The formats no peer fixture is in (VTK's .vtu, the project's JSON), written by the CLI.
    out = tmp_path / f"run{extension}"
    r = subprocess.run([BIN, "refine", "--algo", "bwy", "--field", "shock", "--param", "alpha=3", "--quiet", "-o", str(out)],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    expected = cli_report(out, None, tmp_path, "--field", "shock", "--param", "alpha=3")
    report = anisocert.certify(anisocert.read(out), field="shock", params={"alpha": 3})
    assert report.to_dict() == expected


def test_bounds_as_the_cli(tmp_path):
    mesh, metric = FORMATS / "freefem" / "square_hole.msh", FORMATS / "freefem" / "square_hole.mtr"
    expected = cli_report(mesh, metric, tmp_path, "--rho0", "1.5", "--gamma0", "2", "--length-range", "0.7", "1.4",
                          "--min-quality", "0.5", "--min-angle", "20")
    report = anisocert.certify(anisocert.read(mesh, metric), rho0="1.5", gamma0=2, length_range=("0.7", "1.4"),
                               min_quality=fractions.Fraction(1, 2), min_angle=20)
    assert without_source(report.to_dict()) == without_source(expected)
    assert not report.holds  # bamg's mesh under its own metric meets none of these tight bounds at once


def malformed_cases():
    root = SOURCE / "tests" / "formats" / "malformed"
    return sorted(p for p in root.iterdir() if (p / "case.json").exists() and "args" not in json.loads((p / "case.json").read_text()))


@pytest.mark.parametrize("case", malformed_cases(), ids=lambda p: p.name)
def test_malformed_files_raise_value_error_with_the_clis_message(case):
    c = json.loads((case / "case.json").read_text())
    metric = case / c["metric"] if "metric" in c else None
    with pytest.raises(ValueError) as e:
        anisocert.certify(anisocert.read(case / c["mesh"], metric=metric))
    assert c["message"] in str(e.value)
    assert "\n" not in str(e.value)


def unit_circle_quad(as_text):
    # Four points exactly on the unit circle, as decimals; the quadrilateral split by a diagonal.
    coordinates = [("0.6", "0.8"), ("-0.8", "0.6"), ("0", "-1"), ("1", "0")]
    points = [list(p) for p in coordinates] if as_text else np.array([[float(x), float(y)] for x, y in coordinates])
    return points, np.array([[0, 1, 2], [0, 2, 3]])


def test_decimal_text_is_exact_and_floats_are_the_doubles_they_are():
    identity = [[1, 0, 1]] * 4
    exact = anisocert.certify(*unit_circle_quad(True), identity, checks=["valid", "uniform"]).to_dict()
    fractions_ = anisocert.certify([[fractions.Fraction(x) for x in row] for row in unit_circle_quad(True)[0]],
                                   unit_circle_quad(True)[1], identity, checks=["valid", "uniform"]).to_dict()
    floats = anisocert.certify(*unit_circle_quad(False), identity, checks=["valid", "uniform"]).to_dict()
    # Exactly cocircular: each triangle's fourth point is on its circumcircle, a tie, only when
    # the decimals are read exactly (0.6 and 0.8 are not doubles).
    assert exact["locally_uniform"] == fractions_["locally_uniform"]
    assert exact["locally_uniform"]["tie_count"] == 2 and exact["locally_uniform"]["violation_count"] == 0
    assert floats["locally_uniform"]["tie_count"] == 0


def test_a_number_beyond_the_doubles_is_read(tmp_path):
    # 1e310 is beyond the doubles and within the readers' limit (2^1100): a Fraction, as the CLI reads it.
    mesh = tmp_path / "big.mesh"
    mesh.write_text("MeshVersionFormatted 2\nDimension 2\nVertices\n3\n0 0 1\n1e310 0 1\n0 1 1\nTriangles\n1\n1 2 3 1\nEnd\n")
    m = anisocert.read(mesh)
    assert m.points.dtype == object and m.points[1][0] == fractions.Fraction(10) ** 310
    assert anisocert.certify(m).holds


def test_interrupt_stops_a_refiner():
    # The worker stops at its next progress line (a refiner prints about one a second).
    timer = threading.Timer(1.5, _thread.interrupt_main)
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        anisocert.refine("cube", "ugawg-linear", params={"h0": "0.02"})  # some 35 s if not stopped
    time.sleep(1.5)  # its next line
    cpu = time.process_time()
    time.sleep(1)
    assert time.process_time() - cpu < 0.3  # no worker left computing


def test_wide_numbers_are_not_narrowed():
    # Numbers no double holds are read as they are: were they rounded to doubles first, each pair
    # of reports below would be equal.
    # (0, 0), (2⁵³ + 1, 1), (3·2⁵³ + 3, 3) are collinear; as doubles the third is 3·2⁵³ + 4: not.
    wide = np.array([[0, 0], [2**53 + 1, 1], [3 * 2**53 + 3, 3]], dtype=np.int64)
    exact, rounded = (anisocert.certify(p, TRIANGLE[1]).to_dict() for p in (wide, wide.astype(np.float64)))
    assert exact != rounded
    assert anisocert.certify(np.array([[0, 0], [-2**63, 0], [0, -1]], dtype=np.int64), TRIANGLE[1]).valid.holds
    if np.finfo(np.longdouble).nmant > 52:  # x86-64's 80-bit long double: (1 + 2⁻⁶⁰, 0) is not (1, 0)
        points = np.array([[0, 0], [1, 0], [0, 1], [1 + np.longdouble(2) ** -60, 0]], dtype=np.longdouble)
        cells = np.array([[0, 1, 2], [1, 3, 2]])
        exact, rounded = (anisocert.certify(p, cells).to_dict() for p in (points, points.astype(np.float64)))
        assert exact != rounded


def test_meshio_round_trip(tmp_path):
    meshio = pytest.importorskip("meshio")
    m = anisocert.read(FORMATS / "freefem" / "square_hole.msh", metric=FORMATS / "freefem" / "square_hole.mtr")
    # meshio stores doubles: the reference is the mesh as doubles (the .mtr's decimals rounded).
    direct = anisocert.certify(m.points.astype(float), m.cells, m.metrics.astype(float), edges=m.edges)
    points = np.column_stack([m.points.astype(float), np.zeros(len(m.points))])
    written = meshio.Mesh(points, [("triangle", m.cells), ("line", m.edges)], point_data={"metric": m.metrics.astype(float)})
    path = tmp_path / "m.vtu"
    meshio.write(path, written)
    back = meshio.read(path)
    via_meshio = anisocert.certify_meshio(back, metric="metric")
    assert via_meshio.to_dict() == direct.to_dict()
    full = meshio.Mesh(points, [("triangle", m.cells), ("line", m.edges)],
                       point_data={"M": np.array([[a, b, b, c] for a, b, c in m.metrics.astype(float)])})
    assert anisocert.certify_meshio(full, metric="M").to_dict() == direct.to_dict()
    with pytest.raises(ValueError, match="no point data named"):
        anisocert.certify_meshio(back, metric="missing")
    with pytest.raises(ValueError, match="mesh: quad cells"):
        anisocert.certify_meshio(meshio.Mesh(points, [("triangle", m.cells), ("quad", [[0, 1, 2, 3]])]))


def test_tetrahedra_from_meshio():
    meshio = pytest.importorskip("meshio")
    m = anisocert.read(PEERS / "gmsh-box-h0.3.msh")
    metric = np.tile([100.0, 0, 0, 100, 0, 100], (len(m.points), 1))
    direct = anisocert.certify(m.points, m.cells, metric, triangles=m.triangles)
    nine = np.tile(np.diag([100.0, 100, 100]).reshape(9), (len(m.points), 1))
    via = anisocert.certify_meshio(meshio.Mesh(m.points, [("tetra", m.cells), ("triangle", m.triangles)], point_data={"M": nine}),
                                   metric="M")
    assert via.to_dict() == direct.to_dict()
    assert "locally_uniform" in direct and not direct.holds  # Gmsh's isotropic mesh is no star set


TRIANGLE = (np.array([[0.0, 0], [1, 0], [0, 1]]), np.array([[0, 1, 2]]))


@pytest.mark.parametrize("call,message", [
    (lambda: anisocert.certify(np.zeros((3, 4)), TRIANGLE[1]), "points: expected shape"),
    (lambda: anisocert.certify(TRIANGLE[0], np.array([[0, 1]])), "cells: expected shape (m, 3)"),
    (lambda: anisocert.certify(TRIANGLE[0], np.array([[0.0, 1, 2]])), "cells: expected integer indices"),
    (lambda: anisocert.certify(np.array([[0.0, 0], [1, np.nan], [0, 1]]), TRIANGLE[1]), "points[1][1]"),
    (lambda: anisocert.certify(TRIANGLE[0], np.array([[0, 1, 7]])), "site 7 does not exist"),
    (lambda: anisocert.certify(TRIANGLE[0], np.array([[0, 1, -1]])), "cells[0][2]: index -1 out of range"),
    (lambda: anisocert.certify(*TRIANGLE, [[1, 0, 1], [1, 2, 1], [1, 0, 1]]), "metrics[1]: the metric [1, 2, 1] is not positive definite"),
    (lambda: anisocert.certify(*TRIANGLE, [[[1, 0], [1, 1]]] * 3), "metrics[0]: not symmetric"),
    (lambda: anisocert.certify(*TRIANGLE, [["1", "0", "x"]] * 3), "metrics[0][2]"),
    (lambda: anisocert.certify(*TRIANGLE, [[1, 0, True]] * 3), "metrics[0][2]: True is not a number"),
    (lambda: anisocert.certify(*TRIANGLE, rho0=2), "has no metric"),
    (lambda: anisocert.certify(*TRIANGLE, [[1, 0, 1]] * 3, checks=["valid", "shape"]), 'unknown check "shape"'),
    (lambda: anisocert.certify(*TRIANGLE, [[1, 0, 1]] * 3, gamma0="0.5"), "gamma0 must be at least 1"),
    (lambda: anisocert.read("/nonexistent/mesh.mesh"), "/nonexistent/mesh.mesh"),
    (lambda: anisocert.certify(np.zeros((3, 3)), TRIANGLE[1]), "cells: triangles (m, 3) with points of 3 coordinates"),
    (lambda: anisocert.certify(TRIANGLE[0], np.array([[0, 1, 2**63 + 1]], dtype=np.uint64)), "cells[0][2]: index 9223372036854775809 out of range"),
    (lambda: anisocert.certify(TRIANGLE[0], [[0, 1, 10**30]]), "cells[0][2]: index 1000000000000000000000000000000 out of range"),
    (lambda: anisocert.certify(TRIANGLE[0], np.zeros((0, 3), dtype=int)), "mesh: has no triangles"),
    (lambda: anisocert.certify(*TRIANGLE, threads=2.7), "threads: expected a whole number"),
    (lambda: anisocert.certify(*TRIANGLE, all_witnesses="no"), "all_witnesses: expected True or False"),
    (lambda: anisocert.certify(*TRIANGLE, [[1, 0, 1]] * 3, length_range="12"), "length_range: expected (low, high)"),
    (lambda: anisocert.certify(*TRIANGLE, [[1, 0, 1]] * 3, params={"h": 1}), "params: given without a field"),
    (lambda: anisocert.certify(*TRIANGLE, triangles=[[0, 1, 2]]), "triangles: declared boundary triangles are for tetrahedral meshes"),
    (lambda: anisocert.certify(*TRIANGLE, progress=5), "progress: expected a callable"),
    (lambda: anisocert.certify_meshio("mesh.vtu"), "mesh: expected a meshio.Mesh"),
    (lambda: anisocert.certify(*TRIANGLE, [[1, 0, 1]] * 3, length_range=(None, "0.5")), "length_range: expected (low, high)"),
    (lambda: anisocert.certify(*TRIANGLE, checks=[1]), "checks: expected names"),
    (lambda: anisocert.certify(*TRIANGLE, checks=5), "checks: expected names"),
    (lambda: anisocert.read(SOURCE / "tests" / "peers" / "fixtures" / "gmsh-box-h0.3.msh", format=3), "format: expected"),
])
def test_bad_input_raises_value_error_on_one_line(call, message):
    with pytest.raises(ValueError) as e:
        call()
    assert message in str(e.value)
    assert "\n" not in str(e.value)


def grid(n):
    x, y = np.meshgrid(np.arange(n + 1, dtype=float), np.arange(n + 1, dtype=float))
    points = np.column_stack([x.ravel(), y.ravel()]) / n
    i = np.arange(n)[:, None] * (n + 1) + np.arange(n)[None, :]
    i = i.ravel()
    cells = np.concatenate([np.column_stack([i, i + 1, i + n + 2]), np.column_stack([i, i + n + 2, i + n + 1])])
    return points, cells


def test_progress_lines_and_svg():
    lines = []
    points, cells = grid(4)
    report = anisocert.certify(points, cells, np.tile([16.0, 0, 16], (len(points), 1)), progress=lines.append)
    assert lines == [f"certifying {len(cells)} triangles", "done"]
    assert report.holds and report.valid.holds
    assert report.svg().lstrip().startswith("<")
    assert "certified" in report.text


def test_interrupt_stops_a_long_call():
    points, cells = grid(500)  # 500,000 triangles: several seconds of checks
    metrics = np.tile([250000.0, 0, 250000], (len(points), 1))
    timer = threading.Timer(0.3, _thread.interrupt_main)
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        anisocert.certify(points, cells, metrics)
    interrupted = time.monotonic() - start
    start = time.monotonic()
    anisocert.certify(points, cells, metrics)  # the whole call, on the same machine under the same load
    # about 0.4 s against 4 s on one idle core; a wall bound alone failed under three background campaigns
    assert interrupted < (time.monotonic() - start) / 2


def test_field_as_the_cli(tmp_path):
    mesh = PEERS / "gmsh-lshape-shock-coarse.msh"
    expected = cli_report(mesh, None, tmp_path, "--field", "shock", "--param", "h=0.1")
    report = anisocert.certify(anisocert.read(mesh), field="shock", params={"h": "0.1"})
    assert report.to_dict() == expected  # the metric's source too: "--field shock"
    box = PEERS / "gmsh-box-h0.3.msh"
    expected3 = cli_report(box, None, tmp_path, "--field", "ugawg-linear", "--param", "h0=0.05")
    report3 = anisocert.certify(anisocert.read(box), field="ugawg-linear", params={"h0": 0.05})
    assert report3.to_dict() == expected3
    square = anisocert.read(FORMATS / "freefem" / "square_hole.msh", metric=FORMATS / "freefem" / "square_hole.mtr")
    assert without_source(anisocert.certify(square, field="shock", params={"h": "0.1"}).to_dict()) == without_source(
        cli_report(FORMATS / "freefem" / "square_hole.msh", None, tmp_path, "--field", "shock", "--param", "h=0.1"))
    with pytest.raises(ValueError, match="give one metric source"):
        anisocert.certify(anisocert.read(box), metrics=np.ones((339, 6)), field="ugawg-linear")
    with pytest.raises(ValueError, match="cells: given beside a Mesh"):
        anisocert.certify(anisocert.read(box), np.ones((339, 6)))


def test_refine_dual_as_the_cli(tmp_path):
    out = tmp_path / "bwy.mesh"
    r = subprocess.run([BIN, "refine", "--algo", "bwy", "--field", "shock", "--param", "alpha=3", "--quiet", "-o", str(out)],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    run = anisocert.refine("square", "shock", "bwy", params={"alpha": 3})
    written = anisocert.read(out)
    assert run.consistent and np.array_equal(run.points, written.points) and np.array_equal(run.cells, written.cells)
    assert np.array_equal(run.metrics, written.metrics)
    assert [line for line in run.lines if " s (" not in line] == [line for line in r.stdout.splitlines()[1:] if line.startswith("  ") and " s (" not in line and "mesh:" not in line]
    d = subprocess.run([BIN, "dual", str(out), "--quiet", "--json", str(tmp_path / "dual.json")], capture_output=True, text=True)
    assert d.returncode == 0, d.stderr
    lines = []
    report = anisocert.dual(written, progress=lines.append)
    expected = json.loads((tmp_path / "dual.json").read_text())
    got = report.to_dict()
    assert got["input"]["metric_source"] == "" and anisocert.dual(written.points, written.cells, field="shock", params={"alpha": 3}).input.metric_source == "--field shock"
    for d in (got, expected):  # the time taken, and the metric file's name the module is not given
        d.pop("seconds"), d["input"].pop("metric_source")
    assert report.is_dual and got == expected
    assert lines  # the diagram's progress lines
    assert report.svg().lstrip().startswith("<")


def test_refine_3d_is_certified_as_the_cli(tmp_path):
    out, js = tmp_path / "cube.mesh", tmp_path / "cube.json"
    args = ["--algo", "star", "--domain", "cube", "--field", "constant", "--param", "m11=25", "--param", "m22=25", "--param", "m33=25"]
    r = subprocess.run([BIN, "refine", *args, "--quiet", "-o", str(out), "--json", str(js)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    run = anisocert.refine("cube", "constant", params={"m11": 25, "m22": 25, "m33": 25})
    assert run.consistent and run.certificate.holds
    written = anisocert.read(out)
    assert np.array_equal(run.points, written.points) and np.array_equal(run.cells, written.cells)
    assert run.certificate.to_dict() == json.loads(js.read_text())
    tight = anisocert.refine("cube", "constant", params={"m11": 25, "m22": 25, "m33": 25}, rho0="3.1")
    assert tight.certificate.radius_edge.threshold == "3.1"  # as printed, as the CLI prints it


def test_diagram_as_the_cli(tmp_path):
    source = SOURCE / "tests" / "regressions" / "site-on-domain-corner-called-orphan" / "input.json"
    spec = json.loads(source.read_text())
    r = subprocess.run([BIN, "diagram", str(source), "--quiet", "--json", str(tmp_path / "d.json")], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    report = anisocert.diagram([[s["x"], s["y"]] for s in spec["sites"]], [s["metric"] for s in spec["sites"]], spec["domain"])
    got, expected = report.to_dict(), json.loads((tmp_path / "d.json").read_text())
    for d in (got, expected):
        d.pop("stats")  # the filters' work counts and times, which depend on the threads
    assert got == expected
    assert report.svg().lstrip().startswith("<")


@pytest.mark.parametrize("call,message", [
    (lambda: anisocert.refine(algo="nope"), 'algo: unknown refiner "nope"'),
    (lambda: anisocert.refine(rho0="x"), "rho0"),
    (lambda: anisocert.refine(colour=1), 'parameter "colour": not one of'),
    (lambda: anisocert.refine("triangle"), 'domain "triangle": no such built-in domain'),
    (lambda: anisocert.refine([[0, 0], [1, 0], [1, 1], [2, 0.5]]), "domain"),
    (lambda: anisocert.refine(field="nope"), "nope"),
    (lambda: anisocert.refine(max_vertices="1.5"), "max_vertices 1.5: expected a positive whole number"),
    (lambda: anisocert.dual(TRIANGLE[0], TRIANGLE[1]), "has no metric"),
    (lambda: anisocert.refine(seed=-1), "seed: expected a whole number in [0, 4294967295]"),
    (lambda: anisocert.refine(algo="ls", normalized_metric=0.5), 'parameter "normalized-metric": a flag'),
    (lambda: anisocert.diagram(np.zeros((0, 2)), np.zeros((0, 3)), [[0, 0], [1, 0], [0, 1]]), "sites: none"),
    (lambda: anisocert.diagram([[0.2, 0.2], [0.2, 0.2]], [[1, 0, 1]] * 2, [[0, 0], [1, 0], [0, 1]]), "sites[0] and sites[1] coincide"),
    (lambda: anisocert.diagram([[0, 0]], [[1, 0, 1]], [[0, 0], [0, 1], [1, 0]]), "domain"),
    (lambda: anisocert.diagram([[0, 0], [1, 1]], [[1, 0, 1]], [[0, 0], [1, 0], [0, 1]]), "metrics: 1 metrics for 2 sites"),
])
def test_bad_input_to_dual_diagram_refine(call, message):
    with pytest.raises(ValueError) as e:
        call()
    assert message in str(e.value)
    assert "\n" not in str(e.value)
