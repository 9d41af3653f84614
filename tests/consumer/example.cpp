#include <api/anisocert.hpp>
#include <iostream>

int main() {
  anisocert::DoubleMesh mesh;                                          // your mesher's output
  mesh.sites = {{0, 0}, {0.2, 0}, {0.2, 0.2}, {0, 0.2}, {0.1, 0.1}};
  mesh.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};     // counter-clockwise
  const std::vector<anisocert::DoubleMetric> metrics(5, {100, 10, 400});  // m11, m12, m22 per site
  const anisocert::Certificate c = anisocert::certify(mesh, metrics);
  if (!c.holds) std::cerr << c.text("square");                        // the witnesses
  return c.holds ? 0 : 1;
}
