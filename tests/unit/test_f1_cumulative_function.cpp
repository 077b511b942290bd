// Unit tier: the counted cumulative function h(v, θ) of thesis (5.11) is a distribution function to
// the last bit: non-decreasing in v and θ, and h(v_max, 2π) = 1 (5.12) when every sample is binned.
// (Running sums of the fractions count/total would dip by ~3·10⁻¹⁷.)
#include <gtest/gtest.h>

#include "distribution/cumulative_function.hpp"
#include "init/random.hpp"

namespace granule::distribution {
namespace {

TEST(F1CumulativeFunction, IsExactlyMonotoneAndReachesOne) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Random random(seed);
    const PolarGrid grid{48, 48, 3.0};
    Eigen::MatrixXd counts(grid.speed_bins, grid.angle_bins);
    for (Eigen::Index k = 0; k < counts.rows(); ++k)
      for (Eigen::Index l = 0; l < counts.cols(); ++l) counts(k, l) = static_cast<double>(random.below(40));
    const CumulativeFunction c = cumulative_function(counts, counts.sum(), grid);
    EXPECT_EQ(c.h(grid.speed_bins, grid.angle_bins), 1.0) << "seed " << seed;
    int decreasing = 0;
    for (int k = 0; k <= grid.speed_bins; ++k)
      for (int l = 0; l <= grid.angle_bins; ++l) {
        decreasing += k > 0 && c.h(k, l) < c.h(k - 1, l);
        decreasing += l > 0 && c.h(k, l) < c.h(k, l - 1);
      }
    for (int k = 1; k <= grid.speed_bins; ++k) decreasing += c.phi[k] < c.phi[k - 1];
    EXPECT_EQ(decreasing, 0) << "seed " << seed;
  }
}

}  // namespace
}  // namespace granule::distribution
