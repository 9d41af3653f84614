#include "refiners/ls/ls_varying.hpp"

#include "fields/normalized.hpp"
#include "predicates/angle.hpp"
#include "predicates/orientation.hpp"
#include "refiners/common/exact_split.hpp"
#include "refiners/common/sites.hpp"
#include "refiners/common/vertex_in_domain.hpp"
#include "refiners/common/vertex_subdivision.hpp"
#include "refiners/ls/delaunay_in_metric.hpp"
#include "refiners/ls/exact_tie.hpp"
#include "refiners/ls/rules.hpp"
#include "refiners/ls/run_record.hpp"
#include "refiners/ls/segment_cells.hpp"
#include "refiners/ls/segment_quadratics.hpp"
#include "refiners/ls/subsegments.hpp"
#include "refiners/ls/theorem11_conditions.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <map>

namespace anisocert::refiners::ls {
namespace {

using common::CertifiedPoint;
using common::point_text;

std::string trio_text(const std::array<int, 3>& t) {
  return std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]);
}

// d_s(p)² in doubles (for choices, never for decisions).
double squared_distance(const MetricSite& s, const Point2<double>& p) {
  return common::distance2(common::lift<double>(s, [](double x) { return x; }), p.x, p.y);
}

// Lower bounds on d_Q(z)² over the points z at least gx away from Q in x and gy in y:
// λ_min(M_Q)(gx² + gy²), (det M_Q / m22) gx² and (det M_Q / m11) gy² (d_Q² least over the other
// coordinate), the three factors bounded below in intervals. The last two are what make the
// filter of `reaches` work for the linear field's sites, a hundred times narrower in y than in x:
// λ_min alone is the x factor.
struct ReachBounds {
  double least, across_x, across_y;

  explicit ReachBounds(const Sym2<double>& M) {
    using FI = FilterInterval;
    const FI m11(M.m11), m12(M.m12), m22(M.m22);
    const FI m = (m11 + m22) * 0.5, r = sqrt(sqr((m11 - m22) * 0.5) + sqr(m12));
    least = std::max(0.0, (m - r).lo);
    across_x = std::max(0.0, (m11 - sqr(m12) / m22).lo);
    across_y = std::max(0.0, (m22 - sqr(m12) / m11).lo);
  }
  double below(double gx, double gy) const { return std::max({least * (gx * gx + gy * gy), across_x * gx * gx, across_y * gy * gy}); }
};

// An upper bound on |b − a|²_M: the quadratic form in doubles plus a bound on its rounding error
// (under 2⁻⁵⁰ of the sum of its terms' magnitudes).
double squared_length_above(const Sym2<double>& M, const Point2<double>& a, const Point2<double>& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double xx = M.m11 * dx * dx, xy = 2 * M.m12 * dx * dy, yy = M.m22 * dy * dy;
  return xx + xy + yy + std::ldexp(xx + std::abs(xy) + yy, -50);
}

class LsVaryingRefinement {
 public:
  LsVaryingRefinement(const common::Domain& domain, const fields::MetricField& field, const LsParameters& p)
      : domain_(domain),
        p_(p),
        sites_(domain, p.normalized_metric ? fields::normalized(field) : field),
        size_field_(field),
        diagram_(domain.bounding_box(),
                 std::ldexp(std::max(domain.bounding_box().x1 - domain.bounding_box().x0, domain.bounding_box().y1 - domain.bounding_box().y0), -40),
                 &domain_),
        s2_(sin2_above(p.theta_bound)) {
    const auto& vertices = domain.vertices();  // X's: Ω's corners, then its points
    std::vector<Sym2<double>> metrics;
    for (const auto& c : vertices) metrics.push_back(sites_.field.at(c.x, c.y));
    t11_ = theorem11_conditions(domain, metrics, p.theta_bound);
    for (std::size_t k = 0; k < vertices.size(); ++k) add_site(vertices[k], metrics[k]);
    for (std::size_t e = 0; e < domain.segment_count(); ++e) {
      const auto [a, b] = domain.segment_ends(e);
      subsegments_.add(a, b, static_cast<int>(e));
    }
    for (std::size_t q = 0; q < diagram_.vertices().size(); ++q)
      if (diagram_.vertices()[q].holders > 0) violators_.push_back(static_cast<int>(q));
  }

  std::size_t vertices() const { return sites_.size(); }
  std::size_t queued() const { return subsegments_.queued() + ties_.size() + violators_.size(); }
  const std::string& stalled() const { return stalled_; }
  std::string done() const { return "no encroached subsegment and no violator"; }

  bool step() {
    while (const auto s = subsegments_.pop()) {
      const std::vector<int> by = encroachers(*s);
      if (by.empty()) continue;
      std::vector<MetricSite> in;
      for (int w : by) in.push_back(site(w));
      split(*s, in, near(*s), Rule::encroached_segment);
      return true;
    }
    while (!ties_.empty()) {
      const Point2<double> c = ties_.front();
      ties_.pop_front();
      attack(c, Rule::tie, 0, "the point where the diagram is unresolved (a Voronoi vertex of degree 4 or more)");
      return true;
    }
    while (!violators_.empty()) {
      const int q = violators_.front();
      violators_.pop_front();
      if (diagram_.vertices()[static_cast<std::size_t>(q)].holders == 0) continue;
      const Rule rule = violation(q);
      if (!stalled_.empty()) return true;
      if (rule == Rule::none) continue;
      const auto& v = diagram_.vertices()[static_cast<std::size_t>(q)];
      const auto [c, displacement] = rounded_vertex(q);
      const double radius = std::sqrt(squared_distance(site(v.sites[0]), c));  // at the site inserted
      if (!attack(c, rule, radius, "the Voronoi vertex of sites " + trio_text(v.sites), displacement)) violators_.push_front(q);
      return true;
    }
    for (const JudgedTie& judged : exact_ties_) {
      if (judged.rule == Rule::none) continue;
      const ExactTie& tie = judged.tie;
      const auto [q, displacement] = rounded(tie.c);
      attack(q, judged.rule, std::sqrt(squared_distance(site(tie.sites[0]), q)),
             "the Voronoi vertex of degree " + std::to_string(tie.sites.size()) + " of sites " + tie_text(tie), displacement);
      return true;
    }
    return island();
  }

  LsResult result(const common::Stop& stop) {
    LsResult r;
    r.mesh.sites = sites_.points, r.mesh.metrics = sites_.metrics, r.mesh.domain = domain_.corners();
    r.mesh.segments = subsegments_.all();
    r.left_counted = !stop.out_of_time;
    const std::string stalled = stalled_;
    for (std::size_t q = 0; q < diagram_.vertices().size(); ++q) {
      const auto& v = diagram_.vertices()[q];
      if (v.holders == 0) continue;
      const CertifiedPoint P = point(static_cast<int>(q));
      if (common::in_closed_domain(domain_, P) != std::optional<bool>(true)) continue;
      const auto order = cell_order(static_cast<int>(q));
      r.mesh.triangles.push_back(order == Sign::negative ? std::array<int, 3>{v.sites[0], v.sites[2], v.sites[1]} : v.sites);
      if (r.left_counted) r.violators_left += violation(static_cast<int>(q)) != Rule::none;
    }
    for (const JudgedTie& judged : exact_ties_) {
      for (const auto& t : judged.triangles) r.mesh.triangles.push_back(t);
      if (r.left_counted) r.violators_left += judged.rule != Rule::none;
    }
    if (r.left_counted)
      for (std::size_t s = 0; s < subsegments_.size(); ++s) r.encroached_left += !encroachers(static_cast<int>(s)).empty();
    stalled_ = stalled;
    record_.fill(r, stop.reason, stop.finished);
    return r;
  }

 private:
  MetricSite site(int k) const { return {sites_.points[static_cast<std::size_t>(k)], sites_.metrics[static_cast<std::size_t>(k)]}; }
  CertifiedPoint point(int q) const {
    const auto& v = diagram_.vertices()[static_cast<std::size_t>(q)];
    return CertifiedPoint({site(v.sites[0]), site(v.sites[1]), site(v.sites[2])}, v.box);
  }
  common::Box segment_box(int s) const {
    const auto& a = sites_.points[static_cast<std::size_t>(subsegments_.ends(s).first)];
    const auto& b = sites_.points[static_cast<std::size_t>(subsegments_.ends(s).second)];
    return {std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)};
  }
  // Every site that can be nearest somewhere on subsegment s.
  std::vector<MetricSite> near(int s) const {
    std::vector<MetricSite> out;
    for (int u : diagram_.candidates_near(segment_box(s))) out.push_back(site(u));
    return out;
  }

  // The counter-clockwise order of the three cells around vertex q: sign of the orientation of
  // ½∇d_a², ½∇d_b², ½∇d_c² at q (near q, d_s² ≈ d² + 2 g_s·δ, so s's cell is the normal cone at
  // −g_s of the triangle of the −g's). Nothing when undecided.
  std::optional<Sign> cell_order(int q) const {
    const auto& v = diagram_.vertices()[static_cast<std::size_t>(q)];
    const CertifiedPoint P = point(q);
    const std::array<MetricSite, 3> t{site(v.sites[0]), site(v.sites[1]), site(v.sites[2])};
    return common::sign_at<1>({&P}, [&](const auto& X, auto of) {
      using T = std::decay_t<decltype(X[0].x)>;
      const auto g = [&](int k) { return common::half_gradient(common::lift<T>(t[static_cast<std::size_t>(k)], of), X[0].x, X[0].y); };
      const auto g0 = g(0), g1 = g(1), g2 = g(2);
      return (g1[0] - g0[0]) * (g2[1] - g0[1]) - (g1[1] - g0[1]) * (g2[0] - g0[0]);
    });
  }
  // Rules 5, 3, 4 at vertex q, or none (a vertex outside closed Ω is no violator: LS §9 "q ∈ Ω").
  // Sets stalled_ when a decision is undecided.
  Rule violation(int q) {
    const auto& v = diagram_.vertices()[static_cast<std::size_t>(q)];
    const CertifiedPoint P = point(q);
    const auto in = common::in_closed_domain(domain_, P);
    if (!in) {
      stalled_ = "whether the Voronoi vertex of sites " + trio_text(v.sites) + " lies in Ω is undecided (it is on ∂Ω or too near)";
      return Rule::none;
    }
    if (!*in) return Rule::none;
    const auto order = cell_order(q);
    if (!order || *order == Sign::zero) {
      stalled_ = "the cells of sites " + trio_text(v.sites) + " meet tangentially at their Voronoi vertex, or too nearly to tell";
      return Rule::none;
    }
    std::array<Point2<double>, 3> t{};
    for (int k = 0; k < 3; ++k) t[static_cast<std::size_t>(k)] = sites_.points[static_cast<std::size_t>(v.sites[static_cast<std::size_t>(k)])];
    if (predicates::orientation(t[0], t[1], t[2]) != *order) return Rule::inverted;
    // LS Definition 2: q ∈ wedge(v, w) ⇔ (q − v)ᵀM_v(w − v) > 0 and (q − w)ᵀM_w(v − w) > 0.
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        if (i == j) continue;
        const MetricSite vi = site(v.sites[static_cast<std::size_t>(i)]), vj = site(v.sites[static_cast<std::size_t>(j)]);
        const auto inside = common::sign_at<1>({&P}, [&](const auto& X, auto of) {
          using T = std::decay_t<decltype(X[0].x)>;
          const auto g = common::half_gradient(common::lift<T>(vi, of), X[0].x, X[0].y);  // M_v (q − v)
          return g[0] * (of(vj.p.x) - of(vi.p.x)) + g[1] * (of(vj.p.y) - of(vi.p.y));
        });
        if (!inside) {
          stalled_ = "whether the Voronoi vertex of sites " + trio_text(v.sites) + " is wedged is undecided (it is on a wedge's line or too near)";
          return Rule::none;
        }
        if (*inside != Sign::positive) return Rule::unwedged;
      }
    if (*order == Sign::negative) std::swap(t[1], t[2]);  // counter-clockwise
    const Point2<double> c = v.box.approx();
    const std::array<Sym2<double>, 4> metrics{sites_.metrics[static_cast<std::size_t>(v.sites[0])], sites_.metrics[static_cast<std::size_t>(v.sites[1])],
                                              sites_.metrics[static_cast<std::size_t>(v.sites[2])], sites_.field.at(c.x, c.y)};
    for (const auto& M : metrics)
      for (int i = 0; i < 3; ++i)
        if (!predicates::angle_at_least_arcsin(t[static_cast<std::size_t>((i + 2) % 3)], t[static_cast<std::size_t>(i)],
                                               t[static_cast<std::size_t>((i + 1) % 3)], M, s2_))
          return Rule::poor_angle;
    // Too large: d_p(q) > size in the field's metric M_p. The three sites' distances are equal in
    // the diagram's metrics; with M′ they differ in M, and each is judged.
    const int judged = p_.size <= 0 ? 0 : p_.normalized_metric ? 3 : 1;
    for (int k = 0; k < judged; ++k) {
      const std::size_t u = static_cast<std::size_t>(v.sites[static_cast<std::size_t>(k)]);
      const MetricSite a{sites_.points[u], size_metrics_[u]};
      const auto large = common::sign_at<1>({&P}, [&](const auto& X, auto of) {
        using T = std::decay_t<decltype(X[0].x)>;
        return common::distance2(common::lift<T>(a, of), X[0].x, X[0].y) - of(p_.size) * of(p_.size);
      });
      if (!large) {
        stalled_ = "whether the Voronoi vertex of sites " + trio_text(v.sites) + " is too large is undecided";
        return Rule::none;
      }
      if (*large == Sign::positive) return Rule::too_large;
    }
    return Rule::none;
  }

  // A rational point rounded to doubles (Boost's conversion rounds to nearest; truncation would do
  // too), within an ulp per coordinate: the point and its displacement (from above).
  static std::pair<Point2<double>, double> rounded(const Point2<Rational>& c) {
    const Point2<double> q{c.x.convert_to<double>(), c.y.convert_to<double>()};
    return {q, within_ulps(q, 1)};
  }
  // Vertex q as the site rule 3, 4, 5 or 7 inserts, with its displacement: when its three sites
  // share one metric the vertex is their rational circumcentre in it, rounded (so that grid
  // corners of one metric stay exactly on their grid and their ties stay exact ties, exact_tie.hpp);
  // otherwise the middle of its certified box.
  std::pair<Point2<double>, double> rounded_vertex(int q) const {
    const auto& v = diagram_.vertices()[static_cast<std::size_t>(q)];
    const MetricSite a = site(v.sites[0]), b = site(v.sites[1]), c = site(v.sites[2]);
    if (a.M == b.M && a.M == c.M) {
      const Point2<double> r = rounded_circumcentre(a.p, b.p, c.p, a.M);
      return {r, within_ulps(r, 1)};
    }
    const Point2<double> m = v.box.approx();
    return {m, farthest_in_box(m, v.box.box.x.lo, v.box.box.x.hi, v.box.box.y.lo, v.box.box.y.hi)};
  }
  static std::string tie_text(const ExactTie& tie) {
    std::string out;
    for (int u : tie.sites) out += (out.empty() ? "" : ", ") + std::to_string(u);
    return out;
  }
  // The metrics a tie's triangles are judged in: the sites' one metric and the field's at the
  // vertex (as violation() judges a vertex of degree 3).
  std::vector<Sym2<double>> tie_metrics(const ExactTie& tie) const {
    const Point2<double> q = rounded(tie.c).first;
    return {site(tie.sites[0]).M, sites_.field.at(q.x, q.y)};
  }
  // An exact tie with its verdict and the triangles the mesh gets for it: a good fan, or any fan
  // while it is a violator. Both depend on the tie's sites alone (their places and metrics, and the
  // field at its vertex), so they are judged once, when the tie is first found.
  struct JudgedTie {
    ExactTie tie;
    Rule rule;
    std::vector<std::array<int, 3>> triangles;
  };
  // Rules 3 and 4 at an exact tie (one metric: no inverted or unwedged triangle): poor when no fan
  // of its polygon has all its angles at least θ_bound; too large as violation() judges a vertex,
  // exactly at the rational vertex.
  JudgedTie judged(const ExactTie& tie) const {
    const auto good = good_fan(tie, diagram_.sites(), tie_metrics(tie), s2_);
    return {tie, good ? too_large(tie) : Rule::poor_angle, good ? *good : fan(tie, 0)};
  }
  Rule too_large(const ExactTie& tie) const {
    if (p_.size <= 0) return Rule::none;
    const std::size_t judged = p_.normalized_metric ? tie.sites.size() : 1;
    const auto exact = [](double x) { return Rational(x); };
    for (std::size_t k = 0; k < judged; ++k) {
      const std::size_t u = static_cast<std::size_t>(tie.sites[k]);
      const auto a = common::lift<Rational>(MetricSite{sites_.points[u], size_metrics_[u]}, exact);
      if (common::distance2(a, tie.c.x, tie.c.y) > exact(p_.size) * exact(p_.size)) return Rule::too_large;
    }
    return Rule::none;
  }

  // LS §9: a site at q, unless it would encroach a subsegment, which is then split in the cell q
  // would have. False when q was not inserted (the subsegment was split instead, or the run stalls).
  bool attack(const Point2<double>& q, Rule rule, double radius, const std::string& what, double displacement = 0) {
    const MetricSite Q{q, sites_.field.at(q.x, q.y)};
    if (const auto s = encroached_by(Q)) {
      const auto [a, b] = subsegments_.ends(*s);
      split(*s, {Q}, {site(a), site(b)}, rule);
      return false;
    }
    if (!domain_.contains(q)) {
      stalled_ = what + " rounds to " + point_text(q) + ", outside Ω, and encroaches no subsegment";
      return false;
    }
    insert(Q, rule, radius, displacement);
    return true;
  }

  // A subsegment whose cell Q would meet, were Q inserted (no subsegment is encroached now, so only
  // its endpoints are nearest along it).
  std::optional<int> encroached_by(const MetricSite& Q) const {
    const ReachBounds near(Q.M);
    for (std::size_t s = 0; s < subsegments_.size(); ++s)
      if (reaches(static_cast<int>(s), Q, near)) return static_cast<int>(s);
    return std::nullopt;
  }
  // Queues the subsegments that site k, Q, reaches (their cells among their ends and Q meet).
  void queue_reached(int k, const MetricSite& Q) {
    const ReachBounds near(Q.M);
    for (std::size_t s = 0; s < subsegments_.size(); ++s) {
      const auto [a, b] = subsegments_.ends(static_cast<int>(s));
      if (a != k && b != k && reaches(static_cast<int>(s), Q, near)) subsegments_.queue(static_cast<int>(s));
    }
  }
  // Q's closed cell among Q and the ends of subsegment s meets s (segment_quadratics.hpp), after a
  // filter in doubles: Q is as near as a and b at a point z of s only if d_Q(z)² ≤ min{d_a(z)²,
  // d_b(z)²} ≤ min{|s|²_a, |s|²_b}, and d_Q(z)² is at least `near`'s bound over the box of s
  // (the filter leaves a factor 2 to the rounding of the bound below).
  bool reaches(int s, const MetricSite& Q, const ReachBounds& near) const {
    const auto [ia, ib] = subsegments_.ends(s);
    const MetricSite a = site(ia), b = site(ib);
    const common::Box box = segment_box(s);
    const double gx = std::max({box.x0 - Q.p.x, Q.p.x - box.x1, 0.0}), gy = std::max({box.y0 - Q.p.y, Q.p.y - box.y1, 0.0});
    const double length2 = std::min(squared_length_above(a.M, a.p, b.p), squared_length_above(b.M, a.p, b.p));
    // Below the least normal double the rounding errors are absolute, and the bound above may not
    // hold: the exact test decides such tiny subsegments.
    if (length2 >= std::numeric_limits<double>::min() && near.below(gx, gy) > 2 * length2) return false;
    return ls::reaches(a, b, Q, p_.filters);
  }

  std::vector<int> encroachers(int s) const {
    const auto [a, b] = subsegments_.ends(s);
    std::vector<int> by;
    for (int w : diagram_.candidates_near(segment_box(s)))
      if (w != a && w != b && ls::reaches(site(a), site(b), site(w), p_.filters)) by.push_back(w);
    return by;
  }

  // LS §9: s is split at a point z in the closed cell of one of `in` among `near` (every site that
  // can be nearest on s), as near the "midpoint" d_a(z) = d_b(z) as a double exactly on s allows:
  // that point itself when it is in such a cell, else the point nearest to it of the range of s
  // where the first encroacher that has one is nearest. The choice is in doubles; membership is
  // checked exactly. cause: rule 1, or the rule of the point that would encroach s (the split is
  // rule 2's).
  void split(int s, const std::vector<MetricSite>& in, const std::vector<MetricSite>& near, Rule cause) {
    const auto [a, b] = subsegments_.ends(s);
    const Point2<double>&pa = sites_.points[static_cast<std::size_t>(a)], &pb = sites_.points[static_cast<std::size_t>(b)];
    const double tm = midpoint_parameter(site(a), site(b));
    const auto on_s = [&](const Point2<double>& z) {
      return Point2<Rational>{Rational(z.x), Rational(z.y)};
    };
    // Within 1/64 of the subsegment of the wanted point, the coarsest dyadic point of the edge's
    // grid (coarse_split_point on the edge, its parameter u = u_a + t(u_b − u_a)): every site on
    // an edge is such a point, so a subsegment holds grid points down to 2⁻⁶⁰ of its edge. On the
    // subsegment's own grid a + j2⁻ᵏ(b − a) they ran out: after splits at arbitrary points, b − a
    // may be an odd number of a's ulps, and then no point of that grid is a double.
    const Rational slack(1, 64);
    const auto edge = subsegments_.edge_ends(domain_, s);
    const Point2<double> c0 = edge.first, c1 = edge.second;  // named, not bound: clang 14 cannot capture bindings
    const Rational ua = edge_parameter(c0, c1, pa), ub = edge_parameter(c0, c1, pb);
    const auto on_edge = [&](const Rational& lo, const Rational& hi, const Rational& target, const Rational& within) {
      const Rational L = ub - ua;
      const Rational e0 = ua + lo * L, e1 = ua + hi * L;
      return coarse_split_point(c0, c1, std::min(e0, e1), std::max(e0, e1), ua + target * L, within * abs(L));
    };
    std::optional<Point2<double>> z = on_edge(0, 1, Rational(tm), slack);
    if (z && !std::any_of(in.begin(), in.end(), [&](const MetricSite& w) { return nearest_at(on_s(*z), w, near); })) z.reset();
    const auto gap = [tm](const std::pair<double, double>& r) { return tm < r.first ? r.first - tm : tm > r.second ? tm - r.second : 0; };
    for (std::size_t i = 0; i < in.size() && !z; ++i) {
      std::optional<std::pair<double, double>> best;
      for (const auto& r : nearest_ranges(pa, pb, in[i], near))
        if (!best || gap(r) < gap(*best)) best = r;
      if (!best) continue;
      const double inset = (best->second - best->first) * 0x1p-20;
      const double lo = best->first + inset, hi = best->second - inset;
      if (!(lo <= hi)) continue;
      if (lo < hi) {
        z = on_edge(Rational(lo), Rational(hi), Rational(std::clamp(tm, lo, hi)), slack);
      } else {  // a cell that touches s at one point (a site on s's diametral ellipse): that point, if a double of the grid
        const Rational e = ua + Rational(lo) * (ub - ua);
        z = split_point(c0, c1, e, e, e);
      }
      if (z && !nearest_at(on_s(*z), in[i], near)) z.reset();
    }
    if (!z) {
      stalled_ = "subsegment " + point_text(pa) + " – " + point_text(pb) + " is to be split in a cell where no double point exactly on it was found" +
                 corner_note(domain_, t11_, a, b);
      return;
    }
    stalled_ = subsegments_.too_fine(domain_, t11_, s, pa, pb, *z);
    if (!stalled_.empty()) return;
    const MetricSite Z{*z, sites_.field.at(z->x, z->y)};
    const int k = cause == Rule::encroached_segment ? insert(Z, cause, 0) : insert(Z, Rule::violator_encroaches, 0, 0, cause);
    if (k < 0) return;
    queue_reached(k, Z);
    subsegments_.split(s, k);
  }

  // Rule 6, when nothing else applies: a site whose cell holds no Voronoi vertex (of degree 3, or an
  // exact tie) that the diagram keeps, i.e. in or near Ω.
  bool island() {
    std::vector<char> has(sites_.size(), 0);
    for (const auto& v : diagram_.vertices())
      if (v.holders > 0)
        for (int k : v.sites) has[static_cast<std::size_t>(k)] = 1;
    for (const ExactTie& tie : ties_anywhere_)
      for (int k : tie.sites) has[static_cast<std::size_t>(k)] = 1;
    for (std::size_t u = 0; u < has.size(); ++u) {
      if (has[u]) continue;
      // On the segment from u to its nearest other site w (in w's metric at u), where d_u = d_w.
      const MetricSite U = site(static_cast<int>(u));
      int w = -1;
      double least = INFINITY;
      for (int c : diagram_.candidates_near({U.p.x, U.p.x, U.p.y, U.p.y})) {
        if (c == static_cast<int>(u)) continue;
        const MetricSite C = site(c);
        const double d2 = squared_distance(C, U.p);
        if (d2 < least) least = d2, w = c;
      }
      if (w < 0) continue;
      const MetricSite W = site(w);
      const double t = midpoint_parameter(U, W);
      const Point2<double> z{U.p.x + t * (W.p.x - U.p.x), U.p.y + t * (W.p.y - U.p.y)};
      if ((z.x == U.p.x && z.y == U.p.y) || (z.x == W.p.x && z.y == W.p.y)) {
        stalled_ = "site " + std::to_string(u) + "'s cell holds no Voronoi vertex, and its bisector with site " + std::to_string(w) +
                   " has no double point between them";
        return true;
      }
      attack(z, Rule::island, 0, "the point between sites " + std::to_string(u) + " and " + std::to_string(w) + " on their bisector");
      return true;
    }
    return false;
  }

  void add_site(const Point2<double>& q, const Sym2<double>& M) {
    sites_.add(q, M);
    size_metrics_.push_back(p_.normalized_metric ? size_field_.at(q.x, q.y) : M);
    sites_.grow_grid();
    diagram_.insert({q, M});
    ties_.clear();
    exact_ties_.clear();
    ties_anywhere_.clear();
    if (diagram_.full()) {
      stalled_ = "the diagram's subdivision reached its bound on boxes after the site at " + point_text(q) +
                 " (sites too near to tell apart, or distances that tie along a curve)";
      return;
    }
    // The unresolved leaves that meet Ω, all of them again after every insertion (an insertion may
    // resolve some): a leaf whose candidates make an exact tie (exact_tie.hpp) holds its vertex,
    // kept when in closed Ω, or no vertex; any other gives rule 8 its centre.
    if (diagram_.resolved()) return;
    // Ties are kept from one insertion to the next by their leaves' candidates (sites keep their
    // places and metrics: a set's tie, and its verdict, never change), only those of leaves still
    // unresolved.
    std::map<std::vector<int>, std::optional<JudgedTie>> known;
    for (const auto& leaf : diagram_.unresolved()) {
      const common::Box& b = leaf.box;
      auto cached = known.find(leaf.candidates);
      if (cached == known.end()) {
        auto earlier = tie_of_.find(leaf.candidates);
        std::optional<JudgedTie> found;
        if (earlier != tie_of_.end()) found = std::move(earlier->second);
        else if (const auto tie = exact_tie(diagram_.sites(), leaf.candidates)) found = judged(*tie);
        cached = known.emplace(leaf.candidates, std::move(found)).first;
      }
      if (const auto& judged_tie = cached->second) {
        const ExactTie& tie = judged_tie->tie;
        const auto same = [&](const ExactTie& t) { return t.c.x == tie.c.x && t.c.y == tie.c.y; };
        if (in_closed_box(tie.c, b) && std::none_of(ties_anywhere_.begin(), ties_anywhere_.end(), same)) {
          ties_anywhere_.push_back(tie);
          if (domain_.contains(tie.c)) exact_ties_.push_back(*judged_tie);
        }
        continue;
      }
      if (domain_.contains(b) == std::optional<bool>(false)) continue;  // no vertex of the mesh there
      // The leaf's centre, or when a site is there already (an earlier rule 8 site, in a leaf still
      // unresolved), the centre of one of its quarters; none free stops the run.
      const double w = b.x1 - b.x0, h = b.y1 - b.y0;
      const std::array<Point2<double>, 5> at{{{b.x0 + w / 2, b.y0 + h / 2},
                                              {b.x0 + w / 4, b.y0 + h / 4},
                                              {b.x1 - w / 4, b.y0 + h / 4},
                                              {b.x0 + w / 4, b.y1 - h / 4},
                                              {b.x1 - w / 4, b.y1 - h / 4}}};
      const auto free = std::find_if(at.begin(), at.end(), [&](const Point2<double>& p) {
        return sites_.grid.nearest_site2(p, sites_.field.at(p.x, p.y), sites_.points) > 0;
      });
      if (free == at.end()) {
        stalled_ = "the diagram is unresolved in the box from " + point_text({b.x0, b.y0}) + " to " + point_text({b.x1, b.y1}) +
                   ", and its centre and its quarters' centres are sites";
        return;
      }
      const Point2<double> c = *free;
      if (std::none_of(ties_.begin(), ties_.end(), [&](const Point2<double>& t) { return t.x == c.x && t.y == c.y; })) ties_.push_back(c);
    }
    tie_of_ = std::move(known);
  }

  // Inserts Q as a site; its index, or −1 when the run stalls. The caller queues the subsegments
  // Q reaches (attack: none, or it would have split one instead).
  int insert(const MetricSite& Q, Rule rule, double radius, double displacement = 0, Rule for_rule = Rule::none) {
    const double nearest = sites_.grid.nearest_site2(Q.p, Q.M, sites_.points);
    if (nearest == 0) {  // two sites at one point: their distances tie along curves through it
      stalled_ = "a site by rule \"" + std::string(rule_name(rule)) + "\" would lie at " + point_text(Q.p) + ", where a site is";
      return -1;
    }
    record_.insertion(rule, Q.p, nearest, radius, displacement, for_rule);
    const int k = static_cast<int>(sites_.size());
    add_site(Q.p, Q.M);
    for (int q : diagram_.created()) violators_.push_back(q);
    return stalled_.empty() ? k : -1;
  }


  const common::Domain& domain_;
  LsParameters p_;
  common::Sites sites_;                     // with the diagram's metrics (M′ with normalized_metric)
  fields::MetricField size_field_;           // the field, for the size rule
  std::vector<Sym2<double>> size_metrics_;  // the field's metric at each site
  common::VertexSubdivision diagram_;
  double s2_;
  Theorem11Conditions t11_;
  Subsegments subsegments_;
  std::deque<int> violators_;
  std::deque<Point2<double>> ties_;
  std::vector<ExactTie> ties_anywhere_;  // every exact tie of the diagram (in Ω's bounding box)
  std::vector<JudgedTie> exact_ties_;   // those in closed Ω
  std::map<std::vector<int>, std::optional<JudgedTie>> tie_of_;  // by the unresolved leaves' candidates
  std::string stalled_;
  RunRecord record_;
};

}  // namespace

LsResult refine_ls_varying(const common::Domain& domain, const fields::MetricField& field, const LsParameters& p,
                           const common::Progress& progress) {
  return common::run_refinement<LsVaryingRefinement>(p, progress, domain, field, p);
}

}  // namespace anisocert::refiners::ls
