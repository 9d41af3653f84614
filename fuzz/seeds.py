"""The hand-made seeds of fuzz/corpora (run by fuzz/seed-corpora): inputs that are not files of
the tests. Each aims at a case the harness's header comment names."""
import os
import struct
import sys

corpora = sys.argv[1]


def put(harness, name, data):
    os.makedirs(os.path.join(corpora, harness), exist_ok=True)
    with open(os.path.join(corpora, harness, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def slots(header, *values):
    return bytes(header) + b"".join(struct.pack("<d", v) for v in values)


# exact_numbers: every form parse_rational reads, and texts it must refuse in one line.
for name, text in {
    "integer": "-12", "plus": "+7", "decimal": "12.5", "leading-point": ".5", "trailing-point": "3.",
    "exponent": "1.25e-3", "capital-exponent": "4E2", "fraction": "-7/3", "tenth": "0.1",
    "tiny": "1e-1000", "long": "123456789012345678901234567890.000000000000000000001",
    "largest-exponent": "1e100000", "exponent-too-large": "1e100001", "nan": "nan", "zero-denominator": "1/0",
    "newline": "1\nanisocert: fake second line", "hex": "0x10", "double-sign": "--1", "empty-exponent": "1e",
    "lone-point": ".", "negative-zero": "-0", "leading-zeros": "00012", "subnormal": "4.9406564584124654e-324",
    "largest-double": "1.7976931348623157e308", "halfway": "9007199254740993",
}.items():
    put("exact_numbers", name, text)

# filtered_predicates: one degenerate input per check (header byte = the check), and hostile values.
nan, inf = float("nan"), float("inf")
put("filtered_predicates", "orientation-collinear", slots([0], 0, 0, 1, 1, 2, 2))
put("filtered_predicates", "orientation-nearly-collinear", slots([0], 0.1, 0.1, 0.2, 0.2, 0.30000000000000004, 0.3))
put("filtered_predicates", "orientation-nan", slots([0], nan, 0, 1, 1, 2, 2))
put("filtered_predicates", "incircle-cocircular-square", slots([1], 0, 0, 1, 0, 1, 1, 0, 1, 1, 0, 1))
put("filtered_predicates", "incircle-cocircular-metric", slots([1], 0, 0, 2, 0, 2, 1, 0, 1, 1, 0, 4))
put("filtered_predicates", "incircle-infinity", slots([1], 0, 0, 1, 0, 1, 1, 0, inf, 1, 0, 1))
put("filtered_predicates", "bisector-on", slots([2], 0.5, 7, 0, 0, 1, 0, 1, 0, 1, 1, 0, 1))
for k in range(3, 11):
    put("filtered_predicates", f"check-{k}-zeros", slots([k], *([0.0] * 12)))
    put("filtered_predicates", f"check-{k}-extremes", slots([k], 1.7976931348623157e308, -5e-324, 1, 2.2250738585072014e-308, -1, 0.5, 3, 1e300, 1e-300, 2, 1, 1))
put("filtered_predicates", "root-sum-zero", slots([9], 3, -1, 9))
put("filtered_predicates", "enclosure-third", slots([10], 1, 3))

# conics_second_engine: each construction (first byte), coefficients in [-6, 6] as byte % 13 - 6.
def conic_bytes(kind, *ints):
    return bytes([kind] + [(i + 6) % 13 for i in ints])

put("conics_second_engine", "circles", conic_bytes(0, 1, 0, 1, 0, 0, -4, 1, 0, 1, -2, 0, 0))
put("conics_second_engine", "pencil-four-points", conic_bytes(1, 0, 0, 1, 0, 0, 1, 1, 1, 2, -1))
put("conics_second_engine", "tangent", conic_bytes(2, 1, 0, 1, 0, 0, -1, 1, 0, 2))
put("conics_second_engine", "shared-line", conic_bytes(3, 0, 0, 1, 1, 2, 0, 0, 2, -1, 3))
put("conics_second_engine", "singular-point", conic_bytes(4, 0, 0, 1, 0, 0, 1, 1, 1, -1, 1))

# diagram_brute_force: sites, shape (0 square, 1 triangle, 2 L), then x, y (eighths), a, b, c per site.
put("diagram_brute_force", "two-isotropic", bytes([1, 0, 2, 4, 0, 3, 0, 6, 4, 0, 3, 0]))
put("diagram_brute_force", "four-cocircular", bytes([3, 0, 2, 2, 0, 3, 0, 6, 2, 0, 3, 0, 6, 6, 0, 3, 0, 2, 6, 0, 3, 0]))
put("diagram_brute_force", "anisotropic-l-shape", bytes([4, 2, 1, 1, 3, 5, 2, 3, 1, 0, 3, 1, 1, 3, 1, 0, 1, 2, 4, 3, 0]))
put("diagram_brute_force", "corner-site", bytes([2, 1, 0, 0, 0, 3, 0, 4, 4, 1, 4, 2]))
# diagram_filtered_vs_exact: the same inputs (fuzz/support/small_diagram.hpp).
put("diagram_filtered_vs_exact", "two-isotropic", bytes([1, 0, 2, 4, 0, 3, 0, 6, 4, 0, 3, 0]))
put("diagram_filtered_vs_exact", "four-cocircular", bytes([3, 0, 2, 2, 0, 3, 0, 6, 2, 0, 3, 0, 6, 6, 0, 3, 0, 2, 6, 0, 3, 0]))
put("diagram_filtered_vs_exact", "anisotropic-l-shape", bytes([4, 2, 1, 1, 3, 5, 2, 3, 1, 0, 3, 1, 1, 3, 1, 0, 1, 2, 4, 3, 0]))
put("diagram_filtered_vs_exact", "corner-site", bytes([2, 1, 0, 0, 0, 3, 0, 4, 4, 1, 4, 2]))

# refiners_certified: refiner, field, shape, stretch, seed, then field and refiner parameter scales (2 = x1).
put("refiners_certified", "constant-square", bytes([0, 0, 0, 2, 1] + [2] * 12))
# refiner3_certified: shape, three sizes, six metric entries (L's diagonal, then below it), seed, rho0 and gamma0 scales.
put("refiner3_certified", "box-isotropic", bytes([0, 1, 1, 1, 3, 3, 3, 2, 2, 2, 1, 0, 1]))
put("refiner3_certified", "box-stretched", bytes([0, 3, 1, 0, 1, 3, 0, 2, 2, 2, 2, 0, 1]))
put("refiner3_certified", "triangular-prism-rotated", bytes([1, 1, 2, 1, 2, 1, 3, 3, 1, 4, 3, 1, 1]))
put("refiner3_certified", "l-prism-reflex-ridge", bytes([2, 3, 3, 1, 3, 3, 2, 2, 2, 2, 4, 0, 1]))
put("refiner3_certified", "cube-cylinder", bytes([3, 0, 0, 0, 1, 1, 1, 2, 2, 2, 5, 0, 1]))
put("refiners_certified", "linear-l-shape", bytes([0, 1, 3, 2, 2] + [2] * 12))
put("refiners_certified", "field-2-pentagon", bytes([0, 2, 4, 2, 3] + [2] * 12))
put("refiners_certified", "field-3-triangle", bytes([0, 3, 2, 2, 4] + [1] * 12))
# The BWY refiner (third in the registry: star, ls, bwy), its parameters at their defaults (x1).
put("refiners_certified", "bwy-constant-square", bytes([2, 0, 0, 2, 1] + [2] * 12))
put("refiners_certified", "bwy-linear-l-shape", bytes([2, 1, 3, 2, 2] + [2] * 12))
put("refiners_certified", "bwy-field-2-pentagon", bytes([2, 2, 4, 2, 3] + [2] * 12))

# certify_simple: k − 2, metric mode, corruption, then perturbations, metrics, diagonals.
put("certify_simple", "grid-identity", bytes([1, 0, 0] + [4] * 8 + [0, 1, 0, 1, 0, 1, 0, 1, 0]))
put("certify_simple", "grid-shared-metric", bytes([2, 1, 0] + [4, 5, 3, 4, 4, 4, 2, 6] + [1, 3, 2] + [1, 0] * 8))
put("certify_simple", "grid-per-vertex", bytes([3, 2, 0] + list(range(40))))
put("certify_simple", "duplicated-triangle", bytes([1, 0, 1] + [4] * 8 + [0] * 9 + [3]))
put("certify_simple", "clockwise-triangle", bytes([1, 0, 2] + [4] * 8 + [0] * 9 + [2]))
put("certify_simple", "missing-triangle", bytes([1, 0, 3] + [4] * 8 + [0] * 9 + [1]))
put("certify_simple", "coincident-vertices", bytes([1, 0, 4] + [4] * 8 + [0] * 9 + [0, 1]))
put("certify_simple", "folded", bytes([2, 0, 0] + [8, 8, 0, 0, 8, 0, 0, 8] + [1, 0] * 8))

# json_input: the input example of docs/oracle.md § Input, and small site sets in every number form.
put("json_input", "docs-oracle-input-example",
    '{"sites":  [{"x": "0", "y": "1/3", "metric": ["4", "0", "1"]}],\n'
    ' "domain": [["0","0"], ["10","0"], ["10","10"], ["0","10"]],\n "segments": [[0, 1]]}\n')
put("json_input", "pslg-slit-and-point",
    '{"domain": [[0,0],[1,0],[1,1],[0,1]], "points": [["1/4","1/2"],["3/4","1/2"],[0.5,0.25]],\n'
    ' "interior_segments": [[4,5],[0,6]]}\n')
put("json_input", "pslg-crossing-segments",
    '{"domain": [[0,0],[1,0],[1,1],[0,1]], "points": [[0.25,0.5],[0.75,0.5],[0.5,0.25],[0.5,0.75]],\n'
    ' "interior_segments": [[4,5],[6,7]]}\n')
put("json_input", "three-sites-number-forms",
    '{"sites": [{"x": 0.1, "y": "1/3", "metric": [1, 0, 1]}, {"x": "1e-3", "y": 2, "metric": ["2", "-1/2", "3"]},'
    ' {"x": "-0.5", "y": "0.25", "metric": ["1e2", "0", "1e-2"]}]}\n')

# vtu: one tetrahedron in each encoding VTK's XML format allows (header and data as one base64
# stream and as two, zlib blocks, appended raw and base64, UInt64 headers, big endian) and a
# planar triangle with Omega_h's 2D metric order.
import base64
import zlib


def vtu_array(data, fmt, compress, header_q, big):
    e = ">" if big else "<"
    h = "Q" if header_q else "I"
    if not compress:
        return struct.pack(e + h, len(data)), data
    blocks = [zlib.compress(data[i:i + 32]) for i in range(0, len(data), 32)]
    head = struct.pack(e + h * 3, len(blocks), 32, len(data) % 32) + b"".join(struct.pack(e + h, len(b)) for b in blocks)
    return head, b"".join(blocks)


def vtu(fmt="binary", compress=False, header_q=False, big=False, two=True, appended_b64=False):
    e = ">" if big else "<"
    arrays = [("Points", 'type="Float64" NumberOfComponents="3"', struct.pack(e + "12d", 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1)),
              ("Cells", 'type="Int32" Name="connectivity"', struct.pack(e + "4i", 0, 1, 2, 3)),
              ("Cells", 'type="Int64" Name="offsets"', struct.pack(e + "q", 4)),
              ("Cells", 'type="UInt8" Name="types"', bytes([10])),
              ("PointData", 'type="Float64" Name="metric" NumberOfComponents="6"', struct.pack(e + "24d", *([4, 4, 4, 0, 0, 0] * 3 + [2, 3, 4, 0.5, 0.25, 0.125])))]
    body, appended, section = "", b"", None
    for parent, attributes, data in arrays:
        if parent != section:
            body += (f"</{section}>\n" if section else "") + f"<{parent}>\n"
            section = parent
        head, payload = vtu_array(data, fmt, compress, header_q, big)
        if fmt == "binary":
            text = (base64.b64encode(head) + base64.b64encode(payload)) if two else base64.b64encode(head + payload)
            body += f'<DataArray {attributes} format="binary">{text.decode()}</DataArray>\n'
        else:
            body += f'<DataArray {attributes} format="appended" offset="{len(appended)}"/>\n'
            appended += base64.b64encode(head) + base64.b64encode(payload) if appended_b64 else head + payload
    body += f"</{section}>\n"
    root = (f'<VTKFile type="UnstructuredGrid" version="1.0" byte_order="{"BigEndian" if big else "LittleEndian"}"'
            + (' header_type="UInt64"' if header_q else "") + (' compressor="vtkZLibDataCompressor"' if compress else "") + ">\n")
    text = ('<?xml version="1.0"?>\n' + root + '<UnstructuredGrid>\n<Piece NumberOfPoints="4" NumberOfCells="1">\n' + body
            + "</Piece>\n</UnstructuredGrid>\n").encode()
    if fmt == "appended":
        text += f'<AppendedData encoding="{"base64" if appended_b64 else "raw"}">\n_'.encode() + appended + b"\n</AppendedData>\n"
    return text + b"</VTKFile>\n"


put("vtu", "binary-two-streams", vtu())
put("vtu", "binary-one-stream", vtu(two=False))
put("vtu", "binary-zlib", vtu(compress=True))
put("vtu", "binary-zlib-uint64-big-endian", vtu(compress=True, header_q=True, big=True))
put("vtu", "appended-raw", vtu("appended"))
put("vtu", "appended-raw-zlib", vtu("appended", compress=True))
put("vtu", "appended-base64", vtu("appended", appended_b64=True))
put("vtu", "triangle-omega-h-metric",
    '<VTKFile type="UnstructuredGrid"><UnstructuredGrid><Piece NumberOfPoints="3" NumberOfCells="1"><Points>'
    '<DataArray type="Float64" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0</DataArray></Points><Cells>'
    '<DataArray type="Int32" Name="connectivity" format="ascii">0 1 2</DataArray>'
    '<DataArray type="Int32" Name="offsets" format="ascii">3</DataArray>'
    '<DataArray type="UInt8" Name="types" format="ascii">5</DataArray></Cells><PointData>'
    '<DataArray type="Float64" Name="metric" NumberOfComponents="3" format="ascii">4 9 1 4 9 1 4 9 1</DataArray>'
    '</PointData></Piece></UnstructuredGrid></VTKFile>\n')
