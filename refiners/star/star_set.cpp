#include "refiners/star/star_set.hpp"

#include "geometry/circumellipse.hpp"
#include "geometry/ellipse_box.hpp"
#include "predicates/incircle.hpp"
#include "predicates/orientation.hpp"
#include "refiners/star/gift_wrap.hpp"

#include <algorithm>
#include <cmath>

namespace anisocert::refiners::star {
namespace {

// The search for S_v's candidates (floating-point boxes; every decision on the candidates is an
// exact predicate). A candidate set that misses a Delaunay neighbour would make S_v wrong. The
// margins below are far above the rounding of the doubles the reaches are computed in (≈ 10⁻¹⁶
// relative) for well-conditioned metrics and triangles; the errors grow with the metric's
// condition number and, for the circumcentres, with 1/det of nearly flat triangles, so for metrics
// anisotropic beyond about 10⁶ : 1 or nearly flat fans they are not a proof. A star made wrong that
// way makes the final mesh fail the certifier's exact local-uniformity check; it cannot make two
// stars disagree unnoticed (consistency is decided on the stars as computed).
//  - the first search of a site without a star reaches M-distance 2.5 (the first sites: corners,
//    and a mesh's interior vertices) or twice its nearest site's distance (inserted sites);
constexpr double default_first_reach2 = 6.25;
//  - a star's later searches reach its previous reach (stars only shrink, LU Lemma 3.5), 10⁻⁴ more;
//  - a fan fits when every circumellipse's reach is 10⁻⁴ inside the search radius;
constexpr double reach_margin = 1.0001;
//  - the search radius grows fourfold (in M-distance²) until the fan fits and is complete, up to
//    four times Ω's squared M-diameter, beyond which no site lies.
constexpr double reach_growth = 4;

// Folds one triangle of S_v, with circumellipse c in M = M_v, into the star's reach (the M-distance
// from v to the far side of c, squared; returned unsquared) and its conflict zone's box.
double extend_zone(const Point2<double>& pv, const Sym2<double>& M, const geometry::Circumellipse<double>& c,
                   common::Box& zone, double& reach2) {
  const double reach = std::sqrt(predicates::quadratic_form(M, c.cx - pv.x, c.cy - pv.y)) + std::sqrt(c.r2);
  reach2 = std::max(reach2, reach * reach);
  const auto h = geometry::ellipse_half_widths(M, c.r2);
  zone = {std::min(zone.x0, c.cx - h.hx), std::max(zone.x1, c.cx + h.hx), std::min(zone.y0, c.cy - h.hy),
          std::max(zone.y1, c.cy + h.hy)};
  return reach;
}

void sort_unique(std::vector<int>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace

StarSet::StarSet(const common::Domain& domain, const common::Sites& sites, const common::Boundary& boundary)
    : domain_(domain), sites_(sites), boundary_(boundary) {
  index_.reset(sites_.grid);
}

void StarSet::add(double reach2) {
  stars_.emplace_back();
  reach2_.push_back(reach2);
}

void StarSet::set_zone(int v, const common::Box& zone) {
  Star& s = stars_[v];
  s.zone = zone;
  const common::Cells cells = sites_.grid.cells_of(zone);
  if (cells == s.cells) return;
  index_.move(v, s.cells, cells);
  s.cells = cells;
}

void StarSet::refile() {
  index_.reset(sites_.grid);
  for (int v = 0; v < static_cast<int>(stars_.size()); ++v) {
    Star& st = stars_[v];
    st.cells = {};
    if (st.zone.x0 <= st.zone.x1) set_zone(v, st.zone);
  }
}

// Whether a star triangle lies in Ω. Its edges cross no edge of Ω (visibility) and it holds no
// site, so a vertex strictly inside Ω puts it inside; only triangles with all three vertices on
// ∂Ω (in a non-convex Ω) need a test: their centroid, exactly (it is not on ∂Ω).
bool StarSet::triangle_in_domain(int v, int a, int b) const {
  if (domain_.convex() || !boundary_.on_boundary(v) || !boundary_.on_boundary(a) || !boundary_.on_boundary(b)) return true;
  const auto& x = sites_.points;
  return domain_.contains(Point2<Rational>{(Rational(x[v].x) + Rational(x[a].x) + Rational(x[b].x)) / 3,
                                           (Rational(x[v].y) + Rational(x[a].y) + Rational(x[b].y)) / 3});
}

// S_v by gift wrapping among the sites v sees (in a non-convex Ω: the segment to them crosses no
// edge of Ω; with protected, Gabriel, boundary edges this constrained star is the restricted one).
void StarSet::recompute(int v) {
  const Sym2<double>& M = sites_.metrics[v];
  const auto& x = sites_.points;
  const Point2<double>& pv = x[v];
  double R2 = reach2_[v] > 0 ? reach2_[v] * reach_margin : default_first_reach2;
  // Ω's squared M-diameter, beyond which the reach stops growing: asked only when the search falls
  // short, and then computed once (over the corners' pairs: a mesh's Ω has hundreds, `refine --from`).
  double diameter2_once = -1;
  const auto diameter2 = [&] {
    if (diameter2_once < 0) {
      diameter2_once = 0;
      for (const auto& a : domain_.corners())
        for (const auto& b : domain_.corners()) diameter2_once = std::max(diameter2_once, predicates::quadratic_form(M, a.x - b.x, a.y - b.y));
    }
    return diameter2_once;
  };
  Star star;
  while (true) {
    const auto e = geometry::ellipse_half_widths(M, R2);
    std::vector<int>& cand = cand_;
    cand = sites_.in({pv.x - e.hx, pv.x + e.hx, pv.y - e.hy, pv.y + e.hy});
    cand.erase(std::remove_if(cand.begin(), cand.end(),
                              [&](int c) {
                                return c == v || predicates::quadratic_form(M, x[c].x - pv.x, x[c].y - pv.y) > R2 ||
                                       !domain_.visible(pv, x[c]);
                              }),
               cand.end());
    star = Star{};
    if (cand.empty()) {
      if (R2 > reach_growth * diameter2()) break;
      R2 *= reach_growth;
      continue;
    }
    const int first = nearest_candidate(pv, M, cand, x);  // a Delaunay neighbour (gift_wrap.hpp)
    std::vector<int>& ring = ring_;
    ring.assign(1, first);
    bool closed = false;
    for (std::size_t guard = 0; guard <= cand.size(); ++guard) {
      const int w = next_delaunay_neighbour(pv, M, ring.back(), cand, true, x);
      if (w < 0) break;
      if (w == first) {
        closed = true;
        break;
      }
      ring.push_back(w);
    }
    if (!closed)
      for (std::size_t guard = 0; guard <= cand.size(); ++guard) {
        const int w = next_delaunay_neighbour(pv, M, ring.front(), cand, false, x);
        if (w < 0 || w == ring.back()) break;
        ring.insert(ring.begin(), w);
      }
    const std::size_t k = ring.size();
    common::Box zone{pv.x, pv.x, pv.y, pv.y};
    bool fits = true;
    double reach2 = 0;
    for (std::size_t i = 0; i + (closed ? 0 : 1) < k; ++i) {
      const int a = ring[i], b = ring[(i + 1) % k];
      // The search region and the conflict zone cover every triangle of the fan, also those
      // outside Ω (across a reflex corner): a site in their circumellipses changes the star too.
      // (Without them a reflex corner's first star, whose only triangle spans the exterior,
      // stayed empty for good, and the triangles at the corner were refined forever.)
      const double reach = extend_zone(pv, M, geometry::circumellipse(pv, x[a], x[b], M), zone, reach2);
      if (!(reach * reach * reach_margin < R2)) fits = false;
      (triangle_in_domain(v, a, b) ? star.triangles : star.outside).push_back({a, b});  // restricted to Ω
    }
    // A fan is complete when it closes around v, or when both of its open ends are boundary
    // subsegments at v (the rest is outside Ω), or, at a boundary site, when it reaches both
    // boundary neighbours (between them lies Ω); otherwise the search region was too small.
    const auto in_ring = [&](int w) { return std::find(ring.begin(), ring.end(), w) != ring.end(); };
    const auto& nb = boundary_.neighbours(v);
    const bool complete = closed || (k >= 2 && boundary_.is_segment(v, ring.front()) && boundary_.is_segment(v, ring.back())) ||
                          (nb[0] >= 0 && in_ring(nb[0]) && in_ring(nb[1]));
    if ((!fits || !complete) && R2 < reach_growth * diameter2()) {
      R2 *= reach_growth;
      continue;
    }
    for (const auto& t : star.triangles) star.neighbours.push_back(t[0]), star.neighbours.push_back(t[1]);
    sort_unique(star.neighbours);
    star.cells = stars_[v].cells, star.zone = stars_[v].zone;
    stars_[v] = std::move(star);
    reach2_[v] = reach2;
    set_zone(v, zone);
    return;
  }
  star.cells = stars_[v].cells, star.zone = stars_[v].zone;
  stars_[v] = std::move(star);
}

// Z_v's bounding box (in the conflict index) and the star's reach, from its triangles.
void StarSet::refresh_zone(int v) {
  const Sym2<double>& M = sites_.metrics[v];
  const auto& x = sites_.points;
  const Point2<double>& pv = x[v];
  common::Box zone{pv.x, pv.x, pv.y, pv.y};
  double reach2 = 0;
  for (const auto& t : stars_[v].triangles) extend_zone(pv, M, geometry::circumellipse(pv, x[t[0]], x[t[1]], M), zone, reach2);
  reach2_[v] = reach2;
  set_zone(v, zone);
}

// Bowyer–Watson on v's fan for a new site k (convex Ω): the triangles of S_v whose circumellipse
// strictly holds k form one run around v, and are replaced by (v, a, k) and (v, k, b) for the
// run's outer neighbours a and b. Anything else (a tie, a non-convex Ω, an unexpected shape) asks
// for a recomputation.
StarSet::Update StarSet::update(int v, int k) {
  Star& s = stars_[v];
  const auto& x = sites_.points;
  const Sym2<double>& M = sites_.metrics[v];
  if (!domain_.convex()) {  // recomputed when k conflicts with any triangle of the fan, in Ω or not
    for (const auto* list : {&s.triangles, &s.outside})
      for (const auto& t : *list)
        if (predicates::incircle(x[v], x[t[0]], x[t[1]], x[k], M) != Sign::negative) return Update::recompute;
    return Update::unchanged;
  }
  const Point2<double>& pv = x[v];
  const std::size_t n = s.triangles.size();
  std::vector<char>& in = in_;
  in.assign(n, 0);
  std::size_t total = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Sign c = predicates::incircle(pv, x[s.triangles[i][0]], x[s.triangles[i][1]], x[k], M);
    if (c == Sign::zero) return Update::recompute;
    in[i] = c == Sign::positive;
    total += in[i];
  }
  if (total == 0) return Update::unchanged;
  if (total == n) return Update::recompute;
  const bool closed = s.triangles.back()[1] == s.triangles.front()[0];
  std::size_t first = n;
  for (std::size_t i = 0; i < n && first == n; ++i)
    if (in[i] && (closed ? !in[(i + n - 1) % n] : (i == 0 || !in[i - 1]))) first = i;
  if (first == n) return Update::recompute;
  std::size_t run = 0;
  while (run < n && in[(first + run) % n] && (closed || first + run < n)) ++run;
  if (run != total) return Update::recompute;  // not one run
  const int a = s.triangles[first][0], b = s.triangles[(first + run - 1) % n][1];
  if (predicates::orientation(pv, x[a], x[k]) != Sign::positive || predicates::orientation(pv, x[k], x[b]) != Sign::positive)
    return Update::recompute;
  std::vector<std::array<int, 2>>& t = fan_;
  t.clear();
  if (closed) {
    t = {{a, k}, {k, b}};
    for (std::size_t i = run; i < n; ++i) t.push_back(s.triangles[(first + i) % n]);
  } else {
    t.assign(s.triangles.begin(), s.triangles.begin() + static_cast<long>(first));
    t.push_back({a, k}), t.push_back({k, b});
    t.insert(t.end(), s.triangles.begin() + static_cast<long>(first + run), s.triangles.end());
  }
  std::swap(s.triangles, t);  // the old list's buffer is reused next time
  s.neighbours.clear();
  for (const auto& tr : s.triangles) s.neighbours.push_back(tr[0]), s.neighbours.push_back(tr[1]);
  sort_unique(s.neighbours);
  refresh_zone(v);
  return Update::updated;
}

std::vector<std::array<int, 3>> StarSet::consistent_triangles(std::size_t& inconsistent) const {
  std::vector<std::array<int, 3>> seen;  // every star triangle, rotated to the least index first
  for (int v = 0; v < static_cast<int>(stars_.size()); ++v)
    for (const auto& t : stars_[v].triangles) {
      std::array<int, 3> k{v, t[0], t[1]};
      std::rotate(k.begin(), std::min_element(k.begin(), k.end()), k.end());
      seen.push_back(k);
    }
  std::sort(seen.begin(), seen.end());
  std::vector<std::array<int, 3>> merged;
  inconsistent = 0;
  for (std::size_t i = 0, j; i < seen.size(); i = j) {
    for (j = i + 1; j < seen.size() && seen[j] == seen[i];) ++j;
    if (j - i == 3) merged.push_back(seen[i]);
    else ++inconsistent;
  }
  return merged;
}

}  // namespace anisocert::refiners::star
