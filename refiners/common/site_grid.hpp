#pragma once
// A uniform grid over the domain's bounding box, for the refiners' spatial queries: the sites in
// each cell (box queries, nearest site), and BoxIndex, ids filed under the cells their boxes cover
// (a star's conflict zone, a subsegment's encroachment box). The grid grows with the sites (about
// two per cell); whoever owns a BoxIndex files its boxes again after a rebuild.
// Everything here only selects candidates: every decision on them is made by the caller, with
// exact predicates where it shapes the output.
#include "predicates/point.hpp"
#include "refiners/common/domain.hpp"

#include <cstddef>
#include <vector>

namespace anisocert::refiners::common {

using predicates::Sym2;

// A block of grid cells, columns i0..i1 and rows j0..j1 (empty when i0 > i1).
struct Cells {
  int i0 = 0, i1 = -1, j0 = 0, j1 = -1;
  bool contains(int i, int j) const { return i >= i0 && i <= i1 && j >= j0 && j <= j1; }
  friend bool operator==(const Cells&, const Cells&) = default;
};

class SiteGrid {
 public:
  // A 16 × 16 grid over `extent`.
  explicit SiteGrid(const Box& extent);

  // Files site s at p.
  void add(int s, const Point2<double>& p) { sites_[cell_of(p)].push_back(s); }
  // More than four sites per cell on average: time to rebuild.
  bool outgrown(std::size_t sites) const { return sites > 4 * static_cast<std::size_t>(g_) * g_; }
  // About two sites per cell (at most 2048 × 2048 cells), every site filed again in index order.
  void rebuild(const std::vector<Point2<double>>& points);

  // The sites in a closed box, in a buffer reused across calls (valid until the next call).
  const std::vector<int>& sites_in(const Box& b, const std::vector<Point2<double>>& points) const;
  // The squared M-distance from q to the M-nearest site (∞ when there is none).
  double nearest_site2(const Point2<double>& q, const Sym2<double>& M, const std::vector<Point2<double>>& points) const;

  std::size_t cell_count() const { return static_cast<std::size_t>(g_) * g_; }
  int columns() const { return g_; }
  std::size_t cell_of(const Point2<double>& p) const { return cell(cell_x(p.x), cell_y(p.y)); }
  std::size_t cell(int i, int j) const { return static_cast<std::size_t>(j) * g_ + i; }
  Cells cells_of(const Box& b) const { return {cell_x(b.x0), cell_x(b.x1), cell_y(b.y0), cell_y(b.y1)}; }

 private:
  int clamped_cell(double t) const;
  int cell_x(double x) const;
  int cell_y(double y) const;
  void resize(int g);

  Box extent_;
  int g_ = 16;
  double cw_ = 0, ch_ = 0;
  std::vector<std::vector<int>> sites_;
  mutable std::vector<int> found_;
};

// Ids filed under grid cells. A cell's list is unordered: removal swaps with the last entry.
class BoxIndex {
 public:
  // Empties the index for a grid of `grid.cell_count()` cells.
  void reset(const SiteGrid& grid);
  // Moves id from the cells `from` to the cells `to`: out of those of `from` not in `to`, into
  // those of `to` not in `from` (row by row). from = {} files it, to = {} removes it.
  void move(int id, const Cells& from, const Cells& to);
  const std::vector<int>& at(std::size_t cell) const { return cells_[cell]; }

 private:
  int g_ = 0;
  std::vector<std::vector<int>> cells_;
};

// Boxes by id (a subsegment's encroachment box), each filed in the grid cells it covers: the ids
// whose boxes may hold a point are those filed in its cell.
class FiledBoxes {
 public:
  // Forgets every box; ids are then filed in `grid`'s cells.
  void reset(const SiteGrid& grid);
  // Sets id's box (ids 0, 1, 2, … may come in any order), moving it to the cells it covers.
  void set(int id, const Box& b, const SiteGrid& grid);
  // Files every box again in `grid`'s cells, by increasing id (after the grid was rebuilt).
  void refile(const SiteGrid& grid);

  const Box& box(int id) const { return boxes_[static_cast<std::size_t>(id)]; }
  // The ids filed in q's cell, unordered; some of their boxes may not hold q.
  const std::vector<int>& filed_at(const Point2<double>& q, const SiteGrid& grid) const { return index_.at(grid.cell_of(q)); }
  // The ids whose closed boxes hold q, by increasing id, in a buffer reused across calls (valid
  // until the next call).
  const std::vector<int>& holding(const Point2<double>& q, const SiteGrid& grid) const;

 private:
  std::vector<Box> boxes_;
  std::vector<Cells> cells_;
  BoxIndex index_;
  mutable std::vector<int> found_;
};

}  // namespace anisocert::refiners::common
