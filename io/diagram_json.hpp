#pragma once
// The diagram output of `anisocert diagram --json` (DESIGN.md § Command line and files; every
// field is documented in docs/oracle.md), and the exact certificates of its witness points
// (DESIGN.md § Certificates).
#include "oracle/diagram/diagram.hpp"

#include <nlohmann/json.hpp>

namespace anisocert::io {

using OrderedJson = nlohmann::ordered_json;

OrderedJson diagram_json(const oracle::Diagram& d);

// A point of the diagram in the input's coordinates, exactly: {"x": "p/q", "y": ...} when both
// coordinates are rational, otherwise the common point of two curves with rational coefficients
// [a, b, c, d, e, f] (a x² + b xy + c y² + d x + e y + f = 0) and a box with rational bounds that
// contains no other common point. A and B are given in the diagram's (sheared) coordinates.
OrderedJson point_certificate(const oracle::Diagram& d, const oracle::LocatedPoint& p, const oracle::Conic& A,
                              const oracle::Conic& B);

// How many decisions the filters took and how many were exact, per kind (issue 14).
OrderedJson filter_counts_json(const oracle::FilterCounts& f);

struct DiagramCounts {
  std::size_t voronoi_vertices = 0, nodes = 0, arcs = 0, faces = 0, orphans = 0, wedge_violations = 0;
  std::size_t unwedged_arcs = 0, unwedged_vertices = 0;  // wedge_violations = their sum
};
DiagramCounts diagram_counts(const oracle::Diagram& d);

}  // namespace anisocert::io
