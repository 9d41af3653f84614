#include "refiners/common/site_grid.hpp"

#include "predicates/point.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace anisocert::refiners::common {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// The ring search stops when no site beyond the ring can be nearer than the best found: a site
// there is Euclidean-farther than the gap g, so M-farther than λ_min(M) g². λ_min and g are
// computed in doubles; stopping only when best ≤ (1 − 10⁻¹²) λ_min g² leaves room for their
// rounding (a few ulps). The result is reported (the refiners' trace) and sets a new star's first
// search radius, which only grows until the star is complete: it decides nothing.
constexpr double ring_stop_slack = 1 - 1e-12;

}  // namespace

SiteGrid::SiteGrid(const Box& extent) : extent_(extent) { resize(16); }

void SiteGrid::resize(int g) {
  g_ = g;
  cw_ = (extent_.x1 - extent_.x0) / g_, ch_ = (extent_.y1 - extent_.y0) / g_;
  sites_.assign(cell_count(), {});
}

void SiteGrid::rebuild(const std::vector<Point2<double>>& points) {
  resize(std::min(2048, static_cast<int>(std::sqrt(points.size() / 2.0)) + 1));
  for (int i = 0; i < static_cast<int>(points.size()); ++i) add(i, points[i]);
}

// The column of t cells from the grid's side, clamped in doubles before the conversion: a
// coordinate beyond int's range, infinite or NaN (a query box of a huge or overflowed ellipse)
// has no int value.
int SiteGrid::clamped_cell(double t) const { return t > 0 ? (t < g_ ? static_cast<int>(t) : g_ - 1) : 0; }
int SiteGrid::cell_x(double x) const { return clamped_cell((x - extent_.x0) / cw_); }
int SiteGrid::cell_y(double y) const { return clamped_cell((y - extent_.y0) / ch_); }

const std::vector<int>& SiteGrid::sites_in(const Box& b, const std::vector<Point2<double>>& points) const {
  found_.clear();
  for (int j = cell_y(b.y0); j <= cell_y(b.y1); ++j)
    for (int i = cell_x(b.x0); i <= cell_x(b.x1); ++i)
      for (int s : sites_[cell(i, j)])
        if (b.contains(points[s])) found_.push_back(s);
  return found_;
}

// By rings of cells around q's: the ring at distance k, then a stop when the gap to the next
// ring's border makes every site beyond it farther than the best found.
double SiteGrid::nearest_site2(const Point2<double>& q, const Sym2<double>& M, const std::vector<Point2<double>>& points) const {
  const double half_trace = (M.m11 + M.m22) / 2, det = M.m11 * M.m22 - M.m12 * M.m12;
  const double lmin = half_trace - std::sqrt(std::max(0.0, half_trace * half_trace - det));
  const int ci = cell_x(q.x), cj = cell_y(q.y);
  double best = inf;
  auto visit = [&](int i, int j) {
    if (i < 0 || j < 0 || i >= g_ || j >= g_) return;
    for (int s : sites_[cell(i, j)])
      best = std::min(best, predicates::quadratic_form(M, points[s].x - q.x, points[s].y - q.y));
  };
  for (int k = 0;; ++k) {
    for (int i = ci - k; i <= ci + k; ++i) {
      visit(i, cj - k);
      if (k > 0) visit(i, cj + k);
    }
    for (int j = cj - k + 1; j < cj + k; ++j) {
      visit(ci - k, j);
      visit(ci + k, j);
    }
    // Sides with no cells beyond them hide no site.
    const double gap = std::min({ci - k > 0 ? q.x - (extent_.x0 + (ci - k) * cw_) : inf,
                                 ci + k < g_ - 1 ? extent_.x0 + (ci + k + 1) * cw_ - q.x : inf,
                                 cj - k > 0 ? q.y - (extent_.y0 + (cj - k) * ch_) : inf,
                                 cj + k < g_ - 1 ? extent_.y0 + (cj + k + 1) * ch_ - q.y : inf});
    if (gap == inf || best <= lmin * gap * gap * ring_stop_slack) break;
  }
  return best;
}

void BoxIndex::reset(const SiteGrid& grid) {
  g_ = grid.columns();
  cells_.assign(grid.cell_count(), {});
}

void BoxIndex::move(int id, const Cells& from, const Cells& to) {
  for (int j = from.j0; j <= from.j1; ++j)
    for (int i = from.i0; i <= from.i1; ++i) {
      if (to.contains(i, j)) continue;  // stays
      auto& c = cells_[static_cast<std::size_t>(j) * g_ + i];
      *std::find(c.begin(), c.end(), id) = c.back();
      c.pop_back();
    }
  for (int j = to.j0; j <= to.j1; ++j)
    for (int i = to.i0; i <= to.i1; ++i)
      if (!from.contains(i, j)) cells_[static_cast<std::size_t>(j) * g_ + i].push_back(id);
}

void FiledBoxes::reset(const SiteGrid& grid) {
  boxes_.clear();
  cells_.clear();
  index_.reset(grid);
}

void FiledBoxes::set(int id, const Box& b, const SiteGrid& grid) {
  const auto i = static_cast<std::size_t>(id);
  if (boxes_.size() <= i) boxes_.resize(i + 1), cells_.resize(i + 1);
  boxes_[i] = b;
  const Cells cells = grid.cells_of(b);
  index_.move(id, cells_[i], {});
  index_.move(id, {}, cells);
  cells_[i] = cells;
}

void FiledBoxes::refile(const SiteGrid& grid) {
  index_.reset(grid);
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    cells_[i] = grid.cells_of(boxes_[i]);
    index_.move(static_cast<int>(i), {}, cells_[i]);
  }
}

const std::vector<int>& FiledBoxes::holding(const Point2<double>& q, const SiteGrid& grid) const {
  found_.clear();
  for (int id : filed_at(q, grid))
    if (box(id).contains(q)) found_.push_back(id);
  std::sort(found_.begin(), found_.end());
  return found_;
}

}  // namespace anisocert::refiners::common
