#pragma once
// The witnesses of one check of the mesh certifier (mesh_certifier.hpp, metric_checks.hpp): each
// a configuration someone else can check (DESIGN.md § Certificates) — the vertex whose metric
// decides, the triangle, the site or the other end of an edge. A bad mesh from another mesher has
// one per triangle, a million for a million triangles: every one is counted and located (what a
// picture colours, 12 bytes each), and only the first `limit`, in the order found, are described
// in full (with their text), so that a report stays bounded. The verdict needs only the count.
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace anisocert::oracle {

// A limit that describes every witness.
inline constexpr std::size_t all_witnesses = std::numeric_limits<std::size_t>::max();
// The default: the first 100 of each list (`anisocert certify`'s, docs/cli.md).
inline constexpr std::size_t default_described_witnesses = 100;

// One offending (or tied) configuration: the vertex whose metric decides, the triangle, the site
// (or the other end of an edge); -1 where it names none.
struct WitnessPlace {
  int vertex = -1, triangle = -1, site = -1;
};

struct MeshWitness : WitnessPlace {
  std::string text;
};

class WitnessList {
 public:
  explicit WitnessList(std::size_t limit = all_witnesses) : limit_(limit) {}

  // Counts and locates a witness; describes it while fewer than `limit` are, with text(), a
  // callable giving its std::string (not called otherwise: a million texts are not built).
  template <class Text>
  void add(int vertex, int triangle, int site, Text&& text) {
    places_.push_back({vertex, triangle, site});
    if (described_.size() < limit_) described_.push_back({{vertex, triangle, site}, std::forward<Text>(text)()});
  }

  std::size_t count() const { return places_.size(); }          // every witness found, exactly
  bool empty() const { return places_.empty(); }
  const std::vector<WitnessPlace>& places() const { return places_; }      // every one, in order
  // A list iterates over every witness's place (`for (const auto& w : list) ... w.triangle`).
  auto begin() const { return places_.begin(); }
  auto end() const { return places_.end(); }
  const std::vector<MeshWitness>& described() const { return described_; } // the first min(count, limit)
  std::size_t limit() const { return limit_; }

 private:
  std::size_t limit_;
  std::vector<WitnessPlace> places_;
  std::vector<MeshWitness> described_;
};

}  // namespace anisocert::oracle
