#pragma once
// Two runs of one refiner on one input, one with the filters and one without (LsParameters::filters,
// BwyParameters::filters): the filters only speed up (DESIGN.md), so the runs must stop alike,
// make the same insertions and end with the same mesh, double for double.
#include "refiners/common/result.hpp"

#include <rapidcheck.h>

namespace anisocert::gen {

inline void assert_same_run(const refiners::common::RefineResult& filtered, const refiners::common::RefineResult& exact) {
  RC_ASSERT(filtered.stop_reason == exact.stop_reason);
  RC_ASSERT(filtered.mesh.sites.size() == exact.mesh.sites.size());
  for (std::size_t k = 0; k < filtered.mesh.sites.size(); ++k) {
    RC_ASSERT(filtered.mesh.sites[k].x == exact.mesh.sites[k].x);
    RC_ASSERT(filtered.mesh.sites[k].y == exact.mesh.sites[k].y);
  }
  RC_ASSERT(filtered.mesh.triangles == exact.mesh.triangles);
  RC_ASSERT(filtered.mesh.segments == exact.mesh.segments);
}

}  // namespace anisocert::gen
