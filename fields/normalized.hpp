#pragma once
// LS §9's variation of the field for the diagram: M′_p = det(M_p)^(−1/2) M_p (d = 2), of
// determinant one. M′_p and M_p measure angles identically and lengths differently; with M′ the
// relative distortion between two points comes from how they measure angles only, not areas.
//
// In doubles: det M_p is computed with Kahan's fused 2×2 determinant (within a few ulps, even when
// M_p is nearly singular), s = 1/√det rounded, and each entry s·m rounded: every entry of M′_p is
// the exact det^(−1/2)·m within a few ulps (tests/fields_normalized_test.cpp). Its own determinant
// is then 1 within about ε·κ(M_p), κ the condition number. Whoever uses M′ takes the rounded
// tensor as given (the LS refiner writes it as the sites' metrics, which the oracle then reads
// exactly). Where M_p is not positive definite, M_p itself is returned, for the caller's check to
// name.
#include "fields/metric_field.hpp"

namespace anisocert::fields {

predicates::Sym2<double> normalized(const predicates::Sym2<double>& M);

// The field p ↦ M′_p of `f`, named "normalized <f's name>".
MetricField normalized(const MetricField& f);

}  // namespace anisocert::fields
