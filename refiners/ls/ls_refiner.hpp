#pragma once
// Labelle–Shewchuk Voronoi refinement (LS §9) on a domain Ω and a metric field: the sites start as
// Ω's corners; while a constrained subsegment meets the cell of a site other than its endpoints it
// is split (rule 1); otherwise a violator, a Voronoi vertex in Ω whose dual triangle has an angle
// below θ_bound or a circumradius above `size` in the metric, gets a site, unless that site would
// encroach a subsegment, which is then split instead (rules.hpp). The output is the dual of the
// final diagram restricted to Ω (LS Theorem 7): a triangle per Voronoi vertex in closed Ω.
//
// The diagram is kept for sites that share one metric (a constant field), where it is exact and
// every loose diagram equals the true one (delaunay_in_metric.hpp); a field that gives two sites
// different metrics stops the run by name: the loose diagram of LS §8 for bisector conics is not
// built yet (issue 16). Every decision that shapes the output is exact: in-circle and orientation
// in the filtered predicates, Voronoi vertices and the cells along subsegments in rationals, and
// every split point a double exactly on its subsegment. The refiners never include the oracle
// (DESIGN.md § Layers); the tests certify every finished run with it.
#include "fields/metric_field.hpp"
#include "refiners/common/domain.hpp"
#include "refiners/common/refinement_loop.hpp"
#include "refiners/ls/parameters.hpp"

namespace anisocert::refiners::ls {

struct LsResult : common::RefineResult {
  // What a stopped run leaves: subsegments still encroached, Voronoi vertices in Ω still violators.
  std::size_t encroached_left = 0, violators_left = 0;
};

// Throws common::FieldError when the field's metric at a corner of Ω is not finite and positive
// definite or differs from corner 0's.
LsResult refine_ls(const common::Domain& domain, const fields::MetricField& field, const LsParameters& p,
                   const common::Progress& progress = {});

}  // namespace anisocert::refiners::ls
