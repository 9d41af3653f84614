// refine --from's batches (cli/dual_trial.hpp): which changes a round admits together, and which
// of them a failed trial puts back. The trials here are stand-ins for the oracle that name fixed
// sites, so the test says what each failure is charged to without computing a diagram.
#include "cli/dual_trial.hpp"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace anisocert::cli {
namespace {

// The path 0 – 1 – 2 – … – (k − 1): each site's neighbours.
std::vector<std::set<int>> path(int k) {
  std::vector<std::set<int>> n(static_cast<std::size_t>(k));
  for (int v = 0; v + 1 < k; ++v) n[static_cast<std::size_t>(v)].insert(v + 1), n[static_cast<std::size_t>(v + 1)].insert(v);
  return n;
}

TEST(DisjointNeighbourhoods, AdmitsAChangeOnlyWhenNoSiteOfItsClosedNeighbourhoodIsClaimed) {
  const auto n = path(9);
  DisjointNeighbourhoods apart(n);
  EXPECT_TRUE(apart.admit({0}));      // claims 0, 1
  EXPECT_FALSE(apart.admit({2}));     // 1 is a neighbour of both 0 and 2
  EXPECT_TRUE(apart.admit({3}));      // 2, 3, 4: the refused 2 claimed nothing
  EXPECT_FALSE(apart.admit({5}));     // 4
  EXPECT_FALSE(apart.admit({6, 5}));  // a collapse touching 5 as well
  EXPECT_TRUE(apart.admit({6, 7}));   // 5, 6, 7, 8
  EXPECT_FALSE(apart.admit({8}));
}

struct Change {
  std::vector<int> sites;
};

std::vector<int> touched(const Change& c) { return c.sites; }

TEST(KeepCertified, AFailureIsChargedToTheChangesNextToANamedSiteAndTheRestIsKept) {
  const auto n = path(12);
  // Changes at 1, 4 (a collapse with 5) and 9: apart, as DisjointNeighbourhoods admits them.
  const std::vector<Change> batch{{{1}}, {{4, 5}}, {{9}}};
  std::vector<std::size_t> tried;
  std::vector<int> refused;
  const auto kept = keep_certified(
      batch, n, touched,
      [&](const std::vector<Change>& b) {
        tried.push_back(b.size());
        Trial t;
        t.certified = b.size() < 3;
        if (!t.certified) t.near_failures = {6};  // next to 5, the collapse's other site, and to no other change
        return t;
      },
      [](const Trial&) { return true; }, [&](const Change& c) { refused.push_back(c.sites[0]); });
  ASSERT_TRUE(kept);
  EXPECT_EQ(tried, (std::vector<std::size_t>{3, 2}));
  EXPECT_EQ(refused, std::vector<int>{4});
  ASSERT_EQ(kept->batch.size(), 2u);
  EXPECT_EQ(kept->batch[0].sites, std::vector<int>{1});
  EXPECT_EQ(kept->batch[1].sites, std::vector<int>{9});
}

TEST(KeepCertified, AFailureNamingAChangesOwnSiteIsChargedToThatChangeAlone) {
  const auto n = path(12);
  const std::vector<Change> batch{{{1}}, {{4, 5}}, {{9}}};
  std::vector<int> refused;
  for (const int named : {1, 5, 9}) {  // v of a removal, a collapse's moved w, and a lone site at the path's far end
    refused.clear();
    const auto kept = keep_certified(
        batch, n, touched,
        [&](const std::vector<Change>& b) {
          Trial t;
          t.certified = b.size() < 3;
          if (!t.certified) t.near_failures = {named};
          return t;
        },
        [](const Trial&) { return true; }, [&](const Change& c) { refused.push_back(c.sites[0]); });
    ASSERT_TRUE(kept);
    EXPECT_EQ(kept->batch.size(), 2u) << named;
    EXPECT_EQ(refused, std::vector<int>{named == 5 ? 4 : named}) << named;
  }
}

TEST(KeepCertified, AFailureNamingNoChangesNeighbourhoodOrAWorseMeshTriesTheEarlierHalfAndRefusesNothing) {
  const auto n = path(20);
  const std::vector<Change> batch{{{1}}, {{4}}, {{7}}, {{10}}, {{13}}, {{16}}};
  std::vector<std::size_t> tried;
  int refusals = 0;
  const auto kept = keep_certified(
      batch, n, touched,
      [&](const std::vector<Change>& b) {
        tried.push_back(b.size());
        Trial t;
        t.certified = b.size() < 6;
        if (!t.certified) t.near_failures = {19};  // next to no change
        return t;
      },
      [&](const Trial&) { return tried.back() < 3; },  // the mesh of 3 changes is worse, that of 1 better
      [&](const Change&) { ++refusals; });
  ASSERT_TRUE(kept);
  EXPECT_EQ(tried, (std::vector<std::size_t>{6, 3, 1}));
  EXPECT_EQ(refusals, 0);
  ASSERT_EQ(kept->batch.size(), 1u);
  EXPECT_EQ(kept->batch[0].sites, std::vector<int>{1});
}

TEST(KeepCertified, GivesUpAfterEightTrials) {
  const auto n = path(4);
  std::vector<Change> batch(300, Change{{0}});
  int trials = 0;
  const auto kept = keep_certified(
      batch, n, touched,
      [&](const std::vector<Change>&) {
        ++trials;
        return Trial{};  // never certified, nothing named
      },
      [](const Trial&) { return true; }, [](const Change&) {});
  EXPECT_FALSE(kept);
  EXPECT_EQ(trials, 8);
}

}  // namespace
}  // namespace anisocert::cli
