#include "refiners/common/boundary3.hpp"

#include "predicates/dihedral.hpp"
#include "predicates/encroachment3.hpp"
#include "predicates/orientation3.hpp"
#include "refiners/common/exact_split.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>

namespace anisocert::refiners::common {
namespace {

// The diametral M-ball of the triangle abc (its centre in the plane abc, predicates/
// encroachment3.hpp's formula), in doubles: its box, the radius times √2, selects candidates.
Box3 diametral_box(const Point3<double>& a, const Point3<double>& b, const Point3<double>& c, const Sym3<double>& M) {
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const double A = predicates::quadratic_form(M, ux, uy, uz), C = predicates::quadratic_form(M, vx, vy, vz);
  const double B = predicates::bilinear_form(M, ux, uy, uz, vx, vy, vz), D = A * C - B * B;
  const double al = C * (A - B) / (2 * D), be = A * (C - B) / (2 * D);
  const Point3<double> o{a.x + al * ux + be * vx, a.y + al * uy + be * vy, a.z + al * uz + be * vz};
  const double r2 = predicates::quadratic_form(M, a.x - o.x, a.y - o.y, a.z - o.z);
  return metric_ball_box(o, M, 2 * r2);
}

}  // namespace

Boundary3::Boundary3(const Domain3& domain, const Sites3& sites) : domain_(domain), sites_(sites) {
  boxes_.reset(sites_.grid);
  site_facets_.resize(sites.size());  // the vertices' planes below; sites after them (seeds) are inside
  for (int f = 0; f < static_cast<int>(domain.facets().size()); ++f)
    for (int v : domain.facets()[f]) site_facets_[v].push_back(domain.plane_of(f));
  for (auto& planes : site_facets_) {
    std::sort(planes.begin(), planes.end());
    planes.erase(std::unique(planes.begin(), planes.end()), planes.end());
  }
  for (int f = 0; f < static_cast<int>(domain.facets().size()); ++f) add_subfacet(domain.facets()[f], f);
}

int Boundary3::add_subfacet(const std::array<int, 3>& v, int facet) {
  const int id = static_cast<int>(subfacets_.size());
  subfacets_.push_back({v, facet, true});
  for (int e = 0; e < 3; ++e) edges_[key(v[e], v[(e + 1) % 3])].push_back(id);
  const auto& x = sites_.points;
  Box3 box;
  for (int w : v) box = box.hull(diametral_box(x[v[0]], x[v[1]], x[v[2]], sites_.metrics[w]));
  boxes_.set(id, box, sites_.grid);
  queued_.push_back(false);
  enqueue(id);
  return id;
}

void Boundary3::kill(int f) {
  Subfacet& s = subfacets_[f];
  s.alive = false;
  for (int e = 0; e < 3; ++e) {
    auto& list = edges_[key(s.v[e], s.v[(e + 1) % 3])];
    std::erase(list, f);
  }
  boxes_.set(f, Box3{}, sites_.grid);
}

bool Boundary3::is_subsegment(int a, int b) const {
  const auto it = edges_.find(key(a, b));
  if (it == edges_.end() || it->second.size() != 2) return false;
  return !domain_.coplanar(subfacets_[it->second[0]].facet, subfacets_[it->second[1]].facet);
}

bool Boundary3::beyond(int f, const Point3<double>& p) const {
  const auto& v = subfacets_[f].v;
  const auto& x = sites_.points;
  return predicates::orientation3(x[v[0]], x[v[1]], x[v[2]], p) == Sign::positive;
}

bool Boundary3::encroaches(const Point3<double>& p, bool on_boundary, const Sym3<double>& Mp, int f, std::optional<Edge>* edge_of) const {
  const auto& v = subfacets_[f].v;
  const auto& x = sites_.points;
  const auto& m = sites_.metrics;
  for (int e = 0; e < 3; ++e) {
    const int a = v[e], b = v[(e + 1) % 3];
    if (!is_subsegment(a, b)) continue;
    if (predicates::encroaches_edge(p, x[a], x[b], Mp) || predicates::encroaches_edge(p, x[a], x[b], m[a]) ||
        predicates::encroaches_edge(p, x[a], x[b], m[b])) {
      if (edge_of) *edge_of = Edge{std::min(a, b), std::max(a, b)};
      return true;
    }
  }
  if (on_boundary ? !beyond(f, p) : predicates::orientation3(x[v[0]], x[v[1]], x[v[2]], p) == Sign::zero) return false;  // see boundary3.hpp
  if (predicates::encroaches_facet(p, x[v[0]], x[v[1]], x[v[2]], Mp)) return true;
  for (int w : v)
    if (predicates::encroaches_facet(p, x[v[0]], x[v[1]], x[v[2]], m[w])) return true;
  return false;
}

std::pair<double, Boundary3::Edge> Boundary3::length(int a, int b) const {
  const Edge e{std::min(a, b), std::max(a, b)};
  const auto [it, fresh] = lengths_.try_emplace(key(a, b), 0.0);
  if (fresh) {
    // The composite midpoint rule with 8 samples of √(uᵀ M(p) u) for u = b − a, from the lesser
    // site to the greater, so that an edge has one length.
    const auto& p = sites_.points[e[0]];
    const auto& q = sites_.points[e[1]];
    const double ux = q.x - p.x, uy = q.y - p.y, uz = q.z - p.z;
    for (int i = 0; i < 8; ++i) {
      const double t = (i + 0.5) / 8;
      const Sym3<double> M = sites_.metric_at({p.x + t * ux, p.y + t * uy, p.z + t * uz});
      it->second += std::sqrt(predicates::quadratic_form(M, ux, uy, uz)) / 8;
    }
  }
  return {it->second, e};
}

Boundary3::Edge Boundary3::longest_edge(int f) const {
  const auto& v = subfacets_[f].v;
  return std::max({length(v[0], v[1]), length(v[1], v[2]), length(v[2], v[0])}).second;
}

Boundary3::Edge Boundary3::terminal(Edge e) const {
  for (bool moved = true; moved;) {
    moved = false;
    for (int f : edges_.at(key(e[0], e[1])))
      if (const Edge l = longest_edge(f); l != e) {
        e = l, moved = true;
        break;
      }
  }
  return e;
}

std::optional<Boundary3::Edge> Boundary3::next_encroached() {
  while (!queue_.empty()) {
    const int f = queue_.front();
    queue_.pop_front();
    queued_[f] = false;
    if (!subfacets_[f].alive) continue;
    const auto& v = subfacets_[f].v;
    for (int p : sites_.in(boxes_.box(f))) {
      if (p == v[0] || p == v[1] || p == v[2]) continue;
      std::optional<Edge> edge;
      if (encroaches(sites_.points[p], !site_facets_[p].empty(), sites_.metrics[p], f, &edge)) {
        queue_.push_front(f), queued_[f] = true;  // checked again if the split (LEPP's first) left it
        return edge ? *edge : terminal(longest_edge(f));
      }
    }
  }
  return std::nullopt;
}

std::optional<Boundary3::Edge> Boundary3::snap(const Point3<double>& q, const Sym3<double>& Mv, const Sym3<double>& Mq) const {
  const std::vector<int> near = boxes_.holding(q, sites_.grid);  // a copy: the buffer is shared
  // The encroached subsegment, else subfacet, nearest to q (its centroid's M_v-distance): the
  // element between q and the simplex refined, not one it encroaches far away.
  const auto& x = sites_.points;
  const auto distance = [&](const auto& vertices) {
    double cx = 0, cy = 0, cz = 0;
    for (int w : vertices) cx += x[w].x / vertices.size(), cy += x[w].y / vertices.size(), cz += x[w].z / vertices.size();
    return predicates::quadratic_form(Mv, cx - q.x, cy - q.y, cz - q.z);
  };
  std::optional<std::pair<double, Edge>> edge_best, facet_best;
  for (int f : near) {
    std::optional<Edge> edge;
    if (encroaches(q, false, Mq, f, &edge) || encroaches(q, false, Mv, f, &edge)) {
      if (edge) {
        const std::pair<double, Edge> c{distance(*edge), *edge};
        if (!edge_best || c < *edge_best) edge_best = c;
      } else {
        const std::pair<double, Edge> c{distance(subfacets_[f].v), longest_edge(f)};
        if (!facet_best || c < *facet_best) facet_best = c;
      }
    }
  }
  if (edge_best) return edge_best->second;
  if (facet_best) return terminal(facet_best->second);
  return std::nullopt;
}

std::variant<Point3<double>, std::string> Boundary3::midpoint(const Edge& e) const {
  const auto& x = sites_.points;
  if (const auto m = exact_midpoint(x[e[0]], x[e[1]])) return *m;
  return "the boundary edge from site " + std::to_string(e[0]) + " " + point_text(x[e[0]]) + " to site " + std::to_string(e[1]) + " " +
         point_text(x[e[1]]) + " has no midpoint in doubles: the boundary there is finer than doubles resolve";
}

void Boundary3::split(const Edge& e, int m) {
  if (site_facets_.size() <= static_cast<std::size_t>(m)) site_facets_.resize(m + 1);
  const auto& fa = site_facets_[e[0]];
  const auto& fb = site_facets_[e[1]];
  std::vector<int> both;
  std::set_intersection(fa.begin(), fa.end(), fb.begin(), fb.end(), std::back_inserter(both));
  site_facets_[m] = std::move(both);
  const std::vector<int> at = edges_[key(e[0], e[1])];
  for (int f : at) {
    const std::array<int, 3> v = subfacets_[f].v;
    const int facet = subfacets_[f].facet;
    kill(f);
    // Rotate so that the edge runs v[r] → v[r + 1] in f's (outward) order.
    int r = 0;
    while (!((v[r] == e[0] || v[r] == e[1]) && (v[(r + 1) % 3] == e[0] || v[(r + 1) % 3] == e[1]))) ++r;
    const int x = v[r], y = v[(r + 1) % 3], z = v[(r + 2) % 3];
    add_subfacet({x, m, z}, facet);
    add_subfacet({m, y, z}, facet);
    legalize(z, x, m), legalize(y, z, m);
  }
}

void Boundary3::legalize(int a, int b, int m) {
  // Lawson's flips in M_m, one metric for the whole insertion: each flip lowers the lifted
  // surface of the plane's triangulation in that metric, so they end.
  const auto& x = sites_.points;
  const Sym3<double>& M = sites_.metrics[m];
  std::vector<Edge> stack{{a, b}};
  while (!stack.empty()) {
    const int p = stack.back()[0], q = stack.back()[1];
    stack.pop_back();
    const auto it = edges_.find(key(p, q));
    if (it == edges_.end() || it->second.size() != 2) continue;
    const int f = it->second[0], g = it->second[1];
    if (!domain_.coplanar(subfacets_[f].facet, subfacets_[g].facet)) continue;  // a subsegment
    const auto apex = [&](int h) {
      for (int w : subfacets_[h].v)
        if (w != p && w != q) return w;
      return -1;
    };
    const int fm = apex(f) == m ? f : g, other = fm == f ? g : f, d = apex(other);
    if (apex(fm) != m) continue;  // the edge's subfacets no longer both touch this insertion
    // fm is (m, p, q) in outward order, up to rotation; its edge runs p → q or q → p.
    const auto& v = subfacets_[fm].v;
    int r = 0;
    while (v[r] != m) ++r;
    const int s = v[(r + 1) % 3], t = v[(r + 2) % 3];  // fm = (m, s, t), other = (t, s, d)
    if (!predicates::encroaches_facet(x[d], x[m], x[s], x[t], M)) continue;
    const int facet = subfacets_[fm].facet;
    kill(fm), kill(other);
    add_subfacet({m, s, d}, facet);
    add_subfacet({m, d, t}, facet);
    stack.push_back({s, d}), stack.push_back({d, t});
  }
}

void Boundary3::site_added(int k) {
  if (site_facets_.size() <= static_cast<std::size_t>(k)) site_facets_.resize(k + 1);
  for (int f : boxes_.holding(sites_.points[k], sites_.grid)) enqueue(f);
}

Boundary3::RidgeAngles Boundary3::ridge_angles() const {
  std::map<Edge, std::vector<int>> at;  // Ω's edges → their facets
  const auto& facets = domain_.facets();
  for (int f = 0; f < static_cast<int>(facets.size()); ++f)
    for (int e = 0; e < 3; ++e) {
      const int a = facets[f][e], b = facets[f][(e + 1) % 3];
      at[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  const auto& x = domain_.vertices();
  const auto third = [&](int f, const Edge& e) {
    for (int k : facets[f])
      if (k != e[0] && k != e[1]) return k;
    return -1;
  };
  RidgeAngles r;
  for (const auto& [e, fs] : at) {
    if (fs.size() != 2 || domain_.coplanar(fs[0], fs[1])) continue;
    ++r.ridges;
    const int f = fs[0], c = third(fs[0], e), d = third(fs[1], e);
    if (predicates::orientation3(x[facets[f][0]], x[facets[f][1]], x[facets[f][2]], x[d]) == Sign::positive) continue;  // reflex
    // Convex: Ω's angle at the ridge is the dihedral angle between the half-planes through c and
    // d, not above 90° iff the sign of n_cᵀ adj(M) n_d is not negative (predicates/dihedral.hpp).
    for (int end : e) {
      const Sym3<double>& M = sites_.metrics[end];
      const auto &a = x[e[0]], &b = x[e[1]];
      if (predicates::filtered_sign<predicates::DihedralDotKernel>(std::array<double, 18>{
              a.x, a.y, a.z, b.x, b.y, b.z, x[c].x, x[c].y, x[c].z, x[d].x, x[d].y, x[d].z, M.m11, M.m12, M.m13, M.m22, M.m23, M.m33}) !=
          Sign::negative) {
        r.not_obtuse.push_back(e);
        break;
      }
    }
  }
  return r;
}

bool Boundary3::on_one_facet(int a, int b, int c) const {
  const auto &fa = site_facets_[a], &fb = site_facets_[b], &fc = site_facets_[c];
  for (int f : fa)
    if (std::binary_search(fb.begin(), fb.end(), f) && std::binary_search(fc.begin(), fc.end(), f)) return true;
  return false;
}

std::vector<std::array<int, 3>> Boundary3::subfacets() const {
  std::vector<std::array<int, 3>> out;
  for (const auto& s : subfacets_)
    if (s.alive) out.push_back(s.v);
  return out;
}

}  // namespace anisocert::refiners::common
