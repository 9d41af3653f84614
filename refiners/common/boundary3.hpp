#pragma once
// The surface level of the 3D refiner (issue 40; LU §4.1 rule (1) and Insert_or_snap_e/_f): Ω's
// boundary as a triangulation of its facets, the subfacets, refined by splitting edges at their
// midpoints. A midpoint of two points of a facet lies on it, and the refiner checks that it is a
// double (exact_split.hpp), so every boundary vertex lies exactly on every input facet holding
// both ends of its edge; each split cuts the (two) subfacets at the edge, so the surface stays a
// conforming triangulation of ∂Ω. Its edges between subfacets of facets that are not coplanar are
// the subsegments (Ω's ridges).
// Encroachment (LU Definition 3.16, predicates/encroachment3.hpp, exact): a site p encroaches a
// subsegment or a subfacet when it lies strictly inside its diametral M-ball for M = M_p or the
// metric of one of its vertices. A site on ∂Ω encroaches a subfacet only from strictly beyond its
// plane: across a reflex ridge, where it could make a tetrahedron cross the boundary. (Every site
// counts for a subsegment: a ridge coarser than the faces beside it leaves the hull of the sites
// chamfered there, a corner of Ω no tetrahedron covers.) Within a plane the surface's triangulation need not
// be the Delaunay one, which no bisection makes it in every metric, and across a convex ridge of
// 90° (a cube's) the diametral M-balls of the two faces' subfacets take each other's vertices as
// soon as the metrics of the sites differ (LU Lemma 4.1 needs boundary angles above 90°):
// counting those sites refined the faces of a cube without end under UGAWG's linear field. The
// mesh's boundary faces are its tetrahedra's, which the stars make Delaunay; whether each lies on
// ∂Ω is checked (StarResult3::faces_off_boundary) and the certifier checks the mesh.
// An encroached subsegment is split at once (first when p encroaches one of a subfacet's edges
// that is one): propagating from it split an edge from the ridge towards p, whose midpoint lay
// nearer the ridge and encroached it again, a sequence converging to the ridge. An encroached
// subfacet has its longest edge split by Rivara's LEPP–Delaunay: while a subfacet at the edge has
// a longer edge, that one is split first, and after each split Lawson's flips (legalize) make the
// plane's triangulation around the new site Delaunay in its metric. An edge's length is its
// length in the field (the integral of √(uᵀ M u) along it, by quadrature in doubles, once per
// edge), ties broken by the sites' indices: a strict order that no later split changes, and
// additive up to the quadrature, so an edge's halves are shorter than it. Bisection alone (Euclidean lengths, no
// flips) cut UGAWG's linear field's faces into subfacets whose smallest angle in the metric fell
// to 7°: every tetrahedron on such a subfacet has a radius-edge ratio of at least 1/(2 sin 7°) > 3,
// so refining them moved points towards the face without end (edges of 10⁻⁷ at h0 = 0.05;
// Euclidean order also refines across the field's fine direction as finely as along it, 100
// times too fine at h0 = 10⁻³). (Lengths in the metrics of a subfacet's vertices, tried
// before, changed with each new site, and LEPP alternated between two edges without end.) Candidates come from boxes (the diametral balls' in the vertices'
// metrics, the radius times √2: a floating-point choice of which pairs to test, which may miss a
// site whose own metric makes the ball larger; the certifier judges the mesh).
#include "refiners/common/sites3.hpp"

#include <array>
#include <deque>
#include <optional>
#include <string>
#include <unordered_map>
#include <variant>
#include <vector>

namespace anisocert::refiners::common {

class Boundary3 {
 public:
  // The subfacets are Ω's facets; sites 0 … n − 1 must be Ω's vertices, in order.
  Boundary3(const Domain3& domain, const Sites3& sites);

  using Edge = std::array<int, 2>;  // sites, the lesser first
  // The edge to split next for rule (1), if any.
  std::optional<Edge> next_encroached();
  // Insert_or_snap for a point q (metric Mq) picked to refine a simplex of the star of a site
  // with metric Mv: the edge to split instead when q encroaches a subsegment, else when it
  // encroaches a subfacet (in Mv or Mq).
  std::optional<Edge> snap(const Point3<double>& q, const Sym3<double>& Mv, const Sym3<double>& Mq) const;
  // The exact midpoint of e, or why there is none.
  std::variant<Point3<double>, std::string> midpoint(const Edge& e) const;
  // After site m (e's midpoint) was added: cuts the subfacets at e.
  void split(const Edge& e, int m);
  // After site k was added: queues the subfacets it encroaches.
  void site_added(int k);
  // After the site grid was rebuilt.
  void refile() { boxes_.refile(sites_.grid); }

  // Whether sites a, b, c lie in one plane of Ω's facets (the star of a boundary site may be open
  // there). A site is tagged with the planes of the facets holding the ends of its edge, so a
  // midpoint may be tagged with a plane none of whose facets holds it (between two facets of one
  // plane, past a taller part of Ω): exact for convex Ω, a floating-point-free approximation
  // otherwise.
  bool on_one_facet(int a, int b, int c) const;
  // The subfacets, outward (for the output's boundary triangles).
  std::vector<std::array<int, 3>> subfacets() const;
  std::size_t queued() const { return queue_.size(); }
  // LU Lemma 4.1 in 3D: rule 1 applies finitely often when every boundary angle is above 90°.
  // Ω's ridges (edges between facets not in one plane) and those whose interior dihedral angle is
  // not above 90° in the metric of one of its two ends, decided exactly: a reflex ridge (the other
  // facet's far vertex beyond the first facet's plane) is above 180°; a convex one is above 90°
  // iff its dihedral angle's cosine in M is negative (predicates/dihedral.hpp's DihedralDotKernel,
  // the certifier's; sites 0 … n − 1 are Ω's vertices, with their metrics).
  struct RidgeAngles {
    std::size_t ridges = 0;
    std::vector<Edge> not_obtuse;  // the ridges' vertices, the lesser first, in order
  };
  RidgeAngles ridge_angles() const;

 private:
  struct Subfacet {
    std::array<int, 3> v;
    int facet;
    bool alive = true;
  };
  static std::uint64_t key(int a, int b) {
    return a < b ? (std::uint64_t(a) << 32) | std::uint32_t(b) : (std::uint64_t(b) << 32) | std::uint32_t(a);
  }
  int add_subfacet(const std::array<int, 3>& v, int facet);
  void kill(int f);
  // LEPP–Delaunay (Rivara): after site m split an edge, the edge ab of the plane's triangulation
  // opposite m is flipped while its other subfacet's apex lies strictly inside the M_m-circumcircle
  // of m, a, b (encroaches_facet for a point in the plane, exact), and so on outwards.
  void legalize(int a, int b, int m);
  bool is_subsegment(int a, int b) const;
  // Whether p (metric Mp, not a vertex of f) encroaches subfacet f; edge_of: set to a subsegment
  // of f that p encroaches, if any.
  // on_boundary: p is a site on ∂Ω (which counts only beyond the planes, see above).
  bool encroaches(const Point3<double>& p, bool on_boundary, const Sym3<double>& Mp, int f, std::optional<Edge>* edge_of) const;
  // Whether p is strictly beyond subfacet f's plane (on its outward side).
  bool beyond(int f, const Point3<double>& p) const;
  // The edge ab's length in the field, ∫ √(uᵀ M(a + t u) u) dt over [0, 1] for u = b − a, by a
  // quadrature in doubles (computed once per edge), and the edge: the order of LEPP.
  std::pair<double, Edge> length(int a, int b) const;
  Edge longest_edge(int f) const;
  // The edge LEPP splits first on the way to splitting e (e when e is the longest edge of both its subfacets).
  Edge terminal(Edge e) const;

  const Domain3& domain_;
  const Sites3& sites_;
  std::vector<Subfacet> subfacets_;
  std::unordered_map<std::uint64_t, std::vector<int>> edges_;  // edge → its live subfacets
  // Per site: the planes (Domain3::plane_of) of the input facets holding it, sorted. The midpoint
  // of an edge lies on the planes of both ends.
  std::vector<std::vector<int>> site_facets_;
  FiledBoxes3 boxes_;
  mutable std::unordered_map<std::uint64_t, double> lengths_;  // length's, by edge
  void enqueue(int f) {
    if (!queued_[f]) queued_[f] = true, queue_.push_back(f);
  }
  std::deque<int> queue_;      // subfacets to check, each once
  std::vector<char> queued_;
};

}  // namespace anisocert::refiners::common
