#include "oracle/certify/tetrahedralization_check.hpp"

#include "geometry/closed_surface.hpp"

#include <algorithm>
#include <tuple>

namespace anisocert::oracle {
namespace {

using Triple = std::array<int, 3>;

std::string triple_text(const Triple& t) {
  return "(" + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) + ")";
}

// The outward orientation of face f: the face opposite vertex i of a positively oriented
// (a, b, c, d) is, outward, (b, c, d), (a, d, c), (a, b, d), (a, c, b) for i = 0 to 3 (for the unit
// tetrahedron the first has normal (1, 1, 1)/…, away from a); of a negatively oriented one, reversed.
Triple outward(const std::array<int, 4>& v, int i, Sign sign) {
  const auto [a, b, c, d] = v;
  const std::array<Triple, 4> out{Triple{b, c, d}, Triple{a, d, c}, Triple{a, b, d}, Triple{a, c, b}};
  Triple f = out[static_cast<std::size_t>(i)];
  if (sign == Sign::negative) std::swap(f[1], f[2]);
  return f;
}

// Whether an outward triple is an even permutation (a rotation) of its sorted vertices; a
// rotation of their reverse is odd.
bool even(const Triple& outward, const Triple& s) {
  return (outward[0] == s[0] && outward[1] == s[1]) || (outward[0] == s[1] && outward[1] == s[2]) || (outward[0] == s[2] && outward[1] == s[0]);
}

}  // namespace

void TetrahedralizationCheck::fail(std::string text) {
  if (failures.size() < described) failures.push_back(std::move(text));
  ++failure_count;
}

TetrahedralizationCheck check_tetrahedralization(const EnclosedMesh3& m, std::size_t described) {
  TetrahedralizationCheck r;
  r.described = described;
  const auto& tets = m.mesh.tetrahedra;
  const std::size_t n = m.mesh.vertices.size();
  std::vector<int> bad;

  r.checks_run.push_back("every tetrahedron has the same non-zero orientation (exact)");
  std::vector<Sign> sign(tets.size());
  std::size_t positive = 0, negative = 0;
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const auto& v = tets[t];
    sign[t] = v[0] == v[1] || v[0] == v[2] || v[0] == v[3] || v[1] == v[2] || v[1] == v[3] || v[2] == v[3]
                  ? Sign::zero
                  : m.orientation(t);
    positive += sign[t] == Sign::positive, negative += sign[t] == Sign::negative;
  }
  r.orientation = positive == 0 && negative == 0 ? "" : positive >= negative ? "positive" : "negative";
  const Sign usual = positive >= negative ? Sign::positive : Sign::negative;
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const auto& v = tets[t];
    if (sign[t] == Sign::zero) {
      r.fail("tetrahedron " + std::to_string(t) + " (vertices " + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " +
             std::to_string(v[2]) + ", " + std::to_string(v[3]) + ") is flat: its vertices are coplanar or repeated");
      bad.push_back(static_cast<int>(t));
    } else if (sign[t] != usual) {
      r.fail("tetrahedron " + std::to_string(t) + " is " + (usual == Sign::positive ? "negatively" : "positively") + " oriented, " +
             std::to_string(usual == Sign::positive ? positive : negative) + " others " +
             (usual == Sign::positive ? "positively" : "negatively") + ": the file mixes the two conventions");
      bad.push_back(static_cast<int>(t));
    }
  }

  // Faces, each with its tetrahedron's outward orientation (by the tetrahedron's own sign, so
  // that two tetrahedra on one side of a face are found whatever the convention).
  r.checks_run.push_back("every face is in one tetrahedron (boundary) or in two on opposite sides of it");
  const std::vector<TetrahedronFace>& faces = m.faces;  // equal faces adjacent
  const auto outward_of = [&](const TetrahedronFace& f) {
    return outward(tets[static_cast<std::size_t>(f.tetrahedron)], f.opposite, sign[static_cast<std::size_t>(f.tetrahedron)]);
  };
  std::vector<Triple> boundary;  // outward
  std::vector<int> boundary_tetrahedron;
  std::vector<Triple> interior;  // sorted triples, in order
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].sorted == faces[i].sorted) ++j;
    if (j - i == 1) {
      boundary.push_back(outward_of(faces[i])), boundary_tetrahedron.push_back(faces[i].tetrahedron);
    } else if (j - i == 2) {
      ++r.interior_faces;
      interior.push_back(faces[i].sorted);
      if (even(outward_of(faces[i]), faces[i].sorted) == even(outward_of(faces[i + 1]), faces[i].sorted)) {
        r.fail("face " + triple_text(faces[i].sorted) + " is in tetrahedra " + std::to_string(faces[i].tetrahedron) + " and " +
               std::to_string(faces[i + 1].tetrahedron) + ", which lie on the same side of it (they overlap)");
        bad.push_back(faces[i].tetrahedron), bad.push_back(faces[i + 1].tetrahedron);
      }
    } else {
      std::string which;
      for (std::size_t k = i; k < j && k < i + 4; ++k) which += (k > i ? ", " : "") + std::to_string(faces[k].tetrahedron);
      r.fail("face " + triple_text(faces[i].sorted) + " is in " + std::to_string(j - i) + " tetrahedra (" + which + (j - i > 4 ? ", …" : "") + ")");
      for (std::size_t k = i; k < j; ++k) bad.push_back(faces[k].tetrahedron);
    }
    i = j;
  }
  r.boundary_faces = boundary.size();

  r.checks_run.push_back("every vertex is a vertex of a tetrahedron");
  std::vector<char> used(n, 0);
  for (const auto& t : tets)
    for (int v : t) used[static_cast<std::size_t>(v)] = 1;
  for (std::size_t v = 0; v < n; ++v)
    if (!used[v]) r.fail("vertex " + std::to_string(v) + " is a vertex of no tetrahedron");

  // The boundary surface: each boundary edge in two boundary faces, once in each direction; the
  // boundary faces at a vertex one cycle of its link.
  r.checks_run.push_back("the boundary is a closed 2-manifold (no pinched edge or vertex)");
  geometry::closed_surface_defects(boundary, [&](const geometry::SurfaceDefect& d) {
    using Kind = geometry::SurfaceDefect::Kind;
    const std::string e = "boundary edge (" + std::to_string(d.a) + ", " + std::to_string(d.b) + ")";
    if (d.kind == Kind::edge_count) r.fail(e + " is in " + std::to_string(d.count) + " boundary faces" + (d.count > 2 ? " (a pinched edge)" : ""));
    else if (d.kind == Kind::same_direction) r.fail(e + " runs the same way in its two boundary faces");
    else r.fail("vertex " + std::to_string(d.a) + " is pinched: its boundary faces make " + std::to_string(d.count) + " cycles around it, not one");
  });

  const auto& declared = m.mesh.triangles;
  if (!declared.empty()) {
    r.checks_run.push_back("every boundary face is declared, every declared triangle a face (interior: an interface), once or once from each side");
    std::vector<std::pair<Triple, int>> d, b;
    for (std::size_t k = 0; k < declared.size(); ++k) {
      Triple s = declared[k];
      std::sort(s.begin(), s.end());
      d.emplace_back(s, static_cast<int>(k));
    }
    // Whether declared triangle k lists its vertices in an odd permutation of the sorted order.
    const auto odd = [&](int k) {
      const Triple& t = declared[static_cast<std::size_t>(k)];
      return ((t[0] > t[1]) != (t[1] > t[2])) != (t[0] > t[2]);
    };
    for (std::size_t k = 0; k < boundary.size(); ++k) {
      Triple s = boundary[k];
      std::sort(s.begin(), s.end());
      b.emplace_back(s, boundary_tetrahedron[k]);
    }
    std::sort(d.begin(), d.end()), std::sort(b.begin(), b.end());
    std::size_t i = 0, j = 0;
    while (i < d.size() || j < b.size()) {
      if (j == b.size() || (i < d.size() && d[i].first < b[j].first)) {
        const bool repeated = i > 0 && d[i - 1].first == d[i].first;
        // A face declared once from each side (the two orientations), as CGAL's Medit writer lists
        // the facets of a surface patch: counted, not a failure; a third time or the same way twice is.
        const bool other_side = repeated && !(i > 1 && d[i - 2].first == d[i].first) && odd(d[i - 1].second) != odd(d[i].second);
        const bool interface = !repeated && std::binary_search(interior.begin(), interior.end(), d[i].first);
        if (interface)
          ++r.declared_interfaces;
        else if (other_side)
          ++r.declared_both_sides;
        else
          r.fail("declared triangle " + std::to_string(d[i].second) + " " + triple_text(declared[static_cast<std::size_t>(d[i].second)]) +
                 (repeated ? " is declared again in the same orientation or a third time" : " is not a face of the tetrahedra"));
        ++i;
      } else if (i == d.size() || b[j].first < d[i].first) {
        r.fail("the boundary face " + triple_text(b[j].first) + " of tetrahedron " + std::to_string(b[j].second) +
               " is not among the declared triangles");
        ++j;
      } else {
        ++i, ++j;
      }
    }
  }
  r.checks_run.push_back("not checked: that the boundary surface does not intersect itself (the tetrahedra could then cover some "
                         "points twice)");

  std::sort(bad.begin(), bad.end());
  bad.erase(std::unique(bad.begin(), bad.end()), bad.end());
  r.bad_tetrahedra = std::move(bad);
  r.valid = r.failure_count == 0 && !tets.empty();
  if (tets.empty()) r.fail("the mesh has no tetrahedron");
  return r;
}

}  // namespace anisocert::oracle
