#pragma once
// LS §9's Voronoi refinement on the true anisotropic diagram (refiners/common/vertex_subdivision.hpp),
// apart from the rules that judge its Voronoi vertices: the sites, the diagram, the constrained
// subsegments and the shared rules
//   encroached: a subsegment ab is encroached when a site's closed cell meets it, decided exactly
//     along ab (segment_quadratics.hpp); it is split at a double exactly on ab, in that cell, as
//     near the "midpoint" d_a(z) = d_b(z) as the cell and the doubles allow (checked exactly);
//   the conditional insertion (`attack`): a point that would encroach a subsegment is not
//     inserted, the subsegment is split instead (LS §9: "A new site is never permitted to encroach
//     upon a segment"; BWY §3.2.2: "if x encroaches some constrained subsegment e, insert a site on
//     e instead");
//   island: a site whose cell holds no Voronoi vertex (bounded by an ellipse) gets a site on the
//     bisector with its nearest other site, on the segment between them;
//   unresolved: where the diagram is unresolved in Ω and no exact tie explains it (a vertex of
//     degree 4 or more among different metrics), a site.
// Exact ties among sites of one metric (exact_tie.hpp) are kept as ties and judged by the refiner.
// Two refiners derive from it: LS's for fields that vary (ls_varying.cpp) and BWY's
// (refiners/bwy/), whose §3.2.2 takes LS's encroachment and adds the conditional insertion.
#include "fields/metric_field.hpp"
#include "refiners/common/certified_point.hpp"
#include "refiners/common/corner_shells.hpp"
#include "refiners/common/distance_function.hpp"
#include "refiners/common/domain.hpp"
#include "refiners/common/run_record.hpp"
#include "refiners/common/sites.hpp"
#include "refiners/common/vertex_subdivision.hpp"
#include "refiners/common/exact_tie.hpp"
#include "refiners/common/subsegments.hpp"

#include <deque>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace anisocert::refiners::common {

using predicates::Point2;
using predicates::Sym2;

// The numbers the shared rules have in a refiner's table, and the table (in priority order).
struct VoronoiRules {
  int encroached;     // a subsegment split because a site's closed cell meets it
  int split_instead;  // a subsegment split instead of inserting a point that would encroach it
  int unresolved;     // a site where the diagram is unresolved
  int island;         // a site on the bisector of a site whose cell holds no Voronoi vertex
  int corner_shell;   // an apex's first shell (CornerShells::first), before any other split
  std::vector<common::RuleName> by_priority;
  std::string name(int rule) const;
};

class VoronoiRefinement {
 public:
  virtual ~VoronoiRefinement() = default;
  VoronoiRefinement(const VoronoiRefinement&) = delete;
  VoronoiRefinement& operator=(const VoronoiRefinement&) = delete;

  std::size_t vertices() const { return sites_.size(); }
  const std::string& stalled() const { return stalled_; }

 protected:
  // The diagram of the sites in the metrics of diagram_field; filters: false takes every decision
  // of the segment tests in rationals; note(a, b) says, in a stop at a corner, what the refiner's
  // theorem asks there.
  VoronoiRefinement(const common::Domain& domain, const fields::MetricField& diagram_field, VoronoiRules rules, bool filters,
                    CornerNote note);
  // The first sites, Ω's corners and points, and its segments as subsegments; called by the derived
  // refiner's constructor (it judges the ties that the first sites make).
  void start();

  // An exact tie with its rule (0: none) and the triangles the mesh gets for it. Both depend on the
  // tie's sites alone (their places and metrics, and the field at its vertex), so a tie is judged
  // once, when it is first found.
  struct JudgedTie {
    ExactTie tie;
    int rule;
    std::vector<std::array<int, 3>> triangles;
  };
  virtual JudgedTie judged(const ExactTie& tie) const = 0;
  // After each insertion by insert() (site k): the vertices the diagram created and released.
  virtual void inserted(int k) = 0;
  // A subsegment the encroached rule tested and found not encroached.
  virtual void not_encroached(int) {}

  // The next encroached subsegment, split; false when none is queued. The next point where the
  // diagram is unresolved, attacked; false when none is left.
  bool split_encroached();
  bool attack_unresolved();
  // The island rule, when nothing else applies: a site that sites_with_vertices() leaves out gets
  // a site on the segment to its nearest other site, where their distances are equal; false when
  // every site has a vertex.
  bool island();
  // The sites the island rule leaves alone, by index: those of the Voronoi vertices the diagram
  // keeps (in Ω and near it) and of the exact ties. A refiner that needs more overrides it.
  virtual std::vector<char> sites_with_vertices() const;
  // The conditional insertion: a site at q, unless it would encroach a subsegment, which is then
  // split in the cell q would have. False when q was not inserted (the subsegment was split
  // instead, or the run stalls). what: the point, for a stop.
  bool attack(const Point2<double>& q, int rule, double radius, const std::string& what, double displacement = 0);
  // attack() at Voronoi vertex q rounded (rounded_vertex), with its radius at its first site; at
  // an exact tie's vertex rounded (rounded).
  bool attack_vertex(int q, int rule);
  // The unit-aware choice (issue 41, docs/refiners.md § Off-centres): Üngör's off-centre carried to
  // the metric. For a rule whose guarantee is a new site at least `least` from the others, instead
  // of Voronoi vertex q: the point x on the way from the midpoint (d_p = d_o) of q's shortest edge
  // p–o (δ = d_p(o), the least of the six lengths of its sites) to q where d_p(x) = ℓ =
  // clamp(1, least, r(q)), least = ratio·δ when ratio > 0 (a shape rule: r(q) > ratio·δ), else
  // size (a size rule: r(q) > size), when x lies in Ω and no site is nearer to it than ℓ; else q
  // itself. A choice in doubles, as every choice of where to insert: the certificate never
  // depends on it.
  bool attack_off_centre(int q, int rule, double ratio, double size);
  bool attack_tie(const ExactTie& tie, int rule);
  // The sign of d_a(q)² − R² at Voronoi vertex q, decided exactly; nothing when undecided (the size
  // rules).
  std::optional<Sign> beyond(int q, const MetricSite& a, double R) const;
  // The sites other than its ends whose closed cells meet subsegment s.
  std::vector<int> encroachers(int s) const;
  // Splits s at a point exactly on it in the closed cell of one of `in` among `near` (every site
  // that can be nearest on s), as near its midpoint as possible, recorded as `rule` (for_rule: the
  // rule whose point would have encroached s, for split_instead).
  void split(int s, const std::vector<common::MetricSite>& in, const std::vector<common::MetricSite>& near, int rule, int for_rule = 0);

  common::MetricSite site(int k) const {
    return {sites_.points[static_cast<std::size_t>(k)], sites_.metrics[static_cast<std::size_t>(k)]};
  }
  common::CertifiedPoint point(int q) const;
  // The counter-clockwise order of the three cells around vertex q, nothing when undecided.
  std::optional<Sign> cell_order(int q) const;
  // Vertex q as the site a vertex rule inserts, with its displacement (from above).
  std::pair<Point2<double>, double> rounded_vertex(int q) const;
  // A rational point rounded to doubles, within an ulp per coordinate, with its displacement.
  static std::pair<Point2<double>, double> rounded(const Point2<Rational>& c);
  // The apexes of small angles (corner_shells.hpp), known once X's vertices are sites (start); their
  // first shells are split one a step before any encroached subsegment (split_encroached).
  std::optional<CornerShells> corners_;
  bool split_corner_shell();
  // Every site that can be nearest somewhere on subsegment s.
  std::vector<common::MetricSite> near(int s) const;
  // d_s(p)² in doubles (for choices, never for decisions).
  static double squared_distance(const common::MetricSite& s, const Point2<double>& p) {
    return common::distance2(common::lift<double>(s, [](double x) { return x; }), p.x, p.y);
  }

  const common::Domain& domain_;
  common::Sites sites_;  // with the diagram's metrics
  common::VertexSubdivision diagram_;
  Subsegments subsegments_;
  std::deque<Point2<double>> ties_;       // points where the diagram is unresolved, for the unresolved rule
  std::vector<ExactTie> ties_anywhere_;  // every exact tie of the diagram (in Ω's bounding box)
  std::vector<JudgedTie> exact_ties_;   // those in closed Ω
  std::string stalled_;
  common::RunRecord record_;

 private:
  std::optional<int> encroached_by(const common::MetricSite& Q) const;
  int nearest_other(int u) const;
  void queue_reached(int k, const common::MetricSite& Q);
  struct ReachBounds;
  bool reaches(int s, const common::MetricSite& Q, const ReachBounds& near) const;
  common::Box segment_box(int s) const;
  void add_site(const Point2<double>& q, const Sym2<double>& M);
  // Inserts Q as a site; its index, or −1 when the run stalls.
  int insert(const common::MetricSite& Q, int rule, double radius, double displacement = 0, int for_rule = 0);

  VoronoiRules rules_;
  bool filters_;
  CornerNote corner_note_;
  std::map<std::vector<int>, std::optional<JudgedTie>> tie_of_;  // by the unresolved leaves' candidates
};

}  // namespace anisocert::refiners::common
