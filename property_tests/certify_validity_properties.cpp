// BWY §3.2.1 (local embedding) for meshes from other meshers, which come without a domain polygon:
// the certifier's validity check (oracle/certify/triangulation_check.hpp, the union of the triangles
// bounded by the file's edges) against a brute-force verdict written here from the definition of a
// triangulation, every test exact and O(T²):
//  - every triangle has three distinct sites and is strictly counter-clockwise;
//  - no two sites coincide, and every site is a vertex of some triangle;
//  - the triangles form a simplicial complex: no site strictly inside a triangle or in the relative
//    interior of a triangle's edge, no two edges crossing properly, no triangle twice;
//  - its boundary (the edges in exactly one triangle) leaves every site at most once (no pinch);
//  - when the file declares edges: every boundary edge is declared, every declared edge is an edge.
// This is the header's contract: with every triangle counter-clockwise, the union is covered
// exactly as many times as the boundary cycle winds, so "disjoint simple loops wound 0 or 1
// around one another" is "interiors disjoint" plus "no site or edge of the boundary touched twice",
// and a site in the relative interior of an edge makes two boundary edges meet there (or covers a
// point twice). The contract says nothing of declared edges inside the union: they are accepted
// (Medit ridges), and so here.
//
// The meshes: jittered k×k grids (k = 1..4) split along random diagonals, with rational (decimal or
// fractional) coordinates, with an interior hole, with an island inside the hole, or two disjoint
// grids; sites relabelled and triangles rotated and shuffled at random. Then one mutation (the
// class, which shrinking keeps): none; flip a triangle; delete one; duplicate one; fold a vertex
// across (or onto) the opposite edge; two sites made to coincide; an unused site; a copy of a grid
// square (shifted to overlap, on top with new sites, shrunk inside, or far away) or a triangle around
// everything; a pinch (a square
// sharing only a corner); a triangle glued outward on a boundary edge, or glued with a hanging
// vertex; declared edges = the boundary, minus one, plus an interior edge, plus a non-edge.
#include "numbers/rational.hpp"
#include "oracle/certify/triangulation_check.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <optional>
#include <random>
#include <set>
#include <sstream>

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

using anisocert::Rational;
using anisocert::parse_rational;
using anisocert::to_exact_string;
using namespace anisocert::oracle;

namespace {

using P = anisocert::predicates::Point2<Rational>;
using Tri = std::array<int, 3>;
using Edge = std::pair<int, int>;
using Mesh = anisocert::geometry::Mesh<Rational>;

// ---------------------------------------------------------------------------------------------
// The brute force, from the definitions (nothing from the code under test).

Rational cross(const P& a, const P& b, const P& c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }
int sign(const Rational& r) { return r > 0 ? 1 : r < 0 ? -1 : 0; }
bool same(const P& p, const P& q) { return p.x == q.x && p.y == q.y; }

// p in the relative interior of the segment ab (a ≠ b)
bool inside_segment(const P& p, const P& a, const P& b) {
  return cross(a, b, p) == 0 && (p.x - a.x) * (b.x - p.x) + (p.y - a.y) * (b.y - p.y) > 0;
}
// the segments' relative interiors meet in one point that is an end of neither
bool properly_cross(const P& a, const P& b, const P& c, const P& d) {
  return sign(cross(a, b, c)) * sign(cross(a, b, d)) < 0 && sign(cross(c, d, a)) * sign(cross(c, d, b)) < 0;
}
// p strictly inside the counter-clockwise triangle abc
bool strictly_inside(const P& p, const P& a, const P& b, const P& c) {
  return cross(a, b, p) > 0 && cross(b, c, p) > 0 && cross(c, a, p) > 0;
}

Edge undirected(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// How many triangles each undirected edge is in.
std::map<Edge, int> edge_counts(const std::vector<Tri>& tris) {
  std::map<Edge, int> c;
  for (const Tri& t : tris)
    for (int i = 0; i < 3; ++i) ++c[undirected(t[i], t[(i + 1) % 3])];
  return c;
}

// The edges in exactly one triangle, directed as in it.
std::vector<Edge> boundary_of(const std::vector<Tri>& tris) {
  const auto count = edge_counts(tris);
  std::vector<Edge> b;
  for (const Tri& t : tris)
    for (int i = 0; i < 3; ++i)
      if (count.at(undirected(t[i], t[(i + 1) % 3])) == 1) b.emplace_back(t[i], t[(i + 1) % 3]);
  return b;
}

// Why the triangles are not a triangulation of the union bounded by the declared edges, or nothing.
std::optional<std::string> brute_force_violation(const Mesh& m) {
  const auto& s = m.sites;
  const auto& T = m.triangles;
  const int n = static_cast<int>(s.size());
  if (T.empty()) return "no triangle";
  for (std::size_t k = 0; k < T.size(); ++k) {
    const Tri& t = T[k];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return "triangle " + std::to_string(k) + " repeats a site";
    if (cross(s[t[0]], s[t[1]], s[t[2]]) <= 0) return "triangle " + std::to_string(k) + " is not counter-clockwise";
  }
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (same(s[i], s[j])) return "sites " + std::to_string(i) + " and " + std::to_string(j) + " coincide";
  std::vector<bool> used(n, false);
  for (const Tri& t : T)
    for (int v : t) used[v] = true;
  for (int i = 0; i < n; ++i)
    if (!used[i]) return "site " + std::to_string(i) + " is unused";
  for (int p = 0; p < n; ++p)
    for (std::size_t k = 0; k < T.size(); ++k) {
      const Tri& t = T[k];
      if (p == t[0] || p == t[1] || p == t[2]) continue;
      if (strictly_inside(s[p], s[t[0]], s[t[1]], s[t[2]]))
        return "site " + std::to_string(p) + " is inside triangle " + std::to_string(k);
      for (int i = 0; i < 3; ++i)
        if (inside_segment(s[p], s[t[i]], s[t[(i + 1) % 3]]))
          return "site " + std::to_string(p) + " is inside an edge of triangle " + std::to_string(k);
    }
  const auto counts = edge_counts(T);
  std::vector<Edge> edges;
  for (const auto& [e, c] : counts) edges.push_back(e);
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const auto [a, b] = edges[i];
      const auto [c, d] = edges[j];
      if (properly_cross(s[a], s[b], s[c], s[d]))
        return "edges (" + std::to_string(a) + ", " + std::to_string(b) + ") and (" + std::to_string(c) + ", " +
               std::to_string(d) + ") cross";
    }
  std::set<std::array<int, 3>> vertex_sets;
  for (Tri t : T) {
    std::sort(t.begin(), t.end());
    if (!vertex_sets.insert(t).second) return "a triangle is there twice";
  }
  const std::vector<Edge> boundary = boundary_of(T);
  std::vector<int> out(n, 0);
  for (const auto& [a, b] : boundary)
    if (++out[a] > 1) return "the boundary leaves site " + std::to_string(a) + " twice";
  if (!m.edges.empty()) {
    std::set<Edge> declared;
    for (const auto& [a, b] : m.edges) {
      declared.insert(undirected(a, b));
      if (!counts.count(undirected(a, b)))
        return "declared edge (" + std::to_string(a) + ", " + std::to_string(b) + ") is not an edge";
    }
    for (const auto& [a, b] : boundary)
      if (!declared.count(undirected(a, b)))
        return "boundary edge (" + std::to_string(a) + ", " + std::to_string(b) + ") is not declared";
  }
  return std::nullopt;
}

// ---------------------------------------------------------------------------------------------
// The generator.

struct Case {
  Mesh mesh;
  std::string shape, mutation;
};

std::ostream& operator<<(std::ostream& os, const Case& c) {
  os << c.shape << " / " << c.mutation << "\n  sites:";
  for (std::size_t i = 0; i < c.mesh.sites.size(); ++i)
    os << " " << i << ":(" << to_exact_string(c.mesh.sites[i].x) << ", " << to_exact_string(c.mesh.sites[i].y) << ")";
  os << "\n  triangles:";
  for (const Tri& t : c.mesh.triangles) os << " (" << t[0] << ", " << t[1] << ", " << t[2] << ")";
  os << "\n  edges:";
  for (const auto& [a, b] : c.mesh.edges) os << " (" << a << ", " << b << ")";
  return os << "\n";
}

// A uniform integer in [lo, hi) at every test size (rc::gen::inRange scales with the size).
template <class T>
T pick(T lo, T hi) {
  return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange<T>(lo, hi));
}
// A choice of class: never shrunk.
int pick_class(int n) { return *rc::gen::noShrink(rc::gen::resize(rc::kNominalSize, rc::gen::inRange(0, n))); }

// A jitter of absolute value below 1/8 (every quadrilateral of the grid stays strictly convex).
Rational jitter() {
  const long den = std::array<long, 3>{100, 97, 1024}[pick(0, 3)];
  const long r = den / 8 - 1;
  return Rational(pick<long>(-r, r + 1), den);
}

struct Grid {
  int k = 0, first = 0;  // k × k squares, sites first .. first + (k + 1)² − 1
  Rational h;            // the spacing
  int site(int i, int j) const { return first + j * (k + 1) + i; }
  int triangle(int i, int j, int half) const { return 2 * (j * k + i) + half; }  // within the grid's triangles
};

// Appends a k × k grid at origin with spacing h: site (i, j) at origin + h (i + δ, j + δ'), δ and
// δ' jitters (none, at interior sites only, or everywhere), each square split along a random
// diagonal into two counter-clockwise triangles.
Grid add_grid(Mesh& m, int k, const P& origin, const Rational& h) {
  Grid g{k, static_cast<int>(m.sites.size()), h};
  const int jitter_mode = pick(0, 3);  // 0 none (collinear boundary sites), 1 interior, 2 all
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i <= k; ++i) {
      const bool interior = i > 0 && i < k && j > 0 && j < k;
      const bool moved = jitter_mode == 2 || (jitter_mode == 1 && interior);
      const Rational dx = moved ? jitter() : Rational(0), dy = moved ? jitter() : Rational(0);
      m.sites.push_back({origin.x + h * (i + dx), origin.y + h * (j + dy)});
    }
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) {
      const int a = g.site(i, j), b = g.site(i + 1, j), c = g.site(i + 1, j + 1), d = g.site(i, j + 1);
      if (pick(0, 2) == 0)
        m.triangles.push_back({a, b, c}), m.triangles.push_back({a, c, d});
      else
        m.triangles.push_back({a, b, d}), m.triangles.push_back({b, c, d});
    }
  return g;
}

P add(const P& p, const P& q) { return {p.x + q.x, p.y + q.y}; }
P sub(const P& p, const P& q) { return {p.x - q.x, p.y - q.y}; }
P scale(const Rational& s, const P& p) { return {s * p.x, s * p.y}; }

int add_site(Mesh& m, const P& p) {
  m.sites.push_back(p);
  return static_cast<int>(m.sites.size()) - 1;
}

std::vector<Edge> interior_edges(const std::vector<Tri>& tris) {
  std::vector<Edge> e;
  for (const auto& [edge, c] : edge_counts(tris))
    if (c == 2) e.push_back(edge);
  return e;
}

Edge maybe_reversed(const Edge& e) { return pick(0, 2) ? Edge{e.second, e.first} : e; }

std::vector<Edge> declared_boundary(const std::vector<Tri>& tris) {
  std::vector<Edge> d;
  for (const Edge& e : boundary_of(tris)) d.push_back(maybe_reversed(e));
  return d;
}

// A triangle (index) with an edge on the boundary, and that edge's corner order: (a, b, c) with a → b
// on the boundary.
Tri boundary_corner(const Mesh& m) {
  const auto count = edge_counts(m.triangles);
  std::vector<Tri> candidates;
  for (const Tri& t : m.triangles)
    for (int i = 0; i < 3; ++i)
      if (count.at(undirected(t[i], t[(i + 1) % 3])) == 1) candidates.push_back({t[i], t[(i + 1) % 3], t[(i + 2) % 3]});
  return candidates[pick<std::size_t>(0, candidates.size())];
}

const char* const shapes[] = {"grid", "grid_with_hole", "hole_with_island", "two_grids"};
const char* const mutations[] = {"none",          "flip",          "delete",           "duplicate",
                                 "fold",          "fold_onto_edge", "coincide",        "unused_site",
                                 "overlap_copy",  "pinch",         "glue",             "hang",
                                 "declare_boundary", "declare_minus_one", "declare_plus_interior", "declare_plus_non_edge"};
constexpr int mutation_count = sizeof mutations / sizeof mutations[0];

// The mutations after which the triangles are never a triangulation of the declared domain, and
// those after which they always are.
bool always_invalid(const std::string& mutation) {
  for (const char* m : {"flip", "duplicate", "fold", "fold_onto_edge", "coincide", "unused_site",
                        "overlap_copy/shifted", "overlap_copy/on_top", "overlap_copy/shrunk", "overlap_copy/enclosing", "pinch", "hang",
                        "declare_minus_one", "declare_plus_non_edge"})
    if (mutation.rfind(m, 0) == 0 && (mutation.size() == std::string(m).size() || mutation[std::string(m).size()] == '+'))
      return true;
  return false;
}
bool always_valid(const std::string& mutation) {
  return mutation == "none" || mutation == "none+declared" || mutation == "declare_boundary" ||
         mutation == "declare_plus_interior" || mutation == "overlap_copy/far";
}

// The base mesh (valid, no domain polygon) and the first grid.
Grid base_mesh(Case& c, int shape) {
  static const char* const origins[][2] = {{"0", "0"}, {"0.1", "0.7"}, {"-3/7", "5/11"}, {"12.34", "-0.001"}};
  static const char* const spacings[] = {"1", "0.1", "1/3", "0.007"};
  const int o = pick(0, 4);
  const P origin{parse_rational(origins[o][0]), parse_rational(origins[o][1])};
  const Rational h = parse_rational(spacings[pick(0, 4)]);
  c.shape = shapes[shape];
  Mesh& m = c.mesh;
  const int k = shape == 1 || shape == 2 ? pick(3, 5) : pick(1, 5);
  const Grid g = add_grid(m, k, origin, h);
  if (shape == 1 || shape == 2) {  // remove a triangle of an interior square: all its sites are interior
    const int i = pick(1, k - 1), j = pick(1, k - 1), half = pick(0, 2);
    const Tri hole = m.triangles[g.triangle(i, j, half)];
    m.triangles.erase(m.triangles.begin() + g.triangle(i, j, half));
    if (shape == 2) {  // the hole shrunk by 1/3 about its centroid: an island inside it
      const P centroid = scale(Rational(1, 3), add(add(m.sites[hole[0]], m.sites[hole[1]]), m.sites[hole[2]]));
      Tri island;
      for (int v = 0; v < 3; ++v)
        island[v] = add_site(m, add(centroid, scale(Rational(1, 3), sub(m.sites[hole[v]], centroid))));
      m.triangles.push_back(island);
    }
  }
  if (shape == 3) add_grid(m, pick(1, 4), {origin.x + h * (k + 1), origin.y}, h);  // a gap of at least 3/4 h
  return g;
}

// Applies mutation `which` to the valid base mesh; returns its name (with the variant).
std::string mutate(Mesh& m, const Grid& g, int which) {
  const std::string name = mutations[which];
  auto& T = m.triangles;
  auto& S = m.sites;
  const int n = static_cast<int>(S.size());
  const Rational& h = g.h;
  if (name == "none") return name;
  if (name == "flip") {
    Tri& t = T[pick<std::size_t>(0, T.size())];
    std::swap(t[1], t[2]);
    return name;
  }
  if (name == "delete") {
    T.erase(T.begin() + static_cast<std::ptrdiff_t>(pick<std::size_t>(0, T.size())));
    return name;
  }
  if (name == "duplicate") {
    Tri t = T[pick<std::size_t>(0, T.size())];
    std::rotate(t.begin(), t.begin() + pick(0, 3), t.end());
    T.push_back(t);
    return name;
  }
  if (name == "fold" || name == "fold_onto_edge") {
    // An interior site of the first grid when there is one, and a triangle at it.
    int v;
    if (g.k >= 2)
      v = g.site(pick(1, g.k), pick(1, g.k));
    else
      v = T[0][pick(0, 3)];
    std::vector<Tri> at;
    for (const Tri& t : T)
      for (int i = 0; i < 3; ++i)
        if (t[i] == v) at.push_back({t[i], t[(i + 1) % 3], t[(i + 2) % 3]});
    const Tri t = at[pick<std::size_t>(0, at.size())];
    const P &a = S[t[1]], &b = S[t[2]];
    S[v] = name == "fold" ? sub(add(a, b), S[v]) : scale(Rational(1, 2), add(a, b));
    return name;
  }
  if (name == "coincide") {
    const int i = pick(0, n), j = (i + pick(1, n)) % n;
    S[j] = S[i];
    return name;
  }
  if (name == "unused_site") {
    add_site(m, {S[0].x + h * Rational(pick(-10, 60), 10), S[0].y + h * Rational(pick(-10, 60), 10)});
    return name;
  }
  if (name == "overlap_copy") {
    const int i = pick(0, g.k), j = pick(0, g.k);
    const int corner[4] = {g.site(i, j), g.site(i + 1, j), g.site(i + 1, j + 1), g.site(i, j + 1)};
    const P centre = scale(Rational(1, 4), add(add(S[corner[0]], S[corner[1]]), add(S[corner[2]], S[corner[3]])));
    static const char* const variants[] = {"shifted", "on_top", "shrunk", "far", "enclosing"};
    const int variant = pick_class(5);
    if (variant == 4) {  // one big triangle around everything: every other loop is inside it
      const Rational far = 6 * g.k + 10;
      const int a = add_site(m, add(S[0], {-2 * h, -2 * h})), b = add_site(m, add(S[0], {far * h, -2 * h})),
                c = add_site(m, add(S[0], {-2 * h, far * h}));
      T.push_back({a, b, c});
      return name + "/" + variants[variant];
    }
    int copy[4];
    for (int q = 0; q < 4; ++q) {
      const P& p = S[corner[q]];
      switch (variant) {
        case 0: copy[q] = add_site(m, add(p, {h / 2, h / 3})); break;
        case 1: copy[q] = add_site(m, p); break;
        case 2: copy[q] = add_site(m, add(centre, scale(Rational(1, 4), sub(p, centre)))); break;
        default: copy[q] = add_site(m, add(p, {0, -h * (g.k + 3)})); break;
      }
    }
    T.push_back({copy[0], copy[1], copy[2]});
    T.push_back({copy[0], copy[2], copy[3]});
    return name + "/" + variants[variant];
  }
  if (name == "pinch") {  // a square below and left of the grid's first corner, sharing only that corner
    const int v = g.site(0, 0);
    const int w1 = add_site(m, add(S[v], {0, -h})), w2 = add_site(m, add(S[v], {-h, -h})), w3 = add_site(m, add(S[v], {-h, 0}));
    T.push_back({w2, w1, v});
    T.push_back({w2, v, w3});
    return name;
  }
  if (name == "glue" || name == "hang") {  // outward across a boundary edge a → b of triangle abc
    const Tri t = boundary_corner(m);
    const P a = S[t[0]], b = S[t[1]], c = S[t[2]];
    const int p = add_site(m, sub(add(a, b), c));
    if (name == "glue") {
      T.push_back({t[1], t[0], p});
    } else {
      const int mid = add_site(m, scale(Rational(1, 2), add(a, b)));
      T.push_back({t[1], mid, p});
      T.push_back({mid, t[0], p});
    }
    return name;
  }
  // Declared edges.
  m.edges = declared_boundary(T);
  if (name == "declare_minus_one") {
    m.edges.erase(m.edges.begin() + static_cast<std::ptrdiff_t>(pick<std::size_t>(0, m.edges.size())));
  } else if (name == "declare_plus_interior") {
    const auto inner = interior_edges(T);
    m.edges.insert(m.edges.begin() + static_cast<std::ptrdiff_t>(pick<std::size_t>(0, m.edges.size() + 1)),
                   maybe_reversed(inner[pick<std::size_t>(0, inner.size())]));
  } else if (name == "declare_plus_non_edge") {
    const auto counts = edge_counts(T);
    std::vector<Edge> non_edges;
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b)
        if (!counts.count({a, b})) non_edges.emplace_back(a, b);
    m.edges.push_back(maybe_reversed(non_edges[pick<std::size_t>(0, non_edges.size())]));
  }
  return name;
}

// Sites relabelled, triangles rotated and shuffled, declared edges shuffled: the same mesh.
void relabel(Mesh& m, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<int> perm(m.sites.size());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), rng);
  std::vector<P> sites(m.sites.size());
  for (std::size_t i = 0; i < perm.size(); ++i) sites[perm[i]] = m.sites[i];
  m.sites = sites;
  for (Tri& t : m.triangles) {
    for (int& v : t) v = perm[v];
    std::rotate(t.begin(), t.begin() + rng() % 3, t.end());
  }
  std::shuffle(m.triangles.begin(), m.triangles.end(), rng);
  for (auto& [a, b] : m.edges) a = perm[a], b = perm[b];
  std::shuffle(m.edges.begin(), m.edges.end(), rng);
}

// A base mesh of a random shape, mutated by a random class.
rc::Gen<Case> mutated_mesh() {
  return rc::gen::exec([] {
    Case c;
    const int shape = pick_class(4);
    const int which = pick_class(mutation_count);
    const Grid g = base_mesh(c, shape);
    const std::vector<Tri> base = c.mesh.triangles;
    c.mutation = mutate(c.mesh, g, which);
    // After the other mutations, sometimes declare the base mesh's boundary.
    if (std::string(mutations[which]).rfind("declare", 0) != 0 && pick_class(4) == 0) {
      c.mesh.edges = declared_boundary(base);
      c.mutation += "+declared";
    }
    if (pick(0, 4) > 0) relabel(c.mesh, *rc::gen::noShrink(rc::gen::arbitrary<std::uint32_t>()));
    return c;
  });
}

TriangulationCheck certify(const Mesh& m) {
  const EnclosedMesh em(m);
  return check_triangulation(em, triangle_cells(m.triangles));
}

// The check run in a child process with a deadline first: a check that crashes or does not finish
// fails the property instead of taking the test run down or hanging it. Nothing when it did not
// finish (with why in `why`), else its verdict.
std::optional<bool> certify_in_child(const Mesh& m, std::string& why) {
  std::fflush(nullptr);
  const pid_t child = fork();
  if (child == 0) {
    alarm(2);
    _exit(certify(m).is_triangulation ? 1 : 0);
  }
  int status = 0;
  if (child < 0 || waitpid(child, &status, 0) != child) {
    why = "fork or wait failed";
    return std::nullopt;
  }
  if (WIFEXITED(status) && (WEXITSTATUS(status) == 0 || WEXITSTATUS(status) == 1)) return WEXITSTATUS(status) == 1;
  why = WIFSIGNALED(status) ? "the check was killed by signal " + std::to_string(WTERMSIG(status)) +
                                  (WTERMSIG(status) == SIGALRM ? " (did not finish within 2 s)" : "")
                            : "the check exited with status " + std::to_string(WEXITSTATUS(status));
  return std::nullopt;
}

std::string first_failures(const TriangulationCheck& t) {
  std::string s;
  for (std::size_t i = 0; i < std::min<std::size_t>(3, t.failures.size()); ++i) s += "\n  " + t.failures[i];
  return s;
}

}  // namespace

// The certifier's verdict is the brute-force verdict, on every class.
RC_GTEST_PROP(BWY_E321, MeshWithoutDomainIsATriangulationExactlyWhenBruteForceSaysSo, ()) {
  const Case c = *mutated_mesh();
  RC_TAG(c.mutation);
  const auto violation = brute_force_violation(c.mesh);
  RC_CLASSIFY(!violation, "triangulation");
  RC_LOG() << c << "brute force: " << (violation ? *violation : "a triangulation") << "\n";
  std::string why;
  const std::optional<bool> verdict = certify_in_child(c.mesh, why);
  if (!verdict) RC_FAIL(why);
  const TriangulationCheck t = certify(c.mesh);
  RC_LOG() << "certifier:" << (t.is_triangulation ? " a triangulation" : first_failures(t)) << "\n";
  RC_ASSERT(*verdict == t.is_triangulation);
  RC_ASSERT(t.is_triangulation == !violation);
  // A "no" names what is wrong, a "yes" names nothing.
  RC_ASSERT(t.failures.empty() == t.is_triangulation);
  RC_ASSERT(t.failure_count >= t.failures.size());
}

// The classes whose verdict is known in advance: the brute force (and the certifier) say so. This
// keeps the brute force itself honest: it cannot accept everything or reject everything.
RC_GTEST_PROP(BWY_E321, KnownClassesGetTheirKnownVerdict, ()) {
  const Case c = *mutated_mesh();
  RC_PRE(always_valid(c.mutation) || always_invalid(c.mutation));
  RC_TAG(c.mutation);
  const bool expected = always_valid(c.mutation);
  const auto violation = brute_force_violation(c.mesh);
  RC_LOG() << c << "brute force: " << (violation ? *violation : "a triangulation") << "\n";
  RC_ASSERT(!violation == expected);
  std::string why;
  const std::optional<bool> verdict = certify_in_child(c.mesh, why);
  if (!verdict) RC_FAIL(why);
  RC_ASSERT(*verdict == expected);
}

// Relabelling the sites and reordering the triangles never changes the verdict.
RC_GTEST_PROP(BWY_E321, VerdictDoesNotDependOnTheLabels, ()) {
  Case c = *mutated_mesh();
  RC_TAG(c.shape);
  std::string why;
  const std::optional<bool> before = certify_in_child(c.mesh, why);
  if (!before) RC_FAIL(why);
  relabel(c.mesh, *rc::gen::arbitrary<std::uint32_t>());
  RC_LOG() << c;
  const std::optional<bool> after = certify_in_child(c.mesh, why);
  if (!after) RC_FAIL(why);
  RC_ASSERT(*after == *before);
}

// The smallest input of the class that the properties found hanging: a boundary triangle of a
// square listed twice. Its three edges are each in two cells in the same direction (rejected); the
// rest of the boundary, 2 → 3 → 0, is an open path. Expected: "not a triangulation", promptly.
TEST(BWY_E321, DuplicatedBoundaryTriangleIsRejectedPromptly) {
  Mesh m;
  m.sites = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 1, 2}};
  std::string why;
  const std::optional<bool> verdict = certify_in_child(m, why);
  ASSERT_TRUE(verdict.has_value()) << why;
  EXPECT_FALSE(*verdict);
}

// The same square with a triangle's orientation flipped, and with one triangle doubled in the
// opposite direction: never triangulations, and answered.
TEST(BWY_E321, FlippedOrCancellingTrianglesAreRejectedPromptly) {
  const std::vector<std::vector<Tri>> cases = {{{0, 2, 1}, {0, 2, 3}},             // flipped: 0 → 2 twice
                                               {{0, 1, 2}, {0, 2, 3}, {0, 2, 1}},  // a copy that cancels
                                               {{0, 1, 2}, {0, 2, 3}, {2, 3, 0}}}; // a rotated duplicate
  for (const auto& tris : cases) {
    Mesh m;
    m.sites = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    m.triangles = tris;
    std::string why;
    const std::optional<bool> verdict = certify_in_child(m, why);
    EXPECT_TRUE(verdict.has_value()) << why << "\n" << Case{m, "square", "broken"};
    EXPECT_FALSE(verdict.value_or(false)) << Case{m, "square", "broken"};
  }
}
