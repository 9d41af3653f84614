#pragma once
// A static uniform grid of closed boxes in doubles, for locating points among the triangles of a
// background mesh: each box is filed under every cell it meets; a query visits the boxes filed
// under the cells that its own box meets. Nothing is missed whatever the rounding: the cell of a
// coordinate is floor((x − x₀) / w · n) clamped to [0, n − 1], each step rounded to nearest and
// monotone in x, so a point common to a filed box and a query box has one cell that both meet.
// It only selects candidates: the caller decides each one exactly.
#include <cstddef>
#include <vector>

namespace anisocert::fields {

// [x0, x1] × [y0, y1].
struct DoubleBox {
  double x0, x1, y0, y1;
};

class BoxGrid {
 public:
  // About one cell per box, at most 2048 × 2048 cells; every bound finite, x0 ≤ x1, y0 ≤ y1.
  explicit BoxGrid(const std::vector<DoubleBox>& boxes);

  // Calls f(id) for every id filed under a cell that b meets (the ids of one cell increasing; an
  // id filed under several of those cells comes once per cell). Every box meeting b is visited.
  template <class F>
  void visit(const DoubleBox& b, F&& f) const {
    if (!(b.x1 >= extent_.x0 && b.x0 <= extent_.x1 && b.y1 >= extent_.y0 && b.y0 <= extent_.y1)) return;
    for (int j = row(b.y0), j1 = row(b.y1); j <= j1; ++j)
      for (int i = column(b.x0), i1 = column(b.x1); i <= i1; ++i)
        for (std::size_t k = first_[cell(i, j)]; k < first_[cell(i, j) + 1]; ++k) f(ids_[k]);
  }

  int columns() const { return nx_; }
  int rows() const { return ny_; }

 private:
  int column(double x) const { return index(x, extent_.x0, extent_.x1, nx_); }
  int row(double y) const { return index(y, extent_.y0, extent_.y1, ny_); }
  static int index(double v, double lo, double hi, int n);
  std::size_t cell(int i, int j) const { return static_cast<std::size_t>(j) * nx_ + i; }

  DoubleBox extent_;          // the union of the boxes' bounds
  int nx_ = 1, ny_ = 1;
  std::vector<std::size_t> first_;  // the ids of cell c are ids_[first_[c] .. first_[c + 1])
  std::vector<int> ids_;
};

}  // namespace anisocert::fields
