#include "io/svg/certify_svg.hpp"

#include "io/svg/canvas.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace anisocert::io {
namespace {

// A histogram of values in bins over [lo, hi] (values outside are counted and said, not drawn),
// bars scaled to the tallest, at (x, y), w × h px, with a shaded band [band_lo, band_hi] and five
// tick labels from `label`.
template <class Label>
void histogram(std::ostream& o, const std::vector<double>& values, double lo, double hi, int bins, double x, double y, double w,
               double h, double band_lo, double band_hi, const std::string& title, Label label) {
  std::vector<std::size_t> count(bins, 0);
  std::size_t below = 0, above = 0;
  for (double v : values) {
    if (!(v >= lo)) ++below;
    else if (v > hi) ++above;
    else ++count[std::min(bins - 1, static_cast<int>((v - lo) / (hi - lo) * bins))];
  }
  const std::size_t top = std::max<std::size_t>(1, *std::max_element(count.begin(), count.end()));
  auto X = [&](double v) { return x + (v - lo) / (hi - lo) * w; };
  o << "<g font-family=\"sans-serif\" font-size=\"10\">\n";
  if (band_hi > band_lo)
    o << "<rect x=\"" << X(std::max(lo, band_lo)) << "\" y=\"" << y << "\" width=\"" << X(std::min(hi, band_hi)) - X(std::max(lo, band_lo))
      << "\" height=\"" << h << "\" fill=\"#e3f2e1\"/>\n";
  for (int b = 0; b < bins; ++b) {
    const double bh = h * static_cast<double>(count[b]) / static_cast<double>(top);
    o << "<rect x=\"" << x + w * b / bins << "\" y=\"" << y + h - bh << "\" width=\"" << w / bins * 0.9 << "\" height=\"" << bh
      << "\" fill=\"#1f4e9c\"/>\n";
  }
  o << "<line x1=\"" << x << "\" y1=\"" << y + h << "\" x2=\"" << x + w << "\" y2=\"" << y + h << "\" stroke=\"black\"/>\n";
  for (int k = 0; k <= 4; ++k) {
    const double v = lo + (hi - lo) * k / 4;
    o << "<text x=\"" << X(v) << "\" y=\"" << y + h + 12 << "\" text-anchor=\"middle\">" << label(v) << "</text>\n";
  }
  // The title on two lines: what is counted, then how.
  const auto cut = title.find(" (");
  o << "<text x=\"" << x << "\" y=\"" << y - 20 << "\" font-size=\"11\">" << title.substr(0, cut) << "</text>\n";
  if (cut != std::string::npos)
    o << "<text x=\"" << x << "\" y=\"" << y - 6 << "\">" << title.substr(cut + 1) << "</text>\n";
  o << "<text x=\"" << x << "\" y=\"" << y + h + 26 << "\">tallest bar " << top
    << (below ? ", " + std::to_string(below) + " left of the axis" : "") << (above ? ", " + std::to_string(above) + " right of it" : "")
    << "</text>\n</g>\n";
}

// Three significant digits, for tick labels.
std::string tick(double v) {
  std::ostringstream o;
  o.precision(3);
  o << v;
  return o.str();
}

// The metric edge lengths, log₂ of each on an axis spanning the data and the unit band
// [1/√2, √2] (±½), at most 2⁻¹² … 2¹² (the rest counted below or above).
void length_histogram(std::ostream& o, const std::vector<double>& lengths, double x, double y) {
  std::vector<double> log_lengths;
  double lo = -0.5, hi = 0.5;
  for (double l : lengths) {
    const double v = l > 0 ? std::log2(l) : -INFINITY;
    log_lengths.push_back(v);
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  }
  lo = std::max(std::floor(lo), -12.0), hi = std::min(std::ceil(hi), 12.0);
  histogram(o, log_lengths, lo, hi, 48, x, y, 290, 100, -0.5, 0.5,
            "edge lengths in both endpoints' metrics (" + std::to_string(log_lengths.size()) +
                ", 2 per edge; log scale, unit band shaded)",
            [](double v) { return tick(std::exp2(v)); });
}

void triangle_path(std::ostream& o, const Canvas& c, const std::vector<predicates::Point2<double>>& p,
                   const std::array<int, 3>& t) {
  o << "M" << c.X(p[t[0]].x) << " " << c.Y(p[t[0]].y);
  for (int i : {1, 2}) o << " L" << c.X(p[t[i]].x) << " " << c.Y(p[t[i]].y);
  o << " Z";
}

}  // namespace

std::string certify_svg(const geometry::Mesh<Rational>& mesh, const oracle::CertifyReport& r, const std::string& caption) {
  std::vector<predicates::Point2<double>> p;
  for (const auto& s : mesh.sites) p.push_back({s.x.convert_to<double>(), s.y.convert_to<double>()});
  geometry::Polygon<double> frame;
  for (const auto& q : p) frame.push_back(q);
  const Canvas c(frame, 0.03);
  constexpr double footer = 210, width = 660;
  std::ostringstream o;
  o.precision(6);
  c.open(o, footer, width);
  o << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<path fill=\"#eef3fb\" stroke=\"#1f4e9c\" stroke-width=\"0.3\" d=\"";
  for (const auto& t : mesh.triangles) triangle_path(o, c, p, t);
  o << "\"/>\n";
  // Failing triangles, once each.
  std::vector<bool> bad(mesh.triangles.size(), false);
  if (r.valid)
    for (int t : r.valid->bad_cells) bad[t] = true;
  for (const auto* list : {&r.uniform_violations, &r.rho_violations, &r.gamma_violations})
    for (const auto& w : list->places()) bad[w.triangle] = true;
  if (r.quality)
    for (const auto& w : r.quality->violations.places()) bad[w.triangle] = true;
  if (r.angles)
    for (const auto& w : r.angles->violations.places()) bad[w.triangle] = true;
  o << "<path fill=\"#e04030\" fill-opacity=\"0.6\" stroke=\"#a01010\" stroke-width=\"0.4\" d=\"";
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (bad[t]) triangle_path(o, c, p, mesh.triangles[t]);
  o << "\"/>\n<path fill=\"none\" stroke=\"#ff8c00\" stroke-width=\"2\" d=\"";
  std::vector<std::pair<int, int>> edges;
  if (r.valid) edges = r.valid->bad_edges;
  if (r.lengths)
    for (const auto& w : r.lengths->range_violations.places()) edges.emplace_back(w.vertex, w.site);
  for (const auto& [a, b] : edges) o << "M" << c.X(p[a].x) << " " << c.Y(p[a].y) << " L" << c.X(p[b].x) << " " << c.Y(p[b].y) << " ";
  o << "\"/>\n";
  const double y = c.height() + 50;
  if (r.lengths && !r.lengths->lengths.empty()) length_histogram(o, r.lengths->lengths, 20, y);
  if (r.quality)
    histogram(o, r.quality->qualities, 0, 1, 40, 350, y, 290, 100, 0, 0,
              "mean-ratio quality (" + std::to_string(r.quality->qualities.size()) + " triangles, 1 = equilateral)", tick);
  o << "<text x=\"8\" y=\"" << c.height() + footer - 10 << "\" font-family=\"sans-serif\" font-size=\"12\">" << xml_text(caption)
    << ": failing triangles in red, failing edges in orange</text>\n</svg>\n";
  return o.str();
}

std::string certify_svg(const geometry::Mesh3<Rational>& mesh, const oracle::Certify3Report& r, const std::string& caption) {
  std::vector<predicates::Point3<double>> p;
  for (const auto& v : mesh.vertices) p.push_back({v.x.convert_to<double>(), v.y.convert_to<double>(), v.z.convert_to<double>()});
  double z0 = INFINITY, z1 = -INFINITY;
  geometry::Polygon<double> frame;
  for (const auto& q : p) frame.push_back({q.x, q.y}), z0 = std::min(z0, q.z), z1 = std::max(z1, q.z);
  const double zc = z0 / 2 + z1 / 2;  // the slice
  const Canvas c(frame, 0.03);
  constexpr double footer = 210, width = 990;
  std::ostringstream o;
  o.precision(6);
  c.open(o, footer, width);
  std::vector<bool> bad(mesh.tetrahedra.size(), false);
  if (r.valid)
    for (int t : r.valid->bad_tetrahedra) bad[static_cast<std::size_t>(t)] = true;
  for (const auto* list : {&r.uniform_violations, &r.rho_violations, &r.gamma_violations})
    for (const auto& w : list->places()) bad[static_cast<std::size_t>(w.triangle)] = true;
  if (r.quality)
    for (const auto& w : r.quality->violations.places()) bad[static_cast<std::size_t>(w.triangle)] = true;
  if (r.angles)
    for (const auto& w : r.angles->violations.places()) bad[static_cast<std::size_t>(w.triangle)] = true;
  // Each tetrahedron's section by the plane z = zc: the points where its edges cross it, a convex
  // polygon ordered by angle around their mean.
  std::ostringstream good_path, bad_path;
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
    const auto& v = mesh.tetrahedra[t];
    std::vector<predicates::Point2<double>> cut;
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = i + 1; j < 4; ++j) {
        const auto &a = p[static_cast<std::size_t>(v[i])], &b = p[static_cast<std::size_t>(v[j])];
        if ((a.z - zc) * (b.z - zc) > 0 || a.z == b.z) continue;
        const double s = (zc - a.z) / (b.z - a.z);
        cut.push_back({a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)});
      }
    if (cut.size() < 3) continue;
    double mx = 0, my = 0;
    for (const auto& q : cut) mx += q.x / static_cast<double>(cut.size()), my += q.y / static_cast<double>(cut.size());
    std::sort(cut.begin(), cut.end(), [&](const auto& a, const auto& b) { return std::atan2(a.y - my, a.x - mx) < std::atan2(b.y - my, b.x - mx); });
    std::ostringstream& path = bad[t] ? bad_path : good_path;
    path.precision(6);
    path << "M" << c.X(cut[0].x) << " " << c.Y(cut[0].y);
    for (std::size_t k = 1; k < cut.size(); ++k) path << " L" << c.X(cut[k].x) << " " << c.Y(cut[k].y);
    path << " Z";
  }
  o << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<path fill=\"#eef3fb\" stroke=\"#1f4e9c\" stroke-width=\"0.3\" d=\""
    << good_path.str() << "\"/>\n<path fill=\"#e04030\" fill-opacity=\"0.6\" stroke=\"#a01010\" stroke-width=\"0.4\" d=\"" << bad_path.str()
    << "\"/>\n";
  const double y = c.height() + 50;
  if (r.lengths && !r.lengths->lengths.empty()) length_histogram(o, r.lengths->lengths, 20, y);
  if (r.quality)
    histogram(o, r.quality->qualities, 0, 1, 40, 350, y, 290, 100, 0, 0,
              "mean-ratio quality (" + std::to_string(r.quality->qualities.size()) + " tetrahedra, 1 = regular)", tick);
  if (r.angles)
    histogram(o, r.angles->element_smallest, 0, 90, 45, 680, y, 290, 100, 0, 0,
              "smallest dihedral angle of each tetrahedron (degrees; a sliver's is near 0, the regular one's 70.5)", tick);
  std::ostringstream slice;
  slice.precision(6);
  slice << zc;
  o << "<text x=\"8\" y=\"" << c.height() + footer - 10 << "\" font-family=\"sans-serif\" font-size=\"12\">" << xml_text(caption)
    << ": the tetrahedra cut by the plane z = " << slice.str() << ", failing ones in red</text>\n</svg>\n";
  return o.str();
}

}  // namespace anisocert::io
