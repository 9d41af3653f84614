#include "refiners/ls/ls_refiner.hpp"

#include "fields/normalized.hpp"
#include "predicates/angle.hpp"
#include "predicates/orientation.hpp"
#include "refiners/common/corner_shells.hpp"
#include "refiners/common/exact_split.hpp"
#include "refiners/common/run_record.hpp"
#include "refiners/common/sites.hpp"
#include "refiners/ls/delaunay_in_metric.hpp"
#include "refiners/ls/ls_varying.hpp"
#include "refiners/ls/rules.hpp"
#include "refiners/common/segment_cells.hpp"
#include "refiners/common/subsegments.hpp"
#include "refiners/ls/theorem11_conditions.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

namespace anisocert::refiners::ls {
namespace {

using common::cell_along;
using common::CellOnSegment;
using common::cells_along;
using common::metric_text;
using common::near_segment;
using common::outside_diametral_ellipse;
using common::point_text;
using common::split_point;
using common::Subsegments;
using common::within_ulps;

template <class T>
T squared_length(const Sym2<double>& M, const Point2<T>& p, const Point2<double>& v) {
  return predicates::quadratic_form(T(M.m11), T(M.m12), T(M.m22), T(p.x - T(v.x)), T(p.y - T(v.y)));
}

class LsRefinement {
 public:
  LsRefinement(const common::Domain& domain, const fields::MetricField& field, const LsParameters& p)
      : domain_(domain),
        p_(p),
        sites_(domain, p.normalized_metric ? fields::normalized(field) : field),
        metric_(sites_.field.at(domain.corners()[0].x, domain.corners()[0].y)),
        size_metric_(field.at(domain.corners()[0].x, domain.corners()[0].y)),
        corners_(domain, std::vector(domain.vertices().size(), metric_)),
        diagram_(metric_, domain.bounding_box()),
        s2_(sin2_above(p.theta_bound)),
        t11_(theorem11_conditions(domain, std::vector(domain.vertices().size(), metric_), p.theta_bound)),
        size2_(Rational(p.size) * Rational(p.size)) {
    const auto& vertices = domain.vertices();  // X's: Ω's corners, then its points
    for (std::size_t k = 0; k < vertices.size(); ++k) {
      const Sym2<double> M = sites_.field.at(vertices[k].x, vertices[k].y);
      if (M != metric_)
        throw common::FieldError("--algo ls on the field " + field.name + ", taken as constant (one metric, Del_M), gives " +
                                 metric_text(metric_) + " at " + domain.corner_text(0) + " and " +
                                 metric_text(M) + " at " + domain.corner_text(k));
      diagram_.insert(sites_.add(vertices[k], M), vertices[k]);
    }
    boxes_.reset(sites_.grid);
    for (std::size_t e = 0; e < domain.segment_count(); ++e) {
      const auto [a, b] = domain.segment_ends(e);
      const int s = subsegments_.add(a, b, static_cast<int>(e));
      boxes_.set(s, near_segment(vertices[static_cast<std::size_t>(a)], vertices[static_cast<std::size_t>(b)], metric_), sites_.grid);
    }
    for (std::size_t t = 0; t < diagram_.slots(); ++t)
      if (diagram_.triangle(static_cast<int>(t)).alive) queue_if_violator(static_cast<int>(t));
  }

  std::size_t vertices() const { return sites_.size(); }
  std::size_t queued() const { return subsegments_.queued() + violators_.size(); }
  const std::string& stalled() const { return stalled_; }
  std::string done() const { return "no encroached subsegment and no violator"; }

  bool step() {
    if (split_corner_shell()) return true;
    while (const auto s = subsegments_.pop()) {
      const std::vector<CellOnSegment> by = encroachers(*s);
      if (by.empty()) continue;
      split(*s, by, Rule::encroached_segment);
      return true;
    }
    while (!violators_.empty()) {
      const auto [t, v] = violators_.front();
      violators_.pop_front();
      if (!current(t, v)) continue;
      const Rule rule = violation(t);
      if (rule == Rule::none) continue;
      const Point2<double> q = diagram_.rounded_circumcentre(t);
      // LS §9: "A new site is never permitted to encroach upon a segment".
      if (const auto s = encroached_by(q)) {
        split(s->first, {s->second}, rule);
        violators_.emplace_front(t, v);
        return true;
      }
      if (!domain_.contains(q)) {
        stalled_ = "the Voronoi vertex of sites " + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " + std::to_string(v[2]) +
                   " rounds to " + point_text(q) + ", outside Ω, and encroaches no subsegment";
        return true;
      }
      // q is the vertex rounded to nearest (below the normal range by Boost's conversion, which
      // rounds twice): within one of q's own ulps.
      insert(q, rule, std::sqrt(squared_length(metric_, q, diagram_.point(v[0]))), within_ulps(q, 1));
      return true;
    }
    return false;
  }

  LsResult result(const common::Stop& stop) const {
    LsResult r;
    r.mesh.sites = sites_.points, r.mesh.metrics = sites_.metrics, r.mesh.domain = domain_.corners();
    r.mesh.segments = subsegments_.all();
    r.left_counted = !stop.out_of_time;
    for (std::size_t t = 0; t < diagram_.slots(); ++t) {
      const auto& tri = diagram_.triangle(static_cast<int>(t));
      if (!tri.alive || !diagram_.real(static_cast<int>(t))) continue;
      if (vertex_in_domain(static_cast<int>(t), diagram_.circumcentre_box(static_cast<int>(t)))) r.mesh.triangles.push_back(tri.v);
      if (r.left_counted) {
        bool exempted = false;
        r.violators_left += violation(static_cast<int>(t), &exempted) != Rule::none;
        r.exempt_left += exempted;
      }
    }
    if (r.left_counted)
      for (std::size_t s = 0; s < subsegments_.size(); ++s) r.encroached_left += !encroachers(static_cast<int>(s)).empty();
    record_.fill(r, stop.reason, stop.finished);
    return r;
  }

 private:
  bool current(int t, const std::array<int, 3>& v) const {
    return t < static_cast<int>(diagram_.slots()) && diagram_.triangle(t).alive && diagram_.triangle(t).v == v;
  }

  // Rule 3 or 4 for the Voronoi vertex dual to triangle t, or none (a vertex outside closed Ω is
  // no violator: LS §9 "q ∈ Ω"). The filtered predicates and boxes decide; rationals when they
  // cannot. Rule 3 leaves alone a triangle across a small input angle (corner_shells.hpp), and says
  // so in `exempted` when the vertex is in Ω.
  Rule violation(int t, bool* exempted = nullptr) const {
    if (!diagram_.real(t)) return Rule::none;
    const auto& v = diagram_.triangle(t).v;
    bool poor = false;
    for (int i = 0; i < 3 && !poor; ++i)
      poor = !predicates::angle_at_least_arcsin(diagram_.point(v[(i + 2) % 3]), diagram_.point(v[i]), diagram_.point(v[(i + 1) % 3]),
                                                metric_, s2_);
    const bool exempt = poor && corners_.exempt(v, sites_.points);
    poor = poor && !exempt;
    const Point2<FilterInterval>& c = diagram_.circumcentre_box(t);
    if (exempt && exempted && vertex_in_domain(t, c)) *exempted = true;
    if (!poor && !too_large(t, c)) return Rule::none;
    if (!vertex_in_domain(t, c)) return Rule::none;
    return poor ? Rule::poor_angle : Rule::too_large;
  }
  // c: a box holding the vertex.
  // With M′ the circumcentre is equidistant in M′, whose rounded entries are not exactly a multiple
  // of M: each vertex is judged in M, as ls_varying does.
  bool too_large(int t, const Point2<FilterInterval>& c) const {
    if (p_.size <= 0) return false;
    for (int k = 0; k < (p_.normalized_metric ? 3 : 1); ++k) {
      const Point2<double>& a = diagram_.point(diagram_.triangle(t).v[static_cast<std::size_t>(k)]);
      if (p_.filters)
        if (const auto s = (squared_length(size_metric_, c, a) - FilterInterval(p_.size) * p_.size).sign(); s && *s != Sign::zero) {
          if (*s == Sign::positive) return true;
          continue;
        }
      if (squared_length(size_metric_, diagram_.exact_circumcentre(t), a) > size2_) return true;
    }
    return false;
  }
  bool vertex_in_domain(int t, const Point2<FilterInterval>& c) const {
    if (p_.filters)
      if (const auto in = domain_.contains(common::Box{c.x.lo, c.x.hi, c.y.lo, c.y.hi})) return *in;
    return domain_.contains(diagram_.exact_circumcentre(t));
  }

  void queue_if_violator(int t) {
    if (violation(t) != Rule::none) violators_.emplace_back(t, diagram_.triangle(t).v);
  }

  // The cells other than its endpoints' that subsegment s meets. A cell that meets s in a single
  // point (s passes through its Voronoi vertex with a and b) counts only when s lies on ∂Ω and its
  // site strictly outside Ω's side of s: the triangle of a, b and that site, dual to a vertex on s,
  // would lie outside Ω. On Ω's side, or on either side of an interior segment, it is harmless (s
  // stays a dual edge, the triangle lies in Ω), and splitting there would need the vertex's own
  // parameter, which need not be a double point.
  std::vector<CellOnSegment> encroachers(int s) const {
    const auto ends = subsegments_.ends(s);
    const Point2<double>&pa = sites_.points[ends.first], &pb = sites_.points[ends.second];
    const common::Box box = near_segment(pa, pb, metric_);
    std::vector<std::pair<int, Point2<double>>> near;
    for (int u : sites_.in(box))
      if (!p_.filters || !outside_diametral_ellipse(pa, pb, metric_, sites_.points[u])) near.emplace_back(u, sites_.points[u]);
    if (near.size() <= 2) return {};  // a and b only
    std::vector<CellOnSegment> by = cells_along(pa, pb, metric_, near, p_.filters);
    const bool on_boundary = subsegments_.on_boundary(domain_, s);
    std::erase_if(by, [&](const CellOnSegment& c) {
      return c.site == ends.first || c.site == ends.second ||
             (c.point() && (!on_boundary || predicates::orientation(pa, pb, sites_.points[c.site]) != Sign::negative));
    });
    return by;
  }

  // A subsegment q's cell would meet in more than a point, were q inserted, and that part of it
  // (when no subsegment is encroached, the cells along each are its endpoints' only). A violator
  // lies in Ω: a single contact is on Ω's side, which encroachers() lets pass.
  std::optional<std::pair<int, CellOnSegment>> encroached_by(const Point2<double>& q) const {
    for (int s : boxes_.holding(q, sites_.grid))
      if (auto c = would_meet(s, q); c && !c->point()) return std::pair{s, *c};
    return std::nullopt;
  }
  // The part of s that q's closed cell would meet among q and the ends of s, perhaps a single
  // point (a site inserted on one edge of a slot can touch the other's subsegment from outside Ω:
  // that one must be tested again, by encroachers()).
  std::optional<CellOnSegment> would_meet(int s, const Point2<double>& q) const {
    if (!boxes_.box(s).contains(q)) return std::nullopt;
    const auto [a, b] = subsegments_.ends(s);
    const Point2<double>&pa = sites_.points[a], &pb = sites_.points[b];
    if (p_.filters && outside_diametral_ellipse(pa, pb, metric_, q)) return std::nullopt;
    return cell_along(pa, pb, metric_, {{a, pa}, {b, pb}, {-1, q}}, -1, p_.filters);
  }

  // LS §9: s is split in one of the cells `in`, the one nearest its midpoint (one that meets s in
  // more than a point when there is one), as near the midpoint as a double exactly on s allows; at
  // the apex of a small angle, its shell instead of the midpoint (corner_shells.hpp).
  // cause: rule 1, or the rule of the violator whose site would encroach s (the split is rule 2's).
  void split(int s, const std::vector<CellOnSegment>& in, Rule cause) {
    const auto [a, b] = subsegments_.ends(s);
    const std::optional<double> shell = corners_.parameter(a, b, sites_.points);
    const Rational target(shell.value_or(0.5));
    const auto gap = [&](const CellOnSegment& c) { return c.lo > target ? c.lo - target : c.hi < target ? target - c.hi : Rational(0); };
    const auto better = [&](const CellOnSegment& c, const CellOnSegment& d) {
      return c.point() != d.point() ? !c.point() : gap(c) < gap(d);
    };
    const CellOnSegment* best = &in.front();
    for (const CellOnSegment& c : in)
      if (better(c, *best)) best = &c;
    // A shell's split lies on its shell in whichever cell it falls (voronoi_refinement.cpp's split
    // says why not in an encroacher's cell).
    std::optional<Point2<double>> z = corners_.shell_point(subsegments_, s, sites_.points);
    if (!z) z = split_point(sites_.points[a], sites_.points[b], best->lo, best->hi, target);
    if (!z) {
      stalled_ = "subsegment " + point_text(sites_.points[a]) + " – " + point_text(sites_.points[b]) +
                 " is to be split in a cell that holds no double point exactly on it" + corner_note(domain_, t11_, a, b);
      return;
    }
    stalled_ = subsegments_.too_fine(domain_, corner_note(domain_, t11_), s, sites_.points[a], sites_.points[b], *z);
    if (!stalled_.empty()) return;
    const int k = cause == Rule::encroached_segment ? insert(*z, cause, 0) : insert(*z, Rule::violator_encroaches, 0, 0, cause);
    if (k < 0) return;
    const int kb = subsegments_.split(s, k);
    boxes_.set(s, near_segment(sites_.points[a], sites_.points[k], metric_), sites_.grid);
    boxes_.set(kb, near_segment(sites_.points[k], sites_.points[b], metric_), sites_.grid);
  }

  // The corner lopping (corner_shells.hpp), one shell a step before any encroached subsegment.
  bool split_corner_shell() {
    const auto sh = corners_.next_first_shell(subsegments_, sites_.points);
    if (!sh) return false;
    const auto [a, b] = subsegments_.ends(sh->s);
    const int k = insert(sh->z, Rule::corner_shell, 0);
    if (k < 0) return true;
    const int kb = subsegments_.split(sh->s, k);
    boxes_.set(sh->s, near_segment(sites_.points[a], sites_.points[k], metric_), sites_.grid);
    boxes_.set(kb, near_segment(sites_.points[k], sites_.points[b], metric_), sites_.grid);
    return true;
  }

  // Inserts q as a site; its index, or −1 when the run stalls.
  int insert(const Point2<double>& q, Rule rule, double radius, double displacement = 0, Rule for_rule = Rule::none) {
    const Sym2<double> M = sites_.field.at(q.x, q.y);
    if (M != metric_) {
      stalled_ = "the field " + sites_.field.name + ", taken as constant (one metric, Del_M), gives " + metric_text(M) + " at " +
                 point_text(q) + ", not the corners' " + metric_text(metric_);
      return -1;
    }
    const double nearest = sites_.grid.nearest_site2(q, M, sites_.points);
    record_.insertion(static_cast<int>(rule), q, nearest, radius, displacement, static_cast<int>(for_rule));
    const int k = sites_.add(q, M);
    if (sites_.grow_grid()) boxes_.refile(sites_.grid);
    for (int t : diagram_.insert(k, q)) queue_if_violator(t);
    for (int s : boxes_.holding(q, sites_.grid))
      if (would_meet(s, q)) subsegments_.queue(s);
    return k;
  }

  const common::Domain& domain_;
  LsParameters p_;
  common::Sites sites_;
  Sym2<double> metric_;       // the diagram's (M′ with normalized_metric)
  Sym2<double> size_metric_;  // the field's, for the size rule
  common::CornerShells corners_;
  DelaunayInMetric diagram_;
  double s2_;
  Theorem11Conditions t11_;
  Rational size2_;
  Subsegments subsegments_;
  common::FiledBoxes boxes_;  // near_segment of each subsegment
  std::deque<std::pair<int, std::array<int, 3>>> violators_;
  std::string stalled_;
  common::RunRecord record_{rule_table()};
};

}  // namespace

LsResult refine_ls(const common::Domain& domain, const fields::MetricField& field, const LsParameters& p, const common::Progress& progress) {
  if (field.name != "constant") return refine_ls_varying(domain, field, p, progress);
  return common::run_refinement<LsRefinement>(p, progress, domain, field, p);
}

}  // namespace anisocert::refiners::ls
