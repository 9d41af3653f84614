#pragma once
// Metric tensors: symmetric positive definite matrices with rational entries, checked exactly
// at construction (LS §2: M_p symmetric positive definite).

#include "predicates/point.hpp"
#include "numbers/sign.hpp"

#include <optional>
#include <stdexcept>

namespace anisocert::predicates {

// What() names the matrix and the pivot of LDLᵀ (equivalently the leading principal minor)
// that is not positive.
struct NotPositiveDefinite : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// M = L D Lᵀ, L unit lower triangular, D = diag(d): d₁ = m11, d₂ = det₂ / m11, d₃ = det₃ / det₂.
struct LDLt2 {
  Rational l21, d1, d2;
};
struct LDLt3 {
  Rational l21, l31, l32, d1, d2, d3;
};

// Whether m is symmetric positive definite, exactly: m11 > 0 and m11 m22 − m12² > 0 (what Metric2
// requires, as a test for readers that name the place themselves).
bool positive_definite(const Sym2<Rational>& m);
// The same for a 3×3 matrix by Sylvester's criterion: m11 > 0, m11 m22 − m12² > 0 and det > 0 (the
// determinant alone is not enough: diag(−1, −1, 1) has det 1).
bool positive_definite(const Sym3<Rational>& m);
Rational determinant(const Sym3<Rational>& m);

class Metric2 {
 public:
  // Throws NotPositiveDefinite.
  explicit Metric2(const Sym2<Rational>& m);
  // Each double is taken as the rational it denotes; NaN or infinity throws NumberSyntaxError.
  static Metric2 from_doubles(double m11, double m12, double m22);

  const Sym2<Rational>& entries() const { return m_; }
  Rational determinant() const;
  LDLt2 ldlt() const;
  // xᵀ M x.
  Rational quadratic_form(const Rational& dx, const Rational& dy) const;
  // LS §9's normalized metric M' = det(M)^(−1/2) M, when det(M) is the square of a rational.
  std::optional<Metric2> normalized() const;

 private:
  Sym2<Rational> m_;
};

class Metric3 {
 public:
  explicit Metric3(const Sym3<Rational>& m);
  const Sym3<Rational>& entries() const { return m_; }
  Rational determinant() const;
  LDLt3 ldlt() const;
  Rational quadratic_form(const Rational& dx, const Rational& dy, const Rational& dz) const;
  // M' = det(M)^(−1/3) M, when det(M) is the cube of a rational.
  std::optional<Metric3> normalized() const;

 private:
  Sym3<Rational> m_;
};

// LS §9 variant: the diagram of the normalized metrics M'_v = det(M_v)^(−1/2) M_v, decided
// without the irrational roots: sign(d'_v(q)² − d'_w(q)²) = sign(Q_v² det M_w − Q_w² det M_v)
// with Q_v = (q − v)ᵀ M_v (q − v) >= 0 (both sides squared are non-negative).
Sign side_of_normalized_bisector(const Point2<Rational>& q, const Point2<Rational>& v, const Metric2& Mv,
                                 const Point2<Rational>& w, const Metric2& Mw);

}  // namespace anisocert::predicates
