#pragma once
// LS Definition 2: wedge(v, w) = {q : (q − v)ᵀM_v(w − v) > 0 and (q − w)ᵀM_w(v − w) > 0}, open.

#include "predicates/metric_dot.hpp"

namespace anisocert::predicates {

struct WedgePosition {
  Sign toward_w;  // sign((q − v)ᵀ M_v (w − v)); <= 0: q is outside, on v's side
  Sign toward_v;  // sign((q − w)ᵀ M_w (v − w)); <= 0: q is outside, on w's side
  bool inside() const { return toward_w == Sign::positive && toward_v == Sign::positive; }
  // Outside on v's side: the M_v-angle at v between q and w is at least 90°.
  bool on_v_side() const { return toward_w != Sign::positive; }
  // "Outside wedge(v, w) on the side of w" (LS Lemma 5): the M_w-angle at w between q and v
  // is at least 90°.
  bool on_w_side() const { return toward_v != Sign::positive; }
};

template <class S>
WedgePosition wedge_position(const Point2<S>& q, const Point2<S>& v, const Sym2<S>& Mv, const Point2<S>& w,
                             const Sym2<S>& Mw) {
  return {metric_dot_sign(q, v, w, Mv), metric_dot_sign(q, w, v, Mw)};
}

}  // namespace anisocert::predicates
