#include "io/svg/diagram_svg.hpp"

#include "io/svg/canvas.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace anisocert::io {

using oracle::Diagram;

namespace {

struct XY {
  double x, y;
};

// Where to draw a point of the diagram: the middle of its box, unsheared in intervals (what
// Diagram::original_xy rounds exactly to its grid, at the cost of exact signs: that took 90 of the
// 97 s of a 6,233-site picture); original_xy when the box is not finite.
std::pair<double, double> drawn_xy(const Diagram& d, const oracle::LocatedPoint& p) {
  const FilterInterval X = p.x - FilterInterval::around(d.shear) * p.y;
  if (!(std::isfinite(X.lo) && std::isfinite(X.hi) && std::isfinite(p.y.lo) && std::isfinite(p.y.hi))) return d.original_xy(p);
  return {X.lo / 2 + X.hi / 2, p.y.lo / 2 + p.y.hi / 2};
}

// Points along a piece, in increasing x (sheared coordinates), for drawing only.
std::vector<XY> piece_polyline(const Diagram& d, const oracle::Branch& b, const oracle::LocatedPoint& l,
                               const oracle::LocatedPoint& r) {
  const double s = d.shear.convert_to<double>();
  const auto [lx, ly] = std::pair{(l.x.lo + l.x.hi) / 2, (l.y.lo + l.y.hi) / 2};
  const auto [rx, ry] = std::pair{(r.x.lo + r.x.hi) / 2, (r.y.lo + r.y.hi) / 2};
  const auto& G = b.curve;
  const double a = G.a.convert_to<double>(), bb = G.b.convert_to<double>(), c = G.c.convert_to<double>();
  const double dd = G.d.convert_to<double>(), e = G.e.convert_to<double>(), f = G.f.convert_to<double>();
  std::vector<XY> out{{lx - s * ly, ly}};
  constexpr int steps = 32;
  for (int i = 1; i < steps; ++i) {
    const double x = lx + (rx - lx) * i / steps;
    double y;
    if (b.side == 0) {
      y = -(dd * x + f) / e;
    } else {
      const double B = bb * x + e, C = a * x * x + dd * x + f;
      const double disc = std::max(0.0, B * B - 4 * c * C);
      const double r1 = (-B - std::sqrt(disc)) / (2 * c), r2 = (-B + std::sqrt(disc)) / (2 * c);
      y = b.side > 0 ? std::max(r1, r2) : std::min(r1, r2);
    }
    out.push_back({x - s * y, y});
  }
  out.push_back({rx - s * ry, ry});
  return out;
}

// The points along a half-edge in walking order.
std::vector<XY> half_edge_polyline(const Diagram& d, const oracle::HalfEdge& h) {
  std::vector<XY> out;
  if (h.boundary >= 0) {
    for (int n : {d.boundary[h.boundary].from, d.boundary[h.boundary].to}) {
      const auto [x, y] = drawn_xy(d, d.nodes[n].at);
      out.push_back({x, y});
    }
    return out;
  }
  const oracle::Arc& a = d.arcs[h.arc];
  const int n = static_cast<int>(a.pieces.size());
  for (int k = 0; k < n; ++k) {
    const int p = h.reversed ? n - 1 - k : k;
    std::vector<XY> pts = piece_polyline(d, a.pieces[p].branch, *a.pieces[p].left_point, *a.pieces[p].right_point);
    if (a.forward[p] == h.reversed) std::reverse(pts.begin(), pts.end());
    out.insert(out.end(), pts.begin(), pts.end());
  }
  return out;
}

std::string colour_of_site(int s) {
  std::ostringstream o;
  o << "hsl(" << (s * 137) % 360 << ",60%,88%)";
  return o.str();
}

}  // namespace

std::string diagram_svg(const Diagram& d, const std::string& caption) {
  geometry::Polygon<double> frame;
  for (const auto& p : d.input.domain) frame.push_back({p.x.convert_to<double>(), p.y.convert_to<double>()});
  const Canvas canvas(frame, 0.04);
  auto X = [&](double x) { return canvas.X(x); };
  auto Y = [&](double y) { return canvas.Y(y); };
  const double size = canvas.size(), px = canvas.scale(), H = canvas.height();
  std::ostringstream o;
  o.precision(7);
  canvas.open(o, caption.empty() ? 40 : 56);
  o << "<defs><pattern id=\"hatch\" width=\"6\" height=\"6\" patternUnits=\"userSpaceOnUse\" "
       "patternTransform=\"rotate(45)\"><rect width=\"6\" height=\"6\" fill=\"#fbd5d5\"/>"
       "<line x1=\"0\" y1=\"0\" x2=\"0\" y2=\"6\" stroke=\"#d62728\" stroke-width=\"2\"/></pattern></defs>\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  auto path_of = [&](const std::vector<XY>& pts) {
    std::ostringstream p;
    p.precision(7);
    for (std::size_t i = 0; i < pts.size(); ++i) p << (i ? " L" : "M") << X(pts[i].x) << " " << Y(pts[i].y);
    return p.str();
  };
  // Faces: tinted by site, orphans hatched.
  for (const auto& f : d.faces) {
    std::string path;
    for (int c : [&] { std::vector<int> cs{f.outer_cycle}; cs.insert(cs.end(), f.holes.begin(), f.holes.end()); return cs; }()) {
      std::vector<XY> pts;
      for (int h : d.cycles[c].half_edges) {
        const auto seg = half_edge_polyline(d, d.half_edges[h]);
        pts.insert(pts.end(), seg.begin(), seg.end());
      }
      path += path_of(pts) + " Z ";
    }
    o << "<path d=\"" << path << "\" fill-rule=\"evenodd\" fill=\""
      << (f.orphan ? "url(#hatch)" : colour_of_site(f.site)) << "\" stroke=\"none\"/>\n";
  }
  // The domain.
  o << "<polygon fill=\"none\" stroke=\"black\" stroke-width=\"1.5\" points=\"";
  for (const auto& p : d.input.domain) o << X(p.x.convert_to<double>()) << "," << Y(p.y.convert_to<double>()) << " ";
  o << "\"/>\n";
  // The dual.
  for (const auto* cells : {&d.dual_triangles, &d.dual_polygons})
    for (const auto& c : *cells) {
      o << "<polygon fill=\"none\" stroke=\"#2ca02c\" stroke-width=\"0.8\" stroke-dasharray=\"3,2\" points=\"";
      for (int s : c.sites)
        o << X(d.input.sites[s].x.convert_to<double>()) << "," << Y(d.input.sites[s].y.convert_to<double>()) << " ";
      o << "\"/>\n";
    }
  // Arcs.
  for (std::size_t i = 0; i < d.arcs.size(); ++i) {
    const auto& a = d.arcs[i];
    oracle::HalfEdge h{static_cast<int>(i)};
    o << "<path d=\"" << path_of(half_edge_polyline(d, h)) << (a.closed ? " Z" : "") << "\" fill=\"none\" stroke=\""
      << (a.wedged ? "#1f4e9c" : "#d62728") << "\" stroke-width=\"" << (a.wedged ? 1.4 : 2.4) << "\"><title>arc " << i
      << " of sites " << a.v << ", " << a.w << (a.wedged ? "" : ", not wedged") << "</title></path>\n";
    if (a.witness) {
      const auto [x, y] = drawn_xy(d, *a.witness);
      o << "<circle cx=\"" << X(x) << "\" cy=\"" << Y(y) << "\" r=\"4\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"1.5\"/>\n";
    }
  }
  // Sites with their metric ellipses {p : (p − v)ᵀ M (p − v) = r²}, one r for all sites.
  double longest = 0;
  std::vector<std::array<double, 3>> axes;  // semi-axis 1, semi-axis 2, angle (degrees)
  for (const auto& M : d.input.metrics) {
    const double a = M.m11.convert_to<double>(), b = M.m12.convert_to<double>(), c = M.m22.convert_to<double>();
    const double mean = (a + c) / 2, dev = std::hypot((a - c) / 2, b);
    const double l1 = mean + dev, l2 = std::max(mean - dev, 1e-300);
    const double angle = 0.5 * std::atan2(2 * b, a - c) * 180 / M_PI;
    axes.push_back({1 / std::sqrt(l1), 1 / std::sqrt(l2), angle});
    longest = std::max(longest, 1 / std::sqrt(l2));
  }
  const double r = longest > 0 ? size * 0.03 / longest : 0;
  for (std::size_t i = 0; i < d.input.sites.size(); ++i) {
    const double x = X(d.input.sites[i].x.convert_to<double>()), y = Y(d.input.sites[i].y.convert_to<double>());
    o << "<ellipse cx=\"" << x << "\" cy=\"" << y << "\" rx=\"" << axes[i][0] * r * px << "\" ry=\"" << axes[i][1] * r * px
      << "\" transform=\"rotate(" << -axes[i][2] << " " << x << " " << y
      << ")\" fill=\"none\" stroke=\"#555\" stroke-width=\"0.8\"/>\n"
      << "<circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"2.2\" fill=\"black\"><title>site " << i << "</title></circle>\n";
  }
  // Vertices.
  for (std::size_t i = 0; i < d.nodes.size(); ++i) {
    const auto& n = d.nodes[i];
    if (n.sites.size() < 3) continue;
    const auto [x, y] = drawn_xy(d, n.at);
    o << "<circle cx=\"" << X(x) << "\" cy=\"" << Y(y) << "\" r=\"2.5\" fill=\"" << (n.wedged ? "#1f4e9c" : "#d62728")
      << "\"><title>vertex " << i << "</title></circle>\n";
  }
  o << "<text x=\"8\" y=\"" << H + 16 << "\" font-family=\"sans-serif\" font-size=\"12\">"
    << "arcs: wedged (blue), not wedged (red, witness circled); orphans hatched; dual dashed green</text>\n"
    << "<text x=\"8\" y=\"" << H + 32 << "\" font-family=\"sans-serif\" font-size=\"12\">"
    << "sites black with their metric's unit ellipse (common scale); Voronoi vertices dots</text>\n";
  if (!caption.empty())
    o << "<text x=\"8\" y=\"" << H + 48 << "\" font-family=\"sans-serif\" font-size=\"12\">" << xml_text(caption) << "</text>\n";
  o << "</svg>\n";
  return o.str();
}

}  // namespace anisocert::io
