#pragma once
// A second, independent exact engine for conic-conic intersections, used only by tests:
// FLINT's multivariate resultants and Calcium's qqbar (exact algebraic numbers with minimal
// polynomials). Candidates are the pairs (x, y) of roots of Res_y and Res_x, kept when both
// conics evaluate exactly to zero there (complex points included); the multiplicity of a point
// is that of x + t·y as a root of the resultant after the shear x → x − t·y, for an integer t
// that separates all complex common points. It shares no code with oracle/.

#include "oracle/algebraic/bivariate.hpp"

#include "oracle/algebraic/real_algebraic.hpp"

#include <memory>
#include <vector>

namespace anisocert::second_engine {

// An exact algebraic number of Calcium (opaque here: Calcium's headers are not C++-clean, so
// only calcium_shim.c, compiled as C, includes them).
struct QNumber;
using QNumberPtr = std::shared_ptr<const QNumber>;

struct QPoint {
  QNumberPtr x, y;
  int multiplicity = 0;
};

struct QIntersection {
  bool shared_component = false;
  std::vector<QPoint> points;  // real points, sorted by x then y
};

QIntersection intersect(const oracle::Conic& A, const oracle::Conic& B);
int sign_at(const oracle::Bivariate& f, const QPoint& p);  // −1, 0, 1
int compare_x(const QPoint& p, const QPoint& q);
int compare_y(const QPoint& p, const QPoint& q);
// q equals the oracle's number: a root of its defining polynomial inside its isolating interval.
bool equals(const QNumberPtr& q, const oracle::RealAlgebraic& ours);

}  // namespace anisocert::second_engine
