#include "oracle/certify/tetrahedron_faces.hpp"

#include <algorithm>
#include <tuple>

namespace anisocert::oracle {

std::vector<TetrahedronFace> faces_in_order(const std::vector<std::array<int, 4>>& tetrahedra, std::size_t vertices) {
  const auto face = [&](std::size_t t, int i) {
    const auto& v = tetrahedra[t];
    std::array<int, 3> s{v[static_cast<std::size_t>((i + 1) % 4)], v[static_cast<std::size_t>((i + 2) % 4)], v[static_cast<std::size_t>((i + 3) % 4)]};
    if (s[0] > s[1]) std::swap(s[0], s[1]);
    if (s[1] > s[2]) std::swap(s[1], s[2]);
    if (s[0] > s[1]) std::swap(s[0], s[1]);
    return TetrahedronFace{s, static_cast<int>(t), i};
  };
  std::vector<std::size_t> start(vertices + 1, 0);
  for (std::size_t t = 0; t < tetrahedra.size(); ++t)
    for (int i = 0; i < 4; ++i) ++start[static_cast<std::size_t>(face(t, i).sorted[0]) + 1];
  for (std::size_t u = 1; u <= vertices; ++u) start[u] += start[u - 1];
  std::vector<TetrahedronFace> faces(4 * tetrahedra.size());
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < tetrahedra.size(); ++t)
    for (int i = 0; i < 4; ++i) {
      const TetrahedronFace f = face(t, i);
      faces[next[static_cast<std::size_t>(f.sorted[0])]++] = f;
    }
  const auto key = [](const TetrahedronFace& f) { return std::tie(f.sorted[1], f.sorted[2], f.tetrahedron, f.opposite); };
  for (std::size_t u = 0; u < vertices; ++u)
    std::sort(faces.begin() + static_cast<std::ptrdiff_t>(start[u]), faces.begin() + static_cast<std::ptrdiff_t>(start[u + 1]),
              [&](const TetrahedronFace& a, const TetrahedronFace& b) { return key(a) < key(b); });
  return faces;
}

}  // namespace anisocert::oracle
