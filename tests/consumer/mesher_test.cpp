// A mesher's own test against the installed anisocert package (docs/api.md): its mesh, in doubles,
// is certified exactly; a broken one is not; the mesh survives a Medit round trip exactly; bad
// input throws what the API says it throws. Exit 0 when every check passes, 1 with the failures.
// Usage: mesher_test [DIR]   (DIR: where the Medit files go; default ".")
#include <api/anisocert.hpp>

#include <iostream>
#include <stdexcept>
#include <string>

namespace {

int failures = 0;

void check(bool ok, const std::string& what) {
  std::cout << (ok ? "ok: " : "FAIL: ") << what << "\n";
  if (!ok) ++failures;
}

// Whether f() throws E with a message containing fragment.
template <class E, class F>
bool throws(F f, const std::string& fragment) {
  try {
    f();
  } catch (const E& e) {
    if (std::string(e.what()).find(fragment) != std::string::npos) return true;
    std::cout << "  (message: " << e.what() << ")\n";
  } catch (const std::exception& e) {
    std::cout << "  (another exception: " << e.what() << ")\n";
  }
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";

  // The docs/api.md example: a 0.2 x 0.2 square, its centre joined to its corners, one constant
  // anisotropic metric. 0.1 and 0.2 are doubles: the rationals they are, not 1/10 and 1/5.
  anisocert::DoubleMesh mesh;
  mesh.sites = {{0, 0}, {0.2, 0}, {0.2, 0.2}, {0, 0.2}, {0.1, 0.1}};
  mesh.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  const std::vector<anisocert::DoubleMetric> metrics(5, {100, 10, 400});
  const anisocert::Certificate c = anisocert::certify(mesh, metrics);
  if (!c.holds) std::cerr << c.text("square");
  check(c.holds, "the square is certified (valid, locally uniform)");
  check(c.text("square").find("certified") != std::string::npos, "its text says so");
  check(c.json().find("\"holds\": true") != std::string::npos, "its JSON says so");

  // The metric checks, with bounds as verdicts: radius-edge ratio (about 1.14 here), distortion
  // (1: one metric), angles in the metrics (about 26 degrees).
  anisocert::CertifyOptions bounds;
  bounds.metric = true, bounds.rho0 = anisocert::Rational(6, 5), bounds.gamma0 = anisocert::Rational(1);
  bounds.min_angle = anisocert::Rational(25);
  const anisocert::Certificate q = anisocert::certify(mesh, metrics, bounds);
  if (!q.holds) std::cerr << q.text("square");
  check(q.holds && q.report.lengths && q.report.angles, "with rho0 = 6/5, gamma0 = 1, angles >= 25 degrees too");
  bounds.rho0 = anisocert::Rational(1);
  const anisocert::Certificate r = anisocert::certify(mesh, metrics, bounds);
  check(!r.holds && r.report.rho_violations.count() == 2, "not with rho0 = 1: two triangles exceed it");

  // One triangle clockwise: not a triangulation.
  anisocert::DoubleMesh broken = mesh;
  std::swap(broken.triangles[0][0], broken.triangles[0][1]);
  const anisocert::Certificate b = anisocert::certify(broken, metrics);
  check(!b.holds, "a clockwise triangle is not certified");
  check(b.report.valid && !b.report.valid->is_triangulation, "validity is the check that fails");
  check(b.text("broken").find("not certified") != std::string::npos, "its text says so");

  // A Medit .mesh (and its .sol) written and read back: the same rationals.
  anisocert::Mesh exact = anisocert::exact_mesh(mesh);
  for (const auto& m : metrics) exact.metrics.push_back({m.m11, m.m12, m.m22});
  const std::vector<std::string> written = anisocert::write_mesh(exact, dir + "/square.mesh");
  check(written.size() == 2, "write_mesh writes square.mesh and square.sol");
  const anisocert::MeshFile back = anisocert::read_mesh(dir + "/square.mesh", dir + "/square.sol");
  bool same = back.mesh.sites.size() == exact.sites.size() && back.mesh.triangles == exact.triangles &&
              back.mesh.metrics.size() == exact.metrics.size();
  for (std::size_t i = 0; same && i < exact.sites.size(); ++i)
    same = back.mesh.sites[i].x == exact.sites[i].x && back.mesh.sites[i].y == exact.sites[i].y &&
           back.mesh.metrics[i].m11 == exact.metrics[i].m11 && back.mesh.metrics[i].m12 == exact.metrics[i].m12 &&
           back.mesh.metrics[i].m22 == exact.metrics[i].m22;
  check(same, "read_mesh gives back exactly what write_mesh wrote");
  check(back.mesh.sites[1].x != anisocert::Rational(1, 5), "0.2 is the double's rational, not 1/5");
  check(anisocert::certify(back.mesh).holds, "the mesh read back is certified with its own metrics");

  // What throws.
  std::vector<anisocert::DoubleMetric> bad = metrics;
  bad[3] = {1, 2, 1};
  check(throws<std::invalid_argument>([&] { anisocert::certify(mesh, bad); }, "metrics[3]"),
        "a metric that is not positive definite: std::invalid_argument naming it");
  check(throws<std::invalid_argument>([&] { anisocert::certify(mesh, {{1, 0, 1}}); }, "1 metrics for 5 sites"),
        "a metric count other than the site count: std::invalid_argument");
  anisocert::DoubleMesh dangling = mesh;
  dangling.triangles[2][1] = 7;
  check(throws<std::invalid_argument>([&] { anisocert::certify(dangling, metrics); }, "triangles[2]"),
        "a triangle naming no site: std::invalid_argument naming it");
  check(throws<anisocert::InputError>([&] { anisocert::read_mesh(dir + "/no such file.mesh"); }, "no such file.mesh"),
        "a missing file: anisocert::InputError naming it");
  check(throws<anisocert::InputError>([&] { anisocert::write_mesh(exact, dir + "/square.unknown"); }, "square.unknown"),
        "an unknown extension: anisocert::InputError naming it");

  // A tetrahedral mesh (issue 39): two tetrahedra across the face (0,0,0), (1,0,0), (0,1,0), the
  // second apex at (0.3, 0.3, -0.1) inside the first's circumsphere (centre (1/2, 1/2, 1/2),
  // radius^2 3/4; the apex at distance^2 0.44): valid, not locally uniform for M = I; with
  // M = diag(1, 1, 10^4) (z squashed) the apexes are far outside each other's ellipsoids.
  anisocert::DoubleMesh3 tets;
  tets.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.3, 0.3, -0.1}};
  tets.tetrahedra = {{0, 1, 2, 3}, {0, 2, 1, 4}};
  const anisocert::Certificate3 flip = anisocert::certify(tets, std::vector<anisocert::DoubleMetric3>(5, {1, 0, 0, 1, 0, 1}));
  check(!flip.holds && flip.report.valid_holds() && flip.report.uniform_violations.count() == 2,
        "two tetrahedra across a face that should flip: valid, each named once");
  check(flip.json().find("\"tetrahedra\": 2") != std::string::npos, "its JSON counts the tetrahedra");
  const anisocert::Certificate3 squashed = anisocert::certify(tets, std::vector<anisocert::DoubleMetric3>(5, {1, 0, 0, 1, 0, 1e4}));
  if (!squashed.holds) std::cerr << squashed.text("two tetrahedra");
  check(squashed.holds, "with z squashed by the metric they are certified");
  check(throws<std::invalid_argument>([&] { anisocert::certify(tets, std::vector<anisocert::DoubleMetric3>(5, {-1, 0, 0, -1, 0, 1})); },
                                      "metrics[0]"),
        "diag(-1, -1, 1) (det +1) is no metric: std::invalid_argument naming it");

  std::cout << (failures ? std::to_string(failures) + " failed\n" : "all passed\n");
  return failures ? 1 : 0;
}
