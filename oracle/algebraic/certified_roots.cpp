#include "oracle/algebraic/certified_roots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace anisocert::oracle {
namespace {

using I = FilterInterval;

I square(const I& a) {
  if (a.lo >= 0) return a * a;
  if (a.hi <= 0) return (-a) * (-a);
  const double m = std::max(-a.lo, a.hi);
  return {0, (I(m) * I(m)).hi};
}

bool contains_zero(const I& a) { return !(a.lo > 0 || a.hi < 0); }
I hull(const I& a, const I& b) { return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)}; }
double mid(const I& a) { return a.lo + (a.hi - a.lo) / 2; }
double width(const I& a) { return a.hi - a.lo; }

// A conic in intervals (coefficients enclosed) and in doubles (for Newton's iterates only).
struct Curve {
  I a, b, c, d, e, f;
  I a2, c2;  // 2a and 2c (doubling is exact)
  double ad, bd, cd, dd, ed, fd;
  explicit Curve(const IntervalConic& G)
      : a(G.a), b(G.b), c(G.c), d(G.d), e(G.e), f(G.f), a2(2 * G.a.lo, 2 * G.a.hi), c2(2 * G.c.lo, 2 * G.c.hi),
        ad(mid(G.a)), bd(mid(G.b)), cd(mid(G.c)), dd(mid(G.d)), ed(mid(G.e)), fd(mid(G.f)) {}
  I gx(const I& x, const I& y) const { return a2 * x + b * y + d; }
  I gy(const I& x, const I& y) const { return b * x + c2 * y + e; }
  // The natural interval extension on [x] × [y].
  I natural(const I& x, const I& y) const { return a * square(x) + b * x * y + c * square(y) + d * x + e * y + f; }
  // At a point, in Horner's form (a x + b y + d) x + (c y + e) y + f.
  I at(double x, double y) const { return (a * x + b * y + d) * x + (c * y + e) * y + f; }
  double approx(double x, double y) const { return ad * x * x + bd * x * y + cd * y * y + dd * x + ed * y + fd; }
  double approx_gx(double x, double y) const { return 2 * ad * x + bd * y + dd; }
  double approx_gy(double x, double y) const { return bd * x + 2 * cd * y + ed; }
};

class Solver {
 public:
  Solver(const IntervalConic& A, const IntervalConic& B) : A_(A), B_(B) {}

  bool run(const IntervalBox& search) {
    explore(search, 0);
    return !failed_;
  }
  std::vector<IntervalBox> roots;

 private:
  static constexpr int max_depth = 48;
  static constexpr int max_boxes = 4000;
  // F at a point m of X, and the Jacobian J over X: what the tests on X share.
  struct Linearisation {
    double mx, my;
    I fa, fb, j00, j01, j10, j11;
  };
  Linearisation linearise(const IntervalBox& X) const {
    const double mx = mid(X.x), my = mid(X.y);
    return {mx, my, A_.at(mx, my), B_.at(mx, my), A_.gx(X.x, X.y), A_.gy(X.x, X.y), B_.gx(X.x, X.y), B_.gy(X.x, X.y)};
  }

  // 0 ∉ det J(H): F is one-to-one on H.
  static bool regular(const Linearisation& L) { return !contains_zero(L.j00 * L.j11 - L.j01 * L.j10); }
  bool injective_on(const IntervalBox& H) const { return regular(linearise(H)); }

  // 0 ∉ A(X) or 0 ∉ B(X), by the mean value form F(m) + J(X)(X − m) (each component's gradient
  // at some point of the segment, which lies in X), then by the natural extension.
  bool excluded(const IntervalBox& X, const Linearisation& L) const {
    const I dx = X.x - I(L.mx), dy = X.y - I(L.my);
    if (!contains_zero(L.fa + L.j00 * dx + L.j01 * dy) || !contains_zero(L.fb + L.j10 * dx + L.j11 * dy)) return true;
    return !contains_zero(A_.natural(X.x, X.y)) || !contains_zero(B_.natural(X.x, X.y));
  }

  // K(X) at the centre with C the inverse of the Jacobian of the doubles there, if C exists and
  // K(X) is finite.
  std::optional<IntervalBox> krawczyk_image(const IntervalBox& X, const Linearisation& L) const {
    const double mx = L.mx, my = L.my;
    const double a00 = A_.approx_gx(mx, my), a01 = A_.approx_gy(mx, my), a10 = B_.approx_gx(mx, my),
                 a11 = B_.approx_gy(mx, my);
    const double det = a00 * a11 - a01 * a10;
    if (!(std::abs(det) > 0) || !std::isfinite(det)) return std::nullopt;
    const double c00 = a11 / det, c01 = -a01 / det, c10 = -a10 / det, c11 = a00 / det;
    const I m00 = I(1) - (c00 * L.j00 + c01 * L.j10), m01 = -(c00 * L.j01 + c01 * L.j11);
    const I m10 = -(c10 * L.j00 + c11 * L.j10), m11 = I(1) - (c10 * L.j01 + c11 * L.j11);
    const I dx = X.x - I(mx), dy = X.y - I(my);
    const I kx = I(mx) - (c00 * L.fa + c01 * L.fb) + m00 * dx + m01 * dy;
    const I ky = I(my) - (c10 * L.fa + c11 * L.fb) + m10 * dx + m11 * dy;
    if (!std::isfinite(kx.lo) || !std::isfinite(kx.hi) || !std::isfinite(ky.lo) || !std::isfinite(ky.hi))
      return std::nullopt;
    return IntervalBox{kx, ky};
  }

  enum class Krawczyk { none, unique, undecided };
  // Krawczyk's test on X; `out` receives K(X) ∩ X.
  Krawczyk krawczyk(const IntervalBox& X, IntervalBox& out) const { return krawczyk(X, linearise(X), out); }
  Krawczyk krawczyk(const IntervalBox& X, const Linearisation& L, IntervalBox& out) const {
    const std::optional<IntervalBox> K = krawczyk_image(X, L);
    if (!K) return Krawczyk::undecided;
    const I &kx = K->x, &ky = K->y;
    if (kx.hi < X.x.lo || X.x.hi < kx.lo || ky.hi < X.y.lo || X.y.hi < ky.lo) return Krawczyk::none;
    out = {{std::max(kx.lo, X.x.lo), std::min(kx.hi, X.x.hi)}, {std::max(ky.lo, X.y.lo), std::min(ky.hi, X.y.hi)}};
    if (kx.lo > X.x.lo && kx.hi < X.x.hi && ky.lo > X.y.lo && ky.hi < X.y.hi) return Krawczyk::unique;
    return Krawczyk::undecided;
  }

  // Narrows a box holding a unique root by iterating K (each K(X) ∩ X holds the root).
  IntervalBox tighten(IntervalBox X) const {
    for (int k = 0; k < 6; ++k) {
      IntervalBox next;
      if (krawczyk(X, next) == Krawczyk::none) break;  // cannot happen for a box holding a root
      if (width(next.x) >= width(X.x) && width(next.y) >= width(X.y)) break;
      X = next;
    }
    return X;
  }

  // A root in a small box around Newton's iterate from X's centre, if Krawczyk proves one.
  // Newton's steps in doubles shrink until rounding dominates them; the iteration stops at the
  // first step that does not shrink (or moves nothing). Where it stops decides only where a
  // certification is tried; what is returned is proved by Krawczyk's test.
  std::optional<IntervalBox> newton_root(const IntervalBox& X) const {
    double x = mid(X.x), y = mid(X.y);
    double last_step = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 24; ++k) {
      const double fa = A_.approx(x, y), fb = B_.approx(x, y);
      const double a00 = A_.approx_gx(x, y), a01 = A_.approx_gy(x, y), a10 = B_.approx_gx(x, y), a11 = B_.approx_gy(x, y);
      const double det = a00 * a11 - a01 * a10;
      if (!(std::abs(det) > 0) || !std::isfinite(det)) return std::nullopt;
      const double sx = (a11 * fa - a01 * fb) / det, sy = (a00 * fb - a10 * fa) / det;
      const double step = std::max(std::abs(sx), std::abs(sy));
      if (!(step < last_step)) break;
      last_step = step;
      x -= sx, y -= sy;
      if (!std::isfinite(x) || !std::isfinite(y)) return std::nullopt;
    }
    // Outside X's neighbourhood the root says nothing about X.
    if (x < X.x.lo - width(X.x) || x > X.x.hi + width(X.x) || y < X.y.lo - width(X.y) || y > X.y.hi + width(X.y))
      return std::nullopt;
    // The trial box Y = x̃ ± r (Rump's ε-inflation): K({x̃}) = x̃ − C·F(x̃) is one more Newton step
    // in intervals, enclosing the remaining correction δ and the rounding of F(x̃). Then
    // K(Y) = K({x̃}) + (I − C·J(Y))·(Y − x̃) lies within δ + ‖I − C·J(Y)‖·r of x̃, inside Y when
    // r = 2δ and the contraction ‖I − C·J(Y)‖ is below 1/2. Y's ends are rounded outward to the
    // next doubles, so Y is not a point even when F(x̃) encloses 0 exactly.
    const IntervalBox point{I(x), I(y)};
    const std::optional<IntervalBox> step = krawczyk_image(point, linearise(point));
    if (!step) return std::nullopt;
    const double r = 2 * std::max({x - step->x.lo, step->x.hi - x, y - step->y.lo, step->y.hi - y});
    constexpr double inf = std::numeric_limits<double>::infinity();
    const IntervalBox Y{{std::nextafter(x - r, -inf), std::nextafter(x + r, inf)},
                        {std::nextafter(y - r, -inf), std::nextafter(y + r, inf)}};
    IntervalBox K;
    if (krawczyk(Y, K) != Krawczyk::unique) return std::nullopt;
    return K;
  }

  void record(const IntervalBox& R) {
    for (IntervalBox& E : roots) {
      const bool apart = E.x.hi < R.x.lo || R.x.hi < E.x.lo || E.y.hi < R.y.lo || R.y.hi < E.y.lo;
      if (apart) continue;
      if (!injective_on({hull(E.x, R.x), hull(E.y, R.y)})) {
        failed_ = true;
        return;
      }
      E = {{std::max(E.x.lo, R.x.lo), std::min(E.x.hi, R.x.hi)}, {std::max(E.y.lo, R.y.lo), std::min(E.y.hi, R.y.hi)}};
      return;
    }
    roots.push_back(R);
  }

  void explore(const IntervalBox& X, int depth) {
    if (failed_) return;
    if (++boxes_ > max_boxes) {
      failed_ = true;
      return;
    }
    const Linearisation L = linearise(X);
    if (excluded(X, L)) return;
    IntervalBox K;
    const Krawczyk k = krawczyk(X, L, K);
    if (k == Krawczyk::none) return;
    if (k == Krawczyk::unique) {
      record(tighten(K));
      return;
    }
    if (regular(L))
      if (const auto Y = newton_root(X); Y && injective_on({hull(X.x, Y->x), hull(X.y, Y->y)})) {
        record(tighten(*Y));  // the only root in X ∪ Y (X may hold none)
        return;
      }
    if (depth >= max_depth || !(width(X.x) > 0 && width(X.y) > 0)) {
      failed_ = true;
      return;
    }
    // Halves share their split line, so they cover X.
    if (width(X.x) >= width(X.y)) {
      const double m = mid(X.x);
      explore({{X.x.lo, m}, X.y}, depth + 1);
      explore({{m, X.x.hi}, X.y}, depth + 1);
    } else {
      const double m = mid(X.y);
      explore({X.x, {X.y.lo, m}}, depth + 1);
      explore({X.x, {m, X.y.hi}}, depth + 1);
    }
  }

  Curve A_, B_;
  int boxes_ = 0;
  bool failed_ = false;
};

}  // namespace

IntervalConic IntervalConic::around(const Conic& G) {
  return {I::around(G.a), I::around(G.b), I::around(G.c), I::around(G.d), I::around(G.e), I::around(G.f)};
}

std::optional<std::vector<IntervalBox>> certified_common_roots(const IntervalConic& A, const IntervalConic& B,
                                                               const IntervalBox& search) {
  if (!(std::isfinite(search.x.lo) && std::isfinite(search.x.hi) && std::isfinite(search.y.lo) && std::isfinite(search.y.hi)))
    return std::nullopt;
  Solver s(A, B);
  if (!s.run(search)) return std::nullopt;
  return std::move(s.roots);
}

}  // namespace anisocert::oracle
