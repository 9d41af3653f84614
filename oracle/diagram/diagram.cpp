#include "oracle/diagram/build.hpp"
#include "oracle/parallel_for.hpp"

#include <chrono>
#include <cmath>

namespace anisocert::oracle {

namespace build {

IntervalBox Builder::sheared_box(const BoxBounds& b) const {
  const FilterInterval y{b.y_lo, b.y_hi};
  return {FilterInterval{b.x_lo, b.x_hi} + shear_ * y, y};
}

FilterInterval Builder::distance_at(int u, const LocatedPoint& p) const {
  const auto& c = distance_[static_cast<std::size_t>(u)];
  return c[0] * p.x * p.x + c[1] * p.x * p.y + c[2] * p.y * p.y + c[3] * p.x + c[4] * p.y + c[5];
}

CurvePair Builder::bisectors(int a, int b, int c) const {
  const auto minus = [&](int u, int v) {
    const auto& p = distance_[static_cast<std::size_t>(u)];
    const auto& q = distance_[static_cast<std::size_t>(v)];
    return IntervalConic{p[0] - q[0], p[1] - q[1], p[2] - q[2], p[3] - q[3], p[4] - q[4], p[5] - q[5]};
  };
  return {minus(a, b), minus(a, c), [in = sheared_, a, b, c] {
            return std::pair{bisector_conic(*in, a, b), bisector_conic(*in, a, c)};
          }};
}

std::vector<int> Builder::sites_near(const LocatedPoint& p) const { return cand_.sites_near(p.x - shear_ * p.y, p.y); }

Builder::Builder(Diagram& d, const DiagramOptions& options)
    : d_(d),
      progress_(options.progress),
      threads_(thread_count(options.threads)) {}

void Builder::run() {
  using clock = std::chrono::steady_clock;
  // Runs one phase of the construction and records its duration.
  auto timed = [](double& seconds, auto&& phase) {
    const auto t = clock::now();
    phase();
    seconds = std::chrono::duration<double>(clock::now() - t).count();
  };
  d_.stats.threads = threads_;
  timed(d_.stats.seconds_candidates, [&] { cand_ = candidate_sets(d_.input); });
  d_.stats.boxes = cand_.boxes, d_.stats.leaves = cand_.leaves, d_.stats.max_depth = cand_.max_depth_reached;
  d_.stats.triples = cand_.triples.size(), d_.stats.pairs = cand_.pairs.size();
  if (progress_)
    progress_("candidates: " + std::to_string(cand_.boxes) + " boxes, " + std::to_string(cand_.triples.size()) +
              " triples, " + std::to_string(cand_.pairs.size()) + " pairs");

  geometry::SplitPolygon split = geometry::split_at_points(d_.input.domain, d_.input.sites);
  d_.domain = std::move(split.corners);
  d_.corner_site = std::move(split.point);
  Mesh<Rational> split_input = d_.input;
  split_input.domain = d_.domain;
  d_.shear = choose_shear(split_input, cand_.pairs);
  d_.sheared = shear_input(split_input, d_.shear);
  sheared_ = std::make_shared<const Mesh<Rational>>(d_.sheared);
  domain_.emplace(d_.sheared);
  shear_ = FilterInterval::around(d_.shear);
  Rational extent = 1;
  for (const auto& p : d_.sheared.domain) extent = std::max({extent, abs(p.x), abs(p.y)});
  width_ = extent / Rational(Integer(1) << 52);
  Rational size = 0;
  for (const auto& p : d_.sheared.domain) size = std::max({size, abs(p.x), abs(p.y)});
  d_.grid = std::ldexp(1.0, std::ilogb(size.convert_to<double>()) - 40);
  for (std::size_t i = 0; i < d_.sheared.sites.size(); ++i) {
    const Conic q = distance_conic(d_.sheared.sites[i], d_.sheared.metrics[i]);
    auto c = [](const Rational& r) { return anisocert::FilterInterval::around(r); };
    distance_.push_back({c(q.a), c(q.b), c(q.c), c(q.d), c(q.e), c(q.f)});
  }

  timed(d_.stats.seconds_vertices, [&] { add_corners(); find_vertices(); });
  timed(d_.stats.seconds_arcs, [&] { build_arcs(); check_node_wedges(); build_boundary(); });
  timed(d_.stats.seconds_faces, [&] { build_half_edges(); build_cycles(); build_faces(); });
  timed(d_.stats.seconds_dual, [&] { build_dual(); check_triangulation(); check_theorem7(); });
}

}  // namespace build

namespace {

// The k nearest to v/g (the larger at a tie), for the exact value v in the box [b], by bisection
// between the indices of the box's ends, with `compare(r)` = sign(v − r) for r = (k − 1/2)·g.
template <class Compare>
double nearest_grid_index(const FilterInterval& b, double g, Compare compare) {
  double lo = std::floor(b.lo / g + 0.5) - 1, hi = std::floor(b.hi / g + 0.5) + 1;  // lo ≤ k ≤ hi
  while (lo < hi) {
    const double mid = std::floor(lo + (hi - lo + 1) / 2);
    if (compare(Rational((mid - 0.5) * g)) != Sign::negative) lo = mid;
    else hi = mid - 1;
  }
  return lo;
}

}  // namespace

std::pair<double, double> Diagram::original_xy(const LocatedPoint& p) const {
  // x = x' − s·y in the input's coordinates: the sign of x − r is that of the line x' − s·y − r.
  const FilterInterval s = FilterInterval::around(shear), X = p.x - s * p.y;
  if (!(std::isfinite(X.lo) && std::isfinite(X.hi) && std::isfinite(p.y.lo) && std::isfinite(p.y.hi)))
    return {(p.exact().x().lo() - shear * p.exact().y().lo()).convert_to<double>(), p.exact().y().lo().convert_to<double>()};
  // A line's sign at p: from p's box; where a grid line crosses it, from the box narrowed to a few
  // ulps (asked once), which decides all but the points within ulps of a grid line; then exactly.
  // A box of the filtered constructions is often as wide as the grid's spacing (1e-13 of the
  // domain), and the exact point cost 20 times the diagram's own time in `diagram --json`.
  std::optional<std::optional<LocatedPoint>> narrow;
  const auto sign = [&](const Conic& line) {
    if (const auto v = p.value(line).sign(); v && *v != Sign::zero) return *v;
    if (!narrow) {
      const auto box = p.narrowed();
      narrow = box ? std::optional<LocatedPoint>(LocatedPoint(*box, nullptr)) : std::nullopt;
    }
    if (*narrow)
      if (const auto v = (*narrow)->value(line).sign(); v && *v != Sign::zero) return *v;
    return p.sign_of(line);
  };
  const double kx = nearest_grid_index(X, grid, [&](const Rational& r) { return sign(Conic{0, 0, 0, 1, -shear, -r}); });
  const double ky = nearest_grid_index(p.y, grid, [&](const Rational& r) { return sign(Conic{0, 0, 0, 0, 1, -r}); });
  return {kx * grid, ky * grid};
}

Diagram compute_diagram(const Mesh<Rational>& input, const DiagramOptions& options) {
  Diagram d;
  d.input = input;
  FilterContext context;
  context.exact_only = options.exact_only;
  {
    const FilterScope scope(context);
    build::Builder(d, options).run();
  }
  d.stats.filters = context.counts;
  d.stats.exact_only = options.exact_only;
  return d;
}

Diagram compute_diagram(const Mesh<Rational>& input, const std::function<void(const std::string&)>& progress) {
  DiagramOptions options;
  options.progress = progress;
  return compute_diagram(input, options);
}

std::vector<int> nearest_sites(const Mesh<Rational>& in, const Point2<Rational>& p) {
  std::vector<int> best;
  Rational best_q;
  for (int u = 0; u < static_cast<int>(in.sites.size()); ++u) {
    const auto& M = in.metrics[u];
    const Rational q = predicates::quadratic_form(M.m11, M.m12, M.m22, p.x - in.sites[u].x, p.y - in.sites[u].y);
    if (best.empty() || q < best_q) best = {u}, best_q = q;
    else if (q == best_q) best.push_back(u);
  }
  return best;
}

}  // namespace anisocert::oracle
