"""anisocert: exact certification of anisotropic triangle and tetrahedral meshes (docs/python.md).

    import anisocert
    report = anisocert.certify(points, cells, metrics, rho0="3")
    report.holds, report.valid.holds, report.metric.unit_edges, report.svg()

Every number is exact: a float is the rational it is, a ``fractions.Fraction`` or an ``int`` is
itself, a string is the decimal or fraction it spells ("0.1" is 1/10). Nothing is rounded on the
way. The checks and the report are ``anisocert certify``'s (the same C++ code, the same JSON).
Bad input raises ``ValueError`` with one line naming what is wrong and where.
"""

import decimal
import fractions
import json
import numbers

import numpy as np

from . import _anisocert

__all__ = ["certify", "certify_meshio", "read", "dual", "diagram", "refine", "Mesh", "Report", "Refinement"]


class Mesh:
    """A mesh as `read` returns it: points (n, 2) or (n, 3), cells (m, 3) triangles or (m, 4)
    tetrahedra, metrics (n, 3) or (n, 6) or None, the declared edges (2D) or boundary triangles
    (3D), and a JSON mesh's domain polygon and constrained segments (2D). Numbers are float64 arrays when every one is a double, else object arrays of Fractions."""

    def __init__(self, points, cells, metrics=None, edges=None, triangles=None, metric_source="", domain=None, segments=None):
        self.points, self.cells, self.metrics = points, cells, metrics
        self.edges, self.triangles, self.metric_source = edges, triangles, metric_source
        self.domain, self.segments = domain, segments  # a JSON mesh's domain polygon and constrained segments (2D)

    @property
    def dimension(self):
        return self.points.shape[1]

    def __repr__(self):
        kind = "triangles" if self.dimension == 2 else "tetrahedra"
        metric = "with metrics" if self.metrics is not None else "no metric"
        return f"<anisocert.Mesh: {len(self.points)} vertices, {len(self.cells)} {kind}, {metric}>"


def _token(x, where):
    """The exact text of one number (parse_input_number reads it back exactly)."""
    if isinstance(x, (bool, np.bool_)):
        raise ValueError(f"{where}: {x!r} is not a number")
    if isinstance(x, str):
        return x.strip()
    if isinstance(x, numbers.Integral):
        return str(int(x))
    if isinstance(x, fractions.Fraction):
        return f"{x.numerator}/{x.denominator}"
    if isinstance(x, decimal.Decimal):
        if not x.is_finite():
            raise ValueError(f"{where}: {x} is not finite")
        return str(x)
    if isinstance(x, (float, np.floating)):
        if not np.isfinite(x):
            raise ValueError(f"{where}: {x} is not finite")
        n, d = x.as_integer_ratio()
        return f"{n}/{d}"
    raise ValueError(f"{where}: {type(x).__name__} {x!r} is not a number (float, int, Fraction, Decimal or str)")


def _numbers(a, what, columns):
    """A float64 array (exact as it is) or rows of exact tokens, of shape (n, k), k in columns."""
    if isinstance(a, np.ndarray) and a.dtype.kind == "f" and a.dtype.itemsize <= 8:
        arr = a  # float16, float32 and float64 widen to float64 exactly
    else:
        arr = np.asarray(a, dtype=object) if not isinstance(a, np.ndarray) else a
        if arr.dtype.kind in "iu" and (arr.size == 0 or (int(arr.min()) >= -2**53 and int(arr.max()) <= 2**53)):
            arr = arr.astype(np.float64)  # integers of at most 53 bits are doubles exactly
        elif arr.dtype.kind != "O":
            arr = arr.astype(object)  # longdouble, larger integers: element by element, exactly
    if arr.ndim != 2 or arr.shape[1] not in columns:
        expected = " or ".join(f"(n, {c})" for c in columns)
        raise ValueError(f"{what}: expected shape {expected}, got {tuple(arr.shape)}")
    if arr.dtype.kind == "f":
        return np.ascontiguousarray(arr, dtype=np.float64)
    return [[_token(x, f"{what}[{i}][{j}]") for j, x in enumerate(row)] for i, row in enumerate(arr)]


def _indices(a, what, k):
    arr = np.asarray(a)
    if arr.ndim != 2 or arr.shape[1] != k:
        raise ValueError(f"{what}: expected shape (m, {k}), got {tuple(arr.shape)}")
    if arr.dtype == object:  # Python integers, perhaps beyond 64 bits
        for (i, j), x in np.ndenumerate(arr):
            if isinstance(x, (bool, np.bool_)) or not isinstance(x, numbers.Integral):
                raise ValueError(f"{what}[{i}][{j}]: {x!r} is not an index")
            if not 0 <= x < 2**31:
                raise ValueError(f"{what}[{i}][{j}]: index {x} out of range")
        arr = arr.astype(np.int64)
    if arr.size and arr.dtype.kind not in "iu":
        raise ValueError(f"{what}: expected integer indices, got {arr.dtype}")
    if arr.size and arr.dtype.kind == "u" and arr.max() >= 2**31:  # before int64 could wrap it
        i, j = np.unravel_index(int(arr.argmax()), arr.shape)
        raise ValueError(f"{what}[{i}][{j}]: index {arr[i, j]} out of range")
    return np.ascontiguousarray(arr, dtype=np.int64)


def _symmetric(metrics, dimension):
    """Metrics as (n, 3) [m11 m12 m22] in 2D or (n, 6) [m11 m12 m13 m22 m23 m33] in 3D, from those
    or from full matrices ((n, d, d) or (n, d·d)), whose symmetry is checked exactly."""
    arr = metrics if isinstance(metrics, np.ndarray) else np.asarray(metrics, dtype=object)
    full = dimension * dimension
    if arr.ndim == 3 and arr.shape[1:] == (dimension, dimension):
        arr = arr.reshape(len(arr), full)
    if arr.ndim == 2 and arr.shape[1] == full:
        upper = [(i, j) for i in range(dimension) for j in range(i, dimension)]
        for v in range(len(arr)):
            for i, j in upper:
                a, b = arr[v][i * dimension + j], arr[v][j * dimension + i]
                if _exact_value(a, f"metrics[{v}]") != _exact_value(b, f"metrics[{v}]"):
                    raise ValueError(f"metrics[{v}]: not symmetric (entry ({i + 1}, {j + 1}) is {a}, ({j + 1}, {i + 1}) is {b})")
        arr = arr[:, [i * dimension + j for i, j in upper]]
    return _numbers(arr, "metrics", [3] if dimension == 2 else [6])


def _exact_value(x, where):
    t = _token(x, where)
    try:
        return fractions.Fraction(t)
    except (ValueError, ZeroDivisionError):
        raise ValueError(f"{where}: {t!r} is not an exact number") from None


def _integer(x, what, low, high=None):
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, numbers.Integral) or x < low or (high is not None and x > high):
        bound = f"in [{low}, {high}]" if high is not None else f"at least {low}"
        raise ValueError(f"{what}: expected a whole number {bound}, got {x!r}")
    return int(x)


def _flag(x, what):
    if not isinstance(x, (bool, np.bool_)):
        raise ValueError(f"{what}: expected True or False, got {x!r}")
    return bool(x)


def _callback(progress):
    if progress is not None and not callable(progress):
        raise ValueError(f"progress: expected a callable taking a line of text, got {progress!r}")
    return progress


def _bound(x, what):
    return None if x is None else _token(x, what)


def certify(points, cells=None, metrics=None, *, field=None, params=None, checks=None, rho0=None, gamma0=None,
            length_range=None, min_quality=None, min_angle=None, edges=None, triangles=None, domain=None, segments=None,
            all_witnesses=False, threads=0, progress=None, name="mesh"):
    """Certifies a triangle mesh (points (n, 2), cells (m, 3)) or a tetrahedral one (points (n, 3),
    cells (m, 4)), as ``anisocert certify`` does. Returns a Report; ``report.holds`` is the verdict.

    metrics: one per vertex: 2D (n, 3) m11 m12 m22, or (n, 2, 2); 3D (n, 6) m11 m12 m13 m22 m23
        m33, or (n, 3, 3). Without metrics (and field) only validity is checked.
    field, params: instead of metrics, a built-in field (the CLI's --field: "shock", "radial",
        "linear", "constant", "ugawg-linear", ..., or "background:MESH[:METRIC]") with its
        parameters (the CLI's --param), evaluated at the vertices as the CLI does.
    checks: which of "valid", "uniform" (locally uniform), "metric" (edge lengths, qualities,
        angles in the metrics) to run; default all three (only "valid" without a metric).
    rho0, gamma0, length_range=(low, high), min_quality, min_angle: bounds decided exactly
        (radius-edge ratio, distortion, edge lengths, mean-ratio quality, angles in degrees);
        default none (measured, not judged).
    edges (2D): the declared boundary edges (m, 2); triangles (3D): the declared boundary
        triangles (m, 3), which must be exactly the boundary faces. domain (2D): the polygon the
        triangles must cover (c, 2), counter-clockwise; segments (2D): edges the mesh must hold.
    all_witnesses: describe every witness (default: the first 100 of each list, all counted).
    threads: threads for the locally uniform check (0, the default: one per core; same report).
    progress: a callable given progress lines. name: how the report's text names the mesh.
    points may also be a Mesh from `read` (then no cells; its metrics unless metrics or field)."""
    if isinstance(points, Mesh):
        mesh = points
        edges = mesh.edges if edges is None and mesh.dimension == 2 else edges
        domain = mesh.domain if domain is None and mesh.dimension == 2 else domain
        segments = mesh.segments if segments is None and mesh.dimension == 2 and mesh.segments is not None and len(mesh.segments) else segments
        triangles = mesh.triangles if triangles is None and mesh.dimension == 3 else triangles
    points, cells, metrics = _mesh_or_arrays(points, cells, metrics, field)
    if cells is None:
        raise ValueError("cells: missing (give the triangles or tetrahedra)")
    pts = _numbers(points, "points", [2, 3])
    dimension = pts.shape[1] if isinstance(pts, np.ndarray) else len(pts[0]) if pts else np.asarray(points).shape[1]
    shape = np.shape(cells)
    if dimension == 3 and len(shape) == 2 and shape[1] == 3:
        raise ValueError("cells: triangles (m, 3) with points of 3 coordinates: give points (n, 2) for a planar triangle mesh, "
                         "or tetrahedra (m, 4)")
    if len(shape) == 2 and shape[0] == 0:
        raise ValueError(f"{name}: has no {'triangles' if dimension == 2 else 'tetrahedra'}")
    if dimension == 3 and (domain is not None or segments is not None):
        raise ValueError("domain, segments: a polygon and its segments are for triangle meshes")
    if dimension == 3 and edges is not None:
        raise ValueError("edges: declared boundary edges are for triangle meshes (give triangles= for tetrahedra)")
    if dimension == 2 and triangles is not None:
        raise ValueError("triangles: declared boundary triangles are for tetrahedral meshes (give edges= for triangles)")
    if params is not None and field is None:
        raise ValueError("params: given without a field")
    if length_range is not None and (isinstance(length_range, str) or not hasattr(length_range, "__len__") or len(length_range) != 2
                                     or any(end is None for end in length_range)):
        raise ValueError(f"length_range: expected (low, high), got {length_range!r}")
    if checks is not None:
        checks = [checks] if isinstance(checks, str) else checks
        if not isinstance(checks, (list, tuple, set)) or not all(isinstance(c, str) for c in checks):
            raise ValueError(f"checks: expected names among valid, uniform, metric, got {checks!r}")
    bounds = {"rho0": rho0, "gamma0": gamma0, "min_quality": min_quality, "min_angle": min_angle}
    if metrics is not None and field is not None:
        raise ValueError("metrics and field: give one metric source")
    has_metric = metrics is not None or field is not None
    if not has_metric and (any(v is not None for v in bounds.values()) or length_range is not None or
                            (checks is not None and ("uniform" in checks or "metric" in checks))):
        raise ValueError(f"{name}: has no metric, which the requested checks and bounds need (give metrics)")
    options = {k: _bound(v, k) for k, v in bounds.items()}
    if length_range is not None:
        options["length_lo"], options["length_hi"] = _bound(length_range[0], "length_range"), _bound(length_range[1], "length_range")
    if checks is not None:
        options["checks"] = list(checks)
    options["all_witnesses"], options["threads"] = _flag(all_witnesses, "all_witnesses"), _integer(threads, "threads", 0, 1024)
    progress = _callback(progress)
    m = None if metrics is None else _symmetric(metrics, dimension)
    field, params = "" if field is None else str(field), _params(params)
    if dimension == 2:
        native = _anisocert.certify2(pts, _indices(cells, "cells", 3), m,
                                     None if edges is None else _indices(edges, "edges", 2),
                                     None if domain is None else _numbers(domain, "domain", [2]),
                                     None if segments is None else _indices(segments, "segments", 2), field, params, options, progress)
    else:
        native = _anisocert.certify3(pts, _indices(cells, "cells", 4), m,
                                     None if triangles is None else _indices(triangles, "triangles", 3), field, params,
                                     options, progress)
    return Report(native, str(name))


def _params(params):
    """A field's or a refiner's parameters as exact texts (the CLI's --param name=value)."""
    if params is None:
        return {}
    if not isinstance(params, dict):
        raise ValueError("params: expected a dict of name: value")
    return {str(k): _token(v, f"params[{k!r}]") for k, v in params.items()}


def _mesh_or_arrays(points, cells, metrics, field):
    if isinstance(points, Mesh):
        if cells is not None:
            raise ValueError("cells: given beside a Mesh, which has its own (pass metrics=... by name)")
        return points.points, points.cells, points.metrics if metrics is None and field is None else metrics
    return points, cells, metrics


def dual(points, cells=None, metrics=None, *, field=None, params=None, exact_only=False, threads=0, progress=None,
         name="mesh"):
    """Is the triangle mesh the dual of the exact anisotropic Voronoi diagram of its own vertices,
    D|Ω with Ω the boundary of its triangles (``anisocert dual``)? Returns a DualReport:
    ``is_dual``, the JSON's fields as attributes, ``text``, ``svg()``."""
    points, cells, metrics = _mesh_or_arrays(points, cells, metrics, field)
    if cells is None:
        raise ValueError("cells: missing (give the triangles)")
    if metrics is not None and field is not None:
        raise ValueError("metrics and field: give one metric source")
    if params is not None and field is None:
        raise ValueError("params: given without a field")
    m = None if metrics is None else _symmetric(metrics, 2)
    native = _anisocert.dual(_numbers(points, "points", [2]), _indices(cells, "cells", 3), m, "" if field is None else str(field),
                             _params(params), _flag(exact_only, "exact_only"), _integer(threads, "threads", 0, 1024), str(name),
                             _callback(progress))
    return DualReport(native, str(name))


def diagram(sites, metrics, domain, *, exact_only=False, threads=0, progress=None, name="sites"):
    """The exact anisotropic Voronoi diagram of ``sites`` (k, 2) with ``metrics`` (k, 3) [or full],
    restricted to the simple counter-clockwise polygon ``domain`` (c, 2) (``anisocert diagram``).
    Returns a DiagramReport: the JSON's fields (docs/oracle.md) as attributes, ``svg()``."""
    native = _anisocert.diagram(_numbers(sites, "sites", [2]), _symmetric(metrics, 2), _numbers(domain, "domain", [2]),
                                _flag(exact_only, "exact_only"), _integer(threads, "threads", 0, 1024), str(name), _callback(progress))
    return DiagramReport(native)


def refine(domain="square", field=None, algo="star", *, params=None, max_vertices=None, max_seconds=None, seed=1,
           progress=None, **parameters):
    """Runs a refiner (``anisocert refine``): ``algo`` star, ls or bwy; ``domain`` "square", a JSON
    domain file or a polygon's corners (c, 2), or in 3D (algo star) "cube", "cube-cylinder" or a
    closed surface file; ``field`` a built-in field (default: shock in 2D, ugawg-linear in 3D) with
    ``params``; the refiner's parameters as keywords (rho0=3, gamma0=1.5, ...). Returns a
    Refinement: points, cells, metrics (the refiner's doubles), edges (2D boundary) or triangles
    (3D), ``consistent``, ``stop_reason``, the report ``lines``, and for 3D the ``certificate``."""
    if not isinstance(domain, str):
        domain = _numbers(domain, "domain", [2])
    # normalized_metric=True is the CLI's --normalized-metric: "-" for "_", a flag as 1 or 0.
    named = {k.replace("_", "-"): (int(v) if isinstance(v, (bool, np.bool_)) else v) for k, v in parameters.items()}
    d = _anisocert.refine(domain, str(algo), "" if field is None else str(field), _params(params), _params(named),
                          "" if max_vertices is None else _token(max_vertices, "max_vertices"),
                          "" if max_seconds is None else _token(max_seconds, "max_seconds"),
                          _integer(seed, "seed", 0, 2**32 - 1), _callback(progress))
    return Refinement(d)


def read(path, metric=None, format=None, *, progress=None):
    """Reads a mesh in any format ``anisocert certify`` reads (Medit, Gmsh, Triangle, FreeFem/BAMG,
    TetGen, VTK .vtu, JSON), with per-vertex metrics from ``metric`` (a .sol, a .mtr) or the file's
    own. Every number is the rational its text denotes."""
    if format is not None and not isinstance(format, str):
        raise ValueError(f"format: expected a format's name (medit, gmsh, triangle, freefem, vtu, json, ...), got {format!r}")
    d = _anisocert.read(str(path), "" if metric is None else str(metric), "" if format is None else format, _callback(progress))

    def exact(x):
        if x is None or isinstance(x, np.ndarray):
            return x
        return np.array([[fractions.Fraction(t) for t in row] for row in x], dtype=object)

    return Mesh(exact(d["points"]), d["cells"], exact(d["metrics"]), d.get("edges"), d.get("triangles"), d["metric_source"],
                exact(d.get("domain")), d.get("segments"))


def certify_meshio(mesh, metric=None, **options):
    """Certifies a meshio.Mesh: its tetrahedra if it has any, else its triangles (2D when the points
    have two coordinates or every z is exactly 0); ``metric`` names the point data holding a metric
    per vertex (2D: 3 or 4 components, 3D: 6 or 9, as `certify` takes them). Other keywords as for
    `certify`."""
    if not all(hasattr(mesh, a) for a in ("cells", "points", "point_data")):
        raise ValueError(f"mesh: expected a meshio.Mesh, got {type(mesh).__name__}")
    blocks = {}
    for block in mesh.cells:
        if block.type not in ("vertex", "line", "triangle", "tetra"):
            raise ValueError(f"mesh: {block.type} cells (anisocert certifies triangle and tetrahedral meshes)")
        blocks.setdefault(block.type, []).append(np.asarray(block.data))
    cells = lambda kind: np.concatenate(blocks[kind]) if kind in blocks else None  # noqa: E731
    points = np.asarray(mesh.points)
    tets, tris = cells("tetra"), cells("triangle")
    metrics = None
    if metric is not None:
        if metric not in mesh.point_data:
            raise ValueError(f"metric: no point data named {metric!r} (there are: {', '.join(mesh.point_data) or 'none'})")
        metrics = np.asarray(mesh.point_data[metric])
    if tets is not None:
        if metrics is not None and metrics.ndim == 2 and metrics.shape[1] == 9:
            metrics = metrics.reshape(len(metrics), 3, 3)
        return certify(points, tets, metrics, triangles=tris, **options)
    if tris is None:
        raise ValueError("mesh: no triangles or tetrahedra")
    if points.shape[1] == 3:
        if np.any(points[:, 2] != 0):
            raise ValueError("mesh: a triangle mesh with points off the plane z = 0 (anisocert certifies planar triangle meshes)")
        points = points[:, :2]
    if metrics is not None and metrics.ndim == 2 and metrics.shape[1] == 4:
        metrics = metrics.reshape(len(metrics), 2, 2)
    return certify(points, tris, metrics, edges=cells("line"), **options)


class _View:
    """Attribute access to a part of the JSON report (report.valid.holds)."""

    def __init__(self, data):
        self._data = data

    def __getattr__(self, key):
        try:
            return _wrap(self._data[key])
        except KeyError:
            raise AttributeError(f"the report has no field {key!r} here (fields: {', '.join(self._data)})") from None

    def __getitem__(self, key):
        return _wrap(self._data[key])

    def __contains__(self, key):
        return key in self._data

    def __dir__(self):
        return list(self._data)

    def to_dict(self):
        return json.loads(json.dumps(self._data))

    def __repr__(self):
        return repr(self._data)


def _wrap(x):
    if isinstance(x, dict):
        return _View(x)
    if isinstance(x, list):
        return [_wrap(v) for v in x]
    return x


class Refinement(Mesh):
    """A refiner's run: its mesh (a Mesh, numbers the refiner's doubles), ``consistent`` (the run
    finished and its output condition holds), ``stop_reason``, ``lines`` (the CLI's report), and for
    a 3D run ``certificate`` (a Report: the exact 3D certifier's, as the CLI prints it)."""

    def __init__(self, d):
        super().__init__(d["points"], d["cells"], d["metrics"], d.get("edges"), d.get("triangles"), "the refiner")
        self.consistent, self.stop_reason, self.lines = d["consistent"], d["stop_reason"], d["lines"]
        self.certificate = Report(d["certificate"], "the run's mesh") if "certificate" in d else None

    @property
    def text(self):
        return "\n".join(self.lines) + "\n"

    def __repr__(self):
        kind = "triangles" if self.dimension == 2 else "tetrahedra"
        caveat = "" if self.consistent else " (stopped early: not necessarily a triangulation of the domain)"
        return f"<anisocert.Refinement: {len(self.points)} vertices, {len(self.cells)} {kind}; {self.stop_reason}{caveat}>"


class DualReport(_View):
    """``anisocert dual``'s report: the fields of its --json as attributes, ``is_dual``, ``text``, ``svg()``."""

    def __init__(self, native, name):
        super().__init__(json.loads(native.json()))
        self._native, self._name = native, name

    @property
    def is_dual(self):
        return self._native.is_dual

    @property
    def text(self):
        return self._native.text(self._name)

    def svg(self, caption=None):
        return self._native.svg(caption or f"{self._name}: {'the dual of D|Ω' if self.is_dual else 'not the dual of D|Ω'}")

    def __repr__(self):
        t, m = self._data["triangles"], self._data["missing"]["count"]
        return (f"<anisocert.DualReport {self._name}: {'the dual' if self.is_dual else 'not the dual'} of D|Ω "
                f"({t['dual']} dual, {t['ties']} tied, {t['not_dual']} not dual, {m} dual triangles missing)>")


class DiagramReport(_View):
    """``anisocert diagram``'s JSON (docs/oracle.md) as attributes, and ``svg()``."""

    def __init__(self, native):
        super().__init__(json.loads(native.json()))
        self._native = native

    def svg(self):
        return self._native.svg()

    def __repr__(self):
        c, dual = self._data["counts"], self._data["dual"]
        return (f"<anisocert.DiagramReport: {c['vertices']} Voronoi vertices, {c['arcs']} arcs, {c['faces']} faces, "
                f"{c['orphans']} orphans; the dual {'triangulates' if dual['is_triangulation'] else 'does not triangulate'} Ω>")


class Report(_View):
    """The certify report: the fields of ``anisocert certify --json`` (docs/cli.md) as attributes,
    ``holds`` the verdict, ``text`` what the CLI prints, ``svg()`` its picture."""

    def __init__(self, native, name="mesh"):
        super().__init__(json.loads(native.json()))
        self._native, self._name = native, name

    @property
    def text(self):
        return self._native.text(self._name)

    def svg(self, caption=None):
        """The picture ``anisocert certify --svg`` draws, as SVG text."""
        if caption is None:
            caption = f"{self._name}: {'certified' if self._data['holds'] else 'not certified'}"
        return self._native.svg(caption)

    def __repr__(self):
        d = self._data
        cells = f"{d['triangles']} triangles" if "triangles" in d else f"{d['tetrahedra']} tetrahedra"
        n = d.get("sites", d.get("vertices"))
        parts = [f"{k} {'holds' if v['holds'] else 'fails'}" for k, v in d.items() if isinstance(v, dict) and "holds" in v]
        verdict = "certified" if d["holds"] else "not certified"
        return f"<anisocert.Report {self._name}: {n} vertices, {cells}: {verdict} ({', '.join(parts)})>"
