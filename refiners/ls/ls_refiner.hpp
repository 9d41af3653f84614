#pragma once
// Labelle–Shewchuk Voronoi refinement (LS §9) on a domain Ω and a metric field: the sites start as
// Ω's corners; while a constrained subsegment meets the cell of a site other than its endpoints it
// is split (rule 1); otherwise a violator, a Voronoi vertex in Ω whose dual triangle has an angle
// below θ_bound or a circumradius above `size` in the metric, gets a site, unless that site would
// encroach a subsegment, which is then split instead (rules.hpp). The output is the dual of the
// final diagram restricted to Ω (LS Theorem 7): a triangle per Voronoi vertex in closed Ω.
//
// The constant field's sites share one metric: the diagram is then kept as its dual Del_M, exact,
// with the ties (vertices of degree 4 and more) that grids give kept as ties
// (delaunay_in_metric.hpp). Every other field takes ls_varying.hpp's path, on the true diagram of
// sites with different metrics. Every decision that shapes the output is exact: in-circle and
// orientation in the filtered predicates, Voronoi vertices (rational, or certified boxes refined
// on demand) and the cells along subsegments exactly, and every split point a double exactly on its
// subsegment. The refiners never include the oracle (DESIGN.md § Layers); the tests certify every
// finished run with it.
#include "fields/metric_field.hpp"
#include "refiners/common/domain.hpp"
#include "refiners/common/refinement_loop.hpp"
#include "refiners/ls/parameters.hpp"

namespace anisocert::refiners::ls {

struct LsResult : common::RefineResult {
  // What a stopped run leaves: subsegments still encroached, Voronoi vertices in Ω still violators;
  // not counted (left_counted false) when the time budget stopped it, since counting is as long as
  // a pass over the whole mesh.
  std::size_t encroached_left = 0, violators_left = 0;
  // Triangles left with a poor angle by rule 3's exemption at sharp corners (counted with the rest).
  std::size_t exempt_left = 0;
  bool left_counted = true;
};

// Throws common::FieldError when the field's metric at a corner of Ω is not finite and positive
// definite or differs from corner 0's.
LsResult refine_ls(const common::Domain& domain, const fields::MetricField& field, const LsParameters& p,
                   const common::Progress& progress = {});

}  // namespace anisocert::refiners::ls
