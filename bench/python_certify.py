#!/usr/bin/python3
"""The Python module beside the CLI on one mesh (issue 43): a structured 500 × 500 grid of the
unit square (500,000 triangles), the constant metric 250,000 I (edges along the axes of unit
length, diagonals √2), certified by `anisocert.certify` from numpy arrays and by `anisocert
certify` from a JSON file holding the same rationals (exact fractions), one thread each, wall
clock, one run each. Both reports must be equal (the metric's source apart).
Run: /usr/bin/python3 bench/python_certify.py   (after scripts/build all; figures in docs/bench.md)."""

import json
import pathlib
import subprocess
import sys
import tempfile
import time

import numpy as np

root = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(root / "build" / "python"))
import anisocert  # noqa: E402

n = 500
x, y = np.meshgrid(np.arange(n + 1, dtype=float), np.arange(n + 1, dtype=float))
points = np.column_stack([x.ravel(), y.ravel()]) / n
i = (np.arange(n)[:, None] * (n + 1) + np.arange(n)[None, :]).ravel()
cells = np.concatenate([np.column_stack([i, i + 1, i + n + 2]), np.column_stack([i, i + n + 2, i + n + 1])])
metrics = np.tile([250000.0, 0, 250000], (len(points), 1))


def exact(v):
    p, q = float(v).as_integer_ratio()
    return f"{p}/{q}"


with tempfile.TemporaryDirectory() as work:
    mesh = pathlib.Path(work) / "grid.json"
    mesh.write_text(json.dumps({"sites": [{"x": exact(a), "y": exact(b), "metric": ["250000", "0", "250000"]} for a, b in points],
                                "triangles": cells.tolist()}))
    t0 = time.perf_counter()
    report = anisocert.certify(points, cells, metrics, threads=1)
    module = time.perf_counter() - t0
    out = pathlib.Path(work) / "cli.json"
    t0 = time.perf_counter()
    run = subprocess.run([str(root / "build" / "bin" / "anisocert"), "certify", str(mesh), "--threads", "1", "--json", str(out)],
                         capture_output=True, text=True)
    cli = time.perf_counter() - t0
    assert run.returncode in (0, 1), run.stderr
    expected, got = json.loads(out.read_text()), report.to_dict()
    for d in (expected, got):
        d.pop("metric_source")
    print(f"{len(cells)} triangles: module {module:.2f} s (from numpy arrays), CLI {cli:.2f} s (from a JSON file), "
          f"same report: {expected == got}, {report!r}")
    sys.exit(0 if expected == got else 1)
