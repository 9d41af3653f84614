#include "refiners/common/voronoi_refinement.hpp"

#include "geometry/ellipse_box.hpp"

#include "refiners/common/exact_split.hpp"
#include "refiners/common/circumcentre.hpp"
#include "refiners/common/segment_cells.hpp"
#include "refiners/common/segment_quadratics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace anisocert::refiners::common {


namespace {

// An upper bound on |b − a|²_M: the quadratic form in doubles plus a bound on its rounding error
// (under 2⁻⁵⁰ of the sum of its terms' magnitudes).
double squared_length_above(const Sym2<double>& M, const Point2<double>& a, const Point2<double>& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double xx = M.m11 * dx * dx, xy = 2 * M.m12 * dx * dy, yy = M.m22 * dy * dy;
  return xx + xy + yy + std::ldexp(xx + std::abs(xy) + yy, -50);
}

}  // namespace

// Lower bounds on d_Q(z)² over the points z at least gx away from Q in x and gy in y:
// λ_min(M_Q)(gx² + gy²), (det M_Q / m22) gx² and (det M_Q / m11) gy² (d_Q² least over the other
// coordinate), the three factors bounded below in intervals. The last two are what make the
// filter of `reaches` work for the linear field's sites, a hundred times narrower in y than in x:
// λ_min alone is the x factor.
struct VoronoiRefinement::ReachBounds {
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

std::string VoronoiRules::name(int rule) const {
  for (const common::RuleName& r : by_priority)
    if (r.number == rule) return r.name;
  return "rule " + std::to_string(rule);
}

VoronoiRefinement::VoronoiRefinement(const common::Domain& domain, const fields::MetricField& diagram_field, VoronoiRules rules,
                                     bool filters, CornerNote note)
    : domain_(domain),
      sites_(domain, diagram_field),
      diagram_(domain.bounding_box(),
               std::ldexp(std::max(domain.bounding_box().x1 - domain.bounding_box().x0, domain.bounding_box().y1 - domain.bounding_box().y0), -40),
               &domain_),
      record_(rules.by_priority),
      rules_(std::move(rules)),
      filters_(filters),
      corner_note_(std::move(note)) {}

void VoronoiRefinement::start() {
  for (const auto& c : domain_.vertices()) add_site(c, sites_.field.at(c.x, c.y));  // X's: Ω's corners, then its points
  for (std::size_t e = 0; e < domain_.segment_count(); ++e) {
    const auto [a, b] = domain_.segment_ends(e);
    subsegments_.add(a, b, static_cast<int>(e));
  }
  corners_.emplace(domain_, std::vector(sites_.metrics.begin(), sites_.metrics.begin() + static_cast<std::ptrdiff_t>(domain_.vertices().size())));
}

bool VoronoiRefinement::split_encroached() {
  if (split_corner_shell()) return true;
  while (const auto s = subsegments_.pop()) {
    const std::vector<int> by = encroachers(*s);
    if (by.empty()) {
      not_encroached(*s);
      continue;
    }
    std::vector<MetricSite> in;
    for (int w : by) in.push_back(site(w));
    split(*s, in, near(*s), rules_.encroached);
    return true;
  }
  return false;
}

bool VoronoiRefinement::attack_unresolved() {
  if (ties_.empty()) return false;
  const Point2<double> c = ties_.front();
  ties_.pop_front();
  attack(c, rules_.unresolved, 0, "the point where the diagram is unresolved (a Voronoi vertex of degree 4 or more)");
  return true;
}

CertifiedPoint VoronoiRefinement::point(int q) const {
  const auto& v = diagram_.vertices()[static_cast<std::size_t>(q)];
  return CertifiedPoint({site(v.sites[0]), site(v.sites[1]), site(v.sites[2])}, v.box);
}

common::Box VoronoiRefinement::segment_box(int s) const {
  const auto& a = sites_.points[static_cast<std::size_t>(subsegments_.ends(s).first)];
  const auto& b = sites_.points[static_cast<std::size_t>(subsegments_.ends(s).second)];
  return {std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)};
}

std::vector<MetricSite> VoronoiRefinement::near(int s) const {
  std::vector<MetricSite> out;
  for (int u : diagram_.candidates_near(segment_box(s))) out.push_back(site(u));
  return out;
}


// The counter-clockwise order of the three cells around vertex q: sign of the orientation of
// ½∇d_a², ½∇d_b², ½∇d_c² at q (near q, d_s² ≈ d² + 2 g_s·δ, so s's cell is the normal cone at
// −g_s of the triangle of the −g's). Nothing when undecided.
std::optional<Sign> VoronoiRefinement::cell_order(int q) const {
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

// A rational point rounded to doubles (Boost's conversion rounds to nearest; truncation would do
// too), within an ulp per coordinate: the point and its displacement (from above).
std::pair<Point2<double>, double> VoronoiRefinement::rounded(const Point2<Rational>& c) {
  const Point2<double> q{c.x.convert_to<double>(), c.y.convert_to<double>()};
  return {q, within_ulps(q, 1)};
}
// Vertex q as the site rule 3, 4, 5 or 7 inserts, with its displacement: when its three sites
// share one metric the vertex is their rational circumcentre in it, rounded (so that grid
// corners of one metric stay exactly on their grid and their ties stay exact ties, exact_tie.hpp);
// otherwise the middle of its certified box.
std::pair<Point2<double>, double> VoronoiRefinement::rounded_vertex(int q) const {
  const auto& v = diagram_.vertices()[static_cast<std::size_t>(q)];
  const MetricSite a = site(v.sites[0]), b = site(v.sites[1]), c = site(v.sites[2]);
  if (a.M == b.M && a.M == c.M) {
    const Point2<double> r = rounded_circumcentre(a.p, b.p, c.p, a.M);
    return {r, within_ulps(r, 1)};
  }
  const Point2<double> m = v.box.approx();
  return {m, farthest_in_box(m, v.box.box.x.lo, v.box.box.x.hi, v.box.box.y.lo, v.box.box.y.hi)};
}

bool VoronoiRefinement::attack(const Point2<double>& q, int rule, double radius, const std::string& what, double displacement) {
  const MetricSite Q{q, sites_.field.at(q.x, q.y)};
  if (const auto s = encroached_by(Q)) {
    const auto [a, b] = subsegments_.ends(*s);
    split(*s, {Q}, {site(a), site(b)}, rules_.split_instead, rule);
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
bool VoronoiRefinement::attack_vertex(int q, int rule) {
  const auto& v = diagram_.vertices()[static_cast<std::size_t>(q)];
  const auto [c, displacement] = rounded_vertex(q);
  const double radius = std::sqrt(squared_distance(site(v.sites[0]), c));  // at the site inserted
  return attack(c, rule, radius, "the Voronoi vertex of sites " + trio_text(v.sites), displacement);
}

bool VoronoiRefinement::attack_off_centre(int q, int rule, double ratio, double size) {
  const auto& v = diagram_.vertices()[static_cast<std::size_t>(q)];
  int p = v.sites[0], o = v.sites[1];
  double delta2 = std::numeric_limits<double>::infinity();
  for (int i : v.sites)
    for (int j : v.sites)
      if (i != j)
        if (const double l2 = squared_distance(site(i), sites_.points[static_cast<std::size_t>(j)]); l2 < delta2) delta2 = l2, p = i, o = j;
  const double least = ratio > 0 ? ratio * std::sqrt(delta2) : size, unit = 1;
  const MetricSite P = site(p), O = site(o);
  const Point2<double> c = rounded_vertex(q).first;
  const double r = std::sqrt(squared_distance(P, c));
  const double l = std::clamp(unit, std::min(least, r), r);
  const double tm = midpoint_parameter(P, O);
  const Point2<double> m{P.p.x + tm * (O.p.x - P.p.x), P.p.y + tm * (O.p.y - P.p.y)};
  const auto at = [&](double t) { return Point2<double>{m.x + t * (c.x - m.x), m.y + t * (c.y - m.y)}; };
  if (!(l < r * (1 - 1e-9)) || !(std::sqrt(squared_distance(P, m)) < l)) return attack_vertex(q, rule);
  double lo = 0, hi = 1;  // d_p(at(lo)) < ℓ ≤ d_p(at(hi)): d_p is convex along the way
  for (int i = 0; i < 60; ++i) {
    const double t = (lo + hi) / 2;
    (std::sqrt(squared_distance(P, at(t))) < l ? lo : hi) = t;
  }
  const Point2<double> x = at(hi);
  if (!domain_.contains(x)) return attack_vertex(q, rule);
  const auto h = geometry::ellipse_half_widths(P.M, 16 * l * l);
  for (int s : sites_.grid.sites_in({x.x - h.hx, x.x + h.hx, x.y - h.hy, x.y + h.hy}, sites_.points))
    if (squared_distance(site(s), x) < l * l * (1 - 1e-9)) return attack_vertex(q, rule);
  return attack(x, rule, l, "the off-centre of the Voronoi vertex of sites " + trio_text(v.sites));
}

bool VoronoiRefinement::attack_tie(const ExactTie& tie, int rule) {
  const auto [q, displacement] = rounded(tie.c);
  std::string sites;
  for (int u : tie.sites) sites += (sites.empty() ? "" : ", ") + std::to_string(u);
  return attack(q, rule, std::sqrt(squared_distance(site(tie.sites[0]), q)),
                "the Voronoi vertex of degree " + std::to_string(tie.sites.size()) + " of sites " + sites, displacement);
}

std::optional<Sign> VoronoiRefinement::beyond(int q, const MetricSite& a, double R) const {
  const CertifiedPoint P = point(q);
  return sign_at<1>({&P}, [&](const auto& X, auto of) {
    using T = std::decay_t<decltype(X[0].x)>;
    return distance2(lift<T>(a, of), X[0].x, X[0].y) - of(R) * of(R);
  });
}

std::optional<int> VoronoiRefinement::encroached_by(const MetricSite& Q) const {
  const ReachBounds near(Q.M);
  for (std::size_t s = 0; s < subsegments_.size(); ++s)
    if (reaches(static_cast<int>(s), Q, near)) return static_cast<int>(s);
  return std::nullopt;
}
// Queues the subsegments that site k, Q, reaches (their cells among their ends and Q meet).
void VoronoiRefinement::queue_reached(int k, const MetricSite& Q) {
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
bool VoronoiRefinement::reaches(int s, const MetricSite& Q, const ReachBounds& near) const {
  const auto [ia, ib] = subsegments_.ends(s);
  const MetricSite a = site(ia), b = site(ib);
  const common::Box box = segment_box(s);
  const double gx = std::max({box.x0 - Q.p.x, Q.p.x - box.x1, 0.0}), gy = std::max({box.y0 - Q.p.y, Q.p.y - box.y1, 0.0});
  const double length2 = std::min(squared_length_above(a.M, a.p, b.p), squared_length_above(b.M, a.p, b.p));
  // Below the least normal double the rounding errors are absolute, and the bound above may not
  // hold: the exact test decides such tiny subsegments.
  if (length2 >= std::numeric_limits<double>::min() && near.below(gx, gy) > 2 * length2) return false;
  return common::reaches(a, b, Q, filters_);
}

std::vector<int> VoronoiRefinement::encroachers(int s) const {
  const auto [a, b] = subsegments_.ends(s);
  std::vector<int> by;
  for (int w : diagram_.candidates_near(segment_box(s)))
    if (w != a && w != b && common::reaches(site(a), site(b), site(w), filters_)) by.push_back(w);
  return by;
}

bool VoronoiRefinement::split_corner_shell() {
  const auto sh = corners_->next_first_shell(subsegments_, sites_.points);
  if (!sh) return false;
  const MetricSite Z{sh->z, sites_.field.at(sh->z.x, sh->z.y)};
  const int k = insert(Z, rules_.corner_shell, 0, 0, 0);
  if (k < 0) return true;
  queue_reached(k, Z);
  subsegments_.split(sh->s, k);
  return true;
}

// LS §9: s is split at a point z in the closed cell of one of `in` among `near` (every site that
// can be nearest on s), as near the "midpoint" d_a(z) = d_b(z) as a double exactly on s allows:
// that point itself when it is in such a cell, else the point nearest to it of the range of s
// where the first encroacher that has one is nearest. The choice is in doubles; membership is
// checked exactly, unless no double of s lies in any such cell (then the nearest, below).
void VoronoiRefinement::split(int s, const std::vector<MetricSite>& in, const std::vector<MetricSite>& near, int rule, int for_rule) {
  const auto [a, b] = subsegments_.ends(s);
  const Point2<double>&pa = sites_.points[static_cast<std::size_t>(a)], &pb = sites_.points[static_cast<std::size_t>(b)];
  const std::optional<double> shell = corners_->parameter(a, b, sites_.points);
  const double tm = shell.value_or(midpoint_parameter(site(a), site(b)));
  const auto on_s = [&](const Point2<double>& z) {
    return Point2<Rational>{Rational(z.x), Rational(z.y)};
  };
  // Within 1/64 of the subsegment of the wanted point, the coarsest dyadic point of the edge's
  // grid (coarse_split_point on the edge, its parameter u = u_a + t(u_b − u_a)): every site on
  // an edge is such a point, so a subsegment holds grid points down to 2⁻⁶⁰ of its edge. On the
  // subsegment's own grid a + j2⁻ᵏ(b − a) they ran out: after splits at arbitrary points, b − a
  // may be an odd number of a's ulps, and then no point of that grid is a double.
  const Rational slack = shell ? CornerShells::slack() : Rational(1, 64);
  const auto edge = subsegments_.edge_ends(domain_, s);
  const Point2<double> c0 = edge.first, c1 = edge.second;  // named, not bound: clang 14 cannot capture bindings
  const Rational ua = edge_parameter(c0, c1, pa), ub = edge_parameter(c0, c1, pb);
  const auto on_edge = [&](const Rational& lo, const Rational& hi, const Rational& target, const Rational& within) {
    const Rational L = ub - ua;
    const Rational e0 = ua + lo * L, e1 = ua + hi * L;
    return coarse_split_point(c0, c1, std::min(e0, e1), std::max(e0, e1), ua + target * L, within * abs(L));
  };
  std::optional<Point2<double>> z = shell ? corners_->shell_point(subsegments_, s, sites_.points) : on_edge(0, 1, Rational(tm), slack);
  // A shell's split stays on its shell, in whichever cell it falls (Ruppert's modified segment
  // splitting). LS §9 asks for an encroacher's cell for Theorem 11's insertion radii, which a sharp
  // corner voids anyway; moved off its shell into that cell, the two edges' shells drift apart
  // (0.4% under the shock field) and the ping-pong starts again (seen: a dart of 4.8°).
  if (z && !shell && !std::any_of(in.begin(), in.end(), [&](const MetricSite& w) { return nearest_at(on_s(*z), w, near); })) z.reset();
  const auto gap = [tm](const std::pair<double, double>& r) { return tm < r.first ? r.first - tm : tm > r.second ? tm - r.second : 0; };
  std::optional<std::pair<double, double>> first_range;  // of the first encroacher that has one
  for (std::size_t i = 0; i < in.size() && !z; ++i) {
    std::optional<std::pair<double, double>> best;
    for (const auto& r : nearest_ranges(pa, pb, in[i], near))
      if (!best || gap(r) < gap(*best)) best = r;
    if (!best) continue;
    if (!first_range) first_range = best;
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
  // No double of s passed the exact check: the ranges where the encroachers are nearest hold no
  // double of the edge's grid (narrower than an ulp, where sites whose metrics differ in their last
  // bits, as a P1 interpolation makes them, tie within rounding). The split is then at the grid's
  // double nearest the first encroacher's range, within 2⁻⁵⁰ of the subsegment's length outside it
  // and strictly inside the subsegment (an end found instead stops the run by name, below); it
  // need not lie in that encroacher's cell, and the encroachment is gone once s is split near it.
  // (It stopped the run before: a background field's four corners with metrics 400 ± 1 ulp,
  // whose centre's site touched an edge at its midpoint in a range of 7·10⁻¹⁷.)
  if (!z && first_range) {
    const Rational w(std::ldexp(1.0, -50)), L = ub - ua;
    const Rational lo = std::max(Rational(first_range->first) - w, Rational(0)), hi = std::min(Rational(first_range->second) + w, Rational(1));
    const Rational e0 = ua + lo * L, e1 = ua + hi * L;
    z = split_point(c0, c1, std::min(e0, e1), std::max(e0, e1), ua + Rational(std::clamp(tm, first_range->first, first_range->second)) * L);
    if (z && ((z->x == pa.x && z->y == pa.y) || (z->x == pb.x && z->y == pb.y))) z.reset();
  }
  if (!z) {
    stalled_ = "subsegment " + point_text(pa) + " – " + point_text(pb) + " is to be split in a cell where no double point exactly on it was found" +
               corner_note_(a, b);
    return;
  }
  stalled_ = subsegments_.too_fine(domain_, corner_note_, s, pa, pb, *z);
  if (!stalled_.empty()) return;
  const MetricSite Z{*z, sites_.field.at(z->x, z->y)};
  const int k = insert(Z, rule, 0, 0, for_rule);
  if (k < 0) return;
  queue_reached(k, Z);
  subsegments_.split(s, k);
}


std::vector<char> VoronoiRefinement::sites_with_vertices() const {
  std::vector<char> has(sites_.size(), 0);
  for (const auto& v : diagram_.vertices())
    if (v.holders > 0)
      for (int k : v.sites) has[static_cast<std::size_t>(k)] = 1;
  for (const ExactTie& tie : ties_anywhere_)
    for (int k : tie.sites) has[static_cast<std::size_t>(k)] = 1;
  return has;
}

// The nearest site to u other than u, each site w measured in its own metric at u: among the
// candidates of the leaves at u, or among all sites when u is the only one there (its cell holds
// those leaves whole: an island larger than a leaf, seen in BWY_R); −1 when u is the only site.
int VoronoiRefinement::nearest_other(int u) const {
  const Point2<double>& p = sites_.points[static_cast<std::size_t>(u)];
  std::vector<int> near = diagram_.candidates_near({p.x, p.x, p.y, p.y});
  if (std::none_of(near.begin(), near.end(), [u](int c) { return c != u; })) {
    near.resize(sites_.size());
    std::iota(near.begin(), near.end(), 0);
  }
  int w = -1;
  double least = INFINITY;
  for (int c : near) {
    if (c == u) continue;
    const double d2 = squared_distance(site(c), p);
    if (d2 < least) least = d2, w = c;
  }
  return w;
}

bool VoronoiRefinement::island() {
  const std::vector<char> has = sites_with_vertices();
  for (std::size_t u = 0; u < has.size(); ++u) {
    if (has[u]) continue;
    // On the segment from u to its nearest other site w, where d_u = d_w.
    const int w = nearest_other(static_cast<int>(u));
    if (w < 0) continue;
    const MetricSite U = site(static_cast<int>(u)), W = site(w);
    const double t = midpoint_parameter(U, W);
    const Point2<double> z{U.p.x + t * (W.p.x - U.p.x), U.p.y + t * (W.p.y - U.p.y)};
    if ((z.x == U.p.x && z.y == U.p.y) || (z.x == W.p.x && z.y == W.p.y)) {
      stalled_ = "site " + std::to_string(u) + " is an island (the island rule), and its bisector with site " + std::to_string(w) +
                 " has no double point between them";
      return true;
    }
    attack(z, rules_.island, 0, "the point between sites " + std::to_string(u) + " and " + std::to_string(w) + " on their bisector");
    return true;
  }
  return false;
}


void VoronoiRefinement::add_site(const Point2<double>& q, const Sym2<double>& M) {
  sites_.add(q, M);
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
int VoronoiRefinement::insert(const MetricSite& Q, int rule, double radius, double displacement, int for_rule) {
  const double nearest = sites_.grid.nearest_site2(Q.p, Q.M, sites_.points);
  if (nearest == 0) {  // two sites at one point: their distances tie along curves through it
    stalled_ = "a site by rule \"" + rules_.name(rule) + "\" would lie at " + point_text(Q.p) + ", where a site is";
    return -1;
  }
  record_.insertion(rule, Q.p, nearest, radius, displacement, for_rule);
  const int k = static_cast<int>(sites_.size());
  add_site(Q.p, Q.M);
  inserted(k);
  return stalled_.empty() ? k : -1;
}

}  // namespace anisocert::refiners::common
