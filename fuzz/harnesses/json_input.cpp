// The project's JSON input (docs/fuzzing.md § Parsers): one text read as a site set or mesh
// (read_mesh_json, the input of `diagram`), as a domain file (read_domain_file, `refine --domain`,
// then refiners::common::Domain, which checks a PSLG's points and interior segments exactly, and
// refuses in one short line too) and as the mesh format "json" (the properties of fuzz/support/mesh_reader_check.hpp: one short
// line for bad input, an exact round trip through mesh_json, a small mesh certified).
// A site set read is also written back by mesh_json and read again, unchanged.
// Limit: 256 KiB (-max_len in fuzz/campaign): room for JSON nested tens of thousands deep.
#include "fuzz/support/finding.hpp"
#include "fuzz/support/input_files.hpp"
#include "fuzz/support/mesh_reader_check.hpp"
#include "fuzz/support/message_contract.hpp"
#include "io/mesh_json.hpp"
#include "refiners/common/domain.hpp"

#include <sstream>

using anisocert::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 262144) return -1;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    std::istringstream in(text);
    const auto m = anisocert::io::read_mesh_json(in, "fuzz-input.json");
    if (!m.metrics.empty()) {
      std::istringstream again(anisocert::io::mesh_json(m));
      const auto n = anisocert::io::read_mesh_json(again, "written.json");
      require(n.sites.size() == m.sites.size() && n.triangles == m.triangles && n.segments == m.segments &&
                  n.domain.size() == m.domain.size(),
              "mesh_json then read_mesh_json changed the mesh");
      for (std::size_t i = 0; i < m.sites.size(); ++i)
        require(n.sites[i].x == m.sites[i].x && n.sites[i].y == m.sites[i].y && n.metrics[i].m11 == m.metrics[i].m11 &&
                    n.metrics[i].m12 == m.metrics[i].m12 && n.metrics[i].m22 == m.metrics[i].m22,
                "mesh_json then read_mesh_json changed site " + std::to_string(i));
    }
  } catch (const anisocert::io::InputError& e) {
    anisocert::fuzz::require_one_short_line(e.what(), "fuzz-input");
  }
  try {
    const auto d = anisocert::io::read_domain_file(anisocert::fuzz::write_scratch(".json", text));
    (void)anisocert::refiners::common::Domain::from_exact(d.corners, d.points, d.interior_segments);
  } catch (const anisocert::io::InputError& e) {
    anisocert::fuzz::require_one_short_line(e.what(), "fuzz-input");
  } catch (const anisocert::refiners::common::DomainError& e) {
    anisocert::fuzz::require_one_short_line(e.what(), "");
  }
  static const anisocert::fuzz::MeshReaderCase json{"json", {".json"}, "", false};
  anisocert::fuzz::check_mesh_reader(json, data, size);
  return 0;
}
