#include "fields/box_grid.hpp"

#include <algorithm>
#include <cmath>

namespace anisocert::fields {

int BoxGrid::index(double v, double lo, double hi, int n) {
  if (!(hi > lo)) return 0;
  const double t = std::floor((v - lo) / (hi - lo) * n);
  return static_cast<int>(std::clamp(t, 0.0, static_cast<double>(n - 1)));
}

BoxGrid::BoxGrid(const std::vector<DoubleBox>& boxes) {
  if (boxes.empty()) {
    extent_ = {0, -1, 0, -1};  // meets nothing
    first_ = {0, 0};
    return;
  }
  extent_ = boxes.front();
  for (const DoubleBox& b : boxes)
    extent_ = {std::min(extent_.x0, b.x0), std::max(extent_.x1, b.x1), std::min(extent_.y0, b.y0), std::max(extent_.y1, b.y1)};
  // n cells of the extent's shape: nx / ny = width / height, nx · ny ≈ n.
  constexpr double max_side = 2048;
  const double n = static_cast<double>(boxes.size()), w = extent_.x1 - extent_.x0, h = extent_.y1 - extent_.y0;
  const double aspect = w > 0 && h > 0 ? w / h : 1;
  nx_ = static_cast<int>(std::clamp(std::round(std::sqrt(n * aspect)), 1.0, max_side));
  ny_ = static_cast<int>(std::clamp(std::round(n / nx_), 1.0, max_side));
  // Counting sort by cell: count, prefix sums, fill in id order (so each cell's ids increase).
  first_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  auto each_cell = [&](const DoubleBox& b, auto&& g) {
    for (int j = row(b.y0), j1 = row(b.y1); j <= j1; ++j)
      for (int i = column(b.x0), i1 = column(b.x1); i <= i1; ++i) g(cell(i, j));
  };
  for (const DoubleBox& b : boxes) each_cell(b, [&](std::size_t c) { ++first_[c + 1]; });
  for (std::size_t c = 1; c < first_.size(); ++c) first_[c] += first_[c - 1];
  ids_.resize(first_.back());
  std::vector<std::size_t> next(first_.begin(), first_.end() - 1);
  for (std::size_t id = 0; id < boxes.size(); ++id) each_cell(boxes[id], [&](std::size_t c) { ids_[next[c]++] = static_cast<int>(id); });
}

}  // namespace anisocert::fields
