#include "refiners/star/star_refiner.hpp"

#include "refiners/star/exact_split.hpp"
#include "refiners/star/quasi_cocircular.hpp"

#include "numbers/rational.hpp"
#include "predicates/incircle.hpp"
#include "predicates/length_compare.hpp"
#include "predicates/orientation.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <deque>
#include <limits>
#include <random>
#include <stdexcept>

namespace anisocert::refiners::star {

using predicates::Point2;
using predicates::Sym2;

const char* rule_name(int rule) {
  switch (rule) {
    case encroachment: return "encroachment";
    case distortion: return "distortion";
    case radius_edge: return "radius-edge ratio";
    case size: return "size";
    case inconsistency: return "inconsistency";
  }
  return "none";
}

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// The shortest decimal that reads back as x.
std::string decimal(double x) {
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
}

double qform(const Sym2<double>& M, double dx, double dy) { return dx * (M.m11 * dx + M.m12 * dy) + dy * (M.m12 * dx + M.m22 * dy); }

// The M-circumcentre of a, b, c and its squared M-radius (floating point).
struct Circle {
  double cx, cy, r2;
};
Circle circumcircle(const Point2<double>& a, const Point2<double>& b, const Point2<double>& c, const Sym2<double>& M) {
  const double d1x = b.x - a.x, d1y = b.y - a.y, d2x = c.x - a.x, d2y = c.y - a.y;
  const double g1x = M.m11 * d1x + M.m12 * d1y, g1y = M.m12 * d1x + M.m22 * d1y;
  const double g2x = M.m11 * d2x + M.m12 * d2y, g2y = M.m12 * d2x + M.m22 * d2y;
  const double q1 = qform(M, d1x, d1y) / 2, q2 = qform(M, d2x, d2y) / 2, det = g1x * g2y - g1y * g2x;
  const double x = (q1 * g2y - q2 * g1y) / det, y = (g1x * q2 - g2x * q1) / det;
  return {a.x + x, a.y + y, qform(M, x, y)};
}

// τ(A, B)²: the largest eigenvalue of A⁻¹B and of B⁻¹A (LS/BWY distortion).
double tau2(const Sym2<double>& A, const Sym2<double>& B) {
  auto largest = [](const Sym2<double>& P, const Sym2<double>& Q) {
    const double a2 = P.m11 * P.m22 - P.m12 * P.m12, b1 = -(P.m11 * Q.m22 + P.m22 * Q.m11 - 2 * P.m12 * Q.m12),
                 c0 = Q.m11 * Q.m22 - Q.m12 * Q.m12;
    return (-b1 + std::sqrt(std::max(0.0, b1 * b1 - 4 * a2 * c0))) / (2 * a2);
  };
  return std::max(largest(A, B), largest(B, A));
}

// τ² < g2 for each pair of the three metrics of a triangle's vertices.
bool pairs_within(const Sym2<double>& A, const Sym2<double>& B, const Sym2<double>& C, double g2) {
  return tau2(A, B) < g2 && tau2(A, C) < g2 && tau2(B, C) < g2;
}

// Half-widths of the bounding box of {x : (x − c)ᵀ M (x − c) ≤ r²}.
std::pair<double, double> ellipse_extent(const Sym2<double>& M, double r2) {
  const double det = M.m11 * M.m22 - M.m12 * M.m12;
  return {std::sqrt(r2 * M.m22 / det), std::sqrt(r2 * M.m11 / det)};
}

bool inside_polygon(const std::vector<Point2<double>>& poly, double x, double y) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
    if ((poly[i].y > y) != (poly[j].y > y) &&
        x < (poly[j].x - poly[i].x) * (y - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x)
      in = !in;
  return in;
}

struct Star {
  std::vector<std::array<int, 2>> triangles;  // (a, b): triangle (v, a, b) counter-clockwise
  std::vector<std::array<int, 2>> outside;    // the rest of v's Delaunay fan, outside Ω
  std::vector<int> neighbours;                // sorted
  int box[4] = {0, -1, 0, -1};                // grid cells covered by the conflict zone
  double zone[4] = {0, -1, 0, -1};            // the conflict zone's bounding box (empty: x0 > x1)
};

class Refiner {
 public:
  Refiner(const std::vector<Point2<double>>& domain, const MetricField& field, const RefineParameters& p,
          const std::function<void(const std::string&)>& progress)
      : domain_(domain), field_(field), p_(p), progress_(progress), rng_(p.seed) {
    x0_ = y0_ = inf;
    double x1 = -inf, y1 = -inf;
    for (const auto& q : domain) x0_ = std::min(x0_, q.x), y0_ = std::min(y0_, q.y), x1 = std::max(x1, q.x), y1 = std::max(y1, q.y);
    g_ = 16;  // grows with the number of sites (rebuild_grid)
    cw_ = (x1 - x0_) / g_, ch_ = (y1 - y0_) / g_;
    sites_cells_.assign(static_cast<std::size_t>(g_) * g_, {});
    segment_grid_.assign(static_cast<std::size_t>(g_) * g_, {});
    convex_ = true;
    for (std::size_t i = 0; i < domain.size(); ++i)
      if (predicates::orientation(domain[i], domain[(i + 1) % domain.size()], domain[(i + 2) % domain.size()]) == Sign::negative)
        convex_ = false;
    conflict_cells_.assign(static_cast<std::size_t>(g_) * g_, {});
  }

  RefineResult run() {
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    const int m = static_cast<int>(domain_.size());
    for (const auto& q : domain_) insert(q, 0, false);
    for (int i = 0; i < m; ++i) segments_.push_back({i, (i + 1) % m});
    for (int i = 0; i < m; ++i) set_segment_box(i);
    for (int i = 0; i < m; ++i) boundary_[i] = {(i + m - 1) % m, (i + 1) % m};
    for (int v = 0; v < m; ++v) recompute(v);
    for (int v = 0; v < m; ++v) enqueue(v);
    for (std::size_t s = 0; s < segments_.size(); ++s) segment_queue_.push_back(static_cast<int>(s));
    double next_report = 1;
    std::size_t steps = 0;
    RefineResult r;
    while (true) {
      if (sites_.size() >= p_.max_vertices) {
        r.stop_reason = "vertex budget (" + std::to_string(p_.max_vertices) + ") reached";
        break;
      }
      if (++steps % 64 == 0 && elapsed() > p_.max_seconds) {  // the clock is read every 64 steps
        r.stop_reason = "time budget (" + std::to_string(p_.max_seconds) + " s) reached";
        break;
      }
      if (progress_ && steps % 64 == 0 && elapsed() > next_report) {
        next_report += 1;
        progress_("refine: " + std::to_string(sites_.size()) + " vertices, " +
                  std::to_string(static_cast<long>(sites_.size() / elapsed())) + " per second, queue " +
                  std::to_string(site_queue_.size()));
      }
      if (!stalled_.empty()) {
        r.stop_reason = stalled_;
        break;
      }
      if (!step()) {
        r.stop_reason = "all stars consistent";
        break;
      }
    }
    merge(r);
    for (int k = 0; k < m; ++k)
      if (acute_corner(k)) r.acute_corners.push_back(k);
    r.seconds = elapsed();
    r.rule_counts = counts_;
    r.picks_rejected = picks_rejected_, r.picks_exhausted = picks_exhausted_, r.refinements = refinements_;
    r.last_rule = last_rule_;
    r.trace = std::move(trace_);
    return r;
  }

 private:
  // --- the point grid and the conflict-zone index -------------------------------------------
  int cell_x(double x) const { return std::clamp(static_cast<int>((x - x0_) / cw_), 0, g_ - 1); }
  int cell_y(double y) const { return std::clamp(static_cast<int>((y - y0_) / ch_), 0, g_ - 1); }
  std::size_t cell(int i, int j) const { return static_cast<std::size_t>(j) * g_ + i; }

  // The sites in a box, into a buffer reused across calls (allocation was a third of the time).
  const std::vector<int>& sites_in(double xa, double xb, double ya, double yb) const {
    std::vector<int>& out = found_;
    out.clear();
    for (int j = cell_y(ya); j <= cell_y(yb); ++j)
      for (int i = cell_x(xa); i <= cell_x(xb); ++i)
        for (int s : sites_cells_[cell(i, j)])
          if (sites_[s].x >= xa && sites_[s].x <= xb && sites_[s].y >= ya && sites_[s].y <= yb) out.push_back(s);
    return out;
  }

  // The squared M-distance from q to the M-nearest site (∞ when there is none), by rings of grid
  // cells around q's: a site outside the ring at distance k is Euclidean-farther than the gap g
  // from q to that ring's border, so M-farther than λ_min(M) g², and the search stops there.
  double nearest_site2(const Point2<double>& q, const Sym2<double>& M) const {
    const double half_trace = (M.m11 + M.m22) / 2, det = M.m11 * M.m22 - M.m12 * M.m12;
    const double lmin = half_trace - std::sqrt(std::max(0.0, half_trace * half_trace - det));
    const int ci = cell_x(q.x), cj = cell_y(q.y);
    double best = inf;
    auto visit = [&](int i, int j) {
      if (i < 0 || j < 0 || i >= g_ || j >= g_) return;
      for (int s : sites_cells_[cell(i, j)]) best = std::min(best, qform(M, sites_[s].x - q.x, sites_[s].y - q.y));
    };
    for (int k = 0;; ++k) {
      for (int i = ci - k; i <= ci + k; ++i) {
        visit(i, cj - k);
        if (k > 0) visit(i, cj + k);
      }
      for (int j = cj - k + 1; j < cj + k; ++j) {
        visit(ci - k, j);
        visit(ci + k, j);
      }
      // Sides with no cells beyond them hide no site.
      const double gap = std::min({ci - k > 0 ? q.x - (x0_ + (ci - k) * cw_) : inf, ci + k < g_ - 1 ? x0_ + (ci + k + 1) * cw_ - q.x : inf,
                                   cj - k > 0 ? q.y - (y0_ + (cj - k) * ch_) : inf, cj + k < g_ - 1 ? y0_ + (cj + k + 1) * ch_ - q.y : inf});
      if (gap == inf || best <= lmin * gap * gap * (1 - 1e-12)) break;
    }
    return best;
  }

  // A grid of about two sites per cell, rebuilt when the sites outgrow it: every index (sites,
  // conflict zones, segments) is filled again from the stored boxes.
  void rebuild_grid() {
    g_ = std::min(2048, static_cast<int>(std::sqrt(sites_.size() / 2.0)) + 1);
    double x1 = -inf, y1 = -inf;
    x0_ = y0_ = inf;
    for (const auto& q : domain_) x0_ = std::min(x0_, q.x), y0_ = std::min(y0_, q.y), x1 = std::max(x1, q.x), y1 = std::max(y1, q.y);
    cw_ = (x1 - x0_) / g_, ch_ = (y1 - y0_) / g_;
    sites_cells_.assign(static_cast<std::size_t>(g_) * g_, {});
    conflict_cells_.assign(static_cast<std::size_t>(g_) * g_, {});
    segment_grid_.assign(static_cast<std::size_t>(g_) * g_, {});
    for (int i = 0; i < static_cast<int>(sites_.size()); ++i) sites_cells_[cell(cell_x(sites_[i].x), cell_y(sites_[i].y))].push_back(i);
    for (int v = 0; v < static_cast<int>(stars_.size()); ++v) {
      Star& st = stars_[v];
      st.box[0] = 0, st.box[1] = -1, st.box[2] = 0, st.box[3] = -1;
      if (st.zone[0] <= st.zone[1]) set_conflict_box(v, st.zone[0], st.zone[1], st.zone[2], st.zone[3]);
    }
    for (int sgm = 0; sgm < static_cast<int>(segment_cells_.size()); ++sgm) {
      segment_cells_[sgm] = {0, -1, 0, -1};
      set_segment_box(sgm);
    }
  }

  void set_conflict_box(int v, double xa, double xb, double ya, double yb) {
    Star& s = stars_[v];
    s.zone[0] = xa, s.zone[1] = xb, s.zone[2] = ya, s.zone[3] = yb;
    const int box[4] = {cell_x(xa), cell_x(xb), cell_y(ya), cell_y(yb)};
    if (std::equal(box, box + 4, s.box)) return;  // the same cells
    auto inside = [](const int* b, int i, int j) { return i >= b[0] && i <= b[1] && j >= b[2] && j <= b[3]; };
    for (int j = s.box[2]; j <= s.box[3]; ++j)
      for (int i = s.box[0]; i <= s.box[1]; ++i) {
        if (inside(box, i, j)) continue;  // stays
        auto& c = conflict_cells_[cell(i, j)];
        *std::find(c.begin(), c.end(), v) = c.back();  // order does not matter
        c.pop_back();
      }
    for (int j = box[2]; j <= box[3]; ++j)
      for (int i = box[0]; i <= box[1]; ++i)
        if (!inside(s.box, i, j)) conflict_cells_[cell(i, j)].push_back(v);
    std::copy(box, box + 4, s.box);
  }

  // --- stars ----------------------------------------------------------------------------------
  // Del_{M_v} neighbours by gift wrapping around v with exact in-circle tests: from the M_v-nearest
  // site (always a Delaunay neighbour), the next neighbour counter-clockwise is the candidate left
  // of the current edge whose circle through v and the current neighbour holds no other candidate.
  void recompute(int v) {
    const Sym2<double>& M = metrics_[v];
    const Point2<double>& pv = sites_[v];
    // The search radius (in M_v units): the star's previous reach (stars only shrink, LU Lemma
    // 3.5), or for a new site twice its nearest distance, doubled until every circumellipse fits.
    double R2 = reach2_[v] > 0 ? reach2_[v] * 1.0001 : 6.25;
    const double diameter2 = [&] {
      double d = 0;
      for (const auto& a : domain_)
        for (const auto& b : domain_) d = std::max(d, qform(M, a.x - b.x, a.y - b.y));
      return d;
    }();
    Star star;
    while (true) {
      const auto [ex, ey] = ellipse_extent(M, R2);
      std::vector<int>& cand = cand_;
      cand = sites_in(pv.x - ex, pv.x + ex, pv.y - ey, pv.y + ey);
      cand.erase(std::remove_if(cand.begin(), cand.end(),
                                [&](int c) {
                                  return c == v || qform(M, sites_[c].x - pv.x, sites_[c].y - pv.y) > R2 ||
                                         !visible(pv, sites_[c]);
                                }),
                 cand.end());
      star = Star{};
      if (cand.empty()) {
        if (R2 > 4 * diameter2) break;
        R2 *= 4;
        continue;
      }
      // The M_v-nearest candidate (a Delaunay neighbour): by doubles, and by the exact comparison
      // only among candidates whose double distances are within 10⁻¹⁰ (relative) of the least.
      auto d2 = [&](int c) { return qform(M, sites_[c].x - pv.x, sites_[c].y - pv.y); };
      double least = inf;
      for (int c : cand) least = std::min(least, d2(c));
      int first = -1;
      for (int c : cand)
        if (d2(c) <= least * (1 + 1e-10) &&
            (first < 0 || predicates::compare_scaled_lengths(1.0, pv, sites_[c], M, pv, sites_[first], M) == Sign::negative))
          first = c;
      std::vector<int>& ring = ring_;
      ring.assign(1, first);
      bool closed = false;
      for (std::size_t guard = 0; guard <= cand.size(); ++guard) {
        const int w = wrap(v, ring.back(), cand, true);
        if (w < 0) break;
        if (w == first) {
          closed = true;
          break;
        }
        ring.push_back(w);
      }
      if (!closed)
        for (std::size_t guard = 0; guard <= cand.size(); ++guard) {
          const int w = wrap(v, ring.front(), cand, false);
          if (w < 0 || w == ring.back()) break;
          ring.insert(ring.begin(), w);
        }
      const std::size_t k = ring.size();
      double xa = pv.x, xb = pv.x, ya = pv.y, yb = pv.y;
      bool fits = true;
      double reach2 = 0;
      for (std::size_t i = 0; i + (closed ? 0 : 1) < k; ++i) {
        const int a = ring[i], b = ring[(i + 1) % k];
        const Circle c = circumcircle(pv, sites_[a], sites_[b], M);
        const double reach = std::sqrt(qform(M, c.cx - pv.x, c.cy - pv.y)) + std::sqrt(c.r2);
        reach2 = std::max(reach2, reach * reach);
        if (!(reach * reach * 1.0001 < R2)) fits = false;
        // The search region and the conflict zone cover every triangle of the fan, also those
        // outside Ω (across a reflex corner): a site in their circumellipses changes the star too.
        // (Without them a reflex corner's first star, whose only triangle spans the exterior,
        // stayed empty for good, and the triangles at the corner were refined forever.)
        const auto [hx, hy] = ellipse_extent(M, c.r2);
        xa = std::min(xa, c.cx - hx), xb = std::max(xb, c.cx + hx), ya = std::min(ya, c.cy - hy), yb = std::max(yb, c.cy + hy);
        (triangle_in_domain(v, a, b) ? star.triangles : star.outside).push_back({a, b});  // restricted to Ω
      }
      // A fan is complete when it closes around v, or when both of its open ends are boundary
      // subsegments at v (the rest is outside Ω); otherwise the search region was too small.
      // (or, at a boundary site, when it reaches both boundary neighbours: between them lies Ω).
      const auto in_ring = [&](int w) { return std::find(ring.begin(), ring.end(), w) != ring.end(); };
      const bool complete = closed || (k >= 2 && is_segment(v, ring.front()) && is_segment(v, ring.back())) ||
                            (boundary_[v][0] >= 0 && in_ring(boundary_[v][0]) && in_ring(boundary_[v][1]));
      if ((!fits || !complete) && R2 < 4 * diameter2) {
        R2 *= 4;
        continue;
      }
      for (const auto& t : star.triangles) star.neighbours.push_back(t[0]), star.neighbours.push_back(t[1]);
      std::sort(star.neighbours.begin(), star.neighbours.end());
      star.neighbours.erase(std::unique(star.neighbours.begin(), star.neighbours.end()), star.neighbours.end());
      std::copy(stars_[v].box, stars_[v].box + 4, star.box);
      std::copy(stars_[v].zone, stars_[v].zone + 4, star.zone);
      stars_[v] = std::move(star);
      reach2_[v] = reach2;
      set_conflict_box(v, xa, xb, ya, yb);
      return;
    }
    std::copy(stars_[v].box, stars_[v].box + 4, star.box);
    std::copy(stars_[v].zone, stars_[v].zone + 4, star.zone);
    stars_[v] = std::move(star);
  }

  // Z_v's bounding box (in the conflict index) and the star's reach, from its triangles.
  void refresh_zone(int v) {
    const Sym2<double>& M = metrics_[v];
    const Point2<double>& pv = sites_[v];
    double xa = pv.x, xb = pv.x, ya = pv.y, yb = pv.y, reach2 = 0;
    for (const auto& t : stars_[v].triangles) {
      const Circle c = circumcircle(pv, sites_[t[0]], sites_[t[1]], M);
      const double reach = std::sqrt(qform(M, c.cx - pv.x, c.cy - pv.y)) + std::sqrt(c.r2);
      reach2 = std::max(reach2, reach * reach);
      const auto [hx, hy] = ellipse_extent(M, c.r2);
      xa = std::min(xa, c.cx - hx), xb = std::max(xb, c.cx + hx), ya = std::min(ya, c.cy - hy), yb = std::max(yb, c.cy + hy);
    }
    reach2_[v] = reach2;
    set_conflict_box(v, xa, xb, ya, yb);
  }

  // Bowyer–Watson on v's fan for a new site k (convex Ω): the triangles of S_v whose
  // circumellipse strictly holds k form one run around v, and are replaced by (v, a, k) and
  // (v, k, b) for the run's outer neighbours a and b. Returns 0 when S_v does not change, 1 when
  // it was updated, 2 when it must be recomputed (a tie, a non-convex Ω, or an unexpected shape).
  int update_star(int v, int k) {
    Star& s = stars_[v];
    if (!convex_) {  // recomputed when k conflicts with any triangle of the fan, in Ω or not
      for (const auto* list : {&s.triangles, &s.outside})
        for (const auto& t : *list)
          if (predicates::incircle(sites_[v], sites_[t[0]], sites_[t[1]], sites_[k], metrics_[v]) != Sign::negative) return 2;
      return 0;
    }
    const Point2<double>& pv = sites_[v];
    const std::size_t n = s.triangles.size();
    std::vector<char>& in = in_;
    in.assign(n, 0);
    std::size_t total = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const Sign c = predicates::incircle(pv, sites_[s.triangles[i][0]], sites_[s.triangles[i][1]], sites_[k], metrics_[v]);
      if (c == Sign::zero) return 2;
      in[i] = c == Sign::positive;
      total += in[i];
    }
    if (total == 0) return 0;
    if (total == n) return 2;
    const bool closed = s.triangles.back()[1] == s.triangles.front()[0];
    std::size_t first = n;
    for (std::size_t i = 0; i < n && first == n; ++i)
      if (in[i] && (closed ? !in[(i + n - 1) % n] : (i == 0 || !in[i - 1]))) first = i;
    if (first == n) return 2;
    std::size_t run = 0;
    while (run < n && in[(first + run) % n] && (closed || first + run < n)) ++run;
    if (run != total) return 2;  // not one run
    const int a = s.triangles[first][0], b = s.triangles[(first + run - 1) % n][1];
    if (predicates::orientation(pv, sites_[a], sites_[k]) != Sign::positive ||
        predicates::orientation(pv, sites_[k], sites_[b]) != Sign::positive)
      return 2;
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
    std::sort(s.neighbours.begin(), s.neighbours.end());
    s.neighbours.erase(std::unique(s.neighbours.begin(), s.neighbours.end()), s.neighbours.end());
    refresh_zone(v);
    return 1;
  }

  // The next Delaunay neighbour of v after u, counter-clockwise (ccw) or clockwise; −1 if none.
  int wrap(int v, int u, const std::vector<int>& cand, bool ccw) const { return wrap(sites_[v], metrics_[v], u, cand, ccw); }
  int wrap(const Point2<double>& pv, const Sym2<double>& M, int u, const std::vector<int>& cand, bool ccw) const {
    const Point2<double>& pu = sites_[u];
    int w = -1;
    for (int x : cand) {
      if (x == u) continue;
      const Sign side = predicates::orientation(pv, pu, sites_[x]);
      if (side != (ccw ? Sign::positive : Sign::negative)) continue;
      if (w < 0) {
        w = x;
        continue;
      }
      // Triangle (v, u, w) counter-clockwise for ccw, (v, w, u) for cw: is x inside its circle?
      const Sign in = ccw ? predicates::incircle(pv, pu, sites_[w], sites_[x], M)
                          : predicates::incircle(pv, sites_[w], pu, sites_[x], M);
      const bool closer_in_angle = predicates::orientation(pv, sites_[w], sites_[x]) == (ccw ? Sign::negative : Sign::positive);
      if (in == Sign::positive || (in == Sign::zero && closer_in_angle)) w = x;
    }
    return w;
  }

  // --- insertion ------------------------------------------------------------------------------
  int insert(const Point2<double>& q, int rule, bool update = true, int star = -1, double radius = 0) {
    const int k = static_cast<int>(sites_.size());
    double nearest = inf, initial_reach2 = 0;
    const Sym2<double> Mq = field_.at(q.x, q.y);
    if (update) {
      nearest = nearest_site2(q, Mq);
      trace_.push_back({rule, q.x, q.y, std::sqrt(nearest), star, radius});
      if (std::isfinite(nearest)) initial_reach2 = 4 * nearest;
      ++counts_[rule];
      last_rule_ = rule;
    }
    sites_.push_back(q);
    metrics_.push_back(Mq);
    for (int h : pending_boxes_) set_segment_box(h);
    pending_boxes_.clear();
    stars_.emplace_back();
    queued_.push_back(false);
    boundary_.resize(std::max(boundary_.size(), sites_.size()), {-1, -1});  // split() may have set it
    reach2_.push_back(initial_reach2);
    sites_cells_[cell(cell_x(q.x), cell_y(q.y))].push_back(k);
    if (sites_.size() > 4 * static_cast<std::size_t>(g_) * g_) rebuild_grid();
    if (!update) return k;
    // Stars whose conflict zone holds q change (LU Lemma 3.5); so may their neighbours' consistency.
    zone_ = conflict_cells_[cell(cell_x(q.x), cell_y(q.y))];  // a copy: updates edit the index
    for (int v : zone_) {
      const double* z = stars_[v].zone;  // the box the index filed v under, not just its cells
      if (q.x < z[0] || q.x > z[1] || q.y < z[2] || q.y > z[3]) continue;
      before_ = stars_[v].neighbours;
      const int change = update_star(v, k);
      if (change == 0) continue;
      if (change == 2) recompute(v);
      enqueue(v);
      for (int w : before_) enqueue(w);
    }
    recompute(k);
    enqueue(k);
    for (int w : stars_[k].neighbours) enqueue(w);
    // Segments q encroaches.
    for (int s : segment_grid_[cell(cell_x(q.x), cell_y(q.y))])
      if (encroaches(k, s)) segment_queue_.push_back(s);
    return k;
  }

  // In a non-convex Ω a star is computed among the sites v sees (the segment to them crosses no
  // edge of Ω): with protected (Gabriel) boundary edges this constrained star is the restricted one.
  bool visible(const Point2<double>& a, const Point2<double>& b) const {
    if (convex_) return true;
    for (std::size_t i = 0; i < domain_.size(); ++i) {
      const Point2<double>& p = domain_[i];
      const Point2<double>& q = domain_[(i + 1) % domain_.size()];
      const int s1 = static_cast<int>(predicates::orientation(p, q, a)) * static_cast<int>(predicates::orientation(p, q, b));
      const int s2 = static_cast<int>(predicates::orientation(a, b, p)) * static_cast<int>(predicates::orientation(a, b, q));
      if (s1 < 0 && s2 < 0) return false;
    }
    return true;
  }

  // Whether a star triangle lies in Ω. Its edges cross no edge of Ω (visibility) and it holds no
  // site, so a vertex strictly inside Ω puts it inside; only triangles with all three vertices on
  // ∂Ω (in a non-convex Ω) need a test: their centroid, exactly (rational ray casting).
  bool triangle_in_domain(int v, int a, int b) const {
    if (convex_ || boundary_[v][0] < 0 || boundary_[a][0] < 0 || boundary_[b][0] < 0) return true;
    const Rational cx = (Rational(sites_[v].x) + Rational(sites_[a].x) + Rational(sites_[b].x)) / 3;
    const Rational cy = (Rational(sites_[v].y) + Rational(sites_[a].y) + Rational(sites_[b].y)) / 3;
    bool in = false;
    for (std::size_t i = 0, j = domain_.size() - 1; i < domain_.size(); j = i++) {
      const Rational xi(domain_[i].x), yi(domain_[i].y), xj(domain_[j].x), yj(domain_[j].y);
      if ((yi > cy) != (yj > cy) && ((cx - xi) * (yj - yi) < (xj - xi) * (cy - yi)) == (yj - yi > 0)) in = !in;
    }
    return in;
  }

  bool is_segment(int a, int b) const {
    return (boundary_[a][0] == b || boundary_[a][1] == b);
  }

  void enqueue(int v) {
    if (!queued_[v]) queued_[v] = true, site_queue_.push_back(v);
  }

  // LU Definition 3.16: p inside the diametral ellipse of segment s in p's or an endpoint's metric.
  bool encroaches(int p, int s) const {
    const auto [a, b] = segments_[s];
    if (p == a || p == b) return false;
    return encroaches(sites_[p], metrics_[p], s);
  }
  // A box around segment s outside which no point encroaches it in its endpoints' metrics; twice
  // as large, so that it also serves a nearby point's own (similar) metric: a prefilter only.
  void set_segment_box(int s) {
    const auto [a, b] = segments_[s];
    const double mx = (sites_[a].x + sites_[b].x) / 2, my = (sites_[a].y + sites_[b].y) / 2;
    double hx = 0, hy = 0;
    for (int w : {a, b}) {
      const Sym2<double>& M = metrics_[w];
      const auto [ex, ey] = ellipse_extent(M, qform(M, sites_[b].x - sites_[a].x, sites_[b].y - sites_[a].y) / 4);
      hx = std::max(hx, ex), hy = std::max(hy, ey);
    }
    if (static_cast<int>(segment_box_.size()) <= s) segment_box_.resize(s + 1), segment_cells_.resize(s + 1, {0, -1, 0, -1});
    segment_box_[s] = {mx - 2 * hx, mx + 2 * hx, my - 2 * hy, my + 2 * hy};
    // Register s in the grid cells its box covers (segments near a point are found there).
    auto& c = segment_cells_[s];
    for (int j = c[2]; j <= c[3]; ++j)
      for (int i = c[0]; i <= c[1]; ++i) {
        auto& list = segment_grid_[cell(i, j)];
        *std::find(list.begin(), list.end(), s) = list.back();
        list.pop_back();
      }
    c = {cell_x(segment_box_[s][0]), cell_x(segment_box_[s][1]), cell_y(segment_box_[s][2]), cell_y(segment_box_[s][3])};
    for (int j = c[2]; j <= c[3]; ++j)
      for (int i = c[0]; i <= c[1]; ++i) segment_grid_[cell(i, j)].push_back(s);
  }
  bool near_segment(const Point2<double>& x, int s) const {
    const auto& b = segment_box_[s];
    return x.x >= b[0] && x.x <= b[1] && x.y >= b[2] && x.y <= b[3];
  }

  bool encroaches(const Point2<double>& x, const Sym2<double>& Mx, int s) const {
    if (!near_segment(x, s)) return false;
    const auto [a, b] = segments_[s];
    const double mx = (sites_[a].x + sites_[b].x) / 2, my = (sites_[a].y + sites_[b].y) / 2;
    for (const Sym2<double>* M : {&Mx, &metrics_[a], &metrics_[b]})
      if (qform(*M, x.x - mx, x.y - my) < qform(*M, sites_[b].x - sites_[a].x, sites_[b].y - sites_[a].y) / 4) return true;
    return false;
  }

  // LU Lemma 4.1 fails at corner k (the domain's corners are sites 0 … m − 1): the angle between
  // its two edges is not obtuse in the corner's metric, e₁ᵀ M e₂ ≥ 0.
  bool acute_corner(int k) const {
    const int m = static_cast<int>(domain_.size());
    const auto &c = domain_[k], &a = domain_[(k + m - 1) % m], &b = domain_[(k + 1) % m];
    const Sym2<double>& M = metrics_[k];
    const double ex = a.x - c.x, ey = a.y - c.y, fx = b.x - c.x, fy = b.y - c.y;
    return ex * (M.m11 * fx + M.m12 * fy) + ey * (M.m12 * fx + M.m22 * fy) >= 0;
  }

  void split(int s) {
    const auto [a, b] = segments_[s];
    const std::optional<Point2<double>> exact = exact_midpoint(sites_[a], sites_[b]);
    if (!exact) {
      // The domain allows at least `min_halvings` exact splits of every edge (refine_star), so
      // encroachment does not end at a corner: name it, and say whether Lemma 4.1 explains it.
      const int m = static_cast<int>(domain_.size());
      int k = 0;
      for (int i = 1; i < m; ++i)
        if (std::hypot(domain_[i].x - sites_[a].x, domain_[i].y - sites_[a].y) <
            std::hypot(domain_[k].x - sites_[a].x, domain_[k].y - sites_[a].y))
          k = i;
      const std::string corner = "corner " + std::to_string(k) + " (" + decimal(domain_[k].x) + ", " + decimal(domain_[k].y) + ")";
      stalled_ = "boundary segments near " + corner + " were split until their midpoints are no longer doubles: " +
                 (acute_corner(k) ? "encroachment does not end at a corner whose angle is not obtuse in the metric (LU Lemma 4.1 needs > 90°)"
                                  : "refinement does not end there although LU Lemma 4.1 holds at that corner (a refiner failure)");
      return;
    }
    const Point2<double> m = *exact;
    const int k = static_cast<int>(sites_.size());
    segments_[s] = {a, k};
    segments_.push_back({k, b});
    pending_boxes_ = {s, static_cast<int>(segments_.size()) - 1};  // set once k's metric exists
    boundary_.resize(k + 1, {-1, -1});
    boundary_[k] = {a, b};  // before insert(), which computes k's star
    for (int e : {0, 1}) {
      if (boundary_[a][e] == b) boundary_[a][e] = k;
      if (boundary_[b][e] == a) boundary_[b][e] = k;
    }
    insert(m, encroachment);
    for (int h : {s, static_cast<int>(segments_.size()) - 1}) {
      const auto [u, w] = segments_[h];
      const double mx = (sites_[u].x + sites_[w].x) / 2, my = (sites_[u].y + sites_[w].y) / 2;
      const double half = std::max(std::abs(sites_[w].x - sites_[u].x), std::abs(sites_[w].y - sites_[u].y));
      for (int p : sites_in(mx - half, mx + half, my - half, my + half))
        if (encroaches(p, h)) {
          segment_queue_.push_back(h);
          break;
        }
    }
  }

  // --- rules ----------------------------------------------------------------------------------
  struct Action {
    int rule = 0;
    int a = -1, b = -1;  // the triangle (v, a, b)
  };

  // LU's total distortion γ(τ) is the largest distortion between two points of Ω in one of τ's
  // circumballs; it is estimated from below on samples of the star's own circumball: the three
  // vertices and, when it lies in Ω, the circumcentre (the other vertices' stars sample theirs).
  bool distorted(const Sym2<double>& Mv, const Sym2<double>& Ma, const Sym2<double>& Mb, const Circle& c, double g2) const {
    if (!pairs_within(Mv, Ma, Mb, g2)) return true;
    if (!std::isfinite(c.cx) || !std::isfinite(c.cy) || !inside_polygon(domain_, c.cx, c.cy)) return false;
    const Sym2<double> Mc = field_.at(c.cx, c.cy);
    return tau2(Mc, Mv) >= g2 || tau2(Mc, Ma) >= g2 || tau2(Mc, Mb) >= g2;
  }

  Action check(int v) const {
    const Star& s = stars_[v];
    const Sym2<double>& M = metrics_[v];
    // Rules 2 and 3 fire a hair early (relative 10⁻⁹), so that a consistent mesh also passes the
    // exact checks at exactly γ₀ and ρ₀ (the certifier decides them without rounding).
    const double g2 = p_.gamma0 * p_.gamma0 * (1 - 1e-9), rho2 = p_.rho0 * p_.rho0 * (1 - 1e-9), size2 = p_.size * p_.size;
    Action best;
    auto consider = [&](int rule, int a, int b) {
      if (best.rule == 0 || rule < best.rule) best = {rule, a, b};
    };
    for (const auto& t : s.triangles) {
      const int a = t[0], b = t[1];
      const Circle c = circumcircle(sites_[v], sites_[a], sites_[b], M);
      if (distorted(M, metrics_[a], metrics_[b], c, g2)) consider(distortion, a, b);
      const double shortest = std::min({qform(M, sites_[a].x - sites_[v].x, sites_[a].y - sites_[v].y),
                                        qform(M, sites_[b].x - sites_[v].x, sites_[b].y - sites_[v].y),
                                        qform(M, sites_[b].x - sites_[a].x, sites_[b].y - sites_[a].y)});
      if (c.r2 > rho2 * shortest) consider(radius_edge, a, b);
      if (c.r2 > size2) consider(size, a, b);
    }
    if (best.rule) return best;
    // LU Definition 3.3 at the level of triangles: (v, a, b) must also be (a, b, v) in S_a and
    // (b, v, a) in S_b (edge-consistency alone lets two fans disagree on the third vertex).
    auto has = [&](int w, int x, int y) {
      for (const auto& u : stars_[w].triangles)
        if (u[0] == x && u[1] == y) return true;
      return false;
    };
    for (const auto& t : s.triangles)
      if (!has(t[0], t[1], v) || !has(t[1], v, t[0])) return {inconsistency, t[0], t[1]};
    return best;
  }

  // One step: an encroached segment first (rule 1), else the next queued star's first rule.
  bool step() {
    while (!segment_queue_.empty()) {
      const int s = segment_queue_.front();
      segment_queue_.pop_front();
      bool still = false;
      const auto [a, b] = segments_[s];
      const double mx = (sites_[a].x + sites_[b].x) / 2, my = (sites_[a].y + sites_[b].y) / 2;
      const double half = std::max(std::abs(sites_[b].x - sites_[a].x), std::abs(sites_[b].y - sites_[a].y));
      for (int p : sites_in(mx - half, mx + half, my - half, my + half)) still = still || encroaches(p, s);
      if (still) {
        split(s);
        return true;
      }
    }
    while (!site_queue_.empty()) {
      const int v = site_queue_.front();
      site_queue_.pop_front();
      queued_[v] = false;
      const Action act = check(v);
      if (!act.rule) continue;
      refine(v, act);
      enqueue(v);
      return true;
    }
    return false;
  }

  // Pick_valid (LU §4.1): a point of the picking region is discarded while it would make a new
  // triangle xpq with γ(xpq) < γ₀ that is γ₀-cocircular with a site s, with radius < β r_τ and
  // radius-edge ratio < ρ₀ (both measured on xpq, which bounds LU Definition 3.9's minimum over
  // the four triples from above: every configuration found here is one LU forbids). The new
  // triangles are x's prospective fan in M_x, wrapped counter-clockwise from x's nearest site and
  // tested as they are found, so a forbidden point costs only the triangles before the first hit.
  // `cand`: the sites within about 2 r_τ of the picking region, where x's new fan lies.
  bool forbidden(const Point2<double>& x, double r_tau, const std::vector<int>& cand) const {
    if (cand.size() < 3) return false;
    const Sym2<double> M = field_.at(x.x, x.y);
    auto d2 = [&](const Point2<double>& p, const Point2<double>& q) { return qform(M, p.x - q.x, p.y - q.y); };
    int first = cand[0];
    for (int c : cand)
      if (d2(sites_[c], x) < d2(sites_[first], x)) first = c;
    const double g2 = p_.gamma0 * p_.gamma0, beta_r2 = p_.beta * p_.beta * r_tau * r_tau, rho2 = p_.rho0 * p_.rho0;
    int a = first;
    for (std::size_t guard = 0; guard <= cand.size(); ++guard) {
      const int b = wrap(x, M, a, cand, true);
      if (b < 0) return false;
      const Point2<double>&pa = sites_[a], &pb = sites_[b];
      if (pairs_within(M, metrics_[a], metrics_[b], g2)) {
        const Circle c = circumcircle(x, pa, pb, M);
        const double edges = std::min({d2(pa, x), d2(pb, x), d2(pa, pb)});
        if (c.r2 < beta_r2)
          for (int sx : cand) {
            if (sx == a || sx == b) continue;
            const Point2<double>& ps = sites_[sx];
            if (c.r2 < rho2 * std::min({edges, d2(ps, x), d2(ps, pa), d2(ps, pb)}) &&
                quasi_cocircular(x, pa, pb, ps, M, p_.gamma0))
              return true;
          }
      }
      if (b == first) return false;
      a = b;
    }
    return false;
  }

  void refine(int v, const Action& act) {
    ++refinements_;
    const Sym2<double>& M = metrics_[v];
    const Circle c = circumcircle(sites_[v], sites_[act.a], sites_[act.b], M);
    // M = LLᵀ; a point of the M-ball: c + L⁻ᵀ (δ r u) with |u| < 1.
    const double l11 = std::sqrt(M.m11), l21 = M.m12 / l11, l22 = std::sqrt(M.m22 - l21 * l21);
    std::uniform_real_distribution<double> unit(-1, 1);
    const double s = p_.delta * std::sqrt(c.r2);
    Point2<double> x;
    if (p_.pick_attempts > 0) {
      const double reach2 = std::pow(2 + p_.delta, 2) * c.r2;
      const auto [ex, ey] = ellipse_extent(M, reach2);
      pick_cand_ = sites_in(c.cx - ex, c.cx + ex, c.cy - ey, c.cy + ey);
      std::erase_if(pick_cand_, [&](int w) { return qform(M, sites_[w].x - c.cx, sites_[w].y - c.cy) > reach2; });
    }
    // Up to 1 + pick_attempts points are drawn; every forbidden one but the last is discarded.
    for (int attempt = 0;; ++attempt) {
      double ux, uy;
      do ux = unit(rng_), uy = unit(rng_);
      while (ux * ux + uy * uy >= 1);
      const double zy = s * uy / l22, zx = (s * ux - l21 * zy) / l11;
      x = {c.cx + zx, c.cy + zy};
      if (p_.pick_attempts == 0 || !std::isfinite(x.x) || !std::isfinite(x.y) || !forbidden(x, std::sqrt(c.r2), pick_cand_)) break;
      if (attempt == p_.pick_attempts) {
        ++picks_exhausted_;
        break;
      }
      ++picks_rejected_;
    }
    if (!std::isfinite(x.x) || !std::isfinite(x.y)) {  // a nearly flat triangle: its centroid instead
      x = {(sites_[v].x + sites_[act.a].x + sites_[act.b].x) / 3, (sites_[v].y + sites_[act.a].y + sites_[act.b].y) / 3};
    }
    // Insert_or_snap: a point outside Ω or encroaching a segment (in the star's metric, its own,
    // or the segment's endpoints': the test of rule 1) splits that segment instead.
    const Sym2<double> Mx = field_.at(x.x, x.y);
    const bool outside = !inside_polygon(domain_, x.x, x.y);
    int nearest_segment = -1;
    double best = inf;
    std::vector<int> all;
    if (outside) {
      all.resize(segments_.size());
      for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
    }
    for (int s2 : outside ? all : segment_grid_[cell(cell_x(x.x), cell_y(x.y))]) {
      const auto [a, b] = segments_[s2];
      const double mx = (sites_[a].x + sites_[b].x) / 2 - x.x, my = (sites_[a].y + sites_[b].y) / 2 - x.y;
      const double half = qform(M, sites_[b].x - sites_[a].x, sites_[b].y - sites_[a].y) / 4;
      const double d = qform(M, mx, my);
      if (d < half || encroaches(x, Mx, s2)) {
        split(s2);
        return;
      }
      if (d - half < best) best = d - half, nearest_segment = s2;
    }
    if (outside) {
      // The point lies beyond ∂Ω: split the boundary subsegment between the triangle and it
      // (Ruppert's rule: the segment from the triangle's centroid to the point crosses it).
      const Point2<double> g{(sites_[v].x + sites_[act.a].x + sites_[act.b].x) / 3,
                             (sites_[v].y + sites_[act.a].y + sites_[act.b].y) / 3};
      int crossed = -1;
      double closest = inf;
      for (std::size_t s2 = 0; s2 < segments_.size(); ++s2) {
        const Point2<double>&a = sites_[segments_[s2].first], &b = sites_[segments_[s2].second];
        const int s1 = static_cast<int>(predicates::orientation(a, b, g)) * static_cast<int>(predicates::orientation(a, b, x));
        const int t1 = static_cast<int>(predicates::orientation(g, x, a)) * static_cast<int>(predicates::orientation(g, x, b));
        if (s1 > 0 || t1 > 0) continue;
        const double d = std::hypot((a.x + b.x) / 2 - g.x, (a.y + b.y) / 2 - g.y);
        if (d < closest) closest = d, crossed = static_cast<int>(s2);
      }
      split(crossed >= 0 ? crossed : nearest_segment);
      return;
    }
    if (!sites_in(x.x, x.x, x.y, x.y).empty()) {
      // The picking region is below the resolution of doubles there: stop rather than duplicate.
      stalled_ = "refining a triangle at site " + std::to_string(v) + " near (" + decimal(x.x) + ", " + decimal(x.y) +
                 ") picked an existing site: the mesh there is finer than doubles resolve (" + rule_name(act.rule) + ")";
      return;
    }
    insert(x, act.rule, true, v, std::sqrt(c.r2));
  }

  // --- merge ----------------------------------------------------------------------------------
  void merge(RefineResult& r) const {
    std::vector<std::array<int, 3>> seen;  // every star triangle, rotated to the least index first
    for (int v = 0; v < static_cast<int>(stars_.size()); ++v)
      for (const auto& t : stars_[v].triangles) {
        std::array<int, 3> k{v, t[0], t[1]};
        std::rotate(k.begin(), std::min_element(k.begin(), k.end()), k.end());
        seen.push_back(k);
      }
    std::sort(seen.begin(), seen.end());
    for (std::size_t i = 0, j; i < seen.size(); i = j) {
      for (j = i + 1; j < seen.size() && seen[j] == seen[i];) ++j;
      if (j - i == 3) r.triangles.push_back(seen[i]);
      else ++r.inconsistent_triangles;
    }
    r.consistent = r.inconsistent_triangles == 0;
    r.sites = sites_, r.metrics = metrics_, r.domain = domain_, r.segments = segments_;
  }

  std::vector<Point2<double>> domain_;
  bool convex_;
  MetricField field_;
  RefineParameters p_;
  std::function<void(const std::string&)> progress_;
  std::mt19937 rng_;
  double x0_, y0_, cw_, ch_;
  int g_;
  std::vector<Point2<double>> sites_;
  std::vector<Sym2<double>> metrics_;
  std::vector<Star> stars_;
  std::vector<bool> queued_;
  std::vector<std::vector<int>> sites_cells_, conflict_cells_;
  std::vector<std::pair<int, int>> segments_;
  std::vector<std::array<int, 2>> boundary_;  // per site: its two boundary neighbours, or −1
  std::vector<double> reach2_;                // per site: the squared M_v-reach of its star
  std::string stalled_;                       // why refinement cannot go on, if it cannot
  std::vector<std::array<double, 4>> segment_box_;  // per segment: the encroachment prefilter box
  std::vector<std::array<int, 4>> segment_cells_;   // per segment: the grid cells of its box
  std::vector<std::vector<int>> segment_grid_;      // per grid cell: the segments whose box covers it
  std::vector<int> pending_boxes_;
  // Scratch buffers, reused.
  mutable std::vector<int> found_;
  std::vector<int> cand_, ring_, zone_, before_;
  std::vector<char> in_;
  std::vector<std::array<int, 2>> fan_;
  std::vector<int> pick_cand_;
  std::size_t picks_rejected_ = 0, picks_exhausted_ = 0, refinements_ = 0;
  std::deque<int> segment_queue_, site_queue_;
  std::array<std::size_t, 6> counts_{};
  int last_rule_ = 0;
  std::vector<Insertion> trace_;
};

}  // namespace

RefineResult refine_star(const std::vector<Point2<double>>& domain, const MetricField& field, const RefineParameters& p,
                         const std::function<void(const std::string&)>& progress) {
  for (std::size_t i = 0; i < domain.size(); ++i) {
    const Point2<double>&a = domain[i], &b = domain[(i + 1) % domain.size()];
    const int k = exact_halvings(a, b);
    if (k < min_halvings)
      throw std::invalid_argument(
          "domain edge " + std::to_string(i) + " from (" + decimal(a.x) + ", " + decimal(a.y) + ") to (" +
          decimal(b.x) + ", " + decimal(b.y) + ") can be halved exactly in doubles only " + std::to_string(k) +
          " times (" + std::to_string(min_halvings) +
          " needed: split points must lie exactly on the boundary); give the domain coordinates with fewer binary digits, "
          "e.g. 0.375 or 13/32 rather than 0.4");
  }
  return Refiner(domain, field, p, progress).run();
}

}  // namespace anisocert::refiners::star
