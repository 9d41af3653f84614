#include "oracle/diagram/build.hpp"

#include <chrono>

namespace anisocert::oracle {

namespace build {

void Builder::run() {
  using clock = std::chrono::steady_clock;
  auto seconds = [](clock::time_point a) { return std::chrono::duration<double>(clock::now() - a).count(); };
  auto t = clock::now();
  cand_ = candidate_sets(d_.input);
  d_.stats.boxes = cand_.boxes, d_.stats.leaves = cand_.leaves, d_.stats.max_depth = cand_.max_depth_reached;
  d_.stats.triples = cand_.triples.size(), d_.stats.pairs = cand_.pairs.size();
  d_.stats.seconds_candidates = seconds(t);
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

  t = clock::now();
  add_corners();
  find_vertices();
  d_.stats.seconds_vertices = seconds(t);
  t = clock::now();
  build_arcs();
  check_node_wedges();
  build_boundary();
  d_.stats.seconds_arcs = seconds(t);
  t = clock::now();
  build_half_edges();
  build_cycles();
  build_faces();
  d_.stats.seconds_faces = seconds(t);
  t = clock::now();
  build_dual();
  check_triangulation();
  check_theorem7();
  d_.stats.seconds_dual = seconds(t);
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
