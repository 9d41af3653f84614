// Every registered refiner against the exact certifier (docs/fuzzing.md § Differential): a small
// domain, a built-in field with scaled parameters and the refiner's parameters (scaled, a flag on a byte's parity), all decoded from
// bytes; budgets of 300 vertices and 3 seconds. A run the refiner calls consistent must be
// certified exactly (oracle/, which shares no code with refiners/):
//   - every refiner: a valid triangulation of the domain (and of its constrained segments);
//   - star (BWY locally uniform meshing): locally uniform, radius-edge ratio <= rho0 and
//     distortion <= gamma0, as it claims;
//   - ls and bwy (the refiners whose mesh is the dual of the diagram, RefinerEntry::dual_of_diagram):
//     the dual of the exact anisotropic Voronoi diagram of its sites, a triangulation of Ω; for ls
//     (Labelle–Shewchuk Voronoi refinement) that diagram has no orphans and meets LS Theorem 7's
//     preconditions, which BWY's overlap-driven refinement does not promise.
// Documented refusals are not findings: a parameter out of range (ParameterError), a field
// parameter out of range (std::invalid_argument from make_field), a field that is not a metric
// where it is sampled (FieldError), an oracle that refuses a final mesh as beyond what it supports
// (std::domain_error). A run that is not consistent must say why (its stop reason).
// Input: refiner, field, shape, seed, then one byte per field parameter and per refiner
// parameter; limit 64 bytes.
#include "fields/registry.hpp"
#include "fuzz/support/byte_source.hpp"
#include "fuzz/support/finding.hpp"
#include "geometry/mesh.hpp"
#include "oracle/certify/mesh_certifier.hpp"
#include "oracle/diagram/diagram.hpp"
#include "oracle/diagram/mesh_dual.hpp"
#include "refiners/registry.hpp"

#include <cmath>
#include <stdexcept>

using anisocert::fuzz::require;
namespace refiners = anisocert::refiners;
namespace fields = anisocert::fields;
using Polygon = anisocert::geometry::Polygon<double>;

namespace {

// Domains of the unit's size with exact dyadic corners: the unit square, a stretched rectangle,
// a triangle with an obtuse corner, the L-shape (a reflex corner) and a convex pentagon.
Polygon shape(unsigned k, unsigned stretch) {
  const double w = 0.5 + 0.25 * (stretch % 7);
  switch (k % 5) {
    case 1: return {{0, 0}, {w, 0}, {w, 0.25}, {0, 0.25}};
    case 2: return {{0, 0}, {1, 0}, {-0.25, w}};
    case 3: return {{0, 0}, {1, 0}, {1, 0.5}, {0.5, 0.5}, {0.5, 1}, {0, 1}};
    case 4: return {{0, 0}, {2, 0}, {2.5, 1}, {1, 1.75}, {-0.5, 1}};
    default: return {{0, 0}, {w, 0}, {w, w}, {0, w}};
  }
}

// A parameter's default scaled by one of 1/2, 3/4, 1, 3/2, 2 (a byte's choice).
double scaled(double value, unsigned b) {
  static const double factors[] = {0.5, 0.75, 1, 1.5, 2};
  return value * factors[b % 5];
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 64) return -1;
  anisocert::fuzz::ByteSource b(data, size);
  const auto& entries = refiners::registered_refiners();
  const refiners::RefinerEntry& entry = entries[b.next() % entries.size()];
  const auto& builtin = fields::builtin_fields();
  const fields::FieldEntry& field_entry = builtin[b.next() % builtin.size()];
  const unsigned k = b.next(), stretch = b.next();
  const Polygon corners = shape(k, stretch);
  const unsigned seed = b.next();
  fields::Parameters fp;
  for (const auto& [name, value] : field_entry.defaults) fp[name] = scaled(value, b.next());
  refiners::ParameterValues rp = entry.defaults();
  for (const auto& spec : entry.parameters) rp[spec.name] = spec.flag ? b.next() % 2 : scaled(spec.value, b.next());

  refiners::Run run;
  try {
    const fields::MetricField field = fields::make_field(field_entry.name, fp);
    const refiners::common::Domain domain(corners);
    refiners::common::Budget budget;
    budget.max_vertices = 300;
    budget.max_seconds = 3;
    run = entry.run(domain, field, rp, budget, seed, {});
  } catch (const refiners::ParameterError&) {
    return 0;
  } catch (const fields::FieldError&) {
    return 0;
  } catch (const std::invalid_argument&) {
    return 0;  // make_field: a parameter out of range, named
  }
  if (!run.result.consistent) {
    require(!run.result.stop_reason.empty(), entry.name + ": a run that is not consistent gives no reason");
    return 0;
  }
  anisocert::oracle::CertifyOptions o;
  o.uniform = entry.name == "star";
  o.metric = false;
  if (entry.name == "star") {
    o.rho0 = anisocert::rational_from_double(rp.at("rho0"));
    o.gamma0 = anisocert::rational_from_double(rp.at("gamma0"));
  }
  const auto report = anisocert::oracle::certify_mesh(anisocert::geometry::exact(run.result.mesh), o);
  require(report.valid_holds(), entry.name + " called its run consistent, but the mesh is not a valid triangulation of the domain");
  require(report.holds(o), entry.name + " called its run consistent, but the certifier refutes what it claims (" +
                               field_entry.name + " field)");
  if (entry.dual_of_diagram) {
    anisocert::oracle::Diagram d;
    try {
      d = anisocert::oracle::compute_diagram(anisocert::geometry::exact(run.result.mesh));
    } catch (const std::domain_error&) {
      return 0;  // the oracle's documented refusal (distances doubles cannot tell apart), not a finding
    }
    require(d.dual_check.is_triangulation && anisocert::oracle::compare_with_dual(d, run.result.mesh.triangles, 1).is_dual(),
            entry.name + " called its run finished, but the mesh is not the dual of the exact diagram of its sites, or that dual is no "
                         "triangulation of the domain");
    if (entry.name == "ls") {
      bool orphans = false;
      for (const auto& f : d.faces) orphans = orphans || f.orphan;
      require(!orphans && d.theorem7.preconditions_hold, "ls called its run finished, but the exact diagram of its sites has orphans or fails "
                                                         "Theorem 7's preconditions");
    }
  }
  return 0;
}
