#pragma once
/* Calcium's qqbar (exact algebraic numbers) behind an opaque handle. Calcium's headers convert
   void* implicitly (valid C, not C++: g++ needs -fpermissive, clang++ refuses them), so only
   calcium_shim.c, compiled as C, includes them; qqbar_conics.cpp calls these. One function per
   qqbar function used, same name after the prefix, same meaning (Calcium's documentation). */
#include <flint/fmpq.h>
#include <flint/fmpq_poly.h>
#include <flint/fmpz_mpoly.h>
#include <flint/fmpz_poly.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct anisocert_qqbar anisocert_qqbar; /* a qqbar_struct, never defined here */

anisocert_qqbar* anisocert_qqbar_new(void); /* qqbar_init on a new struct: the number 0 */
void anisocert_qqbar_delete(anisocert_qqbar* x);
void anisocert_qqbar_set(anisocert_qqbar* r, const anisocert_qqbar* x);
void anisocert_qqbar_set_fmpq(anisocert_qqbar* r, const fmpq_t x);
int anisocert_qqbar_equal(const anisocert_qqbar* x, const anisocert_qqbar* y);
int anisocert_qqbar_is_real(const anisocert_qqbar* x);
int anisocert_qqbar_is_zero(const anisocert_qqbar* x);
int anisocert_qqbar_sgn_re(const anisocert_qqbar* x);
int anisocert_qqbar_cmp_re(const anisocert_qqbar* x, const anisocert_qqbar* y);
void anisocert_qqbar_add(anisocert_qqbar* r, const anisocert_qqbar* x, const anisocert_qqbar* y);
void anisocert_qqbar_mul_si(anisocert_qqbar* r, const anisocert_qqbar* x, slong c);
void anisocert_qqbar_evaluate_fmpq_poly(anisocert_qqbar* r, const fmpq_poly_t p, const anisocert_qqbar* x);
/* f(x, y); 0 when Calcium's degree or bit limit is exceeded. */
int anisocert_qqbar_evaluate_fmpz_mpoly(anisocert_qqbar* r, const fmpz_mpoly_t f, const anisocert_qqbar* x,
                                        const anisocert_qqbar* y, slong deg_limit, slong bits_limit,
                                        const fmpz_mpoly_ctx_t ctx);
/* The deg(p) complex roots of p with repetition, each a new number in out[0 .. deg(p) - 1]. */
void anisocert_qqbar_roots_fmpz_poly(anisocert_qqbar** out, const fmpz_poly_t p);

#ifdef __cplusplus
}
#endif
