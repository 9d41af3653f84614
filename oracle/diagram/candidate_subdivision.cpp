#include "oracle/diagram/candidate_subdivision.hpp"

#include "numbers/filter_interval.hpp"

#include <algorithm>
#include <limits>

namespace anisocert::oracle {

namespace {


struct SiteBox {
  FilterInterval x, y, m11, m12, m22;
};

// Outward bounds of Q_u on the box [x_lo, x_hi] × [y_lo, y_hi], from the centred form at a
// double centre c with half-widths h rounded up so that c ± h covers the box.
std::pair<double, double> distance_bounds(const SiteBox& u, const BoxBounds& b) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double cx = b.x_lo + (b.x_hi - b.x_lo) / 2, cy = b.y_lo + (b.y_hi - b.y_lo) / 2;
  const double hx = std::nextafter(std::max(b.x_hi - cx, cx - b.x_lo), inf);
  const double hy = std::nextafter(std::max(b.y_hi - cy, cy - b.y_lo), inf);
  const FilterInterval dx = FilterInterval(cx) - u.x, dy = FilterInterval(cy) - u.y;
  const FilterInterval gx = u.m11 * dx + u.m12 * dy, gy = u.m12 * dx + u.m22 * dy;
  const FilterInterval q = dx * gx + dy * gy;
  const FilterInterval H(hx), K(hy);
  const FilterInterval ax(std::max(std::abs(gx.lo), std::abs(gx.hi))), ay(std::max(std::abs(gy.lo), std::abs(gy.hi)));
  const FilterInterval linear = FilterInterval(2) * (ax * H + ay * K);
  const FilterInterval m12(std::max(std::abs(u.m12.lo), std::abs(u.m12.hi)));
  const FilterInterval quadratic = FilterInterval(u.m11.hi) * H * H + FilterInterval(2) * m12 * H * K +
                                   FilterInterval(u.m22.hi) * K * K;
  const double lower = (q - linear).lo;
  const double upper = (q + linear + quadratic).hi;
  return {std::max(lower, 0.0), upper};
}

struct Subdivider {
  std::vector<SiteBox> sites;
  int max_depth;
  std::size_t max_boxes;  // a budget (about 120 boxes per site are usual)
  CandidateSets out;
  std::vector<std::pair<std::pair<int, int>, BoxBounds>> pairs;
  std::vector<std::pair<std::array<int, 3>, BoxBounds>> triples;

  void record(std::vector<int> cand, const BoxBounds& box, int cell) {
    ++out.leaves;
    std::sort(cand.begin(), cand.end());
    for (std::size_t i = 0; i < cand.size(); ++i)
      for (std::size_t j = i + 1; j < cand.size(); ++j) {
        pairs.push_back({{cand[i], cand[j]}, box});
        for (std::size_t k = j + 1; k < cand.size(); ++k) triples.push_back({{cand[i], cand[j], cand[k]}, box});
      }
    out.cells[cell].leaf = static_cast<int>(out.leaf_sites.size());
    out.leaf_sites.push_back(std::move(cand));
  }

  void refine(const std::vector<int>& parent, const BoxBounds& box, int depth, int cell) {
    ++out.boxes;
    out.max_depth_reached = std::max(out.max_depth_reached, depth);
    std::vector<std::pair<double, double>> bounds(parent.size());
    double best_upper = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < parent.size(); ++i) {
      bounds[i] = distance_bounds(sites[parent[i]], box);
      best_upper = std::min(best_upper, bounds[i].second);
    }
    std::vector<int> cand;
    for (std::size_t i = 0; i < parent.size(); ++i)
      if (!(bounds[i].first > best_upper)) cand.push_back(parent[i]);
    if (out.boxes > max_boxes)
      throw std::domain_error("the candidate subdivision passed its budget of " + std::to_string(max_boxes) +
                              " boxes: the sites' distances cannot be told apart in double precision (coordinates or "
                              "metrics of very different magnitudes); such inputs are not supported yet");
    if (cand.size() <= 3 || depth >= max_depth) {
      record(std::move(cand), box, cell);
      return;
    }
    // Children share their split lines exactly, so they cover the box whatever the rounding.
    const double mx = box.x_lo + (box.x_hi - box.x_lo) / 2, my = box.y_lo + (box.y_hi - box.y_lo) / 2;
    const BoxBounds children[4] = {
        {box.x_lo, mx, box.y_lo, my}, {mx, box.x_hi, box.y_lo, my}, {box.x_lo, mx, my, box.y_hi}, {mx, box.x_hi, my, box.y_hi}};
    const int first = static_cast<int>(out.cells.size());
    out.cells[cell].first_child = first;
    for (const BoxBounds& c : children) out.cells.push_back({c});
    for (int k = 0; k < 4; ++k) refine(cand, children[k], depth + 1, first + k);
  }
};

// Sorts the (key, box) records and merges each key's boxes into their bounding box.
template <class Key>
void merge_regions(std::vector<std::pair<Key, BoxBounds>>& records, std::vector<Key>& keys, std::vector<BoxBounds>& regions) {
  std::sort(records.begin(), records.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [key, box] : records) {
    if (!keys.empty() && keys.back() == key) {
      BoxBounds& b = regions.back();
      b = {std::min(b.x_lo, box.x_lo), std::max(b.x_hi, box.x_hi), std::min(b.y_lo, box.y_lo), std::max(b.y_hi, box.y_hi)};
    } else {
      keys.push_back(key);
      regions.push_back(box);
    }
  }
  records.clear();
  records.shrink_to_fit();
}

}  // namespace

namespace {

// v·2^k, rounded outward when the scaling is not exact (subnormal results).
FilterInterval scaled(const FilterInterval& v, int k) {
  return FilterInterval::widen(std::ldexp(v.lo, k), std::ldexp(v.hi, k));
}

// The k with 2^k·max|q| in [1, 2), for the largest |q| (0 when all are 0).
int normalising_exponent(const std::vector<Rational>& values) {
  Rational largest = 0;
  for (const Rational& q : values) largest = std::max(largest, abs(q));
  if (largest == 0) return 0;
  const double d = largest.convert_to<double>();  // within the doubles' range: readers limit |q| to 2^±1100
  return std::isfinite(d) && d > 0 ? -std::ilogb(d) : 0;
}

Rational times_power_of_two(const Rational& q, int k) {
  const Rational p(Integer(1) << static_cast<unsigned>(k < 0 ? -k : k));
  return k >= 0 ? q * p : q / p;
}

}  // namespace

CandidateSets candidate_sets(const Mesh<Rational>& in, int max_depth) {
  Subdivider s;
  s.max_depth = max_depth;
  s.max_boxes = 1000 * in.sites.size() + 100000;
  // The subdivision works on coordinates scaled by 2^k and metrics scaled by 2^j, both chosen so
  // that the largest is about 1: every squared distance is scaled by 2^(2k + j) alike, so who is
  // closer is unchanged, and tiny or huge inputs (1e-300, 1e300) neither underflow nor overflow.
  std::vector<Rational> coordinates, entries;
  for (const auto& p : in.domain) coordinates.push_back(p.x), coordinates.push_back(p.y);
  for (const auto& M : in.metrics) entries.push_back(M.m11), entries.push_back(M.m12), entries.push_back(M.m22);
  const int k = normalising_exponent(coordinates), j = normalising_exponent(entries);
  s.out.scale_exponent = k;
  for (std::size_t i = 0; i < in.sites.size(); ++i) {
    const auto& p = in.sites[i];
    const auto& M = in.metrics[i];
    s.sites.push_back({FilterInterval::around(times_power_of_two(p.x, k)), FilterInterval::around(times_power_of_two(p.y, k)),
                       FilterInterval::around(times_power_of_two(M.m11, j)), FilterInterval::around(times_power_of_two(M.m12, j)),
                       FilterInterval::around(times_power_of_two(M.m22, j))});
  }
  // The root box: the domain's bounding box, rounded outward.
  constexpr double inf = std::numeric_limits<double>::infinity();
  BoxBounds root{inf, -inf, inf, -inf};
  for (const auto& p : in.domain) {
    const FilterInterval x = FilterInterval::around(times_power_of_two(p.x, k)), y = FilterInterval::around(times_power_of_two(p.y, k));
    root = {std::min(root.x_lo, x.lo), std::max(root.x_hi, x.hi), std::min(root.y_lo, y.lo), std::max(root.y_hi, y.hi)};
  }
  std::vector<int> all(in.sites.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  s.out.sites = static_cast<int>(all.size());
  s.out.cells.push_back({root});
  s.refine(all, root, 0, 0);
  merge_regions(s.triples, s.out.triples, s.out.triple_region);
  merge_regions(s.pairs, s.out.pairs, s.out.pair_region);
  // The regions in the input's coordinates.
  for (auto* regions : {&s.out.triple_region, &s.out.pair_region})
    for (BoxBounds& b : *regions) {
      const FilterInterval x = scaled({b.x_lo, b.x_hi}, -k), y = scaled({b.y_lo, b.y_hi}, -k);
      b = {x.lo, x.hi, y.lo, y.hi};
    }
  return s.out;
}

std::vector<int> CandidateSets::sites_near(const FilterInterval& input_x, const FilterInterval& input_y) const {
  const FilterInterval x = scaled(input_x, scale_exponent), y = scaled(input_y, scale_exponent);
  std::vector<int> out;
  const BoxBounds& root = cells[0].box;
  if (x.hi < root.x_lo || root.x_hi < x.lo || y.hi < root.y_lo || root.y_hi < y.lo) {  // wholly outside Ω's box
    out.resize(static_cast<std::size_t>(sites));
    for (int i = 0; i < sites; ++i) out[static_cast<std::size_t>(i)] = i;
    return out;
  }
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const Cell& c = cells[static_cast<std::size_t>(stack.back())];
    stack.pop_back();
    if (x.hi < c.box.x_lo || c.box.x_hi < x.lo || y.hi < c.box.y_lo || c.box.y_hi < y.lo) continue;
    if (c.leaf >= 0) {
      const auto& l = leaf_sites[static_cast<std::size_t>(c.leaf)];
      out.insert(out.end(), l.begin(), l.end());
    } else {
      for (int k = 0; k < 4; ++k) stack.push_back(c.first_child + k);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace anisocert::oracle
