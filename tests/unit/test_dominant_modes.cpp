// When a spectrum's dominant mode has appeared (reproduce/dominant_modes.hpp): the first of three
// consecutive frames in which the same mode is dominant and significant, so that a lone false alarm,
// or significant frames of different modes in a row, do not count.
#include <gtest/gtest.h>

#include <vector>

#include "reproduce/dominant_modes.hpp"

namespace granule::reproduce {
namespace {

TEST(DominantModes, AModeAppearsAtTheFirstOfThreeSignificantFramesOfTheSameMode) {
  const std::vector<DominantMode> frames{
      {0.0, 0.04, false}, {1.0, 0.02, true},  // a lone false alarm
      {2.0, 0.03, false}, {3.0, 0.05, true}, {4.0, 1.0, true},  {5.0, 0.7, true},  // significant, but three modes
      {6.0, 1.0, true},   {7.0, 1.0, true},  {8.0, 1.0, true},  {9.0, 1.0, false}};
  const DominantMode* first = first_persistent_mode(frames);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first->c, 6.0);
  EXPECT_EQ(first->length, 1.0);
}

TEST(DominantModes, NoModeThatStaysMeansNone) {
  const std::vector<DominantMode> flicker{{0.0, 1.0, true}, {1.0, 1.0, true}, {2.0, 1.0, false}, {3.0, 1.0, true}};
  EXPECT_EQ(first_persistent_mode(flicker), nullptr);
  EXPECT_EQ(first_persistent_mode({}), nullptr);
}

}  // namespace
}  // namespace granule::reproduce
