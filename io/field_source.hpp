#pragma once
// What `--field TEXT` and its `--param name=value` options name, read in one place for every
// command that takes a field: a built-in field (fields/registry.hpp) with its parameters, or a
// background mesh `background:MESH[:METRIC]` (fields/background.hpp): MESH in any format of
// io/formats/registry.hpp (MESH itself holds no ':'), its metrics from METRIC when given, else
// its own.
#include "fields/background.hpp"
#include "fields/metric_field.hpp"
#include "io/input_error.hpp"

#include <memory>
#include <string>
#include <vector>

namespace anisocert::io {

struct FieldSource {
  fields::MetricField field;                                 // what the refiners sample, in doubles
  std::shared_ptr<const fields::BackgroundMesh> background;  // background:…, for exact values; null otherwise
};

// An option's number (a --param value, a bound) as the double nearest it; InputError naming the
// option when it is not a number or lies beyond the doubles' range (or below it, but not 0).
double option_double(const std::string& name, const std::string& text);

// For --help: the background form and what it means.
inline constexpr const char* background_field_help =
    "background:MESH[:METRIC]: the metrics of a background mesh's vertices, interpolated P1 (linearly per component) over\n"
    "    its triangles (or tetrahedra, for a tetrahedral mesh); MESH in any mesh format, METRIC a metric file (else the mesh's own metrics)";

// Throws InputError naming the option, the file or the point, and what is wrong.
FieldSource field_source(const std::string& text, const std::vector<std::string>& params);

// The metric at every point: a background mesh's exactly (P1, rational), a built-in field's at the
// points' nearest doubles (its double values taken as the rationals they are). `text` is the
// --field text, for messages (InputError naming the point by index).
std::vector<predicates::Sym2<Rational>> metrics_at(const FieldSource& source, const std::string& text,
                                                   const std::vector<predicates::Point2<Rational>>& points);

// The metric at every vertex of a tetrahedral mesh: a built-in 3D field's (fields/registry.hpp:
// constant and the UGAWG fields) at the vertices' nearest doubles, taken exactly, positive
// definiteness decided exactly; or a tetrahedral background mesh's, background:MESH[:METRIC], P1
// and exact (fields/background3.hpp). Throws InputError as above.
std::vector<predicates::Sym3<Rational>> metrics3_at(const std::string& text, const std::vector<std::string>& params,
                                                    const std::vector<predicates::Point3<Rational>>& points);
// The 3D field `text` names, in doubles, for the 3D refiner (issue 40): a built-in 3D field, or a
// tetrahedral background mesh's P1 metric (exact, rounded to the nearest doubles; a point outside
// it has no metric: fields::FieldError). Throws InputError as above.
fields::MetricField3 field3_source(const std::string& text, const std::vector<std::string>& params);

}  // namespace anisocert::io
