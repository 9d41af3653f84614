#include "oracle/diagram/build.hpp"

#include <chrono>

namespace anisocert::oracle {

namespace build {

void Builder::run() {
  using clock = std::chrono::steady_clock;
  // Runs one phase of the construction and records its duration.
  auto timed = [](double& seconds, auto&& phase) {
    const auto t = clock::now();
    phase();
    seconds = std::chrono::duration<double>(clock::now() - t).count();
  };
  timed(d_.stats.seconds_candidates, [&] { cand_ = candidate_sets(d_.input); });
  d_.stats.boxes = cand_.boxes, d_.stats.leaves = cand_.leaves, d_.stats.max_depth = cand_.max_depth_reached;
  d_.stats.triples = cand_.triples.size(), d_.stats.pairs = cand_.pairs.size();
  if (progress_)
    progress_("candidates: " + std::to_string(cand_.boxes) + " boxes, " + std::to_string(cand_.triples.size()) +
              " triples, " + std::to_string(cand_.pairs.size()) + " pairs");

  d_.shear = choose_shear(d_.input, cand_.pairs);
  d_.sheared = shear_input(d_.input, d_.shear);
  Rational extent = 1;
  for (const auto& p : d_.sheared.domain) extent = std::max({extent, abs(p.x), abs(p.y)});
  width_ = extent / Rational(Integer(1) << 52);
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

std::pair<double, double> Diagram::original_xy(const LocatedPoint& p) const {
  const double y = (p.y.lo + p.y.hi) / 2;
  const double x = (p.x.lo + p.x.hi) / 2 - shear.convert_to<double>() * y;
  return {x, y};
}

Diagram compute_diagram(const Mesh<Rational>& input, const std::function<void(const std::string&)>& progress) {
  Diagram d;
  d.input = input;
  build::Builder(d, progress).run();
  return d;
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
