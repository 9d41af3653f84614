#pragma once
// The in-sphere test in a metric M under a symbolic perturbation of the lifting (simulation of
// simplicity, Edelsbrunner & Mücke 1990), for LU's stars in 3D (issue 40; LU Definitions 2.1 and
// 3.1: S_v is the star of v in Del_{M_v}(V)). The lattices a refiner meets (a box's corners, a
// Kuhn grid) put five sites on one M-sphere, where insphere.hpp answers 0 and Del_M is not
// unique. Lifting site i to Q(p_i) + ε_i, with ε infinitesimal and ε_i ≫ ε_j when index i <
// index j, makes it unique: the perturbed Delaunay tetrahedralization is one of the Delaunay
// tetrahedralizations of the sites (the regular one for the weights −ε_i), the same for every
// star that asks with the same metric.
//
// With P(a, b, c, d, e) the in-sphere value of insphere.hpp (P = −det₅ [p_i, Q(p_i), 1] over the
// rows a, b, c, d, e), each lift enters one row, so P is affine in each ε and
//   P_ε = P + Σ_r ε_r (−1)^(r+1) orientation3(the four rows other than r, in order)
// (the lift's cofactor: det [p_j, 1] over four rows is −orientation3 of them). When P = 0 the
// sign is that of the first non-zero term, the rows taken by increasing site index (the largest
// perturbation first). For a non-flat abcd the term of e is −orientation3(a, b, c, d) ≠ 0, so
// then the answer is never 0: positive (e inside, for positively oriented abcd) or negative.
// Zero only when the five are coplanar. No new polynomial: the two kernels' filtered signs.

#include "predicates/insphere.hpp"
#include "predicates/orientation3.hpp"

#include <algorithm>
#include <array>

namespace anisocert::predicates {

// p = (a, b, c, d, e) with their sites' distinct indices.
template <class S>
Sign insphere_perturbed(const std::array<Point3<S>, 5>& p, const std::array<int, 5>& index, const Sym3<S>& M) {
  if (const Sign s = insphere(p[0], p[1], p[2], p[3], p[4], M); s != Sign::zero) return s;
  std::array<std::size_t, 5> rows{0, 1, 2, 3, 4};
  std::sort(rows.begin(), rows.end(), [&](std::size_t r, std::size_t q) { return index[r] < index[q]; });
  for (const std::size_t r : rows) {
    std::array<const Point3<S>*, 4> o;
    for (std::size_t i = 0, j = 0; i < 5; ++i)
      if (i != r) o[j++] = &p[i];
    const Sign s = orientation3(*o[0], *o[1], *o[2], *o[3]);
    if (s != Sign::zero) return r % 2 == 1 ? s : -s;
  }
  return Sign::zero;
}

}  // namespace anisocert::predicates
