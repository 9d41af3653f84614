#include "refiners/bwy/bwy_refiner.hpp"

#include "predicates/orientation.hpp"
#include "refiners/bwy/dual_triangles.hpp"
#include "refiners/bwy/local_embedding.hpp"
#include "refiners/bwy/rules.hpp"
#include "refiners/common/vertex_in_domain.hpp"
#include "refiners/common/voronoi_refinement.hpp"

#include <cmath>
#include <deque>
#include <limits>

namespace anisocert::refiners::bwy {
namespace {

using common::CertifiedPoint;
using common::MetricSite;
using common::ExactTie;
using predicates::Point2;

common::VoronoiRules bwy_rules() {
  return {number(Rule::encroached_segment), number(Rule::split_instead), number(Rule::unresolved), number(Rule::island), number(Rule::corner_shell), rule_table()};
}

// A tie's key in T (a Voronoi vertex's is its id): −1 − its index among the ties in closed Ω.
int tie_key(std::size_t i) { return -1 - static_cast<int>(i); }

class BwyRefinement : public common::VoronoiRefinement {
 public:
  BwyRefinement(const common::Domain& domain, const fields::MetricField& field, const BwyParameters& p)
      : VoronoiRefinement(domain, field, bwy_rules(), p.filters, [](int, int) { return std::string(); }), p_(p) {
    start();
    for (std::size_t q = 0; q < diagram_.vertices().size(); ++q) enter(static_cast<int>(q));
    enter_ties();
  }

  std::size_t queued() const {
    std::size_t n = subsegments_.queued() + pending_.size() + ties_.size() + unedged_.size();
    for (const auto& q : vertex_queues_) n += q.size();
    return n;
  }
  std::string done() const { return "no rule of BWY §3.2.2 applies"; }

  bool step() {
    // Rule 2 judges T, which lacks the vertices of unresolved places: those get their sites first.
    if (split_encroached() || !settle_pending() || attack_unresolved() || not_an_edge()) return true;
    for (std::size_t k = 0; k < vertex_rules.size(); ++k) {
      if (vertex_rule(k)) return true;
      if (tie_rule(vertex_rules[k])) return true;
    }
    return island();
  }

  BwyResult result(const common::Stop& stop) {
    BwyResult r;
    r.mesh.sites = sites_.points, r.mesh.metrics = sites_.metrics, r.mesh.domain = domain_.corners();
    r.mesh.segments = subsegments_.all();
    for (int t : triangles_.alive()) r.mesh.triangles.push_back(triangles_.triangle(t).sites);
    r.left_counted = !stop.out_of_time;
    r.other_vertex_choices = other_vertex_choices_;
    const std::string stalled = stalled_;
    if (r.left_counted) {
      for (std::size_t s = 0; s < subsegments_.size(); ++s) {
        const auto [a, b] = subsegments_.ends(static_cast<int>(s));
        r.encroached_left += !encroachers(static_cast<int>(s)).empty();
        r.unedged_left += !triangles_.is_edge(a, b);
      }
      for (std::size_t q = 0; q < diagram_.vertices().size(); ++q)
        if (in_T(static_cast<int>(q))) {
          r.violators_left += std::any_of(vertex_rules.begin(), vertex_rules.end(), [&](Rule rule) { return applies(rule, static_cast<int>(q)); });
          r.exempt_left += exempt(static_cast<int>(q)) && badly_shaped(static_cast<int>(q));
        }
      for (std::size_t i = 0; i < exact_ties_.size(); ++i) r.violators_left += exact_ties_[i].rule != 0 || tie_overlaps(i) || tie_shares_sites(i);
      r.embedding_failure = embedding_failure();
    }
    stalled_ = stalled;
    record_.fill(r, stop.reason, stop.finished);
    if (stop.finished && !r.embedding_failure.empty()) {
      r.consistent = false;
      r.stop_reason = "no rule applies, but T is no triangulation of Ω by BWY §3.2.1: " + r.embedding_failure;
    } else if (stop.finished && r.left_counted && r.encroached_left + r.unedged_left + r.violators_left > 0) {
      r.consistent = false;  // a queue missed something: said, never passed off as finished
      r.stop_reason = "no rule was queued, but a pass over the mesh finds one that applies";
    }
    return r;
  }

 private:
  static constexpr std::array<Rule, 4> vertex_rules{Rule::bad_shape, Rule::several_vertices, Rule::overlap, Rule::too_large};

  bool in_T(int q) const {
    return diagram_.vertices()[static_cast<std::size_t>(q)].holders > 0 && !triangles_.of_key(q).empty();
  }

  // Vertex q into T when it lies in closed Ω, with its triangle counter-clockwise (or flat), and
  // into every vertex rule's queue. When that is undecided (an irrational point on the line of an
  // edge of Ω), the vertex waits until no subsegment is encroached: a vertex on a subsegment is in
  // the closed cells of its three sites, one of which is no end of the subsegment and so encroaches
  // it, and rule 1's split then ends the vertex (seen: a comb's slot between two symmetric sites).
  // One still there after is on an edge's line outside the edge, and stops the run by name.
  void enter(int q) {
    const auto& v = diagram_.vertices()[static_cast<std::size_t>(q)];
    if (v.holders == 0) return;
    const auto in = common::in_closed_domain(domain_, point(q));
    if (!in) {
      pending_.push_back(q);
      return;
    }
    if (!*in) return;
    std::array<int, 3> t = v.sites;
    const Sign o = predicates::orientation(sites_.points[static_cast<std::size_t>(t[0])], sites_.points[static_cast<std::size_t>(t[1])],
                                           sites_.points[static_cast<std::size_t>(t[2])]);
    if (o == Sign::negative) std::swap(t[1], t[2]);
    triangles_.add(q, t, o == Sign::zero);
    for (auto& queue : vertex_queues_) queue.push_back(q);
  }
  // The vertices waiting in enter(), once no subsegment is encroached: those still vertices are
  // decided again; false (and a stall) when one is still undecided.
  bool settle_pending() {
    std::vector<int> waiting;
    std::swap(waiting, pending_);
    for (int q : waiting) {
      const auto& v = diagram_.vertices()[static_cast<std::size_t>(q)];
      if (v.holders == 0) continue;
      if (!common::in_closed_domain(domain_, point(q))) {
        stalled_ = "whether the Voronoi vertex of sites " + common::trio_text(v.sites) + ", near " + common::point_text(v.box.approx()) +
                   ", lies in Ω is undecided (it is on the line of an edge of Ω, or too near)";
        return false;
      }
      enter(q);
    }
    return true;
  }
  void leave(int key) {
    for (const auto& [a, b] : triangles_.remove(key))
      if (const auto s = subsegments_.find(a, b)) queue_unedged(*s);
  }
  // The ties' fans in T, afresh (every insertion finds the ties again).
  void enter_ties() {
    for (int i = 0; i < tie_keys_; ++i) leave(tie_key(static_cast<std::size_t>(i)));
    tie_keys_ = static_cast<int>(exact_ties_.size());
    for (std::size_t i = 0; i < exact_ties_.size(); ++i)
      for (const auto& t : exact_ties_[i].triangles) triangles_.add(tie_key(i), t, false);
  }

  void inserted(int) override {
    for (int q : diagram_.released()) leave(q);
    for (int q : diagram_.created()) enter(q);
    enter_ties();
  }
  void not_encroached(int s) override { queue_unedged(s); }
  // The island rule's sites here are T's vertices, since BWY §3.2.1 needs every site a vertex of T.
  // A site of a Voronoi vertex that lies outside Ω, or whose cell meets Ω in an island while
  // another part of it (outside Ω) holds a vertex, is in no triangle of T.
  std::vector<char> sites_with_vertices() const override {
    std::vector<char> in(sites_.size(), 0);
    for (int t : triangles_.alive())
      for (int u : triangles_.triangle(t).sites) in[static_cast<std::size_t>(u)] = 1;
    return in;
  }
  void queue_unedged(int s) {
    if (static_cast<std::size_t>(s) >= unedged_queued_.size()) unedged_queued_.resize(static_cast<std::size_t>(s) + 1, 0);
    if (unedged_queued_[static_cast<std::size_t>(s)]) return;
    unedged_queued_[static_cast<std::size_t>(s)] = 1;
    unedged_.push_back(s);
  }

  // Rule 2: a subsegment that is no edge of T gets a site on it where d_a = d_b. It is not
  // encroached (rule 1's queue is empty, and every insertion queues the subsegments it reaches),
  // so that point lies in the closed cells of a and b.
  bool not_an_edge() {
    while (!unedged_.empty()) {
      const int s = unedged_.front();
      unedged_.pop_front();
      unedged_queued_[static_cast<std::size_t>(s)] = 0;
      const auto [a, b] = subsegments_.ends(s);
      if (triangles_.is_edge(a, b)) continue;
      split(s, {site(a), site(b)}, {site(a), site(b)}, number(Rule::not_an_edge));
      return true;
    }
    return false;
  }

  // The next vertex of T to which vertex_rules[k] applies gets a site (conditionally).
  bool vertex_rule(std::size_t k) {
    const Rule rule = vertex_rules[k];
    auto& queue = vertex_queues_[k];
    while (!queue.empty()) {
      const int q = queue.front();
      queue.pop_front();
      if (!in_T(q)) continue;
      const bool bad = applies(rule, q);
      if (!stalled_.empty()) return true;
      if (!bad) continue;
      if (!insert_for(rule, q)) queue.push_front(q);
      return true;
    }
    return false;
  }
  // The site of vertex rule `rule` at vertex q; false when q is to be judged again (its site was a
  // split instead, or went at another vertex). At q, or, with off-centres (the unit-aware choice),
  // rules 3 and 6 at the off-centre of q's shortest edge at least B δ, resp. the size, from every
  // site (the guarantee of the vertex they replace), and rules 4 and 5 at the vertex their rule
  // allows whose radius is nearest unit (unit_nearest_choice).
  bool insert_for(Rule rule, int q) {
    if (!p_.off_centres) return attack_vertex(q, number(rule));
    if (rule == Rule::several_vertices || rule == Rule::overlap) {
      const int chosen = unit_nearest_choice(rule, q);
      if (chosen == q) return attack_vertex(q, number(rule));
      // q stays in T and is judged again: the site at the other vertex may leave its triangle
      // overlapping a third one, or dual to a third vertex (seen by BWY_R: "no rule applies, but T
      // is no triangulation").
      ++other_vertex_choices_;
      attack_vertex(chosen, number(rule));
      return false;
    }
    if (rule == Rule::bad_shape || rule == Rule::too_large)
      return attack_off_centre(q, number(rule), rule == Rule::bad_shape ? p_.shape_bound : 0, p_.size);
    return attack_vertex(q, number(rule));
  }
  // BWY §3.2.2 lets rule 4 insert at any of the Voronoi vertices dual to one triangle ("one of
  // them") and rule 5 at the vertex of either of two overlapping triangles ("one of them"), and
  // §4.2 states its minimal inter-distance whatever the rule: of q and those others in T, the
  // vertex whose radius r(v) = d_a(a, v) is nearest 1 (least |log r|), a choice in doubles.
  int unit_nearest_choice(Rule rule, int q) const {
    const int t = triangles_.of_key(q).front();
    std::vector<int> candidates{q};
    if (rule == Rule::several_vertices) {
      for (int u : triangles_.same_sites(t)) candidates.push_back(triangles_.triangle(u).key);
    } else if (!triangles_.triangle(t).flat) {  // a flat triangle's site goes at its own vertex
      for (int u : bwy::overlapping(triangles_, t, sites_.points)) candidates.push_back(triangles_.triangle(u).key);
    }
    int best = q;
    double best_score = std::numeric_limits<double>::infinity();
    for (int k : candidates) {
      if (k < 0 || !in_T(k)) continue;  // a tie's fan: its rule is tie_rule's
      const auto& v = diagram_.vertices()[static_cast<std::size_t>(k)];
      const double r2 = squared_distance(site(v.sites[0]), rounded_vertex(k).first);
      const double score = std::abs(std::log(r2));
      if (score < best_score) best_score = score, best = k;
    }
    return best;
  }
  // The first tie to which `rule` applies gets a site at its vertex (conditionally).
  bool tie_rule(Rule rule) {
    for (std::size_t i = 0; i < exact_ties_.size(); ++i) {
      const JudgedTie& judged_tie = exact_ties_[i];
      if (judged_tie.rule != number(rule) && !(rule == Rule::overlap && tie_overlaps(i)) &&
          !(rule == Rule::several_vertices && tie_shares_sites(i)))
        continue;
      attack_tie(judged_tie.tie, number(rule));
      return true;
    }
    return false;
  }

  // Whether `rule` (3 to 6) applies at vertex q of T, decided exactly; sets stalled_ when a sign is
  // undecided.
  bool applies(Rule rule, int q) {
    const auto& v = diagram_.vertices()[static_cast<std::size_t>(q)];
    const int t = triangles_.of_key(q).front();
    switch (rule) {
      case Rule::bad_shape: return badly_shaped(q) && !exempt(q);
      case Rule::several_vertices: return triangles_.same_sites(t).size() > 1;
      case Rule::overlap: return overlaps(t);
      case Rule::too_large: {
        if (p_.size <= 0) return false;
        const auto large = beyond(q, site(v.sites[0]), p_.size);
        if (!large) stalled_ = "whether the Voronoi vertex of sites " + common::trio_text(v.sites) + " is too large is undecided";
        return large == Sign::positive;
      }
      default: return false;
    }
  }
  // Rule 3 leaves alone a triangle across a small input angle (corner_shells.hpp); the report
  // counts those left badly shaped.
  bool exempt(int q) const { return corners_->exempt(diagram_.vertices()[static_cast<std::size_t>(q)].sites, sites_.points); }
  // Rule 3: r(v)² > B² δ(t_v)², i.e. r(v)² > B² d_p(p, q)² for one of the triangle's edges pq and one
  // of its ends p (δ is the least of these six lengths).
  bool badly_shaped(int q) {
    const auto& v = diagram_.vertices()[static_cast<std::size_t>(q)];
    const CertifiedPoint P = point(q);
    const MetricSite a = site(v.sites[0]);
    const double B = p_.shape_bound;
    bool undecided = false;  // a pair undecided: bad only if another pair decides it
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        if (i == j) continue;
        const MetricSite from = site(v.sites[static_cast<std::size_t>(i)]), to = site(v.sites[static_cast<std::size_t>(j)]);
        const auto bad = common::sign_at<1>({&P}, [&](const auto& X, auto of) {
          using T = std::decay_t<decltype(X[0].x)>;
          const T r2 = common::distance2(common::lift<T>(a, of), X[0].x, X[0].y);
          const T l2 = common::distance2(common::lift<T>(from, of), of(to.p.x), of(to.p.y));
          return r2 - of(B) * of(B) * l2;
        });
        if (!bad) undecided = true;
        else if (*bad == Sign::positive) return true;
      }
    if (undecided) stalled_ = "whether the Voronoi vertex of sites " + common::trio_text(v.sites) + " is badly shaped is undecided";
    return false;
  }
  bool tie_overlaps(std::size_t i) const {
    const auto& ts = triangles_.of_key(tie_key(i));
    return std::any_of(ts.begin(), ts.end(), [&](int t) { return overlaps(t); });
  }
  // Rule 4 at a tie: a triangle of its fan has the sites of another triangle of T.
  bool tie_shares_sites(std::size_t i) const {
    const auto& ts = triangles_.of_key(tie_key(i));
    return std::any_of(ts.begin(), ts.end(), [&](int t) { return triangles_.same_sites(t).size() > 1; });
  }
  // The tie's rule: 3 when r² > B²δ² for δ its polygon's shortest side, else 6 when r² > size², in
  // rationals; the mesh gets the fan from its first site.
  JudgedTie judged(const ExactTie& tie) const override {
    const auto exact = [](double x) { return Rational(x); };
    const MetricSite a = site(tie.sites[0]);
    const auto A = common::lift<Rational>(a, exact);
    const Rational r2 = common::distance2(A, tie.c.x, tie.c.y);
    const Rational B2 = exact(p_.shape_bound) * exact(p_.shape_bound);
    bool bad = false;
    for (std::size_t k = 0; k < tie.sites.size() && !bad; ++k) {
      const Point2<double>& p = sites_.points[static_cast<std::size_t>(tie.sites[k])];
      const Point2<double>& q = sites_.points[static_cast<std::size_t>(tie.sites[(k + 1) % tie.sites.size()])];
      bad = r2 > B2 * common::distance2(common::lift<Rational>(MetricSite{p, a.M}, exact), exact(q.x), exact(q.y));
    }
    const bool large = p_.size > 0 && r2 > exact(p_.size) * exact(p_.size);
    return {tie, bad ? number(Rule::bad_shape) : large ? number(Rule::too_large) : 0, common::fan(tie, 0)};
  }

  std::string embedding_failure() const {
    std::vector<Constraint> constraints;
    for (std::size_t s = 0; s < subsegments_.size(); ++s) {
      const auto [a, b] = subsegments_.ends(static_cast<int>(s));
      constraints.push_back({a, b, subsegments_.on_boundary(domain_, static_cast<int>(s))});
    }
    return bwy::embedding_failure(triangles_, sites_.points, constraints);
  }
  bool overlaps(int t) const { return bwy::overlaps(triangles_, t, sites_.points); }

  BwyParameters p_;
  DualTriangles triangles_;
  int tie_keys_ = 0;  // the ties whose fans are in T
  std::size_t other_vertex_choices_ = 0;
  std::array<std::deque<int>, vertex_rules.size()> vertex_queues_;  // vertices of T to judge, rule by rule
  std::vector<int> pending_;            // vertices whose place in Ω is undecided so far (enter)
  std::deque<int> unedged_;             // subsegments to test for rule 2
  std::vector<char> unedged_queued_;
};

}  // namespace

BwyResult refine_bwy(const common::Domain& domain, const fields::MetricField& field, const BwyParameters& p, const common::Progress& progress) {
  return common::run_refinement<BwyRefinement>(p, progress, domain, field, p);
}

}  // namespace anisocert::refiners::bwy
