#pragma once
// LS §9's Voronoi refinement for fields whose sites have different metrics, on the true
// anisotropic diagram (refiners/common/vertex_subdivision.hpp; LS §9: "The algorithm works equally
// well whether D is a true anisotropic Voronoi diagram or a loose anisotropic Voronoi diagram").
// The rules are rules.hpp's, in its priority order:
//   1, 2: a subsegment ab is encroached when a site's closed cell meets it, decided exactly along
//     ab (segment_quadratics.hpp); it is split at a double exactly on ab, in that cell, as near the
//     "midpoint" d_a(z) = d_b(z) as the cell and the doubles allow (checked exactly);
//   5, 3, 4: a Voronoi vertex in closed Ω (decided exactly) whose dual triangle is inverted (the
//     cells' order around the vertex, from the gradients of the three distances there, against the
//     sites' orientation), has an angle below θ_bound in the metric of any of its three sites or of
//     the field at the vertex, or whose radius d_v(q) exceeds `size`, gets a site at the vertex
//     rounded to doubles;
//   6: a site in Ω whose cell holds no Voronoi vertex (bounded by an ellipse) gets a site on the
//     bisector with its nearest other site, on the segment between them.
// The output is the dual of the final diagram: a triangle per Voronoi vertex of degree 3 in closed
// Ω, in the cells' counter-clockwise order, and a fan per vertex of degree 4 or more among sites
// of one metric (exact_tie.hpp). Other unresolved places get rule 8's sites; undecided signs,
// and a subdivision that reaches its bound on boxes, stop the run by name.
#include "fields/metric_field.hpp"
#include "refiners/common/domain.hpp"
#include "refiners/common/refinement_loop.hpp"
#include "refiners/ls/ls_refiner.hpp"

namespace anisocert::refiners::ls {

LsResult refine_ls_varying(const common::Domain& domain, const fields::MetricField& field, const LsParameters& p,
                           const common::Progress& progress = {});

}  // namespace anisocert::refiners::ls
