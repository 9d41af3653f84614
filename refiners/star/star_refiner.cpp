#include "refiners/star/star_refiner.hpp"

#include "refiners/common/boundary.hpp"
#include "refiners/star/pick_valid.hpp"
#include "refiners/star/rules.hpp"
#include "refiners/star/star_set.hpp"

#include <array>
#include <cmath>
#include <deque>
#include <variant>

namespace anisocert::refiners::star {
namespace {

// The first sites: Ω's corners (LU §4.1 starts from them), then the domain's points (a mesh's
// interior vertices, `refine --from`).
common::Sites first_sites(const common::Domain& domain, const fields::MetricField& field) {
  common::Sites sites(domain, field);
  for (const auto& q : domain.vertices()) {
    sites.add(q);
    sites.grow_grid();  // no box is filed yet
  }
  return sites;
}

// The refinement of a star set: the state the rules, Pick_valid and the edge level share, and the
// Refinement interface of common::refine_until_done.
class StarRefiner {
 public:
  StarRefiner(const common::Domain& domain, const fields::MetricField& field, const RefineParameters& p)
      : domain_(domain), p_(p), sites_(first_sites(domain, field)), boundary_(domain, sites_),
        stars_(domain, sites_, boundary_), pick_(domain, sites_, p) {
    const int first = static_cast<int>(sites_.size());
    for (int v = 0; v < first; ++v) stars_.add(0), queued_.push_back(false);
    for (int v = 0; v < first; ++v) stars_.recompute(v);
    for (int v = 0; v < first; ++v) enqueue(v);
  }

  std::size_t vertices() const { return sites_.size(); }
  std::size_t queued() const { return site_queue_.size(); }
  const std::string& stalled() const { return stalled_; }
  // No rule fires on an empty star, so a run can end with some (seen for metrics whose quadratic
  // forms overflow doubles, e.g. a constant metric of 10³⁰⁰): then it says so.
  std::string done() const {
    if (const std::size_t n = empty_stars())
      return std::to_string(n) + " stars have no triangle in Ω: their search failed, the metric's scale is beyond what the "
                                 "refiner resolves in doubles";
    return "all stars consistent";
  }

  // One step: an encroached subsegment first (rule 1), else the next queued star's first rule.
  bool step() {
    if (const auto s = boundary_.next_encroached()) {
      split(*s);
      return true;
    }
    while (!site_queue_.empty()) {
      const int v = site_queue_.front();
      site_queue_.pop_front();
      queued_[v] = false;
      const Action act = first_rule(v, stars_, sites_, domain_, p_);
      if (act.rule == Rule::none) continue;
      refine(v, act);
      enqueue(v);
      return true;
    }
    return false;
  }

  // finished: the run ended because no rule applies anywhere (not a budget, not a stall).
  StarResult result(std::string stop_reason, bool finished) const {
    StarResult r;
    r.mesh.triangles = stars_.consistent_triangles(r.inconsistent_triangles);
    r.empty_stars = empty_stars();
    // A run stopped early can have consistent stars while its rules still fire (ρ₀, γ₀ unmet):
    // only a finished run claims its output condition.
    r.consistent = finished && r.inconsistent_triangles == 0 && r.empty_stars == 0;
    r.mesh.sites = sites_.points, r.mesh.metrics = sites_.metrics, r.mesh.domain = domain_.corners();
    r.mesh.segments = boundary_.segments();
    r.stop_reason = std::move(stop_reason);
    for (std::size_t k = 0; k < domain_.size(); ++k)
      if (!boundary_.corner_is_obtuse(k)) r.acute_corners.push_back(static_cast<int>(k));
    for (Rule rule : rules_by_priority) r.rule_counts.emplace_back(rule_name(rule), counts_[static_cast<int>(rule)]);
    r.last_rule = rule_name(last_rule_);
    r.picks_rejected = pick_.counts().rejected, r.picks_exhausted = pick_.counts().exhausted;
    r.refinements = refinements_;
    r.trace = trace_;
    return r;
  }

 private:
  // Sites whose star has no triangle in Ω.
  std::size_t empty_stars() const {
    std::size_t n = 0;
    for (std::size_t v = 0; v < stars_.size(); ++v) n += stars_[v].triangles.empty();
    return n;
  }

  // Inserts q (LU §4: its metric is the field's at q), updates the stars whose conflict zone holds
  // it and queues them, their former neighbours, the new star and the subsegments q encroaches.
  int insert(const Point2<double>& q, Rule rule, int site = -1, double radius = 0) {
    const Sym2<double> Mq = sites_.field.at(q.x, q.y);
    const double nearest = sites_.grid.nearest_site2(q, Mq, sites_.points);
    trace_.push_back({static_cast<int>(rule), q.x, q.y, std::sqrt(nearest), site, radius});
    ++counts_[static_cast<int>(rule)];
    last_rule_ = rule;
    const int k = sites_.add(q, Mq);
    boundary_.site_added();
    stars_.add(std::isfinite(nearest) ? 4 * nearest : 0);
    queued_.push_back(false);
    if (sites_.grow_grid()) {
      stars_.refile();
      boundary_.refile();
    }
    // Stars whose conflict zone holds q change (LU Lemma 3.5); so may their neighbours' consistency.
    zone_ = stars_.near(q);  // a copy: updates edit the index
    for (int v : zone_) {
      if (!stars_.zone_holds(v, q)) continue;
      before_ = stars_[v].neighbours;
      const StarSet::Update change = stars_.update(v, k);
      if (change == StarSet::Update::unchanged) continue;
      if (change == StarSet::Update::recompute) stars_.recompute(v);
      enqueue(v);
      for (int w : before_) enqueue(w);
    }
    stars_.recompute(k);
    enqueue(k);
    for (int w : stars_[k].neighbours) enqueue(w);
    boundary_.queue_encroached_by(k);
    return k;
  }

  void split(int s) {
    const auto midpoint = boundary_.begin_split(s);
    if (const auto* why = std::get_if<std::string>(&midpoint)) {
      stalled_ = *why;
      return;
    }
    insert(std::get<Point2<double>>(midpoint), Rule::encroachment);
    boundary_.end_split(s);
  }

  // Refine(τ) for the triangle τ = (v, a, b) of S_v: Pick_valid, then Insert_or_snap.
  void refine(int v, const Action& act) {
    ++refinements_;
    const auto& x = sites_.points;
    const Sym2<double> M = sites_.metrics[v];
    const geometry::Circumellipse<double> c = geometry::circumellipse(x[v], x[act.a], x[act.b], M);
    const Point2<double> q = pick_.pick(c, M, v, act.a, act.b);
    const Point2<double> g{(x[v].x + x[act.a].x + x[act.b].x) / 3, (x[v].y + x[act.a].y + x[act.b].y) / 3};
    // Outside Ω q is never inserted and the field need not be defined (a background mesh covering
    // exactly Ω): M_v stands in for M_q, which there only chooses the subsegment to split.
    const Sym2<double> Mq = domain_.contains(q) ? sites_.field.at(q.x, q.y) : M;
    if (const auto s = boundary_.snap(q, M, Mq, g)) {
      split(*s);
      return;
    }
    if (!sites_.in({q.x, q.x, q.y, q.y}).empty()) {
      // The picking region is below the resolution of doubles there: stop rather than duplicate.
      stalled_ = "refining a triangle at site " + std::to_string(v) + " near (" + shortest_decimal(q.x) + ", " +
                 shortest_decimal(q.y) + ") picked an existing site: the mesh there is finer than doubles resolve (" +
                 rule_name(act.rule) + ")";
      return;
    }
    insert(q, act.rule, v, std::sqrt(c.r2));
  }

  void enqueue(int v) {
    if (!queued_[v]) queued_[v] = true, site_queue_.push_back(v);
  }

  const common::Domain& domain_;
  const RefineParameters& p_;
  common::Sites sites_;
  common::Boundary boundary_;
  StarSet stars_;
  PickValid pick_;
  std::deque<int> site_queue_;
  std::vector<bool> queued_;
  std::array<std::size_t, rules_by_priority.size() + 1> counts_{};  // by rule number
  Rule last_rule_ = Rule::none;
  std::size_t refinements_ = 0;
  std::vector<common::Insertion> trace_;
  std::string stalled_;  // why refinement cannot go on, if it cannot
  std::vector<int> zone_, before_;  // scratch
};

}  // namespace

StarResult refine_star(const common::Domain& domain, const fields::MetricField& field, const RefineParameters& p,
                       const common::Progress& progress) {
  const common::Stopwatch clock;
  StarRefiner r(domain, field, p);
  const common::Stop stop = common::refine_until_done(r, p, clock, progress);
  const bool finished = stop.finished && r.stalled().empty() && r.queued() == 0;
  StarResult result = r.result(stop.reason, finished);
  result.seconds = clock.seconds();
  return result;
}

StarResult refine_star(const common::Polygon<double>& domain, const fields::MetricField& field, const RefineParameters& p,
                       const common::Progress& progress) {
  return refine_star(common::Domain(domain), field, p, progress);
}

}  // namespace anisocert::refiners::star
