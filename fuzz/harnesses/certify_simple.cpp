// The certifier against a deliberately simple independent check (docs/fuzzing.md § Differential),
// on meshes of at most 25 vertices decoded from bytes: a k × k grid (k = 2..5) over the square
// [0, k−1]², each cell cut along a diagonal chosen by a bit, interior vertices moved by up to half a
// cell in eighths (which can fold triangles over), metrics M = FᵀF with F = [[a, b], [0, c]] of small
// integers (the identity for all vertices, one shared metric, or one each: the grid's cocircular
// squares make ties), and sometimes one corruption: a triangle repeated, turned clockwise or left
// out, or an interior vertex moved onto another vertex.
// The simple check, in plain rational arithmetic, shares nothing with oracle/certify:
//   valid    every triangle counter-clockwise and not flat; no two triangles overlap (for two
//            convex polygons: no edge line of either separates them); the areas add up to the
//            square's; every vertex is in the square and a vertex of some triangle; no vertex lies
//            inside an edge of a triangle it is not a vertex of; no two vertices coincide;
//   uniform  (on valid meshes) for each triangle and each of its vertices v: the centre of the
//            M_v-circumellipse from its two linear equations (Cramer), and each other vertex's
//            M_v-distance to it against the radius: strictly inside is a violation, equal a tie.
// The certifier's `valid` verdict, its set of violating triangles, and (for triangles without a
// violation) its set of tied triangles must be the simple check's. Limit: 64 bytes.
#include "fuzz/support/byte_source.hpp"
#include "fuzz/support/finding.hpp"
#include "oracle/certify/mesh_certifier.hpp"

#include <algorithm>
#include <set>

using anisocert::Rational;
using anisocert::fuzz::require;
using Point = anisocert::predicates::Point2<Rational>;
using Metric = anisocert::predicates::Sym2<Rational>;
using Mesh = anisocert::geometry::Mesh<Rational>;
using Triangle = std::array<int, 3>;

namespace {

Rational cross(const Point& o, const Point& a, const Point& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

Metric metric_of(anisocert::fuzz::ByteSource& b) {
  const Rational a(1 + b.next() % 3), s(static_cast<int>(b.next() % 5) - 2), c(1 + b.next() % 3);
  return {a * a, a * s, s * s + c * c};
}

Mesh decode(anisocert::fuzz::ByteSource& b, int& k) {
  k = 2 + static_cast<int>(b.next() % 4);
  const unsigned metric_mode = b.next() % 3, corruption = b.next() % 8;
  Mesh m;
  const Rational side(k - 1);
  m.domain = {{0, 0}, {side, 0}, {side, side}, {0, side}};
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) {
      Point p{Rational(i), Rational(j)};
      if (i > 0 && j > 0 && i < k - 1 && j < k - 1) {
        p.x += Rational(static_cast<int>(b.next() % 9) - 4, 8);
        p.y += Rational(static_cast<int>(b.next() % 9) - 4, 8);
      }
      m.sites.push_back(p);
    }
  const Metric shared = metric_mode == 1 ? metric_of(b) : Metric{1, 0, 1};
  for (std::size_t v = 0; v < m.sites.size(); ++v) m.metrics.push_back(metric_mode == 2 ? metric_of(b) : shared);
  const auto id = [k](int i, int j) { return j * k + i; };
  for (int j = 0; j + 1 < k; ++j)
    for (int i = 0; i + 1 < k; ++i) {
      const int a = id(i, j), c = id(i + 1, j), d = id(i + 1, j + 1), e = id(i, j + 1);
      if (b.next() % 2) {
        m.triangles.push_back({a, c, d});
        m.triangles.push_back({a, d, e});
      } else {
        m.triangles.push_back({a, c, e});
        m.triangles.push_back({c, d, e});
      }
    }
  const std::size_t t = b.next() % m.triangles.size();
  switch (corruption) {
    case 1: m.triangles.push_back(m.triangles[t]); break;
    case 2: std::swap(m.triangles[t][1], m.triangles[t][2]); break;
    case 3: m.triangles.erase(m.triangles.begin() + static_cast<long>(t)); break;
    case 4:
      if (k > 2) m.sites[id(1, 1)] = m.sites[std::array<int, 3>{id(0, 0), id(2, 1), id(1, 2)}[b.next() % 3]];
      break;
    default: break;
  }
  return m;
}

// No edge line of s or t separates them (both counter-clockwise): their interiors meet.
bool overlap(const Mesh& m, const Triangle& s, const Triangle& t) {
  for (const auto* pair : {&s, &t}) {
    const Triangle& a = *pair;
    const Triangle& other = pair == &s ? t : s;
    for (int e = 0; e < 3; ++e) {
      const Point &p = m.sites[a[e]], &q = m.sites[a[(e + 1) % 3]];
      if (std::all_of(other.begin(), other.end(), [&](int v) { return cross(p, q, m.sites[v]) <= 0; })) return false;
    }
  }
  return true;
}

bool simple_valid(const Mesh& m, int k) {
  const Rational side(k - 1);
  for (std::size_t v = 0; v < m.sites.size(); ++v) {
    const Point& p = m.sites[v];
    if (p.x < 0 || p.y < 0 || p.x > side || p.y > side) return false;
    for (std::size_t w = 0; w < v; ++w)
      if (m.sites[w].x == p.x && m.sites[w].y == p.y) return false;
  }
  Rational area = 0;
  std::set<int> used;
  for (const Triangle& t : m.triangles) {
    const Rational twice = cross(m.sites[t[0]], m.sites[t[1]], m.sites[t[2]]);
    if (twice <= 0) return false;
    area += twice / 2;
    used.insert(t.begin(), t.end());
  }
  if (area != side * side || used.size() != m.sites.size()) return false;
  for (std::size_t i = 0; i < m.triangles.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (overlap(m, m.triangles[i], m.triangles[j])) return false;
  for (const Triangle& t : m.triangles)
    for (int e = 0; e < 3; ++e) {
      const Point &p = m.sites[t[e]], &q = m.sites[t[(e + 1) % 3]];
      for (int v = 0; v < static_cast<int>(m.sites.size()); ++v) {
        if (v == t[0] || v == t[1] || v == t[2]) continue;
        const Point& r = m.sites[v];
        const Rational along = (r.x - p.x) * (q.x - p.x) + (r.y - p.y) * (q.y - p.y);
        const Rational length2 = (q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y);
        if (cross(p, q, r) == 0 && along > 0 && along < length2) return false;
      }
    }
  return true;
}

Rational norm2(const Metric& M, const Rational& dx, const Rational& dy) {
  return M.m11 * dx * dx + 2 * M.m12 * dx * dy + M.m22 * dy * dy;
}

// Violating and tied triangles, by the circumellipse's centre.
void simple_uniform(const Mesh& m, std::set<int>& violating, std::set<int>& tied) {
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t) {
    const Triangle& tri = m.triangles[t];
    const Point &a = m.sites[tri[0]], &b = m.sites[tri[1]], &c = m.sites[tri[2]];
    for (int v : tri) {
      const Metric& M = m.metrics[v];
      // 2 (b − a)ᵀ M o = |b|² − |a|², 2 (c − a)ᵀ M o = |c|² − |a|² (norms in M).
      const auto row = [&](const Point& p) {
        const Rational dx = p.x - a.x, dy = p.y - a.y;
        return std::array<Rational, 3>{2 * (M.m11 * dx + M.m12 * dy), 2 * (M.m12 * dx + M.m22 * dy),
                                       norm2(M, p.x, p.y) - norm2(M, a.x, a.y)};
      };
      const auto r1 = row(b), r2 = row(c);
      const Rational det = r1[0] * r2[1] - r1[1] * r2[0];
      const Rational ox = (r1[2] * r2[1] - r1[1] * r2[2]) / det, oy = (r1[0] * r2[2] - r1[2] * r2[0]) / det;
      const Rational radius2 = norm2(M, a.x - ox, a.y - oy);
      for (int s = 0; s < static_cast<int>(m.sites.size()); ++s) {
        if (s == tri[0] || s == tri[1] || s == tri[2]) continue;
        const Rational d = norm2(M, m.sites[s].x - ox, m.sites[s].y - oy);
        if (d < radius2) violating.insert(t);
        if (d == radius2) tied.insert(t);
      }
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 64) return -1;
  anisocert::fuzz::ByteSource b(data, size);
  int k = 0;
  const Mesh m = decode(b, k);
  anisocert::oracle::CertifyOptions o;
  const auto report = anisocert::oracle::certify_mesh(m, o);
  const bool valid = simple_valid(m, k);
  require(report.valid_holds() == valid, std::string("the certifier calls the mesh ") + (valid ? "invalid" : "valid") +
                                             ", the simple check " + (valid ? "valid" : "invalid"));
  if (!valid) return 0;
  std::set<int> violating, tied;
  simple_uniform(m, violating, tied);
  std::set<int> reported_violating, reported_tied;
  for (const auto& w : report.uniform_violations) reported_violating.insert(w.triangle);
  for (const auto& w : report.uniform_ties)
    if (!violating.count(w.triangle)) reported_tied.insert(w.triangle);
  for (int t : violating) tied.erase(t);
  require(reported_violating == violating, "the certifier's locally uniform violations differ from the simple check's");
  require(reported_tied == tied, "the certifier's ties (on triangles without a violation) differ from the simple check's");
  return 0;
}
