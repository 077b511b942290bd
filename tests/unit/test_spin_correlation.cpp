// The spin correlation of neighbouring grains (analysis/spin_correlation.hpp, thesis Fig C.4) on
// constructed configurations with known answers — meshing gears on a checkerboard give −1 at
// contact, independent spins 0 — pairs across periodic and Lees–Edwards boundaries counted, none
// across walls, and the O(N) cell search against a brute-force O(N²) oracle over every image.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/spin_correlation.hpp"
#include "unit/particle_rows.hpp"

namespace granule {
namespace {

constexpr double kSigma = 1.0;

PairImages box_of(double lx, double ly, double offset = 0.0, double lz = 1.0) {
  PairImages images;
  images.length = {lx, ly, lz};
  images.shear_offset = offset;
  return images;
}

// An n × n square lattice of spacing σ whose spins alternate ±2 around `mean` (a mean spin such as
// the −γ/2 of a shear flow, which the correlation removes; a variance of 4, which it divides out).
ParticleState checkerboard(int n, double mean) {
  ParticleState s;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      s.x.push_back((i + 0.5) * kSigma);
      s.y.push_back((j + 0.5) * kSigma);
      s.wz.push_back(mean + ((i + j) % 2 == 0 ? 2.0 : -2.0));
    }
  }
  s.vx.assign(s.x.size(), 0.0);
  s.vy.assign(s.x.size(), 0.0);
  return s;
}

TEST(SpinCorrelation, CheckerboardOfMeshingGearsIsMinusOneAtContact) {
  const ParticleState s = checkerboard(10, -3.5);
  const SpinPairSums sums = spin_pair_sums(s, box_of(10.0, 10.0), kSigma, {});
  EXPECT_NEAR(sums.mean_spin[2], -3.5, 1e-12);
  EXPECT_NEAR(sums.spin_variance, 4.0, 1e-12);
  // Every site has 4 nearest neighbours (the lattice is periodic): 200 pairs, half along each axis.
  EXPECT_EQ(sums.contact_pairs, 200.0);
  EXPECT_NEAR(sums.contact_correlation(), -1.0, 1e-12);
  EXPECT_EQ(sums.pairs[1][0], 100.0);
  EXPECT_EQ(sums.pairs[2][0], 100.0);
  EXPECT_NEAR(sums.correlation(PairDirection::kFlow, 0), -1.0, 1e-12);
  EXPECT_NEAR(sums.correlation(PairDirection::kGradient, 0), -1.0, 1e-12);
  // Diagonal neighbours at √2 σ spin alike: +1 in the bin of r = 1.414 (bins of 0.1 from 1).
  EXPECT_NEAR(sums.correlation(PairDirection::kAll, 4), 1.0, 1e-12);
  EXPECT_EQ(sums.pairs[0][4], 200.0);
  // Between lattice distances there are no pairs: NaN, not 0.
  EXPECT_TRUE(std::isnan(sums.correlation(PairDirection::kAll, 2)));
}

TEST(SpinCorrelation, CubicCheckerboardOfSpheresIsMinusOneAtContact) {
  ParticleState s;
  s.dimension = 3;
  for (int i = 0; i < 8; ++i) {
    for (int j = 0; j < 8; ++j) {
      for (int k = 0; k < 8; ++k) {
        s.x.push_back(i + 0.5);
        s.y.push_back(j + 0.5);
        s.z.push_back(k + 0.5);
        const double sign = (i + j + k) % 2 == 0 ? 1.0 : -1.0;
        s.wx.push_back(0.6 * sign);
        s.wy.push_back(0.0);
        s.wz.push_back(0.8 * sign);
      }
    }
  }
  const SpinPairSums sums = spin_pair_sums(s, box_of(8.0, 8.0, 0.0, 8.0), kSigma, {});
  EXPECT_EQ(sums.contact_pairs, 3.0 * 512.0);
  EXPECT_NEAR(sums.contact_correlation(), -1.0, 1e-12);
  EXPECT_EQ(sums.pairs[1][0] + sums.pairs[2][0], 2.0 * 512.0);  // pairs along z count in the overall C only
}

TEST(SpinCorrelation, IndependentSpinsAreUncorrelated) {
  Random random(11);
  const double side = 60.0;
  ParticleState s = uniform_positions(random, 6000, side, side);
  s.wz.resize(s.size());
  for (double& w : s.wz) w = 2.0 * random.uniform() - 1.0 + 7.0;
  const SpinPairSums sums = spin_pair_sums(s, box_of(side, side), kSigma, {});
  ASSERT_GT(sums.contact_pairs, 1000.0);
  // Each pair's product δω_i δω_j/⟨|δω|²⟩ has unit variance and those of distinct pairs are
  // uncorrelated: the mean of n of them is within 5/√n of 0 but for a chance of ~1e-6 per bin.
  EXPECT_LT(std::abs(sums.contact_correlation()), 5.0 / std::sqrt(sums.contact_pairs));
  for (std::size_t bin = 0; bin < sums.pairs[0].size(); ++bin) {
    EXPECT_LT(std::abs(sums.correlation(PairDirection::kAll, bin)), 5.0 / std::sqrt(sums.pairs[0][bin])) << bin;
  }
}

// Two grains a contact distance apart only through an image.
ParticleState two_grains(double x0, double y0, double x1, double y1) {
  ParticleState s = particles_from_rows({{x0, y0, 0.0, 0.0}, {x1, y1, 0.0, 0.0}});
  s.wz = {1.0, -1.0};
  return s;
}

TEST(SpinCorrelation, PairsAcrossThePeriodicBoundaryAreCountedAndNotAcrossWalls) {
  const ParticleState s = two_grains(0.4, 5.0, 9.4, 5.0);  // 1 σ apart through x = 0
  PairImages images = box_of(10.0, 10.0);
  SpinPairSums sums = spin_pair_sums(s, images, kSigma, {});
  EXPECT_EQ(sums.contact_pairs, 1.0);
  EXPECT_EQ(sums.pairs[1][0], 1.0);
  EXPECT_NEAR(sums.contact_correlation(), -1.0, 1e-12);
  images.walls[0] = true;  // walls at x = 0 and L: 9 σ apart, beyond the 3 σ binned
  sums = spin_pair_sums(s, images, kSigma, {});
  EXPECT_EQ(sums.contact_pairs, 0.0);
  EXPECT_EQ(sums.pairs[0][0], 0.0);
}

TEST(SpinCorrelation, PairsAcrossTheLeesEdwardsBoundaryFollowTheShiftedImage) {
  // The image of the upper grain below the box is at (7.5 − Δ, 9.3 − 10): with Δ = 2.5 it sits
  // 1 σ under the lower grain; without the shift it would be 2.7 σ away.
  const ParticleState s = two_grains(5.0, 0.3, 7.5, 9.3);
  SpinPairSums sums = spin_pair_sums(s, box_of(10.0, 10.0, 2.5), kSigma, {});
  EXPECT_EQ(sums.contact_pairs, 1.0);
  EXPECT_EQ(sums.pairs[2][0], 1.0);  // along the gradient
  sums = spin_pair_sums(s, box_of(10.0, 10.0, 0.0), kSigma, {});
  EXPECT_EQ(sums.contact_pairs, 0.0);
  EXPECT_EQ(sums.pairs[0][16], 1.0);  // r = √(2.5² + 1) = 2.69
  PairImages walled = box_of(10.0, 10.0, 2.5);
  walled.walls[1] = true;  // y walls: no image at all
  sums = spin_pair_sums(s, walled, kSigma, {});
  EXPECT_EQ(sums.pairs[0][16] + sums.contact_pairs, 0.0);
}

// Oracle: every pair, every image iy ∈ {−1, 0, 1} shifted by iy·Δ and the nearest along x; a
// pair's separation is the shortest of them.
std::vector<double> brute_force_pairs(const ParticleState& s, const PairImages& images, const SpinCorrelationSettings& settings) {
  std::vector<double> pairs(static_cast<std::size_t>(settings.bins), 0.0);
  const double width = (settings.max_distance - 1.0) / settings.bins;
  for (std::size_t i = 0; i < s.size(); ++i) {
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      double best = INFINITY;
      for (int iy = -1; iy <= 1; ++iy) {
        double dx = s.x[j] + iy * images.shear_offset - s.x[i];
        dx -= images.length[0] * std::round(dx / images.length[0]);
        const double dy = s.y[j] + iy * images.length[1] - s.y[i];
        best = std::min(best, std::hypot(dx, dy));
      }
      if (best < settings.max_distance) pairs[static_cast<std::size_t>(std::max(0.0, (best - 1.0) / width))] += 1.0;
    }
  }
  return pairs;
}

TEST(SpinCorrelation, CellSearchFindsThePairsOfBruteForce) {
  Random random(5);
  for (const double offset : {0.0, 3.7, 11.9}) {
    ParticleState s = uniform_positions(random, 800, 12.0, 9.0);
    s.wz.assign(s.size(), 1.0);
    const PairImages images = box_of(12.0, 9.0, offset);
    const SpinPairSums sums = spin_pair_sums(s, images, kSigma, {});
    const std::vector<double> expected = brute_force_pairs(s, images, {});
    for (std::size_t bin = 0; bin < expected.size(); ++bin) EXPECT_EQ(sums.pairs[0][bin], expected[bin]) << offset << " " << bin;
    EXPECT_EQ(sums.contact_correlation(), 0.0);  // spins all alike: nothing fluctuates
  }
}

TEST(SpinCorrelation, RefusesSmoothGrainsAndBoxesTooSmall) {
  ParticleState smooth = particles_from_rows({{1.0, 1.0, 0.0, 0.0}});
  EXPECT_THROW(spin_pair_sums(smooth, box_of(10.0, 10.0), kSigma, {}), std::invalid_argument);
  const ParticleState s = two_grains(1.0, 1.0, 2.0, 1.0);
  EXPECT_THROW(spin_pair_sums(s, box_of(5.0, 10.0), kSigma, {}), std::invalid_argument);  // 5 < 2 · 3 σ
  PairImages walled = box_of(5.0, 10.0);
  walled.walls[0] = true;  // no images along x: any length will do
  EXPECT_NO_THROW(spin_pair_sums(s, walled, kSigma, {}));
  SpinCorrelationSettings settings;
  settings.max_distance = 1.05;
  EXPECT_THROW(spin_pair_sums(s, box_of(10.0, 10.0), kSigma, settings), std::invalid_argument);
}

TEST(SpinCorrelation, AverageOverFramesGivesTheScatterOfTheContactValue) {
  SpinCorrelationAverage average;
  SpinPairSums frame;
  for (auto& p : frame.pairs) p.assign(2, 0.0);
  frame.products = frame.pairs;
  for (const double c : {-0.1, -0.3}) {
    frame.contact_pairs = 10.0;
    frame.contact_products = 10.0 * c;
    average.add(frame);
  }
  EXPECT_NEAR(average.contact_mean(), -0.2, 1e-12);
  EXPECT_NEAR(average.contact_error(), 0.1, 1e-12);  // sd 0.1414 / √2
  EXPECT_EQ(average.total.contact_pairs, 20.0);
}

}  // namespace
}  // namespace granule
