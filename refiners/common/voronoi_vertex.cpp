#include "refiners/common/voronoi_vertex.hpp"

#include "predicates/orientation.hpp"

#include <algorithm>
#include <cmath>

namespace anisocert::refiners::common {
namespace {

using FI = FilterInterval;

Equidistance<FI> in_doubles(const Trio& s) {
  const auto of = [](double d) { return FI(d); };
  return Equidistance<FI>({lift<FI>(s[0], of), lift<FI>(s[1], of), lift<FI>(s[2], of)});
}

bool same_metric(const Sym2<double>& a, const Sym2<double>& b) {
  return a.m11 == b.m11 && a.m12 == b.m12 && a.m22 == b.m22;
}
bool equal_metrics(const Trio& s) { return same_metric(s[0].M, s[1].M) && same_metric(s[0].M, s[2].M); }

bool inside(const Box2<FI>& inner, const Box2<FI>& outer) {
  return inner.x.lo >= outer.x.lo && inner.x.hi <= outer.x.hi && inner.y.lo >= outer.y.lo && inner.y.hi <= outer.y.hi;
}
bool meet(const Box2<FI>& a, const Box2<FI>& b) { return intersection(a.x, b.x) && intersection(a.y, b.y); }
double width(const FI& a) { return a.hi - a.lo; }

// Krawczyk iterated on a box that holds exactly one point, while it shrinks.
Box2<FI> tighten(const Equidistance<FI>& s, Box2<FI> K) {
  for (int i = 0; i < 8; ++i) {
    const KrawczykStep<FI> k = krawczyk(s, K, FI(1.0));
    if (k.verdict == KrawczykVerdict::no_zero) break;  // cannot happen with a point inside: keep K
    const bool shrank = width(k.box.x) < width(K.x) || width(k.box.y) < width(K.y);
    K = k.box;
    if (!shrank) break;
  }
  return K;
}

// Newton's method in doubles from X's midpoint; when it settles within reach of X and not in the
// isolating box of a point already found, a small box around where it lands, certified by
// Krawczyk (the box may reach beyond X). It only speeds the search up: a point it misses is found
// by halving.
std::optional<VertexBox> newton_box(const Trio& t, const Equidistance<FI>& s, const Box2<FI>& X, const std::vector<VertexBox>& found) {
  double x = X.x.midpoint().lo, y = X.y.midpoint().lo, step = 0;
  bool settled = false;
  for (int i = 0; i < 12 && !settled; ++i) {
    const auto qa = [&](int k) {
      const double dx = x - t[k].p.x, dy = y - t[k].p.y;
      return dx * (t[k].M.m11 * dx + t[k].M.m12 * dy) + dy * (t[k].M.m12 * dx + t[k].M.m22 * dy);
    };
    const auto g = [&](int k) {
      const double dx = x - t[k].p.x, dy = y - t[k].p.y;
      return std::array<double, 2>{t[k].M.m11 * dx + t[k].M.m12 * dy, t[k].M.m12 * dx + t[k].M.m22 * dy};
    };
    const double f0 = (qa(0) - qa(1)) / 2, f1 = (qa(0) - qa(2)) / 2;
    const auto ga = g(0), gb = g(1), gc = g(2);
    const double a = ga[0] - gb[0], b = ga[1] - gb[1], c = ga[0] - gc[0], d = ga[1] - gc[1], det = a * d - b * c;
    if (!(std::abs(det) > 0) || !std::isfinite(det)) return std::nullopt;
    const double sx = (d * f0 - b * f1) / det, sy = (a * f1 - c * f0) / det;
    x -= sx;
    y -= sy;
    step = std::max(std::abs(sx), std::abs(sy));
    settled = step <= 0x1p-50 * (std::abs(x) + std::abs(y)) || step == 0;
  }
  if (!std::isfinite(x) || !std::isfinite(y)) return std::nullopt;
  const double reach_x = width(X.x), reach_y = width(X.y);
  if (x < X.x.lo - reach_x || x > X.x.hi + reach_x || y < X.y.lo - reach_y || y > X.y.hi + reach_y) return std::nullopt;
  const auto isolated = [x, y](const VertexBox& v) { return v.isolating.x.lo <= x && x <= v.isolating.x.hi && v.isolating.y.lo <= y && y <= v.isolating.y.hi; };
  if (std::any_of(found.begin(), found.end(), isolated)) return std::nullopt;
  double r = 8 * step + 0x1p-44 * (std::abs(x) + std::abs(y)) + 0x1p-1000;
  for (int attempt = 0; attempt < 3; ++attempt, r *= 1024) {
    const Box2<FI> R{FI::widen(x - r, x + r), FI::widen(y - r, y + r)};
    const KrawczykStep<FI> k = krawczyk(s, R, FI(1.0));
    if (k.verdict == KrawczykVerdict::no_zero) return std::nullopt;
    if (k.verdict != KrawczykVerdict::unique_zero) continue;
    // Isolate it in as large a box as Krawczyk certifies (fewer boxes to search, and a box
    // another search finds this vertex in is more likely to lie inside it): tried from the
    // search box's width down, so that the first try usually covers all of X and ends its search.
    Box2<FI> isolating = R;
    const double widest = std::min(0x1p-10 * (1 + std::abs(x) + std::abs(y)), std::max(width(X.x), width(X.y)));
    for (double grown = widest; grown > 8 * r; grown /= 16) {
      const Box2<FI> G{FI::widen(x - grown, x + grown), FI::widen(y - grown, y + grown)};
      if (krawczyk(s, G, FI(1.0)).verdict != KrawczykVerdict::unique_zero) continue;
      isolating = G;
      break;
    }
    return VertexBox{tighten(s, k.box), isolating};
  }
  return std::nullopt;
}

Box2<FI> hull(const Box2<FI>& a, const Box2<FI>& b) {
  return {{std::min(a.x.lo, b.x.lo), std::max(a.x.hi, b.x.hi)}, {std::min(a.y.lo, b.y.lo), std::max(a.y.hi, b.y.hi)}};
}

// Whether det ½J vanishes identically: each coefficient's box holds 0 (most trios are told apart
// here), then every coefficient is 0 in rationals.
bool singular_everywhere(const Trio& t, const Equidistance<FI>& s) {
  const auto near_zero = s.jacobian_determinant();
  if (std::any_of(near_zero.begin(), near_zero.end(), [](const FI& c) { return !c.has_zero(); })) return false;
  const auto of = [](double d) { return Rational(d); };
  const Equidistance<Rational> exact({lift<Rational>(t[0], of), lift<Rational>(t[1], of), lift<Rational>(t[2], of)});
  const auto c = exact.jacobian_determinant();
  return std::all_of(c.begin(), c.end(), [](const Rational& x) { return x == 0; });
}

// Y halved across x when along_x, else across y (the other side when no double splits that one);
// nothing when no double splits either.
std::optional<std::array<Box2<FI>, 2>> halved(const Box2<FI>& Y, bool along_x) {
  const auto splits = [](const FI& side) {
    const double m = side.midpoint().lo;
    return m > side.lo && m < side.hi;
  };
  if (!splits(along_x ? Y.x : Y.y)) along_x = !along_x;
  const FI& side = along_x ? Y.x : Y.y;
  if (!splits(side)) return std::nullopt;
  const double m = side.midpoint().lo;
  if (along_x) return std::array<Box2<FI>, 2>{Box2<FI>{FI(side.lo, m), Y.y}, Box2<FI>{FI(m, side.hi), Y.y}};
  return std::array<Box2<FI>, 2>{Box2<FI>{Y.x, FI(side.lo, m)}, Box2<FI>{Y.x, FI(m, side.hi)}};
}

// Whether F has no zero in X, shown by the centred form on X or on the parts of X halved up to
// `budget` boxes (counted in `boxes`). Each part is halved across the side along which F changes
// more (|∂F/∂x| times the width against |∂F/∂y| times the height, ½J enclosed over the part; the
// wider side when they tie): for three sites on a line x = c with metrics diag(a, dᵢ), F depends
// on y alone, and halving across x as well would spend the budget on splits that change nothing
// (lines 6·10⁻⁶ apart in a box 4 high needed more than 256 boxes that way). Over the part, not at
// its midpoint, where both ∂F/∂y can vanish (sites at y = 0, 1, 1.5, midpoint y = 2): the choice
// then rests on the rounding of F's derivatives at one point.
bool excluded(const Equidistance<FI>& s, const Box2<FI>& X, int budget, int& boxes) {
  std::vector<Box2<FI>> pending{X};
  for (; !pending.empty(); ++boxes) {
    if (boxes >= budget) return false;
    const Box2<FI> Y = pending.back();
    pending.pop_back();
    const auto F = s.on(Y);
    if (!F[0].has_zero() || !F[1].has_zero()) continue;
    const FI mx = Y.x.midpoint(), my = Y.y.midpoint();
    const auto J = s.half_jacobian(s.half_jacobian(mx, my), Y.x - mx, Y.y - my);
    const auto magnitude = [](const FI& v) { return std::max(std::abs(v.lo), std::abs(v.hi)); };
    const double across_x = (magnitude(J[0]) + magnitude(J[2])) * width(Y.x), across_y = (magnitude(J[1]) + magnitude(J[3])) * width(Y.y);
    const bool tie = !(across_x < across_y) && !(across_x > across_y);  // equal, or a NaN
    const auto halves = halved(Y, tie ? width(Y.x) >= width(Y.y) : across_x > across_y);
    if (!halves) return false;
    pending.insert(pending.end(), halves->begin(), halves->end());
  }
  return true;
}

// Adds a certified vertex unless it is one already found; false when that cannot be decided.
// Two boxes that meet hold the same point when one lies in the other's isolating box, or when
// Krawczyk proves the hull of their isolating boxes holds a single point.
bool add(const Equidistance<FI>& s, std::vector<VertexBox>& found, const VertexBox& v) {
  for (const VertexBox& u : found) {
    std::optional<bool> same = same_vertex(u, v);
    if (!same && krawczyk(s, hull(u.isolating, v.isolating), FI(1.0)).verdict == KrawczykVerdict::unique_zero) same = true;
    if (!same) return false;
    if (*same) return true;
  }
  found.push_back(v);
  return true;
}

}  // namespace

std::optional<bool> same_vertex(const VertexBox& u, const VertexBox& v) {
  if (!meet(u.box, v.box)) return false;
  if (inside(v.box, u.isolating) || inside(u.box, v.isolating)) return true;
  return std::nullopt;
}

VertexSearch vertices_in(const Trio& t, const Box2<FilterInterval>& search, int budget) {
  VertexSearch out;
  const auto same_point = [&](int i, int j) { return t[i].p.x == t[j].p.x && t[i].p.y == t[j].p.y; };
  if (equal_metrics(t) && predicates::orientation(t[0].p, t[1].p, t[2].p) == Sign::zero) {
    // Distinct collinear sites: the bisectors are parallel lines, no point is equidistant. Two
    // sites that coincide: a whole line is, and no finite list of points answers.
    out.complete = !(same_point(0, 1) || same_point(0, 2) || same_point(1, 2));
    return out;
  }
  const Equidistance<FI> s = in_doubles(t);
  if (singular_everywhere(t, s)) {
    out.singular = true;
    out.complete = excluded(s, search, std::min(budget, 256), out.boxes);
    return out;
  }
  std::vector<Box2<FI>> pending{search};
  const auto undecided = [&out] {
    out.complete = false;
    return out;
  };
  for (; !pending.empty(); ++out.boxes) {
    if (out.boxes >= budget) return undecided();
    const Box2<FI> X = pending.back();
    pending.pop_back();
    if (std::any_of(out.vertices.begin(), out.vertices.end(), [&X](const VertexBox& v) { return inside(X, v.isolating); }))
      continue;  // at most the point already found
    const auto F = s.on(X);
    if (!F[0].has_zero() || !F[1].has_zero()) continue;
    const KrawczykStep<FI> k = krawczyk(s, X, FI(1.0));
    if (k.verdict == KrawczykVerdict::no_zero) continue;
    if (k.verdict == KrawczykVerdict::unique_zero) {
      if (!add(s, out.vertices, {tighten(s, k.box), X})) return undecided();
      continue;
    }
    if (auto v = newton_box(t, s, X, out.vertices))
      if (!add(s, out.vertices, *v)) return undecided();
    // K(X) ∩ X halved across its wider side; a box that no double splits ends the search undecided.
    const auto halves = halved(k.box, width(k.box.x) >= width(k.box.y));
    if (!halves) return undecided();
    pending.insert(pending.end(), halves->begin(), halves->end());
  }
  return out;
}

Box2<Interval> enclose(const Trio& t, const VertexBox& v, mpfr_prec_t bits) {
  const auto of = [bits](double d) { return Interval(d, bits); };
  const Equidistance<Interval> s({lift<Interval>(t[0], of), lift<Interval>(t[1], of), lift<Interval>(t[2], of)});
  const Interval one(1.0, bits);
  // From the double box (it holds the point, and is small enough for Krawczyk to contract: the
  // isolating box may not be). K's image of a box holding the zero holds it too.
  Box2<Interval> X{Interval(v.box.x.lo, v.box.x.hi, bits), Interval(v.box.y.lo, v.box.y.hi, bits)};
  for (int i = 0; i < 64; ++i) {
    const KrawczykStep<Interval> k = krawczyk(s, X, one);
    if (k.verdict == KrawczykVerdict::no_zero) break;  // not with a zero inside; keep X
    const bool shrank = mpfr_cmp(k.box.x.lower(), X.x.lower()) != 0 || mpfr_cmp(k.box.x.upper(), X.x.upper()) != 0 ||
                        mpfr_cmp(k.box.y.lower(), X.y.lower()) != 0 || mpfr_cmp(k.box.y.upper(), X.y.upper()) != 0;
    X = k.box;  // K(X) ⊂ X when unique, K(X) ∩ X otherwise
    if (!shrank) break;
  }
  return X;
}

std::optional<Point2<Rational>> rational_vertex(const Trio& t) {
  if (!equal_metrics(t)) return std::nullopt;
  const auto of = [](double d) { return Rational(d); };
  const Equidistance<Rational> s({lift<Rational>(t[0], of), lift<Rational>(t[1], of), lift<Rational>(t[2], of)});
  const Rational zero(0);
  const auto J = s.half_jacobian(zero, zero);
  const auto F0 = s.at(zero, zero);
  // F(x) = F(0) + 2 (½J) x for a linear F: solve (½J) x = −F(0)/2.
  const Rational det = J[0] * J[3] - J[1] * J[2];
  if (det == 0) return std::nullopt;
  const Rational r0 = -F0[0] / 2, r1 = -F0[1] / 2;
  return Point2<Rational>{(J[3] * r0 - J[1] * r1) / det, (J[0] * r1 - J[2] * r0) / det};
}

}  // namespace anisocert::refiners::common
