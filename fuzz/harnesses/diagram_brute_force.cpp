// The exact diagram against brute force (docs/fuzzing.md § Differential; LS Definition 1), on the
// small inputs of fuzz/support/small_diagram.hpp (up to 6 sites on the grid of eighths, metrics up
// to 4:1, a square, a triangle or an L-shaped domain):
//   - the oracle either builds D|Ω or declines a degenerate input it documents (std::domain_error);
//     any other exception is a finding;
//   - at every point of the grid of twelfths inside Ω, the owners of what contains it (locate) are
//     exactly its nearest sites, computed here from the definition: d_v(p)² = (p − v)ᵀ M_v (p − v),
//     compared exactly (the oracle's own nearest_sites is not used);
//   - every site lies in exactly one face of its own cell that is not an orphan.
// Limit: 2 + 5·6 bytes.
#include "fuzz/support/finding.hpp"
#include "fuzz/support/small_diagram.hpp"
#include "oracle/diagram/diagram.hpp"

#include <algorithm>
#include <stdexcept>

using anisocert::Rational;
using anisocert::fuzz::require;
namespace oracle = anisocert::oracle;
using Point = anisocert::predicates::Point2<Rational>;

namespace {

std::vector<int> nearest_by_definition(const anisocert::geometry::Mesh<Rational>& in, const Point& p) {
  std::vector<int> best;
  Rational least;
  for (std::size_t v = 0; v < in.sites.size(); ++v) {
    const Rational dx = p.x - in.sites[v].x, dy = p.y - in.sites[v].y;
    const auto& M = in.metrics[v];
    const Rational d = M.m11 * dx * dx + 2 * M.m12 * dx * dy + M.m22 * dy * dy;
    if (best.empty() || d < least) {
      best = {static_cast<int>(v)};
      least = d;
    } else if (d == least) {
      best.push_back(static_cast<int>(v));
    }
  }
  return best;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > anisocert::fuzz::small_diagram_max_len) return -1;
  const anisocert::fuzz::SmallDiagram small = anisocert::fuzz::small_diagram(data, size);
  const anisocert::geometry::Mesh<Rational>& in = small.input;
  const anisocert::fuzz::Shape shape = small.shape;
  if (in.sites.empty()) return 0;
  oracle::Diagram d;
  try {
    d = oracle::compute_diagram(in);
  } catch (const std::domain_error&) {
    return 0;  // a degenerate input the oracle declines by name (docs/oracle.md)
  }
  for (int i = 0; i <= 12; ++i)
    for (int j = 0; j <= 12; ++j) {
      const Point p{Rational(i, 12), Rational(j, 12)};
      if (!anisocert::fuzz::inside(p, shape)) continue;
      const oracle::Location loc = oracle::locate(d, p);
      require(loc.owners == nearest_by_definition(in, p),
              "at (" + std::to_string(i) + "/12, " + std::to_string(j) + "/12) the diagram's owners are not the nearest sites");
    }
  for (std::size_t s = 0; s < in.sites.size(); ++s)
    require(std::count_if(d.faces.begin(), d.faces.end(),
                          [&](const oracle::Face& f) { return f.site == static_cast<int>(s) && !f.orphan; }) == 1,
            "site " + std::to_string(s) + " is not in exactly one non-orphan face of its cell");
  return 0;
}
