#include "refiners/bwy/dual_triangles.hpp"

#include <algorithm>

namespace anisocert::refiners::bwy {
namespace {

const std::vector<int> none;

}  // namespace

std::uint64_t DualTriangles::edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

std::array<int, 3> DualTriangles::sorted(std::array<int, 3> s) {
  std::sort(s.begin(), s.end());
  return s;
}

void DualTriangles::add(int key, const std::array<int, 3>& sites, bool flat) {
  const int t = static_cast<int>(triangles_.size());
  triangles_.push_back({sites, flat, key, true});
  for (int i = 0; i < 3; ++i) by_edge_[edge_key(sites[static_cast<std::size_t>(i)], sites[static_cast<std::size_t>((i + 1) % 3)])].push_back(t);
  by_sites_[sorted(sites)].push_back(t);
  by_key_[key].push_back(t);
}

std::vector<std::pair<int, int>> DualTriangles::remove(int key) {
  std::vector<std::pair<int, int>> emptied;
  const auto found = by_key_.find(key);
  if (found == by_key_.end()) return emptied;
  for (int t : found->second) {
    Triangle& tri = triangles_[static_cast<std::size_t>(t)];
    tri.alive = false;
    for (int i = 0; i < 3; ++i) {
      const int a = tri.sites[static_cast<std::size_t>(i)], b = tri.sites[static_cast<std::size_t>((i + 1) % 3)];
      const auto e = by_edge_.find(edge_key(a, b));
      std::erase(e->second, t);
      if (e->second.empty()) {
        by_edge_.erase(e);
        emptied.emplace_back(std::min(a, b), std::max(a, b));
      }
    }
    const auto s = by_sites_.find(sorted(tri.sites));
    std::erase(s->second, t);
    if (s->second.empty()) by_sites_.erase(s);
  }
  by_key_.erase(found);
  return emptied;
}

const std::vector<int>& DualTriangles::on_edge(int a, int b) const {
  const auto e = by_edge_.find(edge_key(a, b));
  return e == by_edge_.end() ? none : e->second;
}

const std::vector<int>& DualTriangles::same_sites(int t) const {
  const auto s = by_sites_.find(sorted(triangles_[static_cast<std::size_t>(t)].sites));
  return s == by_sites_.end() ? none : s->second;
}

const std::vector<int>& DualTriangles::of_key(int key) const {
  const auto k = by_key_.find(key);
  return k == by_key_.end() ? none : k->second;
}

std::vector<int> DualTriangles::alive() const {
  std::vector<int> out;
  for (std::size_t t = 0; t < triangles_.size(); ++t)
    if (triangles_[t].alive) out.push_back(static_cast<int>(t));
  return out;
}

}  // namespace anisocert::refiners::bwy
