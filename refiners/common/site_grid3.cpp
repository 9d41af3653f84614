#include "refiners/common/site_grid3.hpp"

#include <algorithm>
#include <cmath>

namespace anisocert::refiners::common {

SiteGrid3::SiteGrid3(const Box3& extent) : extent_(extent), sites_(cell_count()) {}

int SiteGrid3::index(double t, int axis) const {
  const double lo = axis == 0 ? extent_.x0 : axis == 1 ? extent_.y0 : extent_.z0;
  const double hi = axis == 0 ? extent_.x1 : axis == 1 ? extent_.y1 : extent_.z1;
  const double u = (t - lo) / (hi - lo) * g_;
  if (!(u > 0)) return 0;  // also NaN
  return u >= g_ ? g_ - 1 : static_cast<int>(u);
}

void SiteGrid3::rebuild(const std::vector<Point3<double>>& points) {
  g_ = std::clamp(static_cast<int>(std::cbrt(static_cast<double>(points.size()) / 2)) + 1, 8, 128);
  sites_.assign(cell_count(), {});
  for (int s = 0; s < static_cast<int>(points.size()); ++s) add(s, points[s]);
}

const std::vector<int>& SiteGrid3::sites_in(const Box3& b, const std::vector<Point3<double>>& points) const {
  found_.clear();
  const Cells3 c = cells_of(b);
  for (int k = c.k0; k <= c.k1; ++k)
    for (int j = c.j0; j <= c.j1; ++j)
      for (int i = c.i0; i <= c.i1; ++i)
        for (int s : sites_[cell(i, j, k)])
          if (b.contains(points[s])) found_.push_back(s);
  std::sort(found_.begin(), found_.end());
  return found_;
}

void FiledBoxes3::reset(const SiteGrid3& grid) {
  boxes_.clear(), cells_.clear();
  index_.assign(grid.cell_count(), {});
}

void FiledBoxes3::file(int id, const Cells3& c, const SiteGrid3& grid, bool add) {
  for (int k = c.k0; k <= c.k1; ++k)
    for (int j = c.j0; j <= c.j1; ++j)
      for (int i = c.i0; i <= c.i1; ++i) {
        auto& list = index_[grid.cell(i, j, k)];
        if (add) {
          list.push_back(id);
        } else {
          const auto it = std::find(list.begin(), list.end(), id);
          *it = list.back();
          list.pop_back();
        }
      }
}

void FiledBoxes3::set(int id, const Box3& b, const SiteGrid3& grid) {
  const auto n = static_cast<std::size_t>(id) + 1;
  if (boxes_.size() < n) boxes_.resize(n), cells_.resize(n);
  const Cells3 c = b.empty() ? Cells3{} : grid.cells_of(b);
  boxes_[id] = b;
  if (c == cells_[id]) return;
  file(id, cells_[id], grid, false);
  file(id, c, grid, true);
  cells_[id] = c;
}

void FiledBoxes3::refile(const SiteGrid3& grid) {
  index_.assign(grid.cell_count(), {});
  for (int id = 0; id < static_cast<int>(boxes_.size()); ++id) {
    cells_[id] = boxes_[id].empty() ? Cells3{} : grid.cells_of(boxes_[id]);
    file(id, cells_[id], grid, true);
  }
}

const std::vector<int>& FiledBoxes3::holding(const Point3<double>& q, const SiteGrid3& grid) const {
  found_.clear();
  for (int id : index_[grid.cell_of(q)])
    if (boxes_[id].contains(q)) found_.push_back(id);
  std::sort(found_.begin(), found_.end());
  return found_;
}

}  // namespace anisocert::refiners::common
