#include "refiners/ls/ls_varying.hpp"

#include "fields/normalized.hpp"
#include "predicates/angle.hpp"
#include "predicates/orientation.hpp"
#include "refiners/common/vertex_in_domain.hpp"
#include "refiners/common/circumcentre.hpp"
#include "refiners/ls/rules.hpp"
#include "refiners/ls/theorem11_conditions.hpp"
#include "refiners/common/voronoi_refinement.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

namespace anisocert::refiners::ls {
namespace {

using common::CertifiedPoint;
using common::ExactTie;
using common::fan;
using common::good_fan;
using common::MetricSite;
using common::VoronoiRefinement;
using common::VoronoiRules;
using predicates::Point2;
using predicates::Sym2;

// LS's rules as voronoi_refinement.hpp's shared rules.
VoronoiRules ls_rules() {
  return {static_cast<int>(Rule::encroached_segment), static_cast<int>(Rule::violator_encroaches), static_cast<int>(Rule::tie),
          static_cast<int>(Rule::island), static_cast<int>(Rule::corner_shell), rule_table()};
}

class LsVaryingRefinement : public VoronoiRefinement {
 public:
  LsVaryingRefinement(const common::Domain& domain, const fields::MetricField& field, const LsParameters& p)
      : VoronoiRefinement(domain, p.normalized_metric ? fields::normalized(field) : field, ls_rules(), p.filters,
                          [this](int a, int b) { return corner_note(domain_, t11_, a, b); }),
        p_(p),
        size_field_(field),
        s2_(sin2_above(p.theta_bound)) {
    std::vector<Sym2<double>> metrics;
    for (const auto& c : domain.vertices()) metrics.push_back(sites_.field.at(c.x, c.y));
    t11_ = theorem11_conditions(domain, metrics, p.theta_bound);
    start();
    for (std::size_t q = 0; q < diagram_.vertices().size(); ++q)
      if (diagram_.vertices()[q].holders > 0) violators_.push_back(static_cast<int>(q));
  }

  // The site of violator q: at q, or, with off-centres, poor angle and too large at the off-centre
  // of q's shortest edge at least δ/(2 sin θ_bound) (the radius of a triangle whose least angle is
  // θ_bound, which a poor angle's vertex exceeds), resp. the size, from every site.
  bool insert_for(Rule rule, int q) {
    if (!p_.off_centres || (rule != Rule::poor_angle && rule != Rule::too_large)) return attack_vertex(q, static_cast<int>(rule));
    const double ratio = rule == Rule::poor_angle ? 1 / (2 * std::sin(p_.theta_bound * std::acos(-1.0) / 180)) : 0;
    return attack_off_centre(q, static_cast<int>(rule), ratio, p_.size);
  }

  std::size_t queued() const { return subsegments_.queued() + ties_.size() + violators_.size(); }
  std::string done() const { return "no encroached subsegment and no violator"; }

  bool step() {
    if (split_encroached() || attack_unresolved()) return true;
    while (!violators_.empty()) {
      const int q = violators_.front();
      violators_.pop_front();
      if (diagram_.vertices()[static_cast<std::size_t>(q)].holders == 0) continue;
      const Rule rule = violation(q);
      if (!stalled_.empty()) return true;
      if (rule == Rule::none) continue;
      if (!insert_for(rule, q)) violators_.push_front(q);
      return true;
    }
    for (const JudgedTie& judged : exact_ties_) {
      if (judged.rule == 0) continue;
      attack_tie(judged.tie, judged.rule);
      return true;
    }
    return island();
  }

  LsResult result(const common::Stop& stop) {
    LsResult r;
    r.mesh.sites = sites_.points, r.mesh.metrics = sites_.metrics, r.mesh.domain = domain_.corners();
    r.mesh.segments = subsegments_.all();
    r.left_counted = !stop.out_of_time;
    const std::string stalled = stalled_;
    for (std::size_t q = 0; q < diagram_.vertices().size(); ++q) {
      const auto& v = diagram_.vertices()[q];
      if (v.holders == 0) continue;
      const CertifiedPoint P = point(static_cast<int>(q));
      if (common::in_closed_domain(domain_, P) != std::optional<bool>(true)) continue;
      const auto order = cell_order(static_cast<int>(q));
      r.mesh.triangles.push_back(order == Sign::negative ? std::array<int, 3>{v.sites[0], v.sites[2], v.sites[1]} : v.sites);
      if (r.left_counted) {
        bool exempted = false;
        r.violators_left += violation(static_cast<int>(q), &exempted) != Rule::none;
        r.exempt_left += exempted;
      }
    }
    for (const JudgedTie& judged : exact_ties_) {
      for (const auto& t : judged.triangles) r.mesh.triangles.push_back(t);
      if (r.left_counted) r.violators_left += judged.rule != 0;
    }
    if (r.left_counted)
      for (std::size_t s = 0; s < subsegments_.size(); ++s) r.encroached_left += !encroachers(static_cast<int>(s)).empty();
    stalled_ = stalled;
    record_.fill(r, stop.reason, stop.finished);
    return r;
  }

 private:
  // Rules 5, 3, 4 at vertex q, or none (a vertex outside closed Ω is no violator: LS §9 "q ∈ Ω").
  // Sets stalled_ when a decision is undecided. Rule 3 leaves alone a triangle across a small input
  // angle (corner_shells.hpp), and says so in `exempted`.
  Rule violation(int q, bool* exempted = nullptr) {
    const auto& v = diagram_.vertices()[static_cast<std::size_t>(q)];
    const CertifiedPoint P = point(q);
    const auto in = common::in_closed_domain(domain_, P);
    if (!in) {
      stalled_ = "whether the Voronoi vertex of sites " + common::trio_text(v.sites) + " lies in Ω is undecided (it is on ∂Ω or too near)";
      return Rule::none;
    }
    if (!*in) return Rule::none;
    const auto order = cell_order(q);
    if (!order || *order == Sign::zero) {
      stalled_ = "the cells of sites " + common::trio_text(v.sites) + " meet tangentially at their Voronoi vertex, or too nearly to tell";
      return Rule::none;
    }
    std::array<Point2<double>, 3> t{};
    for (int k = 0; k < 3; ++k) t[static_cast<std::size_t>(k)] = sites_.points[static_cast<std::size_t>(v.sites[static_cast<std::size_t>(k)])];
    if (predicates::orientation(t[0], t[1], t[2]) != *order) return Rule::inverted;
    // LS Definition 2: q ∈ wedge(v, w) ⇔ (q − v)ᵀM_v(w − v) > 0 and (q − w)ᵀM_w(v − w) > 0.
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        if (i == j) continue;
        const MetricSite vi = site(v.sites[static_cast<std::size_t>(i)]), vj = site(v.sites[static_cast<std::size_t>(j)]);
        const auto inside = common::sign_at<1>({&P}, [&](const auto& X, auto of) {
          using T = std::decay_t<decltype(X[0].x)>;
          const auto g = common::half_gradient(common::lift<T>(vi, of), X[0].x, X[0].y);  // M_v (q − v)
          return g[0] * (of(vj.p.x) - of(vi.p.x)) + g[1] * (of(vj.p.y) - of(vi.p.y));
        });
        if (!inside) {
          stalled_ = "whether the Voronoi vertex of sites " + common::trio_text(v.sites) + " is wedged is undecided (it is on a wedge's line or too near)";
          return Rule::none;
        }
        if (*inside != Sign::positive) return Rule::unwedged;
      }
    if (*order == Sign::negative) std::swap(t[1], t[2]);  // counter-clockwise
    const Point2<double> c = v.box.approx();
    const std::array<Sym2<double>, 4> metrics{sites_.metrics[static_cast<std::size_t>(v.sites[0])], sites_.metrics[static_cast<std::size_t>(v.sites[1])],
                                              sites_.metrics[static_cast<std::size_t>(v.sites[2])], sites_.field.at(c.x, c.y)};
    bool poor = false;
    for (std::size_t m = 0; m < metrics.size() && !poor; ++m)
      for (int i = 0; i < 3 && !poor; ++i)
        poor = !predicates::angle_at_least_arcsin(t[static_cast<std::size_t>((i + 2) % 3)], t[static_cast<std::size_t>(i)],
                                                  t[static_cast<std::size_t>((i + 1) % 3)], metrics[m], s2_);
    if (poor) {
      if (!corners_->exempt(v.sites, sites_.points)) return Rule::poor_angle;
      if (exempted) *exempted = true;
    }
    // Too large: d_p(q) > size in the field's metric M_p. The three sites' distances are equal in
    // the diagram's metrics; with M′ they differ in M, and each is judged.
    const int judged = p_.size <= 0 ? 0 : p_.normalized_metric ? 3 : 1;
    for (int k = 0; k < judged; ++k) {
      const std::size_t u = static_cast<std::size_t>(v.sites[static_cast<std::size_t>(k)]);
      const auto large = beyond(q, MetricSite{sites_.points[u], size_metric(u)}, p_.size);
      if (!large) {
        stalled_ = "whether the Voronoi vertex of sites " + common::trio_text(v.sites) + " is too large is undecided";
        return Rule::none;
      }
      if (*large == Sign::positive) return Rule::too_large;
    }
    return Rule::none;
  }

  // The metrics a tie's triangles are judged in: the sites' one metric and the field's at the
  // vertex (as violation() judges a vertex of degree 3).
  std::vector<Sym2<double>> tie_metrics(const ExactTie& tie) const {
    const Point2<double> q = rounded(tie.c).first;
    return {site(tie.sites[0]).M, sites_.field.at(q.x, q.y)};
  }
  // Rules 3 and 4 at an exact tie (one metric: no inverted or unwedged triangle): poor when no fan
  // of its polygon has all its angles at least θ_bound; too large as violation() judges a vertex,
  // exactly at the rational vertex.
  // The triangles: a good fan, or any fan while the tie is a violator.
  JudgedTie judged(const ExactTie& tie) const override {
    const auto good = good_fan(tie, diagram_.sites(), tie_metrics(tie), s2_);
    return {tie, static_cast<int>(good ? too_large(tie) : Rule::poor_angle), good ? *good : fan(tie, 0)};
  }
  Rule too_large(const ExactTie& tie) const {
    if (p_.size <= 0) return Rule::none;
    const std::size_t judged = p_.normalized_metric ? tie.sites.size() : 1;
    const auto exact = [](double x) { return Rational(x); };
    for (std::size_t k = 0; k < judged; ++k) {
      const std::size_t u = static_cast<std::size_t>(tie.sites[k]);
      const auto a = common::lift<Rational>(MetricSite{sites_.points[u], size_metric(u)}, exact);
      if (common::distance2(a, tie.c.x, tie.c.y) > exact(p_.size) * exact(p_.size)) return Rule::too_large;
    }
    return Rule::none;
  }

  void inserted(int) override {
    for (int q : diagram_.created()) violators_.push_back(q);
  }
  // The field's metric at site u, for the size rule (the diagram's with M).
  Sym2<double> size_metric(std::size_t u) const {
    return p_.normalized_metric ? size_field_.at(sites_.points[u].x, sites_.points[u].y) : sites_.metrics[u];
  }

  LsParameters p_;
  fields::MetricField size_field_;  // the field, for the size rule
  double s2_;
  Theorem11Conditions t11_;
  std::deque<int> violators_;
};

}  // namespace

LsResult refine_ls_varying(const common::Domain& domain, const fields::MetricField& field, const LsParameters& p,
                           const common::Progress& progress) {
  return common::run_refinement<LsVaryingRefinement>(p, progress, domain, field, p);
}

}  // namespace anisocert::refiners::ls
