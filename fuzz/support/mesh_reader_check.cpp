#include "fuzz/support/mesh_reader_check.hpp"

#include "fuzz/support/finding.hpp"
#include "fuzz/support/input_files.hpp"
#include "fuzz/support/message_contract.hpp"
#include "io/formats/registry.hpp"
#include "oracle/certify/mesh_certifier.hpp"
#include "oracle/certify/mesh_certifier3.hpp"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

namespace anisocert::fuzz {
namespace {

// The certifier's own work grows with the mesh: a parser input beyond this is read, not certified.
constexpr std::size_t max_certified_triangles = 64;

bool is_metric_file(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  for (const io::MetricFormat& f : io::metric_formats())
    if (std::find(f.extensions.begin(), f.extensions.end(), ext) != f.extensions.end()) return true;
  return false;
}

// Reads the written files back: the first mesh file among them, its metric file when one was written.
io::MeshFile read_written(const std::vector<io::FileText>& files, const std::string& format, const io::ReadOptions& o) {
  std::string mesh_path, metric_path;
  for (const io::FileText& f : files) {
    if (is_metric_file(f.path)) {
      if (metric_path.empty()) metric_path = f.path;
    } else if (mesh_path.empty()) {
      mesh_path = f.path;
    }
  }
  require(!mesh_path.empty(), format + " writer wrote no mesh file");
  return io::read_mesh_file(mesh_path, format, o, metric_path);
}

void require_same3(const io::MeshFile& a, const io::MeshFile& b, const std::string& format) {
  const auto& m = a.mesh3;
  const auto& n = b.mesh3;
  require(b.dimension == 3, format + " round trip lost the third dimension");
  require(m.vertices.size() == n.vertices.size(), format + " round trip changed the vertex count");
  for (std::size_t i = 0; i < m.vertices.size(); ++i)
    require(m.vertices[i].x == n.vertices[i].x && m.vertices[i].y == n.vertices[i].y && m.vertices[i].z == n.vertices[i].z,
            format + " round trip changed vertex " + std::to_string(i + 1));
  require(m.tetrahedra == n.tetrahedra, format + " round trip changed the tetrahedra");
  require(m.triangles == n.triangles, format + " round trip changed the triangles");
  if (!m.metrics.empty() && !n.metrics.empty()) require(m.metrics == n.metrics, format + " round trip changed the metrics");
}

void require_same(const io::MeshFile& a, const io::MeshFile& b, const std::string& format) {
  if (a.dimension == 3) return require_same3(a, b, format);
  const auto& m = a.mesh;
  const auto& n = b.mesh;
  require(m.sites.size() == n.sites.size(), format + " round trip changed the vertex count");
  for (std::size_t i = 0; i < m.sites.size(); ++i)
    require(m.sites[i].x == n.sites[i].x && m.sites[i].y == n.sites[i].y,
            format + " round trip changed vertex " + std::to_string(i + 1));
  require(m.triangles == n.triangles, format + " round trip changed the triangles");
  require(m.edges == n.edges, format + " round trip changed the edges");
  if (!m.metrics.empty() && !n.metrics.empty()) {
    for (std::size_t i = 0; i < m.metrics.size(); ++i)
      require(m.metrics[i].m11 == n.metrics[i].m11 && m.metrics[i].m12 == n.metrics[i].m12 &&
                  m.metrics[i].m22 == n.metrics[i].m22,
              format + " round trip changed the metric of vertex " + std::to_string(i + 1));
  }
}

void certify_small(const io::MeshFile& f) {
  if (f.dimension == 3) {
    if (f.mesh3.tetrahedra.size() <= max_certified_triangles && f.mesh3.vertices.size() <= 4 * max_certified_triangles) {
      oracle::Certify3Options o;
      o.uniform = o.metric = !f.mesh3.metrics.empty();
      o.threads = 1;  // a small mesh per input: threads would cost more than they save
      (void)oracle::certify_mesh3(f.mesh3, o);
    }
    return;
  }
  const auto& m = f.mesh;
  if (m.triangles.size() > max_certified_triangles || m.sites.size() > 3 * max_certified_triangles) return;
  oracle::CertifyOptions o;
  o.uniform = !m.metrics.empty();
  o.metric = !m.metrics.empty();
  o.threads = 1;
  try {
    (void)oracle::certify_mesh(m, o);
  } catch (const std::invalid_argument&) {
    // documented: a mesh the certifier cannot take, named by index
  }
}

// The round trip's files of the previous input go first (a Medit .sol left over would be read).
void remove_round_trip_files() {
  for (const io::MeshFormat& f : io::mesh_formats())
    for (const std::string& ext : f.extensions) remove_scratch(".roundtrip" + ext);
  for (const io::MetricFormat& f : io::metric_formats())
    for (const std::string& ext : f.extensions) remove_scratch(".roundtrip" + ext);
}

}  // namespace

void check_mesh_reader(const MeshReaderCase& c, const std::uint8_t* data, std::size_t size) {
  const std::size_t n_files = c.mesh_extensions.size() + (c.metric_extension.empty() ? 0 : 1);
  const std::vector<std::string_view> parts = split_files(data, size, n_files);
  std::vector<std::string> extensions = c.mesh_extensions;
  if (!c.metric_extension.empty()) extensions.push_back(c.metric_extension);
  // A file the input does not hold must not be left over from the previous input.
  for (std::size_t i = 0; i < extensions.size(); ++i) {
    if (i < parts.size())
      write_scratch(extensions[i], parts[i]);
    else
      remove_scratch(extensions[i]);
  }
  const std::string mesh_path = scratch_path(c.mesh_extensions[0]);
  const std::string metric_path =
      !c.metric_extension.empty() && parts.size() == n_files ? scratch_path(c.metric_extension) : std::string();
  io::ReadOptions options;
  options.planar_3d = c.planar_3d;

  io::MeshFile read;
  try {
    read = io::read_mesh_file(mesh_path, c.format, options, metric_path);
  } catch (const io::InputError& e) {
    require_one_short_line(e.what(), "fuzz-input");
    return;
  }
  certify_small(read);

  const io::MeshFormat& format = io::mesh_format_of(mesh_path, c.format);
  remove_round_trip_files();
  std::vector<io::FileText> written;
  try {
    written = format.write(read, scratch_path(".roundtrip" + c.mesh_extensions[0]));
  } catch (const io::InputError& e) {
    require_one_short_line(e.what(), "");
    return;  // a number this format cannot hold exactly: refused, not rounded
  }
  for (io::FileText& f : written) {
    const std::string ext = std::filesystem::path(f.path).extension().string();
    f.path = write_scratch(".roundtrip" + ext, f.content);
  }
  io::MeshFile again;
  try {
    again = read_written(written, c.format, options);
  } catch (const io::InputError& e) {
    finding(c.format + " cannot read what its writer wrote: " + e.what());
  }
  require_same(read, again, c.format);
}

}  // namespace anisocert::fuzz
