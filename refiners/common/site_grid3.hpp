#pragma once
// The 3D twin of site_grid.hpp: a uniform grid over Ω's bounding box for the 3D refiner's spatial
// queries (the sites in a box, the nearest site), and FiledBoxes3, boxes by id filed under the
// cells they cover (a star's conflict zone, a boundary facet's encroachment box). The grid grows
// with the sites (about two per cell); the boxes are filed again after a rebuild.
// Everything here only selects candidates: every decision on them is made by the caller.
#include "refiners/common/domain3.hpp"

#include <vector>

namespace anisocert::refiners::common {

// A block of grid cells (empty when i0 > i1).
struct Cells3 {
  int i0 = 0, i1 = -1, j0 = 0, j1 = -1, k0 = 0, k1 = -1;
  friend bool operator==(const Cells3&, const Cells3&) = default;
};

class SiteGrid3 {
 public:
  // An 8 × 8 × 8 grid over `extent`.
  explicit SiteGrid3(const Box3& extent);

  void add(int s, const Point3<double>& p) { sites_[cell_of(p)].push_back(s); }
  // More than four sites per cell on average: time to rebuild.
  bool outgrown(std::size_t sites) const { return sites > 4 * cell_count(); }
  // About two sites per cell (at most 128³ cells), every site filed again in index order.
  void rebuild(const std::vector<Point3<double>>& points);
  // The sites in a closed box, in a buffer reused across calls (valid until the next call).
  const std::vector<int>& sites_in(const Box3& b, const std::vector<Point3<double>>& points) const;

  std::size_t cell_count() const { return static_cast<std::size_t>(g_) * g_ * g_; }
  std::size_t cell_of(const Point3<double>& p) const { return cell(index(p.x, 0), index(p.y, 1), index(p.z, 2)); }
  std::size_t cell(int i, int j, int k) const { return (static_cast<std::size_t>(k) * g_ + j) * g_ + i; }
  Cells3 cells_of(const Box3& b) const {
    return {index(b.x0, 0), index(b.x1, 0), index(b.y0, 1), index(b.y1, 1), index(b.z0, 2), index(b.z1, 2)};
  }

 private:
  int index(double t, int axis) const;

  Box3 extent_;
  int g_ = 8;
  std::vector<std::vector<int>> sites_;
  mutable std::vector<int> found_;
};

// Boxes by id, each filed in the grid cells it covers.
class FiledBoxes3 {
 public:
  void reset(const SiteGrid3& grid);
  // Sets id's box (an empty box files it nowhere).
  void set(int id, const Box3& b, const SiteGrid3& grid);
  // Files every box again (after the grid was rebuilt).
  void refile(const SiteGrid3& grid);
  const Box3& box(int id) const { return boxes_[static_cast<std::size_t>(id)]; }
  // The ids whose closed boxes hold q, by increasing id, in a buffer reused across calls.
  const std::vector<int>& holding(const Point3<double>& q, const SiteGrid3& grid) const;

 private:
  void file(int id, const Cells3& c, const SiteGrid3& grid, bool add);

  std::vector<Box3> boxes_;
  std::vector<Cells3> cells_;
  std::vector<std::vector<int>> index_;
  mutable std::vector<int> found_;
};

}  // namespace anisocert::refiners::common
