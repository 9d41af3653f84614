#include "fields/p1_enclosure.hpp"

#include <cmath>

namespace anisocert::fields {

using FI = FilterInterval;

P1Gradient p1_gradient(const Point2<FI>& a, const Point2<FI>& b, const Point2<FI>& c, const Sym2<FI>& Ma, const Sym2<FI>& Mb,
                       const Sym2<FI>& Mc) {
  const FI bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y, area = bx * cy - by * cx;
  P1Gradient g;
  for (FI Sym2<FI>::*m : {&Sym2<FI>::m11, &Sym2<FI>::m12, &Sym2<FI>::m22}) {
    const FI fb = Mb.*m - Ma.*m, fc = Mc.*m - Ma.*m;
    g.dx.*m = (fb * cy - fc * by) / area;
    g.dy.*m = (fc * bx - fb * cx) / area;
  }
  return g;
}

Sym2<FI> p1_value(const Point2<FI>& a, const Sym2<FI>& Ma, const P1Gradient& g, const Point2<FI>& p) {
  const FI dx = p.x - a.x, dy = p.y - a.y;
  Sym2<FI> M;
  for (FI Sym2<FI>::*m : {&Sym2<FI>::m11, &Sym2<FI>::m12, &Sym2<FI>::m22}) M.*m = Ma.*m + g.dx.*m * dx + g.dy.*m * dy;
  return M;
}

std::optional<Sym2<double>> tight_midpoints(const Sym2<FI>& M) {
  constexpr double width = 0x1p-40;
  const auto narrow = [](const FI& i, double scale) { return i.hi - i.lo <= width * scale; };
  const auto mid = [](const FI& i) { return i.lo + (i.hi - i.lo) / 2; };
  if (!(M.m11.lo > 0 && M.m22.lo > 0 && narrow(M.m11, M.m11.lo) && narrow(M.m22, M.m22.lo) &&
        narrow(M.m12, std::sqrt(M.m11.lo * M.m22.lo))))
    return std::nullopt;
  return Sym2<double>{mid(M.m11), mid(M.m12), mid(M.m22)};
}

}  // namespace anisocert::fields
