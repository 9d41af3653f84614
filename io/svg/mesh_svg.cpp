#include "io/svg/mesh_svg.hpp"

#include "io/svg/canvas.hpp"

#include <sstream>

namespace anisocert::io {

std::string mesh_svg(const geometry::Mesh<double>& m, const std::string& caption) {
  const Canvas c(m.domain, 0.03);
  std::ostringstream o;
  o.precision(6);
  c.open(o, 24);
  o << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<path fill=\"#eef3fb\" stroke=\"#1f4e9c\" stroke-width=\"0.3\" d=\"";
  for (const auto& t : m.triangles) {
    o << "M" << c.X(m.sites[t[0]].x) << " " << c.Y(m.sites[t[0]].y);
    for (int i : {1, 2}) o << " L" << c.X(m.sites[t[i]].x) << " " << c.Y(m.sites[t[i]].y);
    o << " Z";
  }
  o << "\"/>\n<polygon fill=\"none\" stroke=\"black\" stroke-width=\"1.2\" points=\"";
  for (const auto& p : m.domain) o << c.X(p.x) << "," << c.Y(p.y) << " ";
  o << "\"/>\n<text x=\"8\" y=\"" << c.height() + 16 << "\" font-family=\"sans-serif\" font-size=\"12\">" << xml_text(caption) << "</text>\n</svg>\n";
  return o.str();
}

}  // namespace anisocert::io
