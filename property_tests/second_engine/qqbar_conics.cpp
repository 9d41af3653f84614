#include "property_tests/second_engine/qqbar_conics.hpp"

#include "property_tests/second_engine/calcium_shim.h"

#include <algorithm>
#include <stdexcept>

namespace anisocert::second_engine {

class Qqbar {
 public:
  Qqbar() : v(anisocert_qqbar_new()) {}
  explicit Qqbar(anisocert_qqbar* adopted) : v(adopted) {}
  Qqbar(const Qqbar& o) : v(anisocert_qqbar_new()) { anisocert_qqbar_set(v, o.v); }
  Qqbar& operator=(const Qqbar& o) {
    anisocert_qqbar_set(v, o.v);
    return *this;
  }
  ~Qqbar() { anisocert_qqbar_delete(v); }
  anisocert_qqbar* v;
};

struct QNumber : Qqbar {
  explicit QNumber(const Qqbar& q) : Qqbar(q) {}
};

namespace {

struct Candidate {
  Qqbar x, y;
};

struct Ctx {
  Ctx() { fmpz_mpoly_ctx_init(c, 2, ORD_LEX); }
  ~Ctx() { fmpz_mpoly_ctx_clear(c); }
  fmpz_mpoly_ctx_t c;
};

struct MPoly {
  explicit MPoly(const Ctx& ctx) : ctx_(ctx) { fmpz_mpoly_init(p, ctx.c); }
  ~MPoly() { fmpz_mpoly_clear(p, ctx_.c); }
  MPoly(const MPoly&) = delete;
  fmpz_mpoly_t p;
  const Ctx& ctx_;
};

void set_fmpz(fmpz_t z, const Integer& i) { fmpz_set_mpz(z, i.backend().data()); }

// f scaled by the lcm of its denominators, as an integer polynomial in (x, y).
void to_mpoly(MPoly& out, const oracle::Bivariate& f, const Ctx& ctx) {
  Integer l = 1;
  for (const auto& [ij, c] : f.terms) l = boost::multiprecision::lcm(l, boost::multiprecision::denominator(c));
  fmpz_t z;
  fmpz_init(z);
  for (const auto& [ij, c] : f.terms) {
    set_fmpz(z, boost::multiprecision::numerator(c) * (l / boost::multiprecision::denominator(c)));
    ulong e[2] = {static_cast<ulong>(ij.first), static_cast<ulong>(ij.second)};
    fmpz_mpoly_set_coeff_fmpz_ui(out.p, z, e, ctx.c);
  }
  fmpz_clear(z);
}

// Distinct roots (complex) of a univariate polynomial, and all roots with repetition.
std::vector<Qqbar> roots(const fmpz_poly_t p, bool distinct) {
  const slong d = fmpz_poly_degree(p);
  std::vector<Qqbar> out;
  if (d < 1) return out;
  std::vector<anisocert_qqbar*> r(static_cast<std::size_t>(d));
  anisocert_qqbar_roots_fmpz_poly(r.data(), p);
  for (anisocert_qqbar* root : r) {
    Qqbar owned(root);
    const bool seen =
        distinct && std::any_of(out.begin(), out.end(), [&](const Qqbar& q) { return anisocert_qqbar_equal(q.v, root); });
    if (!seen) out.push_back(owned);
  }
  return out;
}

// The resultant eliminating variable `var`, as a univariate polynomial in the other one.
bool resultant(fmpz_poly_t out, const MPoly& A, const MPoly& B, slong var, const Ctx& ctx) {
  MPoly R(ctx);
  if (!fmpz_mpoly_resultant(R.p, A.p, B.p, var, ctx.c)) throw std::runtime_error("fmpz_mpoly_resultant failed");
  if (fmpz_mpoly_is_zero(R.p, ctx.c)) return false;
  if (!fmpz_mpoly_get_fmpz_poly(out, R.p, 1 - var, ctx.c)) throw std::runtime_error("resultant not univariate");
  return true;
}

bool vanishes(const MPoly& f, const Qqbar& x, const Qqbar& y, const Ctx& ctx) {
  Qqbar v;
  if (!anisocert_qqbar_evaluate_fmpz_mpoly(v.v, f.p, x.v, y.v, 10000, 10000000, ctx.c))
    throw std::runtime_error("qqbar evaluation limit");
  return anisocert_qqbar_is_zero(v.v);
}

}  // namespace

QIntersection intersect(const oracle::Conic& A, const oracle::Conic& B) {
  const auto zero = [](const oracle::Conic& C) { return C.polynomial().is_zero(); };
  if (zero(A) || zero(B)) throw std::invalid_argument("zero conic");
  Ctx ctx;
  MPoly a(ctx), b(ctx);
  to_mpoly(a, A.polynomial(), ctx);
  to_mpoly(b, B.polynomial(), ctx);
  QIntersection out;
  fmpz_poly_t rx, ry;
  fmpz_poly_init(rx);
  fmpz_poly_init(ry);
  // Res_y ≡ 0 or Res_x ≡ 0 ⇔ a common factor (a shared component).
  if (!resultant(rx, a, b, 1, ctx) || !resultant(ry, a, b, 0, ctx)) {
    fmpz_poly_clear(rx), fmpz_poly_clear(ry);
    out.shared_component = true;
    return out;
  }
  // All complex common points.
  std::vector<Candidate> common;
  for (const Qqbar& x : roots(rx, true))
    for (const Qqbar& y : roots(ry, true))
      if (vanishes(a, x, y, ctx) && vanishes(b, x, y, ctx)) common.push_back({x, y});
  fmpz_poly_clear(rx), fmpz_poly_clear(ry);
  // A shear separating them, keeping both degrees in y.
  for (slong t = 1;; ++t) {
    std::vector<Qqbar> u(common.size());
    for (std::size_t k = 0; k < common.size(); ++k) {
      anisocert_qqbar_mul_si(u[k].v, common[k].y.v, t);
      anisocert_qqbar_add(u[k].v, u[k].v, common[k].x.v);
    }
    bool separated = true;
    for (std::size_t i = 0; i < u.size(); ++i)
      for (std::size_t j = i + 1; j < u.size(); ++j) separated = separated && !anisocert_qqbar_equal(u[i].v, u[j].v);
    if (!separated) continue;
    MPoly xs(ctx), ys(ctx), at(ctx), bt(ctx);  // x → x − t y, y → y
    fmpz_mpoly_gen(xs.p, 0, ctx.c);
    fmpz_mpoly_gen(ys.p, 1, ctx.c);
    MPoly ty(ctx);
    fmpz_mpoly_scalar_mul_si(ty.p, ys.p, t, ctx.c);
    fmpz_mpoly_sub(xs.p, xs.p, ty.p, ctx.c);
    fmpz_mpoly_struct* subs[2] = {xs.p, ys.p};
    fmpz_mpoly_compose_fmpz_mpoly(at.p, a.p, subs, ctx.c, ctx.c);
    fmpz_mpoly_compose_fmpz_mpoly(bt.p, b.p, subs, ctx.c, ctx.c);
    if (fmpz_mpoly_degree_si(at.p, 1, ctx.c) != fmpz_mpoly_total_degree_si(a.p, ctx.c) ||
        fmpz_mpoly_degree_si(bt.p, 1, ctx.c) != fmpz_mpoly_total_degree_si(b.p, ctx.c))
      continue;
    fmpz_poly_t rt;
    fmpz_poly_init(rt);
    resultant(rt, at, bt, 1, ctx);
    const std::vector<Qqbar> all = roots(rt, false);
    fmpz_poly_clear(rt);
    for (std::size_t k = 0; k < common.size(); ++k) {
      if (!anisocert_qqbar_is_real(common[k].x.v) || !anisocert_qqbar_is_real(common[k].y.v)) continue;
      QPoint p{std::make_shared<const QNumber>(common[k].x), std::make_shared<const QNumber>(common[k].y), 0};
      p.multiplicity = static_cast<int>(std::count_if(all.begin(), all.end(), [&](const Qqbar& r) { return anisocert_qqbar_equal(r.v, u[k].v); }));
      out.points.push_back(p);
    }
    break;
  }
  std::sort(out.points.begin(), out.points.end(), [](const QPoint& p, const QPoint& q) {
    const int c = compare_x(p, q);
    return c != 0 ? c < 0 : compare_y(p, q) < 0;
  });
  return out;
}

int sign_at(const oracle::Bivariate& f, const QPoint& p) {
  if (f.is_zero()) return 0;
  Ctx ctx;
  MPoly m(ctx);
  Integer l = 1;
  for (const auto& [ij, c] : f.terms) l = boost::multiprecision::lcm(l, boost::multiprecision::denominator(c));
  to_mpoly(m, f, ctx);  // f · l with l > 0: same sign
  Qqbar v;
  if (!anisocert_qqbar_evaluate_fmpz_mpoly(v.v, m.p, p.x->v, p.y->v, 10000, 10000000, ctx.c))
    throw std::runtime_error("qqbar evaluation limit");
  return anisocert_qqbar_sgn_re(v.v);
}

int compare_x(const QPoint& p, const QPoint& q) { return anisocert_qqbar_cmp_re(p.x->v, q.x->v); }
int compare_y(const QPoint& p, const QPoint& q) { return anisocert_qqbar_cmp_re(p.y->v, q.y->v); }

bool equals(const QNumberPtr& q, const oracle::RealAlgebraic& ours) {
  fmpq_poly_t p;
  fmpq_poly_init(p);
  fmpq_t c;
  fmpq_init(c);
  for (int i = 0; i <= ours.polynomial().degree(); ++i) {
    fmpq_set_mpq(c, ours.polynomial().coefficient(i).backend().data());
    fmpq_poly_set_coeff_fmpq(p, i, c);
  }
  Qqbar v, lo, hi;
  anisocert_qqbar_evaluate_fmpq_poly(v.v, p, q->v);
  bool same = anisocert_qqbar_is_zero(v.v);
  fmpq_set_mpq(c, ours.lo().backend().data());
  anisocert_qqbar_set_fmpq(lo.v, c);
  fmpq_set_mpq(c, ours.hi().backend().data());
  anisocert_qqbar_set_fmpq(hi.v, c);
  same = same && anisocert_qqbar_cmp_re(lo.v, q->v) <= 0 && anisocert_qqbar_cmp_re(q->v, hi.v) <= 0;
  fmpq_clear(c);
  fmpq_poly_clear(p);
  return same;
}

}  // namespace anisocert::second_engine
