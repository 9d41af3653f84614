#pragma once
// The exact anisotropic Voronoi diagram restricted to a polygon, D|Ω (LS §3–§5, Definition 1;
// BWY §2), with its wedges (LS Definitions 2–3), faces and orphans, its geometric dual and the
// Theorem 7 verdict. Every field is decided exactly; docs/oracle.md says how and why nothing is
// missed.
//
// Coordinates: the oracle works in sheared coordinates (see diagram_input.hpp); `shear` is the s
// used, every AlgebraicPoint and Conic below is in sheared coordinates, and the accessors for
// output (vertex_xy, witness) map back to the input's coordinates.
#include "oracle/algebraic/branch.hpp"
#include "oracle/diagram/input.hpp"
#include "oracle/certify/triangulation_check.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace anisocert::oracle {

// A point of the graph of D|Ω: a Voronoi vertex (three or more owners), a point where an arc
// meets ∂Ω (two owners), a singular point of a bisector that is in the diagram (two owners,
// where two crossing lines of one bisector meet), or a corner of Ω (no owners listed).
struct Node {
  enum class Kind { voronoi, domain_crossing, singular, corner };
  Kind kind;
  LocatedPoint at;
  std::vector<int> sites;         // owners, sorted (for corners: empty)
  std::vector<int> boundary_edges;  // the edges of Ω containing it (two at a corner)
  int corner = -1;                // the corner of Ω it is, or −1
  bool wedged = true;             // LS Definition 3 for the owner pairs
  std::pair<int, int> unwedged_pair{-1, -1};
};

// An x-monotone open piece of a bisector branch between two breakpoints, all in D|Ω.
struct Piece {
  Branch branch;
  int left = -1, right = -1;                  // node ids, or −1 for a joint (vertical tangent)
  std::optional<LocatedPoint> left_point, right_point;  // the end points
  Rational sample_x;                          // a rational strictly inside the x-range
};

// LS: a Voronoi arc of D|Ω, a maximal connected piece of a bisector where its two sites are the
// nearest, inside Ω, without a node in its interior.
struct Arc {
  int v, w;                                   // sites, v < w
  Conic bisector;                             // F_vw = Q_v − Q_w (sheared)
  std::vector<Piece> pieces;                  // in order along the arc, from `ends[0]` to `ends[1]`
  std::vector<bool> forward;                  // per piece: traversed with increasing x
  std::array<int, 2> ends{-1, -1};            // node ids; both −1 for a closed arc
  bool closed = false;
  std::vector<int> cut_by_edges;              // edges of Ω at its ends (LS Theorem 7: cut arcs)
  bool wedged = true;
  // When not wedged: a point of the arc outside the open wedge, as the common point of the
  // bisector and `witness_line` (a wedge line, or the vertical line of a sample point).
  std::optional<LocatedPoint> witness;
  Conic witness_line;
};

// A piece of ∂Ω between consecutive nodes, oriented counter-clockwise, and its owner.
struct BoundaryPiece {
  int edge;
  int from, to;                               // node ids
  int site;
};

// A boundary cycle of the planar graph: a closed walk with one face of D|Ω on its left.
struct Cycle {
  std::vector<int> half_edges;
  int site = -1;
  bool outer = true;                          // counter-clockwise (outer boundary) or a hole
};

struct Face {
  int site;
  int outer_cycle;
  std::vector<int> holes;                     // cycle ids
  bool orphan;                                // LS Definition 1: does not contain its site
};

struct DualCell {
  int vertex;                                 // node id
  std::vector<int> sites;                     // in the cyclic order of the cells around the vertex
};

struct Theorem7 {
  bool preconditions_hold = false;
  std::vector<std::string> reasons;           // why a precondition fails
  bool disagreement = false;                  // preconditions hold but the dual is no triangulation
};

struct DiagramStats {
  std::size_t boxes = 0, leaves = 0, triples = 0, pairs = 0, candidate_points = 0;
  int max_depth = 0;
  int threads = 1;
  bool exact_only = false;
  FilterCounts filters;  // how many decisions the filters took, and how many were exact
  double seconds_candidates = 0, seconds_vertices = 0, seconds_arcs = 0, seconds_faces = 0, seconds_dual = 0;
};

struct HalfEdge {
  int arc = -1, boundary = -1;                // exactly one is set
  bool reversed = false;                      // against the arc's own direction
  int origin = -1, target = -1;               // node ids (−1 for closed arcs)
  int cycle = -1;
};

struct Diagram {
  Mesh<Rational> input;                         // as given (original coordinates)
  // Ω as the construction takes it: input.domain with its edges split at the sites on them (LS
  // Theorem 7: the sites on ∂Ω are vertices of Ω, so a refined mesh's boundary subsegments are
  // Ω's edges), and the site at each corner (−1 when none is). Edge k runs from domain[k] to
  // domain[k + 1]; Arc::cut_by_edges and the Theorem 7 reasons number edges so.
  geometry::Polygon<Rational> domain;
  std::vector<int> corner_site;
  Mesh<Rational> sheared;
  Rational shear;
  std::vector<Node> nodes;
  std::vector<Arc> arcs;
  std::vector<BoundaryPiece> boundary;
  std::vector<HalfEdge> half_edges;
  std::vector<Cycle> cycles;
  std::vector<Face> faces;
  std::vector<DualCell> dual_triangles, dual_polygons;
  TriangulationCheck dual_check;
  Theorem7 theorem7;
  DiagramStats stats;

  // A point's coordinates in the input's coordinates, approximately: each rounded to the nearest
  // multiple of `grid`, a power of two near 2^-40 of the domain's extent (so within 2^-41 of the
  // extent; multiples of `grid`, such as the corners of the unit square, are exact). It depends
  // only on the exact point, so the filtered and the exact constructions print the same numbers.
  std::pair<double, double> original_xy(const LocatedPoint& p) const;
  double grid = 0;
};

struct DiagramOptions {
  bool exact_only = false;  // build every point exactly (no filtered constructions)
  int threads = 0;          // 0: every core
  std::function<void(const std::string&)> progress;  // progress lines for long work (may be empty)
};

Diagram compute_diagram(const Mesh<Rational>& input, const DiagramOptions& options);
Diagram compute_diagram(const Mesh<Rational>& input, const std::function<void(const std::string&)>& progress = {});

// Where a rational point of Ω lies in the diagram: its exact nearest-site set must equal the
// owners of what contains it (the brute-force check of the tests).
struct Location {
  enum class Kind { node, arc, boundary, face } kind;
  int index;
  std::vector<int> owners;
};
Location locate(const Diagram& d, const Point2<Rational>& p);

// The sites at minimum distance from p (sorted), by exact comparison against every site.
std::vector<int> nearest_sites(const Mesh<Rational>& in, const Point2<Rational>& p);

}  // namespace anisocert::oracle
