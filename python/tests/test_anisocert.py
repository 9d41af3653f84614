"""The Python module against the CLI (issue 43, docs/python.md), run by CTest (Python.Pytest) with
PYTHONPATH=build/python, ANISOCERT_BIN the CLI and ANISOCERT_SOURCE the source tree.

- Every peer and format fixture certified by the module and by `anisocert certify --json`: the
  same report, field for field (the metric's source apart: a file name the module is not given).
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
FIXTURES = [
    (PEERS / "gmsh-constant-20deg.msh", None),
    (PEERS / "freefem-constant-20deg.msh", None),
    (PEERS / "bamg-constant-20deg.msh", None),
    (PEERS / "gmsh-lshape-shock-coarse.msh", None),
    (PEERS / "freefem-lshape-shock-coarse.msh", None),
    (PEERS / "gmsh-box-h0.3.msh", None),
    (PEERS / "cgal-ball-h0.25.mesh", None),
    (PEERS / "tetgen-box-q1.414a0.01.ele", None),
    (FORMATS / "freefem" / "square_hole.msh", FORMATS / "freefem" / "square_hole.mtr"),
    (FORMATS / "freefem" / "square_hole.msh", FORMATS / "freefem" / "square_hole_iso.mtr"),
    (FORMATS / "freefem" / "bamg_adapted.msh", None),
    (FORMATS / "gmsh" / "metric-41-bin.msh", None),
    (FORMATS / "gmsh" / "metric-hand-written.msh", None),
    (FORMATS / "gmsh" / "square-hole-22.msh", None),
    (FORMATS / "gmsh" / "square-hole-41-bin.msh", None),
]


def cli_report(mesh, metric, tmp_path, *args):
    out = tmp_path / "cli.json"
    command = [BIN, "certify", str(mesh), "--json", str(out), *args]
    if metric is not None:
        command += ["--metric", str(metric)]
    r = subprocess.run(command, capture_output=True, text=True)
    assert r.returncode in (0, 1), r.stderr
    return json.loads(out.read_text())


def without_source(d):
    d = dict(d)
    d.pop("metric_source")
    return d


@pytest.mark.parametrize("mesh,metric", FIXTURES, ids=[f"{m.name}{'+' + s.name if s else ''}" for m, s in FIXTURES])
def test_same_report_as_the_cli(mesh, metric, tmp_path):
    expected = cli_report(mesh, metric, tmp_path)
    report = anisocert.certify(anisocert.read(mesh, metric=metric))
    assert without_source(report.to_dict()) == without_source(expected)
    assert report.holds == expected["holds"]
    assert repr(report).startswith("<anisocert.Report")


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
    assert time.monotonic() - start < 2.5  # the whole call takes about 4 s on one core
