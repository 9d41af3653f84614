#pragma once
// Internal to the oracle: the pieces of work compute_diagram is made of, shared by its files.
#include "oracle/algebraic/common_points.hpp"
#include "oracle/diagram/candidate_subdivision.hpp"
#include "oracle/diagram/diagram.hpp"
#include "numbers/filter_interval.hpp"

#include <map>
#include <memory>
#include <optional>

namespace anisocert::oracle::build {

// Where a point lies with respect to Ω (closed polygon, sheared coordinates).
struct DomainPosition {
  bool inside = false;            // strictly inside
  std::vector<int> edges;         // the edges containing it (on ∂Ω when non-empty)
  int corner = -1;
  bool outside() const { return !inside && edges.empty(); }
};
// Ω's edges, ready for many position tests: each edge's x-range and line, enclosed, and exactly.
class DomainEdges {
 public:
  explicit DomainEdges(const Mesh<Rational>& sheared);
  DomainPosition position(const LocatedPoint& p) const;

 private:
  struct Edge {
    Rational xl, xr;             // its x-range
    FilterInterval xl_box, xr_box;
    Conic line;                  // positive on its left
    IntervalConic line_box;
    Point2<Rational> a;          // its first end, a corner
  };
  std::vector<Edge> edges_;
};

// The nearest sites of p, given that site v is among the closest candidates: `closer` is true when
// some site is strictly closer than v (then `owners` is empty), otherwise `owners` are all sites
// at v's distance, sorted. Exact for p in Ω's bounding box (the sites are looked for in the
// subdivision's leaves around p); every caller drops points outside Ω whatever the answer.
struct Nearest {
  bool closer = false;
  std::vector<int> owners;
};

// A node found while building a pair's arcs, registered afterwards (in pair order, so that node
// ids do not depend on the number of threads). Cuts and arcs refer to it as pending_ref(k).
struct PendingNode {
  Node::Kind kind;
  LocatedPoint at;
  std::vector<int> owners;
};
constexpr int pending_ref(std::size_t k) { return -2 - static_cast<int>(k); }

// The arcs of one candidate pair, with their new nodes still pending.
struct PairArcs {
  std::vector<PendingNode> pending;
  std::vector<Arc> arcs;
};

// A point equidistant from the three sites of a candidate triple with none closer.
struct VertexCandidate {
  LocatedPoint at;
  std::vector<int> owners;
};

class Builder {
 public:
  Builder(Diagram& d, const DiagramOptions& options);
  void run();

 private:
  // nodes
  void add_corners();
  void find_vertices();
  std::vector<VertexCandidate> vertices_of_triple(std::size_t t, std::size_t& candidate_points) const;
  int register_node(Node::Kind kind, const LocatedPoint& p, const std::vector<int>& owners);
  // `equal`: sites known (by construction of p) to be at v's distance, not compared again.
  Nearest nearest(const LocatedPoint& p, int v, const std::vector<int>& equal = {}) const;
  // The nearest sites of any point (a nearest site is found by exact comparisons first).
  Nearest nearest_rational(const LocatedPoint& p) const;
  // one-dimensional ties (diagram_ties.cpp): exact checks, throwing std::domain_error by name
  void decline_if_tied_on_edge(int v, int w, int edge) const;
  void decline_if_tied_on_line(int a, int b, int c, const Conic& G) const;
  // arcs
  void build_arcs();
  PairArcs arcs_of_pair(std::size_t i) const;
  void add_arcs(PairArcs& found);
  void check_arc_wedges(Arc& arc, const IntervalBox& region) const;
  void check_node_wedges();
  void build_boundary();
  int owner_of_edge_point(int edge, const LocatedPoint& a, const LocatedPoint& b) const;
  // faces (diagram_faces.cpp)
  void build_half_edges();
  void build_cycles();
  void build_faces();
  // dual (diagram_dual.cpp)
  void build_dual();
  void check_triangulation();
  void check_theorem7();

  Diagram& d_;
  std::function<void(const std::string&)> progress_;
  int threads_;
  // The subdivision is of the input's coordinates; the oracle works in sheared ones.
  CandidateSets cand_;
  std::optional<DomainEdges> domain_;
  DomainPosition domain_position(const LocatedPoint& p) const { return domain_->position(p); }
  FilterInterval shear_;
  IntervalBox sheared_box(const BoxBounds& b) const;                // x' = x + s·y
  std::vector<int> sites_near(const LocatedPoint& p) const;        // cand_.sites_near at x = x' − s·y
  // Nodes by the lower end of their x-box, to find a point among them (register_node); boxes
  // are at most node_width_ wide, except wide_nodes_ (unbounded boxes).
  std::multimap<double, int> node_index_;
  double node_width_ = 0;
  std::vector<int> wide_nodes_;
  Rational width_;                                   // box width for located points
  std::vector<std::array<anisocert::FilterInterval, 6>> distance_;  // Q_u as interval conics
  FilterInterval distance_at(int u, const LocatedPoint& p) const;  // Q_u on p's box
  std::shared_ptr<const Mesh<Rational>> sheared_;  // for the recipes of filtered points (outlives d_)
  // F_ab and F_ac: enclosed from the distances' enclosures, built exactly on demand.
  CurvePair bisectors(int a, int b, int c) const;
  std::map<std::pair<int, int>, std::vector<int>> nodes_of_pair_;
  // germs per node, in counter-clockwise order (diagram_faces.cpp)
  struct Germ {
    int outgoing = -1, incoming = -1;                // half-edge ids
    Branch branch;
    bool right;                                      // leaves the node towards larger x
    LocatedPoint far;                                // the other end of the first piece
  };
  std::vector<std::vector<Germ>> germs_;
  void sort_germs(int node);
  friend Location oracle::locate(const Diagram& d, const Point2<Rational>& p);
};


// Ray casting: whether p (not on the cycle) is inside the closed walk of cycle c.
bool cycle_contains(const Diagram& d, int c, const LocatedPoint& p);
// The pieces a half-edge runs along, as (branch, left point, right point), for ray casting.
struct Span {
  Branch branch;
  const LocatedPoint* left;
  const LocatedPoint* right;
};
std::vector<Span> spans_of(const Diagram& d, const HalfEdge& h);

}  // namespace anisocert::oracle::build
