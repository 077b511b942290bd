// The whole engine, bit for bit: two runs are the same run iff their checkpoints are equal (every
// array the engine saves, and its clocks and counters).
#pragma once

#include <gtest/gtest.h>

#include "engine/simulation.hpp"

namespace granule {

template <int D>
void expect_same_engine(const Simulation<D>& a, const Simulation<D>& b) {
  StateArchive sa, sb;
  a.save(sa, "");
  b.save(sb, "");
  ASSERT_EQ(sa.arrays().size(), sb.arrays().size());
  for (const auto& [name, values] : sa.arrays()) {
    ASSERT_TRUE(sb.contains(name)) << name;
    EXPECT_TRUE(values == sb.arrays().at(name)) << "engine entry " << name << " differs";
  }
  EXPECT_EQ(a.time(), b.time());
  EXPECT_EQ(a.collisions(), b.collisions());
  EXPECT_EQ(a.events(), b.events());
}

}  // namespace granule
