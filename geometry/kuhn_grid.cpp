#include "geometry/kuhn_grid.hpp"

#include "predicates/orientation3.hpp"

#include <algorithm>

namespace anisocert::geometry {

Mesh3<Rational> kuhn_grid(int n) {
  Mesh3<Rational> m;
  const auto index = [n](int i, int j, int k) { return (i * (n + 1) + j) * (n + 1) + k; };
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) m.vertices.push_back({i, j, k});
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        std::array<int, 3> axes{0, 1, 2};
        do {
          std::array<int, 3> p{i, j, k};
          std::array<int, 4> t{index(i, j, k), 0, 0, 0};
          for (std::size_t s = 0; s < 3; ++s) ++p[static_cast<std::size_t>(axes[s])], t[s + 1] = index(p[0], p[1], p[2]);
          const auto& v = m.vertices;
          if (predicates::orientation3(v[t[0]], v[t[1]], v[t[2]], v[t[3]]) == Sign::negative) std::swap(t[2], t[3]);
          m.tetrahedra.push_back(t);
        } while (std::next_permutation(axes.begin(), axes.end()));
      }
  return m;
}

}  // namespace anisocert::geometry
