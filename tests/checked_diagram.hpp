#pragma once
// Issue 14: the oracle's filtered constructions may only speed it up. checked_diagram(in) builds
// the diagram exactly (DiagramOptions::exact_only, one thread) and filtered (one thread and two),
// and expects the same diagram: its whole JSON apart from `stats`, which holds timings and the
// filters' counts. An input the exact path declines (std::domain_error) must be declined with the
// same message, which is rethrown. It returns the filtered diagram.
#include "io/diagram_json.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <stdexcept>
#include <string>

namespace anisocert::test_support {

inline oracle::Diagram checked_diagram(const geometry::Mesh<Rational>& in) {
  const auto run = [&](bool exact_only, int threads, std::string& declined) -> std::optional<oracle::Diagram> {
    oracle::DiagramOptions o;
    o.exact_only = exact_only, o.threads = threads;
    try {
      return oracle::compute_diagram(in, o);
    } catch (const std::domain_error& e) {
      declined = e.what();
      return std::nullopt;
    }
  };
  const auto json = [](const oracle::Diagram& d) {
    io::OrderedJson j = io::diagram_json(d);
    j.erase("stats");
    return j.dump();
  };
  std::string declined_exact, declined_one, declined_two;
  const auto exact = run(true, 1, declined_exact);
  const auto one = run(false, 1, declined_one);
  const auto two = run(false, 2, declined_two);
  EXPECT_EQ(declined_one, declined_exact);
  EXPECT_EQ(declined_two, declined_exact);
  if (!exact) throw std::domain_error(declined_exact);
  EXPECT_TRUE(one && two);
  if (!one || !two) throw std::logic_error("checked_diagram: the filtered path declined an input the exact path answered");
  const std::string expected = json(*exact);
  EXPECT_EQ(json(*one), expected) << "filtered, one thread";
  EXPECT_EQ(json(*two), expected) << "filtered, two threads";
  return *two;
}

}  // namespace anisocert::test_support
