#include "oracle/algebraic/bivariate.hpp"

#include <algorithm>

namespace anisocert::oracle {

Bivariate& Bivariate::add(int i, int j, const Rational& c) {
  Rational& t = terms[{i, j}];
  t += c;
  if (t == 0) terms.erase({i, j});
  return *this;
}

int Bivariate::degree_x() const {
  int d = -1;
  for (const auto& [ij, c] : terms) d = std::max(d, ij.first);
  return d;
}

int Bivariate::degree_y() const {
  int d = -1;
  for (const auto& [ij, c] : terms) d = std::max(d, ij.second);
  return d;
}

Bivariate Conic::polynomial() const {
  Bivariate p;
  p.add(2, 0, a).add(1, 1, b).add(0, 2, c).add(1, 0, d).add(0, 1, e).add(0, 0, f);
  return p;
}

Conic line_conic(const predicates::Point2<Rational>& a, const predicates::Point2<Rational>& b) {
  // orient(a, b, p) = (bx − ax)(py − ay) − (by − ay)(px − ax)
  const Rational dx = b.x - a.x, dy = b.y - a.y;
  return {0, 0, 0, -dy, dx, dy * a.x - dx * a.y};
}

}  // namespace anisocert::oracle
