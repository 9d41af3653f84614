// The 3D star refiner against the exact 3D certifier (issue 40; docs/fuzzing.md § Differential):
// a small polyhedron and a constant metric, decoded from bytes; budgets of 300 vertices and 3
// seconds. A run the refiner calls consistent must be certified exactly (oracle/, which shares no
// code with refiners/): a valid tetrahedralization (a closed boundary, tetrahedra on both sides
// of each inner face), locally uniform, radius-edge ratio <= rho0 and distortion <= gamma0, as
// it claims. A run that is not consistent must say why (its stop reason). Documented refusals are
// not findings: a parameter out of range (ParameterError), a field that is not a metric
// (FieldError), a domain the refiner refuses (DomainError).
// Shapes (dyadic coordinates, so that boundary splits are exact): a box w × h × d, a prism over
// a triangle, the L-shaped prism (a reflex ridge), the cube-cylinder. Metric: L Lᵀ with L lower
// triangular, its entries small integers (rotated and stretched up to about 16 : 1).
// Input: shape, three sizes, six metric entries, seed, rho0 and gamma0 scales; limit 32 bytes.
#include "fuzz/support/byte_source.hpp"
#include "fuzz/support/finding.hpp"
#include "geometry/builtin_polyhedra.hpp"
#include "oracle/certify/mesh_certifier3.hpp"
#include "refiners/registry.hpp"

#include <stdexcept>

using anisocert::fuzz::require;
using anisocert::Rational;
namespace refiners = anisocert::refiners;
using anisocert::geometry::Polyhedron;

namespace {

Polyhedron shape(unsigned k, unsigned a, unsigned b, unsigned c) {
  const Rational w(1 + a % 4, 2), h(1 + b % 4, 2), d(1 + c % 4, 2);  // 1/2 … 2
  switch (k % 4) {
    case 1: return anisocert::geometry::prism_polyhedron({{0, 0}, {w, 0}, {w / 4, h}}, d);
    case 2: return anisocert::geometry::prism_polyhedron({{0, 0}, {w, 0}, {w, h / 2}, {w / 2, h / 2}, {w / 2, h}, {0, h}}, d);
    case 3: return anisocert::geometry::cube_cylinder_polyhedron(4);
    default: return anisocert::geometry::prism_polyhedron({{0, 0}, {w, 0}, {w, h}, {0, h}}, d);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 32) return -1;
  anisocert::fuzz::ByteSource b(data, size);
  const unsigned k = b.next(), sa = b.next(), sb = b.next(), sc = b.next();
  const auto entry = [](int v, int lo, int hi) { return static_cast<double>(lo + v % (hi - lo + 1)); };
  const double l1 = entry(b.next(), 1, 4), l2 = entry(b.next(), 1, 4), l3 = entry(b.next(), 1, 4);
  const double l21 = entry(b.next(), -2, 2), l31 = entry(b.next(), -2, 2), l32 = entry(b.next(), -2, 2);
  const anisocert::predicates::Sym3<double> M{l1 * l1, l1 * l21, l1 * l31, l21 * l21 + l2 * l2, l21 * l31 + l2 * l32,
                                              l31 * l31 + l32 * l32 + l3 * l3};
  const unsigned seed = b.next();
  const refiners::RefinerEntry& star = *refiners::find_refiner("star");
  refiners::ParameterValues rp = star.defaults();
  rp["rho0"] *= 1 + (b.next() % 3) / 2.0;     // 3, 4.5, 6
  rp["gamma0"] = 1.25 + (b.next() % 3) / 4.0;  // 1.25, 1.5, 1.75
  refiners::Run3 run;
  try {
    const refiners::common::Domain3 domain(shape(k, sa, sb, sc));
    const anisocert::fields::MetricField3 field{"constant", {}, [M](double, double, double) { return M; }};
    refiners::common::Budget budget;
    budget.max_vertices = 300;
    budget.max_seconds = 3;
    run = star.run3(domain, field, rp, budget, seed, {});
  } catch (const refiners::ParameterError&) {
    return 0;
  } catch (const refiners::common::FieldError&) {
    return 0;
  } catch (const refiners::common::DomainError&) {
    return 0;
  }
  if (!run.result.consistent) {
    require(!run.result.stop_reason.empty(), "star (3D): a run that is not consistent gives no reason");
    return 0;
  }
  const auto& m = run.result.mesh;
  anisocert::geometry::Mesh3<Rational> exact;
  for (const auto& q : m.vertices) exact.vertices.push_back({Rational(q.x), Rational(q.y), Rational(q.z)});
  for (const auto& N : m.metrics) exact.metrics.push_back({Rational(N.m11), Rational(N.m12), Rational(N.m13), Rational(N.m22), Rational(N.m23), Rational(N.m33)});
  exact.tetrahedra = m.tetrahedra, exact.triangles = m.triangles;
  anisocert::oracle::Certify3Options o;
  o.rho0 = anisocert::rational_from_double(rp.at("rho0")), o.gamma0 = anisocert::rational_from_double(rp.at("gamma0"));
  o.threads = 1;
  const auto report = anisocert::oracle::certify_mesh3(exact, o);
  require(report.valid_holds(), "star (3D) called its run consistent, but the mesh is not a valid tetrahedralization");
  require(report.holds(o), "star (3D) called its run consistent, but the certifier refutes what it claims");
  return 0;
}
