#pragma once
// Signs at the points the refiners' decisions are made at: double points (each the rational it
// denotes) and Voronoi vertices (voronoi_vertex.hpp). A sign of f(p₁, …, p_N) is read from the
// points' double boxes when that decides it; else exactly, when every point is rational (a double
// point, or a vertex of three equal metrics); else from the points enclosed at 128, 256, 512 and
// 1024 bits (MPFI). A sign none of these decides is undecided: the value is zero, or too close to
// it. The caller treats that as a degeneracy and never guesses (DESIGN.md: exact means exact).

#include "numbers/sign.hpp"
#include "refiners/common/voronoi_vertex.hpp"

#include <optional>
#include <utility>

namespace anisocert::refiners::common {

class CertifiedPoint {
 public:
  explicit CertifiedPoint(const Point2<double>& p) : box_{FilterInterval(p.x), FilterInterval(p.y)}, point_(p) {}
  CertifiedPoint(const Trio& t, const VertexBox& v) : box_(v.box), trio_(t), vertex_(v) {}

  const Box2<FilterInterval>& box() const { return box_; }
  Box2<Interval> box(mpfr_prec_t bits) const {
    if (!vertex_) return {Interval(point_.x, bits), Interval(point_.y, bits)};
    return enclose(trio_, *vertex_, bits);
  }
  std::optional<Point2<Rational>> exact() const {
    if (!vertex_) return Point2<Rational>{Rational(point_.x), Rational(point_.y)};
    return rational_vertex(trio_);
  }

 private:
  Box2<FilterInterval> box_;
  Point2<double> point_{0, 0};
  Trio trio_{};
  std::optional<VertexBox> vertex_;
};

// sign(f(p, of)) for points p (a std::array of N boxes in one number type T) and of(d), the T
// that denotes the double d. f is called with FilterInterval, Rational and Interval.
template <std::size_t N, class F>
std::optional<Sign> sign_at(const std::array<const CertifiedPoint*, N>& points, F f) {
  {
    std::array<Box2<FilterInterval>, N> b;
    for (std::size_t i = 0; i < N; ++i) b[i] = points[i]->box();
    if (auto s = f(b, [](double d) { return FilterInterval(d); }).sign()) return s;
  }
  {
    std::array<Box2<Rational>, N> b;
    bool rational = true;
    for (std::size_t i = 0; i < N && rational; ++i) {
      const auto e = points[i]->exact();
      rational = e.has_value();
      if (rational) b[i] = {e->x, e->y};
    }
    if (rational) return sign_of(f(b, [](double d) { return Rational(d); }));
  }
  for (mpfr_prec_t bits = 128; bits <= 1024; bits *= 2) {
    const auto b = [&]<std::size_t... I>(std::index_sequence<I...>) {
      return std::array<Box2<Interval>, N>{points[I]->box(bits)...};
    }(std::make_index_sequence<N>{});
    const Interval value = f(b, [bits](double d) { return Interval(d, bits); });
    if (value.certainly_positive()) return Sign::positive;
    if (value.certainly_negative()) return Sign::negative;
  }
  return std::nullopt;
}

}  // namespace anisocert::refiners::common
