// The quantities a refinement study follows (study/quantities.hpp), read from a run's
// summary: a key the run did not write (no contact, no fluid, a failed level) is NaN,
// which the study reports as "not at every level", never a zero it would extrapolate.
#include "study/quantities.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fsi::quantities_test {
namespace {

TEST(Quantities, WhatARunDidNotWriteIsNaN) {
  const std::vector<Quantity> qs = quantities(load_case(""));  // the §7.2 case: structure and fluid
  ASSERT_FALSE(qs.empty());
  Json written = Json::object();
  written["max_displacement"] = 0.038;
  written["contact"] = {{"x_min", 0.2}};
  for (const Quantity& q : qs) {
    EXPECT_TRUE(std::isnan(q.read(Json::object()))) << q.name;
    if (q.name == "max_displacement") EXPECT_EQ(q.read(written), 0.038);
    else if (q.name == "contact_x_min") EXPECT_EQ(q.read(written), 0.2);
    else EXPECT_TRUE(std::isnan(q.read(written))) << q.name;
  }
}

}  // namespace
}  // namespace fsi::quantities_test
