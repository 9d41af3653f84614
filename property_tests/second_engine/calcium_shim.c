#include "property_tests/second_engine/calcium_shim.h"

#include <calcium/qqbar.h>
#include <stdlib.h>

static qqbar_struct* q(anisocert_qqbar* x) { return (qqbar_struct*)x; }
static const qqbar_struct* cq(const anisocert_qqbar* x) { return (const qqbar_struct*)x; }

anisocert_qqbar* anisocert_qqbar_new(void) {
  qqbar_struct* x = malloc(sizeof(qqbar_struct));
  if (!x) abort();
  qqbar_init(x);
  return (anisocert_qqbar*)x;
}

void anisocert_qqbar_delete(anisocert_qqbar* x) {
  if (!x) return;
  qqbar_clear(q(x));
  free(x);
}

void anisocert_qqbar_set(anisocert_qqbar* r, const anisocert_qqbar* x) { qqbar_set(q(r), cq(x)); }
void anisocert_qqbar_set_fmpq(anisocert_qqbar* r, const fmpq_t x) { qqbar_set_fmpq(q(r), x); }
int anisocert_qqbar_equal(const anisocert_qqbar* x, const anisocert_qqbar* y) { return qqbar_equal(cq(x), cq(y)); }
int anisocert_qqbar_is_real(const anisocert_qqbar* x) { return qqbar_is_real(cq(x)); }
int anisocert_qqbar_is_zero(const anisocert_qqbar* x) { return qqbar_is_zero(cq(x)); }
int anisocert_qqbar_sgn_re(const anisocert_qqbar* x) { return qqbar_sgn_re(cq(x)); }
int anisocert_qqbar_cmp_re(const anisocert_qqbar* x, const anisocert_qqbar* y) { return qqbar_cmp_re(cq(x), cq(y)); }

void anisocert_qqbar_add(anisocert_qqbar* r, const anisocert_qqbar* x, const anisocert_qqbar* y) {
  qqbar_add(q(r), cq(x), cq(y));
}

void anisocert_qqbar_mul_si(anisocert_qqbar* r, const anisocert_qqbar* x, slong c) { qqbar_mul_si(q(r), cq(x), c); }

void anisocert_qqbar_evaluate_fmpq_poly(anisocert_qqbar* r, const fmpq_poly_t p, const anisocert_qqbar* x) {
  qqbar_evaluate_fmpq_poly(q(r), p, cq(x));
}

int anisocert_qqbar_evaluate_fmpz_mpoly(anisocert_qqbar* r, const fmpz_mpoly_t f, const anisocert_qqbar* x,
                                        const anisocert_qqbar* y, slong deg_limit, slong bits_limit,
                                        const fmpz_mpoly_ctx_t ctx) {
  qqbar_struct xy[2];
  xy[0] = *cq(x); /* shallow copies: read only */
  xy[1] = *cq(y);
  return qqbar_evaluate_fmpz_mpoly(q(r), f, xy, deg_limit, bits_limit, ctx);
}

void anisocert_qqbar_roots_fmpz_poly(anisocert_qqbar** out, const fmpz_poly_t p) {
  const slong d = fmpz_poly_degree(p);
  if (d < 1) return;
  qqbar_ptr r = _qqbar_vec_init(d);
  qqbar_roots_fmpz_poly(r, p, 0);
  for (slong i = 0; i < d; ++i) {
    out[i] = anisocert_qqbar_new();
    qqbar_set(q(out[i]), r + i);
  }
  _qqbar_vec_clear(r, d);
}
