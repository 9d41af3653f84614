#pragma once
// The refiners by name: what `anisocert refine --algo NAME` runs (registry.cpp lists them, one line
// each). An entry names its parameters (each becomes an option --NAME of `refine`, with its
// default and meaning), runs on a domain and a metric field within the budgets every run has, and
// writes the lines of its report: the common ones (common/summary.hpp) and its own.
#include "fields/metric_field.hpp"
#include "refiners/common/domain.hpp"
#include "refiners/common/domain3.hpp"
#include "refiners/common/refinement_loop.hpp"

#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace anisocert::refiners {

// A parameter out of range: what() names the option and the range.
struct ParameterError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

struct ParameterSpec {
  std::string name;  // the option --name
  std::string help;
  double value;      // the default
  bool flag = false;  // an option without a value: given, 1; else 0 (the default)
};
using ParameterValues = std::map<std::string, double>;  // a value for every parameter of the entry

struct Run {
  common::RefineResult result;
  std::vector<std::string> report;  // the summary, one line each
};
struct Run3 {
  common::RefineResult3 result;
  std::vector<std::string> report;
};

struct RefinerEntry {
  std::string name, summary;
  std::vector<ParameterSpec> parameters;
  // Every parameter at its default.
  ParameterValues defaults() const {
    ParameterValues v;
    for (const ParameterSpec& p : parameters) v[p.name] = p.value;
    return v;
  }
  // Throws ParameterError naming a parameter out of range, common::DomainError for a domain the
  // refiner cannot use, common::FieldError for a field that is not a metric where it is sampled.
  std::function<Run(const common::Domain&, const fields::MetricField&, const ParameterValues&, const common::Budget&,
                    unsigned seed, const common::Progress&)>
      run;
  // Whether a finished run's mesh is the dual of the exact anisotropic Voronoi diagram of its
  // vertices (LS §7, Theorem 7): then `anisocert dual` checks it and `refine --svg` draws that
  // diagram with its dual; otherwise `anisocert certify` checks it (LU's stars) and --svg draws
  // the mesh.
  bool dual_of_diagram = false;
  // The command that checks a finished run against the refiner's own paper.
  std::string check() const { return dual_of_diagram ? "anisocert dual" : "anisocert certify"; }
  bool seeded = false;  // the run draws random points from `seed` (otherwise --seed is bad input)
  // The run on a polyhedron for a 3D field (issue 40), for the refiners that mesh in 3D (empty
  // otherwise); throws as `run` does.
  std::function<Run3(const common::Domain3&, const fields::MetricField3&, const ParameterValues&, const common::Budget&,
                     unsigned seed, const common::Progress&)>
      run3;
};

const std::vector<RefinerEntry>& registered_refiners();
std::vector<std::string> refiner_names();
// The entry called `name`, or nullptr.
const RefinerEntry* find_refiner(const std::string& name);

}  // namespace anisocert::refiners
