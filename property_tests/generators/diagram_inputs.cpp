#include "property_tests/generators/diagram_inputs.hpp"

#include "property_tests/generators/metrics.hpp"

#include <algorithm>

namespace anisocert::gen {

namespace {

rc::Gen<Frame> frame(int spread) {  // F = [[a, b], [0, c]] with a, c in 1..spread, b small: det > 0
  return rc::gen::apply([](int a, int b, int c) { return Frame{Rational(a), Rational(b, 2), Rational(0), Rational(c)}; },
                        rc::gen::inRange(1, spread + 1), rc::gen::inRange(-3, 4), rc::gen::inRange(1, spread + 1));
}

rc::Gen<Frame> perturbed(const Frame& F) {
  return rc::gen::apply(
      [F](int a, int b, int c) {
        return Frame{F.f11 + Rational(a, 20), F.f12 + Rational(b, 20), F.f21, F.f22 + Rational(c, 20)};
      },
      rc::gen::inRange(-1, 2), rc::gen::inRange(-1, 2), rc::gen::inRange(-1, 2));
}

// Metrics for `n` sites of one class.
rc::Gen<std::pair<std::vector<Sym2<Rational>>, std::string>> metrics_of(int n, bool allow_varied) {
  std::vector<rc::Gen<std::pair<std::vector<Sym2<Rational>>, std::string>>> classes;
  classes.push_back(rc::gen::map(frame(3), [n](const Frame& F) {
    return std::pair{std::vector<Sym2<Rational>>(n, F.metric()), std::string("constant")};
  }));
  classes.push_back(rc::gen::mapcat(frame(3), [n](const Frame& F) {
    return rc::gen::map(rc::gen::container<std::vector<Frame>>(n, perturbed(F)), [](const std::vector<Frame>& fs) {
      std::vector<Sym2<Rational>> ms;
      for (const Frame& f : fs) ms.push_back(f.metric());
      return std::pair{ms, std::string("nearly_constant")};
    });
  }));
  if (allow_varied)
    classes.push_back(rc::gen::map(rc::gen::container<std::vector<Frame>>(n, frame(10)), [](const std::vector<Frame>& fs) {
      std::vector<Sym2<Rational>> ms;
      for (const Frame& f : fs) ms.push_back(f.metric());
      return std::pair{ms, std::string("varied")};
    }));
  return one_of_classes(classes);
}

std::vector<Point2<Rational>> distinct(std::vector<Point2<Rational>> p) {
  std::sort(p.begin(), p.end(), [](const auto& a, const auto& b) { return std::tie(a.x, a.y) < std::tie(b.x, b.y); });
  p.erase(std::unique(p.begin(), p.end(), [](const auto& a, const auto& b) { return a.x == b.x && a.y == b.y; }), p.end());
  return p;
}

rc::Gen<Point2<Rational>> grid_point(int lo, int hi) {  // coordinates k/64, lo <= k <= hi
  return rc::gen::apply([](int x, int y) { return Point2<Rational>{Rational(x, 64), Rational(y, 64)}; },
                        rc::gen::inRange(lo, hi + 1), rc::gen::inRange(lo, hi + 1));
}

}  // namespace

rc::Gen<DiagramCase> diagram_case() {
  return rc::gen::mapcat(rc::gen::container<std::vector<Point2<Rational>>>(
                             static_cast<std::size_t>(8), grid_point(1, 63)),
                         [](const std::vector<Point2<Rational>>& raw) {
                           return rc::gen::mapcat(rc::gen::inRange(2, 9), [raw](int n) {
                             std::vector<Point2<Rational>> sites = distinct({raw.begin(), raw.begin() + n});
                             const int m = static_cast<int>(sites.size());
                             return rc::gen::map(metrics_of(m, true), [sites](const auto& ms) {
                               DiagramCase c;
                               c.input.sites = sites;
                               c.input.metrics = ms.first;
                               c.input.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
                               c.kind = ms.second;
                               return c;
                             });
                           });
                         });
}

rc::Gen<DiagramCase> theorem7_case() {
  return rc::gen::mapcat(rc::gen::inRange(0, 4), [](int k) {
    return rc::gen::mapcat(rc::gen::container<std::vector<Point2<Rational>>>(static_cast<std::size_t>(5),
                                                                             grid_point(20, 44)),
                           [k](const std::vector<Point2<Rational>>& raw) {
                             return rc::gen::mapcat(rc::gen::inRange(1, 6), [k, raw](int n) {
                               // The boundary, counter-clockwise: corners and k points per side.
                               std::vector<Point2<Rational>> boundary;
                               const Point2<Rational> corner[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
                               for (int s = 0; s < 4; ++s)
                                 for (int i = 0; i <= k; ++i) {
                                   const Rational t(i, k + 1);
                                   const auto& a = corner[s];
                                   const auto& b = corner[(s + 1) % 4];
                                   boundary.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
                                 }
                               std::vector<Point2<Rational>> sites = boundary;
                               for (const auto& p : distinct({raw.begin(), raw.begin() + n})) sites.push_back(p);
                               const int m = static_cast<int>(sites.size());
                               return rc::gen::map(metrics_of(m, false), [sites, boundary](const auto& ms) {
                                 DiagramCase c;
                                 c.input.sites = sites;
                                 c.input.metrics = ms.first;
                                 c.input.domain = boundary;
                                 c.kind = ms.second;
                                 return c;
                               });
                             });
                           });
  });
}

std::ostream& operator<<(std::ostream& os, const DiagramCase& c) {
  os << c.kind << " sites:";
  for (std::size_t i = 0; i < c.input.sites.size(); ++i)
    os << " [" << c.input.sites[i] << " M " << c.input.metrics[i] << "]";
  os << " domain:";
  for (const auto& p : c.input.domain) os << " " << p;
  return os;
}

}  // namespace anisocert::gen
