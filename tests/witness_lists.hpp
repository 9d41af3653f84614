#pragma once
// Two witness lists (oracle/certify/witness_list.hpp) are the same, witness for witness: every
// place in order, and every described text. The threaded certifiers' tests compare the report of
// one thread with that of several.
#include "oracle/certify/witness_list.hpp"

#include <gtest/gtest.h>

#include <string>

inline void expect_same_witnesses(const anisocert::oracle::WitnessList& a, const anisocert::oracle::WitnessList& b, const std::string& what) {
  ASSERT_EQ(a.count(), b.count()) << what;
  for (std::size_t i = 0; i < a.count(); ++i) {
    EXPECT_EQ(a.places()[i].vertex, b.places()[i].vertex) << what << " " << i;
    EXPECT_EQ(a.places()[i].triangle, b.places()[i].triangle) << what << " " << i;
    EXPECT_EQ(a.places()[i].site, b.places()[i].site) << what << " " << i;
  }
  ASSERT_EQ(a.described().size(), b.described().size()) << what;
  for (std::size_t i = 0; i < a.described().size(); ++i) EXPECT_EQ(a.described()[i].text, b.described()[i].text) << what << " " << i;
}
