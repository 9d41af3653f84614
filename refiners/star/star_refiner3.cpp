#include "refiners/star/star_refiner3.hpp"

#include "geometry/circumellipsoid.hpp"
#include "refiners/common/boundary3.hpp"
#include "refiners/star/pick_valid3.hpp"
#include "refiners/star/rules3.hpp"
#include "refiners/star/star_set3.hpp"

#include <cmath>
#include <algorithm>
#include <deque>
#include <map>
#include <random>
#include <variant>

namespace anisocert::refiners::star {
namespace {

using predicates::Point3;
using predicates::Sym3;

// The faces of the tetrahedra (positively oriented) that only one of them has, outward.
std::vector<std::array<int, 3>> boundary_faces(const std::vector<std::array<int, 4>>& tetrahedra) {
  std::map<std::array<int, 3>, std::pair<int, std::array<int, 3>>> faces;  // sorted face → count, the outward face
  for (const auto& t : tetrahedra) {
    const auto [a, b, c, d] = t;
    for (const std::array<int, 3>& f : {std::array<int, 3>{b, c, d}, {a, d, c}, {a, b, d}, {a, c, b}}) {
      std::array<int, 3> k = f;
      std::sort(k.begin(), k.end());
      auto& [count, face] = faces[k];
      ++count, face = f;
    }
  }
  std::vector<std::array<int, 3>> out;
  for (const auto& [k, entry] : faces)
    if (entry.first == 1) out.push_back(entry.second);
  return out;
}

// The first sites: Ω's vertices, then (p.seed_interior) one site in each cell of an adaptive
// subdivision of Ω's box whose sides are at most √2 `size` long in the metric at its centre (a cell
// is halved across its longest side in that metric), at a random point of the cell's middle half
// (a lattice would make five sites cospherical everywhere, each a tie the perturbation decides in
// exact arithmetic), for the cells whose corners Ω holds, when Ω holds the seed. Without interior sites, rule 1 refines the surface first
// among tetrahedra that span Ω, whose huge spheres make every new star's search reach every
// site (15 vertices/s on the cube under UGAWG's linear field); seeded, stars are local from the
// start. A choice of where to begin, not a decision: the run refines from there by LU's rules and
// the certifier judges the result.
common::Sites3 initial_sites(const common::Domain3& domain, const fields::MetricField3& field, const RefineParameters& p) {
  common::Sites3 sites(domain, field);
  for (const auto& q : domain.vertices()) sites.add(q, sites.metric_at(q));
  if (p.seed_interior) {
    std::mt19937 rng(p.seed);
    std::uniform_real_distribution<double> middle(0.25, 0.75);
    const common::Box3& b = domain.bounding_box();
    std::vector<std::array<double, 6>> cells{{b.x0, b.x1, b.y0, b.y1, b.z0, b.z1}};
    const double size2 = 2 * p.size * p.size;  // sides in (0.7, 1.4] × size: about size apart
    while (!cells.empty() && sites.size() < p.max_vertices / 2) {
      const auto c = cells.back();
      cells.pop_back();
      const Point3<double> o{(c[0] + c[1]) / 2, (c[2] + c[3]) / 2, (c[4] + c[5]) / 2};
      // Outside Ω the field need not be defined: the nearest vertex's metric stands in.
      const bool inside = domain.side(o) == common::Side::inside;
      const Sym3<double> M = inside ? sites.metric_at(o) : sites.metrics[0];
      const std::array<double, 3> side{predicates::quadratic_form(M, c[1] - c[0], 0.0, 0.0), predicates::quadratic_form(M, 0.0, c[3] - c[2], 0.0),
                                       predicates::quadratic_form(M, 0.0, 0.0, c[5] - c[4])};
      const int axis = static_cast<int>(std::max_element(side.begin(), side.end()) - side.begin());
      if (side[axis] > size2) {
        auto lo = c, hi = c;
        const double mid = (c[2 * axis] + c[2 * axis + 1]) / 2;
        lo[2 * axis + 1] = mid, hi[2 * axis] = mid;
        cells.push_back(lo), cells.push_back(hi);
        continue;
      }
      // Only cells whose corners Ω holds (a seed near ∂Ω would have rule 1 refine the surface to
      // its distance, finer than the metric asks), and a seed Ω holds (a non-convex Ω may hold a
      // cell's corners and not all of it).
      bool within = true;
      for (int k = 0; k < 8 && within; ++k)
        within = domain.side({c[k & 1], c[2 + ((k >> 1) & 1)], c[4 + ((k >> 2) & 1)]}) == common::Side::inside;
      if (!within) continue;
      const Point3<double> q{c[0] + middle(rng) * (c[1] - c[0]), c[2] + middle(rng) * (c[3] - c[2]), c[4] + middle(rng) * (c[5] - c[4])};
      if (domain.side(q) == common::Side::inside) sites.add(q, sites.metric_at(q));
    }
  }
  sites.grow_grid();
  return sites;
}

// The refinement of a 3D star set: the Refinement interface of common::refine_until_done.
class StarRefiner3 {
 public:
  StarRefiner3(const common::Domain3& domain, const fields::MetricField3& field, const RefineParameters& p)
      : domain_(domain), p_(p), sites_(initial_sites(domain, field, p)), boundary_(domain, sites_), stars_(domain, sites_, boundary_),
        pick_(domain, sites_, p) {
    const int n = static_cast<int>(sites_.size());
    // The seeds are about `size` apart: a first search of M-distance 2 size holds their neighbours.
    for (int v = 0; v < n; ++v) stars_.add(p.seed_interior ? 4 * p.size * p.size : 0), queued_.push_back(false);
    for (int v = 0; v < n; ++v) stars_.recompute(v);
    for (int v = 0; v < n; ++v) enqueue(v);
  }

  std::size_t vertices() const { return sites_.size(); }
  std::size_t queued() const { return site_queue_.size() + boundary_.queued(); }
  const std::string& stalled() const { return stalled_; }
  std::string done() const {
    if (const std::size_t n = stars_.empty_stars())
      return std::to_string(n) + " stars have no tetrahedron in Ω: their search failed, the metric's scale is beyond what the "
                                 "refiner resolves in doubles";
    return "all stars consistent";
  }

  bool step() {
    if (const auto e = boundary_.next_encroached()) {
      split(*e, true);
      return true;
    }
    while (!site_queue_.empty()) {
      const int v = site_queue_.front();
      site_queue_.pop_front();
      queued_[v] = false;
      const Action3 act = first_rule3(v, stars_, sites_, domain_, p_);
      if (act.rule == Rule::none) continue;
      refine(v, act);
      enqueue(v);
      return true;
    }
    return false;
  }

  StarResult3 result(std::string stop_reason, bool finished) const {
    StarResult3 r;
    r.mesh.tetrahedra = stars_.consistent_tetrahedra(r.inconsistent_tetrahedra);
    r.empty_stars = stars_.empty_stars();
    r.consistent = finished && r.inconsistent_tetrahedra == 0 && r.empty_stars == 0;
    r.mesh.vertices = sites_.points, r.mesh.metrics = sites_.metrics;
    r.mesh.triangles = boundary_faces(r.mesh.tetrahedra);
    for (const auto& t : r.mesh.triangles) r.faces_off_boundary += !boundary_.on_one_facet(t[0], t[1], t[2]);
    if (r.consistent && r.faces_off_boundary > 0) {
      r.consistent = false;
      stop_reason = "the stars are consistent, but " + std::to_string(r.faces_off_boundary) +
                    " boundary faces of their tetrahedra lie in no plane of Ω's facets: the mesh does not conform to Ω there";
    }
    r.subfacets = boundary_.subfacets().size();
    const common::Boundary3::RidgeAngles angles = boundary_.ridge_angles();
    r.ridges = angles.ridges, r.right_or_acute_ridges = angles.not_obtuse;
    r.stop_reason = std::move(stop_reason);
    for (Rule rule : rules_by_priority) r.rule_counts.emplace_back(rule_name(rule), counts_[static_cast<int>(rule)]);
    r.last_rule = rule_name(last_rule_);
    r.picks_rejected = pick_.counts().rejected, r.picks_exhausted = pick_.counts().exhausted;
    r.refinements = refinements_;
    r.boundary_splits = splits_;
    r.snap_splits = splits_ - rule1_splits_;
    r.trace = trace_;
    return r;
  }

 private:
  // Inserts the record's point q (its metric Mq, the field's at q), kept in the trace: the stars
  // whose conflict zone holds q change (LU Lemma 3.5), and so may their neighbours' consistency;
  // queues them, the new star and its neighbours; the surface level queues the subfacets q may encroach. reach2: the new star's
  // first search radius (squared, in its metric). split: the boundary edge q is the midpoint of
  // (cut before the stars are updated, which ask which facets hold q).
  int insert(const common::Insertion3& record, const Sym3<double>& Mq, double reach2, const common::Boundary3::Edge* split = nullptr) {
    const Point3<double>& q = record.p;
    ++counts_[record.rule];
    trace_.push_back(record);
    last_rule_ = static_cast<Rule>(record.rule);
    const int k = sites_.add(q, Mq);
    stars_.add(reach2);
    queued_.push_back(false);
    if (sites_.grow_grid()) {
      stars_.refile();
      boundary_.refile();
    }
    if (split) boundary_.split(*split, k);
    boundary_.site_added(k);
    zone_ = stars_.near(q);  // a copy: updates edit the index
    for (int v : zone_) {
      before_ = stars_.neighbours(v);
      const Star3Update change = stars_.update(v, k);
      if (change == Star3Update::unchanged) continue;
      if (change == Star3Update::recompute) stars_.recompute(v);
      enqueue(v);
      for (int w : before_) enqueue(w);
    }
    stars_.recompute(k);
    enqueue(k);
    for (int w : stars_.neighbours(k)) enqueue(w);
    return k;
  }

  // rule1: for rule 1 (else Insert_or_snap's).
  void split(const common::Boundary3::Edge& e, bool rule1 = false) {
    const auto m = boundary_.midpoint(e);
    if (const auto* why = std::get_if<std::string>(&m)) {
      stalled_ = *why;
      return;
    }
    const Point3<double> q = std::get<Point3<double>>(m);
    const Sym3<double> Mq = sites_.metric_at(q);
    const auto& a = sites_.points[e[0]];
    const double half2 = predicates::quadratic_form(Mq, q.x - a.x, q.y - a.y, q.z - a.z);
    ++splits_, rule1_splits_ += rule1;
    insert({static_cast<int>(Rule::encroachment), q}, Mq, 16 * half2, &e);
  }

  // Refine(τ) for the tetrahedron τ = (v, t) of S_v: Pick_valid, then Insert_or_snap.
  void refine(int v, const Action3& act) {
    ++refinements_;
    const auto& x = sites_.points;
    const Sym3<double> M = sites_.metrics[v];
    const std::array<int, 4> q{v, act.t[0], act.t[1], act.t[2]};
    const auto c = geometry::circumellipsoid(x[v], x[q[1]], x[q[2]], x[q[3]], M);
    const Point3<double> o{x[v].x + c.x[0], x[v].y + c.x[1], x[v].z + c.x[2]};
    Point3<double> p = pick_.pick(o, c.r2, M, q);
    // Outside Ω the field need not be defined: M_v stands in for M_p to choose the split.
    const bool inside = domain_.side(p) == common::Side::inside;
    const Sym3<double> Mp = inside ? sites_.metric_at(p) : M;
    if (const auto e = boundary_.snap(p, M, Mp)) {
      split(*e);
      return;
    }
    if (!inside) {
      // Outside Ω and encroaching nothing (a picking region beyond a facet the boundary's boxes
      // missed): the tetrahedron's centroid, inside Ω, instead.
      p = {0, 0, 0};
      for (int w : q) p = {p.x + x[w].x / 4, p.y + x[w].y / 4, p.z + x[w].z / 4};
      if (domain_.side(p) != common::Side::inside) {
        stalled_ = "refining a tetrahedron of the star of site " + std::to_string(v) + " found no point inside Ω to insert (" +
                   rule_name(act.rule) + ")";
        return;
      }
      const Sym3<double> Mg = sites_.metric_at(p);
      if (const auto e = boundary_.snap(p, M, Mg)) {
        split(*e);
        return;
      }
      return add_refinement(v, act, p, Mg, c.r2, true);
    }
    add_refinement(v, act, p, Mp, c.r2, false);
  }

  void add_refinement(int v, const Action3& act, const Point3<double>& p, const Sym3<double>& Mp, double r2, bool stand_in) {
    const common::Box3 here{p.x, p.x, p.y, p.y, p.z, p.z};
    if (!sites_.in(here).empty()) {
      stalled_ = "refining a tetrahedron of the star of site " + std::to_string(v) + " near " + common::point_text(p) +
                 " picked an existing site: the mesh there is finer than doubles resolve (" + rule_name(act.rule) + ")";
      return;
    }
    insert({static_cast<int>(act.rule), p, v, std::sqrt(r2), stand_in}, Mp, 4 * r2);
  }

  void enqueue(int v) {
    if (!queued_[v]) queued_[v] = true, site_queue_.push_back(v);
  }

  const common::Domain3& domain_;
  const RefineParameters& p_;
  common::Sites3 sites_;
  common::Boundary3 boundary_;
  StarSet3 stars_;
  PickValid3 pick_;
  std::deque<int> site_queue_;
  std::vector<bool> queued_;
  std::array<std::size_t, rules_by_priority.size() + 1> counts_{};
  Rule last_rule_ = Rule::none;
  std::size_t refinements_ = 0, splits_ = 0, rule1_splits_ = 0;
  std::string stalled_;
  std::vector<int> zone_, before_;
  std::vector<common::Insertion3> trace_;
};

}  // namespace

StarResult3 refine_star3(const common::Domain3& domain, const fields::MetricField3& field, const RefineParameters& p,
                         const common::Progress& progress) {
  const common::Stopwatch clock;
  StarRefiner3 r(domain, field, p);
  const common::Stop stop = common::refine_until_done(r, p, clock, progress);
  const bool finished = stop.finished && r.stalled().empty() && r.queued() == 0;
  StarResult3 result = r.result(stop.reason, finished);
  result.seconds = clock.seconds();
  return result;
}

}  // namespace anisocert::refiners::star
