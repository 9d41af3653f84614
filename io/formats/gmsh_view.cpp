#include "io/formats/gmsh_view.hpp"

namespace anisocert::io {

std::vector<FileText> write_gmsh_view(const MeshFile& m, const std::string& path) {
  require_triangle_mesh(m, "a Gmsh tensor view");
  const geometry::Mesh<Rational>& mesh = m.mesh;
  if (mesh.metrics.empty()) throw InputError(path + ": a Gmsh tensor view needs a metric at every vertex");
  std::vector<std::string> xy, tensor;
  for (std::size_t i = 0; i < mesh.sites.size(); ++i) {
    const std::string what = path + ": vertex " + std::to_string(i);
    xy.push_back(decimal_text(mesh.sites[i].x, what + ": x") + "," + decimal_text(mesh.sites[i].y, what + ": y") + ",0");
    const auto& M = mesh.metrics[i];
    const std::string m11 = decimal_text(M.m11, what + ": m11"), m12 = decimal_text(M.m12, what + ": m12"),
                      m22 = decimal_text(M.m22, what + ": m22"), m33 = decimal_text(M.m11 + M.m22, what + ": m11 + m22");
    tensor.push_back(m11 + "," + m12 + ",0," + m12 + "," + m22 + ",0,0,0," + m33);
  }
  std::string s = "View \"metric\" {\n";
  for (const auto& t : mesh.triangles)
    s += "TT(" + xy[t[0]] + "," + xy[t[1]] + "," + xy[t[2]] + "){" + tensor[t[0]] + "," + tensor[t[1]] + "," + tensor[t[2]] + "};\n";
  s += "};\n";
  return {{path, s}};
}

}  // namespace anisocert::io
