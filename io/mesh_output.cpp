#include "io/mesh_output.hpp"

#include "numbers/rational.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace anisocert::io {

namespace {

std::string exact(double x) { return "\"" + to_exact_string(rational_from_double(x)) + "\""; }

std::string round_trip(double x) {
  std::ostringstream o;
  o.precision(17);
  o << x;
  return o.str();
}

}  // namespace

std::string mesh_json(const MeshData& m) {
  std::ostringstream o;
  o << "{\"sites\": [\n";
  for (std::size_t i = 0; i < m.sites.size(); ++i)
    o << "  {\"x\": " << exact(m.sites[i].x) << ", \"y\": " << exact(m.sites[i].y) << ", \"metric\": ["
      << exact(m.metrics[i].m11) << ", " << exact(m.metrics[i].m12) << ", " << exact(m.metrics[i].m22) << "]}"
      << (i + 1 < m.sites.size() ? ",\n" : "\n");
  o << "],\n\"domain\": [";
  for (std::size_t i = 0; i < m.domain.size(); ++i) o << (i ? ", " : "") << "[" << exact(m.domain[i].x) << ", " << exact(m.domain[i].y) << "]";
  o << "],\n\"segments\": [";
  for (std::size_t i = 0; i < m.segments.size(); ++i) o << (i ? ", " : "") << "[" << m.segments[i].first << ", " << m.segments[i].second << "]";
  o << "],\n\"triangles\": [\n";
  for (std::size_t i = 0; i < m.triangles.size(); ++i)
    o << "  [" << m.triangles[i][0] << ", " << m.triangles[i][1] << ", " << m.triangles[i][2] << "]"
      << (i + 1 < m.triangles.size() ? ",\n" : "\n");
  o << "]}\n";
  return o.str();
}

std::string medit_mesh(const MeshData& m) {
  std::ostringstream o;
  o << "MeshVersionFormatted 2\nDimension 2\nVertices\n" << m.sites.size() << "\n";
  for (const auto& p : m.sites) o << round_trip(p.x) << " " << round_trip(p.y) << " 0\n";
  o << "Edges\n" << m.segments.size() << "\n";
  for (const auto& [a, b] : m.segments) o << a + 1 << " " << b + 1 << " 1\n";
  o << "Triangles\n" << m.triangles.size() << "\n";
  for (const auto& t : m.triangles) o << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << " 0\n";
  o << "End\n";
  return o.str();
}

std::string medit_sol(const MeshData& m) {
  std::ostringstream o;
  o << "MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n" << m.metrics.size() << "\n1 3\n";
  for (const auto& M : m.metrics) o << round_trip(M.m11) << " " << round_trip(M.m12) << " " << round_trip(M.m22) << "\n";
  o << "End\n";
  return o.str();
}

std::string mesh_svg(const MeshData& m, const std::string& caption) {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const auto& p : m.domain) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  const double size = std::max(x1 - x0, y1 - y0), margin = size * 0.03, px = 800 / (size + 2 * margin);
  const double W = (x1 - x0 + 2 * margin) * px, H = (y1 - y0 + 2 * margin) * px;
  auto X = [&](double x) { return (x - x0 + margin) * px; };
  auto Y = [&](double y) { return (y1 - y + margin) * px; };
  std::ostringstream o;
  o.precision(6);
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H + 24 << "\" viewBox=\"0 0 " << W << " "
    << H + 24 << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<path fill=\"#eef3fb\" stroke=\"#1f4e9c\" stroke-width=\"0.3\" d=\"";
  for (const auto& t : m.triangles) {
    o << "M" << X(m.sites[t[0]].x) << " " << Y(m.sites[t[0]].y);
    for (int i : {1, 2}) o << " L" << X(m.sites[t[i]].x) << " " << Y(m.sites[t[i]].y);
    o << " Z";
  }
  o << "\"/>\n<polygon fill=\"none\" stroke=\"black\" stroke-width=\"1.2\" points=\"";
  for (const auto& p : m.domain) o << X(p.x) << "," << Y(p.y) << " ";
  o << "\"/>\n<text x=\"8\" y=\"" << H + 16 << "\" font-family=\"sans-serif\" font-size=\"12\">" << caption << "</text>\n</svg>\n";
  return o.str();
}

}  // namespace anisocert::io
