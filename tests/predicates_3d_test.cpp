// The 3D predicates (issue 39): orientation of four points and the in-sphere test in a metric,
// against closed forms, against an independent construction in rationals (the M-circumcentre
// solved from its linear system), on exactly degenerate inputs (coplanar, M-cospherical) and a
// few ulps away, and filtered against exact across magnitudes (zero disagreements allowed).

#include "geometry/distortion_estimate.hpp"
#include "predicates/dihedral.hpp"
#include "predicates/distortion.hpp"
#include "predicates/insphere.hpp"
#include "predicates/orientation3.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

using anisocert::Rational;
using anisocert::Sign;
using namespace anisocert::predicates;

namespace {

using P3 = Point3<Rational>;

// Random numbers for the filtered-against-exact tests: uniform reals and integers from one engine.
struct Draw {
  explicit Draw(std::uint64_t seed) : rng(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
  std::mt19937_64 rng;
};

template <class K>
Sign checked(const std::array<double, K::arity>& x) {
  std::array<Rational, K::arity> q;
  for (std::size_t i = 0; i < K::arity; ++i) q[i] = Rational(x[i]);
  const Sign exact = exact_sign<K>(q);
  EXPECT_EQ(filtered_sign<K>(x), exact) << K::name;
  EXPECT_EQ(filtered_sign<K>(q), exact) << K::name;
  return exact;
}

Rational det3(const std::array<std::array<Rational, 3>, 3>& m) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

std::array<Rational, 3> times(const Sym3<Rational>& M, const std::array<Rational, 3>& v) {
  return {M.m11 * v[0] + M.m12 * v[1] + M.m13 * v[2], M.m12 * v[0] + M.m22 * v[1] + M.m23 * v[2],
          M.m13 * v[0] + M.m23 * v[1] + M.m33 * v[2]};
}

Rational q(const Sym3<Rational>& M, const P3& p, const std::array<Rational, 3>& c) {
  return quadratic_form(M, p.x - c[0], p.y - c[1], p.z - c[2]);
}

// sign(r² − (e − c)ᵀM(e − c)) for c the M-circumcentre of a, b, c, d, solved by Cramer's rule from
// 2 (p − a)ᵀ M c = pᵀMp − aᵀMa for p = b, c, d: an independent construction (no lifted
// determinant). The tetrahedron must not be flat.
Sign inside_by_centre(const P3& a, const P3& b, const P3& c, const P3& d, const P3& e, const Sym3<Rational>& M) {
  std::array<std::array<Rational, 3>, 3> A;
  std::array<Rational, 3> rhs;
  const P3* ps[3] = {&b, &c, &d};
  const std::array<Rational, 3> origin{0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    const std::array<Rational, 3> diff{ps[i]->x - a.x, ps[i]->y - a.y, ps[i]->z - a.z};
    const auto row = times(M, diff);
    A[i] = {2 * row[0], 2 * row[1], 2 * row[2]};
    rhs[i] = q(M, *ps[i], origin) - q(M, a, origin);
  }
  const Rational D = det3(A);
  std::array<Rational, 3> centre;
  for (int k = 0; k < 3; ++k) {
    auto Ak = A;
    for (int i = 0; i < 3; ++i) Ak[i][k] = rhs[i];
    centre[k] = det3(Ak) / D;
  }
  const Rational r2 = q(M, a, centre), e2 = q(M, e, centre);
  return r2 > e2 ? Sign::positive : r2 < e2 ? Sign::negative : Sign::zero;
}

}  // namespace

// The unit tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1) is positively oriented (its determinant
// is det I = 1); an odd permutation turns it negative; a fourth point in the plane z = 0 is coplanar.
TEST(Orientation3, ClosedForms) {
  const P3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  EXPECT_EQ(orientation3(o, x, y, z), Sign::positive);
  EXPECT_EQ(orientation3(o, y, x, z), Sign::negative);
  EXPECT_EQ(orientation3(x, y, z, o), Sign::negative);  // a cyclic shift of four is odd
  EXPECT_EQ(orientation3(o, x, y, P3{Rational(7, 3), Rational(-5, 2), 0}), Sign::zero);
  EXPECT_EQ(orientation3(Point3<double>{0, 0, 0}, Point3<double>{1, 0, 0}, Point3<double>{0, 1, 0}, Point3<double>{0.5, 0.5, 1e-300}),
            Sign::positive);
}

// In-sphere with M = I: the unit tetrahedron's circumsphere has centre (1/2, 1/2, 1/2) and radius²
// 3/4; (1/4, 1/4, 1/4) is inside (the lifted determinant is −9/16), (1, 1, 1) is on it (the eight
// corners of a cube are cospherical), (1, 1, 1.1) outside. M = diag(1, 4, 9) maps
// (x, y, z) ↦ (x, 2y, 3z) to the Euclidean picture: the stretched cube's corners (0,0,0), (1,0,0),
// (0,1/2,0), (0,0,1/3), (1,1/2,1/3) are M-cospherical. A negatively oriented tetrahedron flips
// the sign.
TEST(InSphere, ClosedForms) {
  const Sym3<Rational> I{1, 0, 0, 1, 0, 1};
  const P3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  EXPECT_EQ(insphere(o, x, y, z, P3{Rational(1, 4), Rational(1, 4), Rational(1, 4)}, I), Sign::positive);
  EXPECT_EQ(insphere(o, x, y, z, P3{1, 1, 1}, I), Sign::zero);
  EXPECT_EQ(insphere(o, x, y, z, P3{1, 1, Rational(11, 10)}, I), Sign::negative);
  EXPECT_EQ(insphere(o, y, x, z, P3{Rational(1, 4), Rational(1, 4), Rational(1, 4)}, I), Sign::negative);
  const Sym3<Rational> M{1, 0, 0, 4, 0, 9};
  const P3 y2{0, Rational(1, 2), 0}, z3{0, 0, Rational(1, 3)};
  EXPECT_EQ(insphere(o, x, y2, z3, P3{1, Rational(1, 2), Rational(1, 3)}, M), Sign::zero);
  EXPECT_EQ(insphere(o, x, y2, z3, P3{1, Rational(1, 2), Rational(3, 10)}, M), Sign::positive);
}

// Random integer points and metrics M = LLᵀ + I (L integer lower triangular): the lifted
// determinant's sign is orientation × the sign found from the solved centre; cospherical fifth
// points are made exactly (the centre's antipode of a vertex: 2c − a is on the M-sphere).
TEST(InSphere, AgreesWithTheSolvedCircumcentre) {
  std::mt19937 rng(39);
  std::uniform_int_distribution<int> coordinate(-6, 6), entry(-3, 3);
  int zeros = 0, inside = 0, outside = 0;
  for (int t = 0; t < 400; ++t) {
    const auto point = [&] { return P3{coordinate(rng), coordinate(rng), coordinate(rng)}; };
    const P3 a = point(), b = point(), c = point(), d = point();
    const Sign o = orientation3(a, b, c, d);
    if (o == Sign::zero) continue;
    const Rational l11 = entry(rng), l21 = entry(rng), l22 = entry(rng), l31 = entry(rng), l32 = entry(rng), l33 = entry(rng);
    const Sym3<Rational> M{l11 * l11 + 1, l11 * l21, l11 * l31, l21 * l21 + l22 * l22 + 1, l21 * l31 + l22 * l32,
                           l31 * l31 + l32 * l32 + l33 * l33 + 1};
    P3 e = point();
    if (t % 4 == 0) {  // the antipode of a through the M-circumcentre: on the sphere, rational
      std::array<std::array<Rational, 3>, 3> A;
      std::array<Rational, 3> rhs;
      const P3* ps[3] = {&b, &c, &d};
      for (int i = 0; i < 3; ++i) {
        const std::array<Rational, 3> diff{ps[i]->x - a.x, ps[i]->y - a.y, ps[i]->z - a.z};
        const auto row = times(M, diff);
        A[i] = {2 * row[0], 2 * row[1], 2 * row[2]};
        rhs[i] = q(M, *ps[i], {0, 0, 0}) - q(M, a, {0, 0, 0});
      }
      std::array<Rational, 3> centre;
      for (int k = 0; k < 3; ++k) {
        auto Ak = A;
        for (int i = 0; i < 3; ++i) Ak[i][k] = rhs[i];
        centre[k] = det3(Ak) / det3(A);
      }
      e = {2 * centre[0] - a.x, 2 * centre[1] - a.y, 2 * centre[2] - a.z};
    }
    const Sign expected = o * inside_by_centre(a, b, c, d, e, M);
    EXPECT_EQ(insphere(a, b, c, d, e, M), expected) << t;
    zeros += expected == Sign::zero, inside += expected == o, outside += expected == -o;
  }
  EXPECT_GT(zeros, 50);
  EXPECT_GT(inside, 30);
  EXPECT_GT(outside, 30);
}

// Filtered against exact: random doubles across magnitudes 2^±70 (inside and outside the static
// filter's range), points on a grid with M-cospherical fifth points (the cube's corners under
// M = diag(1, 4, 9), translated and scaled by powers of two, so exact in doubles), and each moved
// by one to four ulps.
TEST(FilteredVsExact, Orientation3AndInSphere) {
  Draw draw(20261202);
  const auto nudged = [&](auto x) {
    const std::size_t i = static_cast<std::size_t>(draw.integer(0, static_cast<int>(x.size()) - 1));
    for (int k = draw.integer(1, 4); k > 0; --k) x[i] = std::nextafter(x[i], draw.integer(0, 1) ? INFINITY : -INFINITY);
    return x;
  };
  int zero_orientations = 0, zero_spheres = 0;
  for (int t = 0; t < 3000; ++t) {
    const int e = draw.integer(-70, 70), m = draw.integer(-70, 70);
    std::array<double, 12> o;
    for (double& v : o) v = std::ldexp(draw.uniform(-1, 1), e);
    checked<Orientation3Kernel>(o);
    std::array<double, 21> s;
    for (std::size_t i = 0; i < 15; ++i) s[i] = std::ldexp(draw.uniform(-1, 1), e);
    const double m11 = std::ldexp(draw.uniform(0.1, 1), m), m22 = std::ldexp(draw.uniform(0.1, 1), m), m33 = std::ldexp(draw.uniform(0.1, 1), m);
    s[15] = m11, s[16] = draw.uniform(-0.5, 0.5) * std::sqrt(m11 * m22), s[17] = draw.uniform(-0.5, 0.5) * std::sqrt(m11 * m33);
    s[18] = m22, s[19] = draw.uniform(-0.5, 0.5) * std::sqrt(m22 * m33), s[20] = m33;
    checked<InSphereKernel>(s);
    // Exactly degenerate, then a few ulps away.
    const double scale = std::ldexp(1.0, draw.integer(-40, 40)), cx = draw.integer(-1000, 1000) * scale, cy = draw.integer(-1000, 1000) * scale,
                 cz = draw.integer(-1000, 1000) * scale;
    const std::array<double, 12> flat{cx, cy, cz, cx + scale, cy, cz, cx, cy + 3 * scale, cz, cx + 5 * scale, cy + 7 * scale, cz};
    zero_orientations += checked<Orientation3Kernel>(flat) == Sign::zero;
    checked<Orientation3Kernel>(nudged(flat));
    const std::array<double, 21> cube{cx, cy, cz, cx + scale, cy, cz, cx, cy + scale / 2, cz, cx, cy, cz + scale / 4,
                                      cx + scale, cy + scale / 2, cz + scale / 4, 1, 0, 0, 4, 0, 16};
    zero_spheres += checked<InSphereKernel>(cube) == Sign::zero;
    checked<InSphereKernel>(nudged(cube));
  }
  EXPECT_EQ(zero_orientations, 3000);
  EXPECT_EQ(zero_spheres, 3000);
}

// The dihedral angle in a metric (predicates/dihedral.hpp) against closed forms: the regular
// tetrahedron's arccos(1/3) (sin² = 8/9 exactly), the corner tetrahedron's right angles at its axes
// and arccos(1/√3) at the hypotenuse of a face, and the same angles after an affine map F with the
// metric FᵀF's inverse image (the regular tetrahedron squashed by 1/2 in z, measured by
// diag(1, 1, 4): the angles of the regular one).
TEST(Dihedral, ClosedFormsAndTheirAffineImages) {
  const auto exact = [](const std::array<Rational, 12>& p, const Sym3<Rational>& M, const Rational& s) {
    std::array<Rational, 19> x;
    std::copy(p.begin(), p.end(), x.begin());
    x[12] = M.m11, x[13] = M.m12, x[14] = M.m13, x[15] = M.m22, x[16] = M.m23, x[17] = M.m33, x[18] = s;
    return x;
  };
  const auto dot = [](const std::array<Rational, 19>& x) {
    std::array<Rational, 18> h;
    std::copy_n(x.begin(), 18, h.begin());
    return exact_sign<DihedralDotKernel>(h);
  };
  const Sym3<Rational> I{1, 0, 0, 1, 0, 1}, z4{1, 0, 0, 1, 0, 4};
  const std::array<Rational, 12> regular{1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1};
  std::array<Rational, 12> squashed = regular;
  for (std::size_t i = 2; i < 12; i += 3) squashed[i] /= 2;
  for (const auto& [p, M] : {std::pair{regular, I}, std::pair{squashed, z4}}) {
    EXPECT_EQ(dot(exact(p, M, 0)), Sign::positive);                                       // acute
    EXPECT_EQ(exact_sign<DihedralSinKernel>(exact(p, M, Rational(8, 9))), Sign::zero);      // sin² θ = 8/9
    EXPECT_EQ(exact_sign<DihedralSinKernel>(exact(p, M, Rational(3, 4))), Sign::negative);  // θ > 60°
    EXPECT_EQ(exact_sign<DihedralSinKernel>(exact(p, M, Rational(9, 10))), Sign::positive); // θ < arcsin √0.9
  }
  EXPECT_NE(exact_sign<DihedralSinKernel>(exact(squashed, I, Rational(8, 9))), Sign::zero);  // not in I
  // A shear (a reviewer's case, every cofactor of M in play): F = [1 1 0; 0 1 0; 0 0 1], M = FᵀF =
  // [1 1 0; 1 2 0; 0 0 1], and the regular tetrahedron mapped by F⁻¹, (x, y, z) ↦ (x − y, y, z): regular
  // in M, every edge's sin² 8/9 (the six edges as ab, each with the other two as c, d).
  const Sym3<Rational> shear{1, 1, 0, 2, 0, 1};
  const std::array<std::array<Rational, 3>, 4> q{{{0, 1, 1}, {2, -1, -1}, {-2, 1, -1}, {0, -1, 1}}};
  for (const auto& [i, j, k, l] : {std::array<int, 4>{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}, {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}}) {
    std::array<Rational, 12> p;
    for (std::size_t c = 0; c < 3; ++c)
      p[c] = q[static_cast<std::size_t>(i)][c], p[3 + c] = q[static_cast<std::size_t>(j)][c], p[6 + c] = q[static_cast<std::size_t>(k)][c],
      p[9 + c] = q[static_cast<std::size_t>(l)][c];
    EXPECT_EQ(exact_sign<DihedralSinKernel>(exact(p, shear, Rational(8, 9))), Sign::zero) << i << j;
    EXPECT_NE(exact_sign<DihedralSinKernel>(exact(p, I, Rational(8, 9))), Sign::zero) << i << j;
  }
  // The corner tetrahedron 0, x, y, z: right at edge 0–x (faces in the planes z = 0 and y = 0);
  // at edge x–y, cos θ = 1/√3: sin² θ = 2/3.
  const std::array<Rational, 12> corner{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  EXPECT_EQ(dot(exact(corner, I, 0)), Sign::zero);
  const std::array<Rational, 12> at_xy{1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1};
  EXPECT_EQ(dot(exact(at_xy, I, 0)), Sign::positive);
  EXPECT_EQ(exact_sign<DihedralSinKernel>(exact(at_xy, I, Rational(2, 3))), Sign::zero);
  // A metric stretching z by 2 (diag(1, 1, 4)) keeps the right angle at 0–x (both faces contain x).
  EXPECT_EQ(dot(exact(corner, z4, 0)), Sign::zero);
}

// The interval stage then exact (what the certifier calls for kernels beyond the static filter's
// degree 8, predicates/dihedral.hpp) against exact alone.
template <class K>
Sign interval_checked(const std::array<double, K::arity>& x) {
  std::array<Rational, K::arity> q;
  std::array<anisocert::FilterInterval, K::arity> xi;
  for (std::size_t i = 0; i < K::arity; ++i) q[i] = Rational(x[i]), xi[i] = anisocert::FilterInterval(x[i]);
  const Sign exact = exact_sign<K>(q);
  EXPECT_EQ(interval_then_exact<K>(xi, [&] { return q; }), exact) << K::name;
  return exact;
}

// Filtered against exact for the two dihedral kernels: random doubles across magnitudes, and the
// corner tetrahedron (an exact right angle) translated and scaled by powers of two, then nudged.
TEST(FilteredVsExact, Dihedral) {
  Draw draw(39039);
  int zeros = 0;
  for (int t = 0; t < 2000; ++t) {
    const int e = draw.integer(-60, 60), m = draw.integer(-60, 60);
    std::array<double, 19> x;
    for (std::size_t i = 0; i < 12; ++i) x[i] = std::ldexp(draw.uniform(-1, 1), e);
    const double m11 = std::ldexp(draw.uniform(0.1, 1), m), m22 = std::ldexp(draw.uniform(0.1, 1), m), m33 = std::ldexp(draw.uniform(0.1, 1), m);
    x[12] = m11, x[13] = draw.uniform(-0.5, 0.5) * std::sqrt(m11 * m22), x[14] = draw.uniform(-0.5, 0.5) * std::sqrt(m11 * m33);
    x[15] = m22, x[16] = draw.uniform(-0.5, 0.5) * std::sqrt(m22 * m33), x[17] = m33, x[18] = draw.uniform(0, 1);
    interval_checked<DihedralSinKernel>(x);
    std::array<double, 18> head;
    std::copy_n(x.begin(), 18, head.begin());
    checked<DihedralDotKernel>(head);
    interval_checked<DihedralDotKernel>(head);
    const double scale = std::ldexp(1.0, draw.integer(-40, 40)), cx = draw.integer(-1000, 1000) * scale, cy = draw.integer(-1000, 1000) * scale,
                 cz = draw.integer(-1000, 1000) * scale;
    std::array<double, 18> right{cx, cy, cz, cx + scale, cy, cz, cx, cy + 3 * scale, cz, cx, cy, cz + 5 * scale, 1, 0, 0, 2, 0, 4};
    zeros += checked<DihedralDotKernel>(right) == Sign::zero;
    const auto i = static_cast<std::size_t>(draw.integer(0, 11));
    right[i] = std::nextafter(right[i], draw.integer(0, 1) ? INFINITY : -INFINITY);
    checked<DihedralDotKernel>(right);
  }
  EXPECT_EQ(zeros, 2000);
}

// The distortion between 3×3 metrics (predicates/distortion.hpp): I against diag(1, 4, 9) and
// against that metric rotated by the rational rotation with the 3-4-5 triangle in the xy-plane
// (R = [3/5 −4/5 0; 4/5 3/5 0; 0 0 1], RᵀMR has the same generalized eigenvalues 1, 4, 9 against I):
// γ = 3, so γ₀² = 9 holds and 9 − 10⁻¹⁵ does not; the estimate agrees. A metric and a multiple:
// γ² is the factor.
TEST(Distortion3, ExactAgainstClosedForms) {
  const Sym3<Rational> I{1, 0, 0, 1, 0, 1}, D{1, 0, 0, 4, 0, 9};
  // RᵀDR: entries from [3/5 4/5; −4/5 3/5] diag(1, 4) [3/5 −4/5; 4/5 3/5] in the xy-block.
  const Sym3<Rational> R{Rational(9, 25) + 4 * Rational(16, 25), Rational(-12, 25) + 4 * Rational(12, 25), 0,
                         Rational(16, 25) + 4 * Rational(9, 25), 0, 9};
  const Rational below = 9 - Rational(1, 1000000000000000);
  for (const auto& M : {D, R}) {
    EXPECT_TRUE(tau_at_most(I, M, Rational(9)));
    EXPECT_TRUE(tau_at_most(M, I, Rational(9)));
    EXPECT_FALSE(tau_at_most(I, M, below));
    const auto d = [](const Rational& q) { return q.convert_to<double>(); };
    const Sym3<double> Md{d(M.m11), d(M.m12), d(M.m13), d(M.m22), d(M.m23), d(M.m33)};
    EXPECT_NEAR(anisocert::geometry::tau_squared_estimate(Sym3<double>{1, 0, 0, 1, 0, 1}, Md), 9, 1e-9);
  }
  const Sym3<Rational> twice{2, Rational(1, 2), 0, 4, 1, 6}, scaled{10, Rational(5, 2), 0, 20, 5, 30};
  EXPECT_TRUE(tau_at_most(twice, scaled, Rational(5)));
  EXPECT_FALSE(tau_at_most(twice, scaled, below / 9 * 5));
  // Off-diagonal m13 (a reviewer's case): [3 0 −2; 0 4 0; −2 0 3] has eigenvalues 1, 4, 5 against I,
  // so γ² = 5; the (1,3) minor of 4I − M is 1·1 − 4 < 0, which only the full set of minors sees.
  const Sym3<Rational> slanted{3, 0, -2, 4, 0, 3};
  EXPECT_TRUE(tau_at_most(I, slanted, Rational(5)));
  EXPECT_NEAR(anisocert::geometry::tau_squared_estimate(Sym3<double>{1, 0, 0, 1, 0, 1}, Sym3<double>{3, 0, -2, 4, 0, 3}), 5, 1e-12);
  // Far apart in scale (det P ≪ det Q): γ² = 10⁶ for P = 10⁻⁶ I and Q = I, estimated to 10⁻⁹.
  EXPECT_NEAR(anisocert::geometry::tau_squared_estimate(Sym3<double>{1e-6, 0, 0, 1e-6, 0, 1e-6}, Sym3<double>{1, 0, 0, 1, 0, 1}), 1e6, 1e-3);
  EXPECT_FALSE(tau_at_most(I, slanted, Rational(4)));
  EXPECT_FALSE(tau_at_most(I, slanted, 5 - Rational(1, 1000000000000)));
  // A leading-minor test alone would pass diag(0, −1, …)-like differences: γ₀² = 1 between I and
  // diag(1, 1/4, 1) has the difference diag(0, 3/4, 0) one way and diag(0, −3/4, 0) the other.
  EXPECT_FALSE(tau_at_most(I, Sym3<Rational>{1, 0, 0, Rational(1, 4), 0, 1}, Rational(1)));
}

// Filtered against exact for the 3×3 determinant of γ²P − Q: random doubles across magnitudes and
// proportional metrics (an exact zero: the determinant of γ²P − γ²P), then nudged.
TEST(FilteredVsExact, Distortion3Determinant) {
  Draw draw(3939);
  int zeros = 0;
  for (int t = 0; t < 3000; ++t) {
    std::array<double, 13> x;
    const int e = draw.integer(-60, 60);
    x[0] = std::ldexp(draw.uniform(0.1, 4), draw.integer(-4, 4));
    for (std::size_t i = 1; i < 13; ++i) x[i] = std::ldexp(draw.uniform(-1, 1), e);
    checked<ScaledDifference3DeterminantKernel>(x);
    const double g = std::ldexp(1.0, draw.integer(-3, 3));
    for (std::size_t i = 1; i < 7; ++i) x[i + 6] = g * x[i];
    x[0] = g;
    zeros += checked<ScaledDifference3DeterminantKernel>(x) == Sign::zero;
    const auto i = static_cast<std::size_t>(draw.integer(0, 12));
    x[i] = std::nextafter(x[i], draw.integer(0, 1) ? INFINITY : -INFINITY);
    checked<ScaledDifference3DeterminantKernel>(x);
  }
  EXPECT_EQ(zeros, 3000);
}

// static_enclosure (filtered_sign.hpp): the double evaluation ± the static bound holds the exact
// value, on random doubles at magnitudes 2⁻²⁰ to 2²⁰ and nearly degenerate inputs (a fifth point
// near the sphere, a fourth near the plane), where the double evaluation itself is often not the
// exact value (counted: the test sees rounding happen, so a bound of 0 would fail it).
TEST(StaticEnclosure, HoldsTheExactValue) {
  Draw draw(4517);
  int rounded = 0, runs = 0;
  const auto check = [&]<class K>(K, const std::array<double, K::arity>& x) {
    const auto e = static_enclosure<K>(x);
    ASSERT_TRUE(e.has_value());
    std::array<Rational, K::arity> q;
    for (std::size_t i = 0; i < K::arity; ++i) q[i] = Rational(x[i]);
    const Rational exact = K::eval(q);
    EXPECT_LE(Rational(e->lo), exact) << K::name;
    EXPECT_GE(Rational(e->hi), exact) << K::name;
    rounded += Rational(K::eval(x)) != exact;
    ++runs;
  };
  for (int n = 0; n < 2000; ++n) {
    const double s = std::ldexp(1.0, draw.integer(-20, 20));
    std::array<double, 12> o;
    for (auto& v : o) v = s * draw.uniform(-1, 1);
    if (n % 2) o[11] = o[2] + (o[5] - o[2]) * 0.5 + (o[8] - o[2]) * 0.5 + s * 1e-12 * draw.uniform(-1, 1);  // d near a plane
    check(Orientation3Kernel{}, o);
    std::array<double, 21> i;
    for (std::size_t k = 0; k < 15; ++k) i[k] = s * draw.uniform(-1, 1);
    const std::array<double, 6> m{1 + draw.uniform(0, 1), 0.2 * draw.uniform(-1, 1), 0.2 * draw.uniform(-1, 1), 1 + draw.uniform(0, 1),
                                  0.2 * draw.uniform(-1, 1), 1 + draw.uniform(0, 1)};
    for (std::size_t k = 0; k < 6; ++k) i[15 + k] = m[k];
    check(InSphereKernel{}, i);
  }
  EXPECT_GT(rounded, runs / 4);
}
