#pragma once
// The site-set input file: sites with their metrics, the domain polygon and the constrained
// segments, read exactly and validated (DESIGN.md § Command line and files).

#include "numbers/rational.hpp"
#include "predicates/metric.hpp"
#include "predicates/point.hpp"

#include <array>
#include <istream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace anisocert::io {

struct SiteSet {
  std::vector<predicates::Point2<Rational>> sites;
  std::vector<predicates::Metric2> metrics;          // metrics[i] belongs to sites[i]
  std::vector<predicates::Point2<Rational>> domain;  // simple polygon, counter-clockwise, validated
  bool domain_given = false;                         // false: the default box was built
  std::vector<std::pair<int, int>> segments;         // constrained segments by site index
  std::vector<std::array<int, 3>> triangles;         // a mesh's triangles by site index (mesh files)
};

// Bad input: what() is one line naming the source (file name), the JSON path or index, and what
// is wrong, e.g. "sites.json: sites[3].metric: metric [1, 2, 1] is not positive definite: ...".
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Reads
//   {"sites": [{"x": X, "y": Y, "metric": [m11, m12, m22]}, ...],   required, non-empty
//    "domain": [[X, Y], ...],                                        optional, >= 3 vertices
//    "segments": [[i, j], ...],                                      optional
//    "triangles": [[i, j, k], ...]}                                  optional (mesh files)
// where a number is a JSON string (integer, fraction or decimal, see parse_rational) or a plain
// JSON number, both taken exactly from their text (0.1 is 1/10). Checks, exactly: every metric is
// positive definite; the domain is a simple counter-clockwise polygon (consecutive collinear
// vertices allowed when the boundary runs straight on); no two sites coincide; every site lies
// in the closed domain; segments join two distinct existing sites and none repeats; triangles
// name three distinct existing sites (whether they form a mesh is the certifier's verdict).
// Without "domain", the domain is the sites' bounding box enlarged on every side by
// max(width, height)/8 (by 1 when both are 0), counter-clockwise from the lower left corner.
// Throws InputError; source_name is the file name used in messages.
SiteSet read_site_set(std::istream& in, const std::string& source_name);

// The validated "domain" of a file in this format (for the refiners; "sites" may be absent).
std::vector<predicates::Point2<Rational>> read_domain_file(const std::string& path);

// read_site_set on the file at path; a file that cannot be opened is an InputError too.
SiteSet read_site_set_file(const std::string& path);

}  // namespace anisocert::io
