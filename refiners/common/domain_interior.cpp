// Domain::check_interior: the PSLG's points and interior segments against Ω and each other, exactly
// (domain.hpp).
#include "refiners/common/domain.hpp"
#include "refiners/common/exact_split.hpp"

namespace anisocert::refiners::common {

void Domain::check_interior() {
  const std::size_t n = corners_.size(), v = vertices_.size();
  Polygon<Rational> exact;
  for (const auto& q : vertices_) exact.push_back({Rational(q.x), Rational(q.y)});
  const auto vertex = [&](std::size_t k) { return corner_text(k); };
  for (std::size_t k = n; k < v; ++k) {
    if (!geometry::in_closed_polygon(exact[k], exact_))
      throw DomainError(vertex(k) + " lies outside the domain");
    for (std::size_t e = 0; e < n; ++e)
      if (geometry::on_segment(exact[k], exact[e], exact[(e + 1) % n]))
        throw DomainError(vertex(k) + " lies on domain edge " + std::to_string(e) + "; make it a corner");
    for (std::size_t i = 0; i < k; ++i)
      if (exact[i].x == exact[k].x && exact[i].y == exact[k].y) throw DomainError(vertex(k) + " is " + vertex(i) + " again");
  }
  // Two segments ab and cd of X may share an end and meet nowhere else.
  const auto meet_at_most_at_an_end = [&](int a, int b, int c, int d) {
    const auto meeting = geometry::segments_meet(exact[a], exact[b], exact[c], exact[d]);
    if (meeting == geometry::Meeting::none) return true;
    if (meeting == geometry::Meeting::crossing) return false;
    const int shared = a == c || a == d ? a : b == c || b == d ? b : -1;
    if (shared < 0 || (a == c && b == d) || (a == d && b == c)) return false;
    const int other = shared == a ? b : a, far = shared == c ? d : c;
    return !geometry::on_segment(exact[other], exact[c], exact[d]) && !geometry::on_segment(exact[far], exact[a], exact[b]);
  };
  for (std::size_t s = 0; s < interior_.size(); ++s) {
    const int a = interior_[s].first, b = interior_[s].second;  // not bound: clang 14 cannot capture bindings
    const std::string name = "interior segment " + std::to_string(s);
    if (a < 0 || b < 0 || static_cast<std::size_t>(a) >= v || static_cast<std::size_t>(b) >= v)
      throw DomainError(name + " names vertex " + std::to_string(a < 0 || static_cast<std::size_t>(a) >= v ? a : b) + ", but there are " +
                        std::to_string(v) + " (the " + std::to_string(n) + " corners, then the points)");
    if (a == b) throw DomainError(name + " joins " + vertex(static_cast<std::size_t>(a)) + " to itself");
    const std::string ends = name + " from " + vertex(static_cast<std::size_t>(a)) + " to " + vertex(static_cast<std::size_t>(b));
    const auto same = [&](int c, int d) { return (a == c && b == d) || (a == d && b == c); };
    for (std::size_t e = 0; e < n; ++e) {
      const int c = static_cast<int>(e), d = static_cast<int>((e + 1) % n);
      if (same(c, d)) throw DomainError(ends + " is domain edge " + std::to_string(e));
      if (!meet_at_most_at_an_end(a, b, c, d)) throw DomainError(ends + " meets domain edge " + std::to_string(e) + " elsewhere than at a shared end");
    }
    const Point2<Rational> mid{(exact[a].x + exact[b].x) / 2, (exact[a].y + exact[b].y) / 2};
    if (!geometry::in_closed_polygon(mid, exact_)) throw DomainError(ends + " runs outside the domain");
    for (std::size_t t = 0; t < s; ++t) {
      if (same(interior_[t].first, interior_[t].second)) throw DomainError(ends + " is interior segment " + std::to_string(t) + " again");
      if (!meet_at_most_at_an_end(a, b, interior_[t].first, interior_[t].second))
        throw DomainError(ends + " meets interior segment " + std::to_string(t) + " elsewhere than at a shared end");
    }
    for (std::size_t k = 0; k < v; ++k)
      if (static_cast<int>(k) != a && static_cast<int>(k) != b && geometry::on_segment(exact[k], exact[a], exact[b]))
        throw DomainError(ends + " passes through " + vertex(k) + "; split it there");
    if (const int h = split_halvings(vertices_[a], vertices_[b]); h < min_halvings)
      throw DomainError(ends + " can be halved exactly in doubles only " + std::to_string(h) + " times (" + std::to_string(min_halvings) +
                        " needed: split points must lie exactly on it); give coordinates with fewer binary digits");
  }
}

}  // namespace anisocert::refiners::common
