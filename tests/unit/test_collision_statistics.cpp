// Collisional stress (1.6), impact parameters (3.19) and free paths (§3.2.3) from hand-made
// collision records, and the summaries of §3.2.2–3.2.3 on samples from known distributions (the
// fits of (3.24) against analytic errors: test_free_path_fits.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <tuple>

#include "observers/collision_statistics_fits.hpp"
#include "observers/collisional_stress.hpp"
#include "observers/free_paths.hpp"
#include "observers/impact_parameters.hpp"
#include "init/random.hpp"

namespace granule {
namespace {

CollisionRecord<2> record(double t, int a, int b, Vec2 contact, Vec2 k, Vec2 v21, double impulse = 1.0) {
  CollisionRecord<2> r;
  r.time = t;
  r.first = a;
  r.second = b;
  r.contact_point = contact;
  r.contact_normal = k;
  r.relative_velocity = v21;
  r.impulse = impulse;
  return r;
}

TEST(CollisionalStress, EachCollisionAddsSigmaJkkOverCellAreaAndInterval) {
  const FieldGrid grid{2, 1, 2.0, 1.0};
  CollisionalStressField<2> field(grid, 0.1);
  field.restart(1.0);
  const double s = std::sqrt(0.5);
  field.on_collision(record(1.2, 0, 1, {0.5, 0.5}, {1.0, 0.0}, {1.0, 0.0}, 2.0));
  field.on_collision(record(1.4, 2, 3, {1.5, 0.5}, {s, s}, {1.0, 0.0}, 4.0));
  const CollisionalStress c = field.stress(3.0);  // interval 2, cell area 1
  EXPECT_DOUBLE_EQ(c.interval, 2.0);
  EXPECT_NEAR(c.xx[0], 0.1 * 2.0 / 2.0, 1e-15);
  EXPECT_NEAR(c.xy[0], 0.0, 1e-15);
  EXPECT_NEAR(c.xx[1], 0.1 * 4.0 * 0.5 / 2.0, 1e-15);
  EXPECT_NEAR(c.xy[1], 0.1 * 4.0 * 0.5 / 2.0, 1e-15);
  EXPECT_DOUBLE_EQ(c.collisions[1], 1.0);
}

TEST(ImpactParameter, HeadOnIsZeroGrazingIsSigmaObliqueIsSigmaSine) {
  const double sigma = 0.01;
  EXPECT_NEAR(impact_parameter(record(0, 0, 1, {}, {1, 0}, {2, 0}), sigma), 0.0, 1e-18);
  EXPECT_NEAR(impact_parameter(record(0, 0, 1, {}, {1, 0}, {0, -3}), sigma), sigma, 1e-18);
  const double angle = 0.3;  // between v₂₁ and k̂
  const Vec2 v{std::cos(angle), std::sin(angle)};
  EXPECT_NEAR(impact_parameter(record(0, 0, 1, {}, {1, 0}, 5.0 * v), sigma), sigma * std::sin(angle), 1e-15);
}

TEST(ImpactParameterStatistics, WindowsOfConsecutiveCollisionsAndDensityWindows) {
  const FieldGrid grid{2, 1, 2.0, 1.0};
  LocalDensity density(grid);
  ParticleState s;
  s.x = {0.1, 0.2, 0.3, 1.5};  // 3 disks in the left cell, 1 in the right
  s.y = {0.5, 0.5, 0.5, 0.5};
  s.vx = s.vy = {0, 0, 0, 0};
  density.update(s);
  ImpactParameterStatistics<2> stats(1.0, 4, 2, {{2.0, 4.0}}, &density);
  stats.on_collision(record(1.0, 0, 1, {0.5, 0.5}, {1, 0}, {1, 0}));  // b = 0, dense cell
  stats.on_collision(record(2.0, 0, 1, {1.5, 0.5}, {1, 0}, {0, 1}));  // b = σ, dilute cell
  stats.on_collision(record(3.0, 0, 1, {0.5, 0.5}, {1, 0}, {0, 1}));  // opens the second window
  ASSERT_EQ(stats.windows().size(), 1u);
  EXPECT_DOUBLE_EQ(stats.windows()[0].t_start, 1.0);
  EXPECT_DOUBLE_EQ(stats.windows()[0].t_end, 2.0);
  EXPECT_EQ(stats.windows()[0].counts, (std::vector<double>{1, 0, 0, 1}));
  EXPECT_EQ(stats.total(), (std::vector<double>{1, 0, 0, 2}));
  EXPECT_EQ(stats.by_density()[0], (std::vector<double>{1, 0, 0, 1}));
}

TEST(FreePathStatistics, PathIsTheFlightSinceThePreviousCollision) {
  FreePathSettings settings;
  settings.length_bins = 10;
  settings.angle_bins = 4;
  settings.max_length = 10.0;
  FreePathStatistics<2> paths(3, settings, nullptr);
  paths.start();
  CollisionRecord<2> a = record(1.0, 0, 1, {}, {1, 0}, {1, 0});
  a.first_velocity_after = {0.0, 2.0};   // disk 0 then flies up at speed 2
  a.second_velocity_after = {-1.0, 0.0};
  paths.on_collision(a);  // first collisions: no paths yet
  EXPECT_DOUBLE_EQ(paths.total().paths, 0.0);
  CollisionRecord<2> b = record(3.5, 2, 0, {}, {1, 0}, {1, 0});
  paths.on_collision(b);  // disk 0 has flown 2 × 2.5 = 5 at α = π/2
  EXPECT_DOUBLE_EQ(paths.total().paths, 1.0);
  EXPECT_DOUBLE_EQ(paths.total().sum_length, 5.0);
  EXPECT_DOUBLE_EQ(paths.total().sum_speed, 2.0);
  EXPECT_DOUBLE_EQ(paths.total().counts[5 * 4 + 1], 1.0);  // length bin 5, angle bin 1 (π/2 ≤ α < π)
}

// Paths longer than the starting range widen it (bins merged pairwise) instead of overflowing: the
// histogram is then the one a fixed range of the final width would have built, path for path, and
// the windows follow.  Lengths 0.05 … 37 with a starting range of 1 end on [0, 64) (6 doublings).
TEST(FreePathStatistics, RangeWidensSoThatNoPathIsDropped) {
  const auto histogram_of = [](double max_length) {
    FreePathSettings settings;
    settings.length_bins = 10;
    settings.angle_bins = 4;
    settings.max_length = max_length;
    settings.speed_windows = {{0.0, 100.0}};
    FreePathStatistics<2> paths(2, settings, nullptr);
    paths.start();
    double t = 0.0;
    for (const double length : {0.05, 0.9, 3.7, 1.2, 37.0, 0.31, 12.5, 6.4, 63.9}) {
      CollisionRecord<2> r = record(t, 0, 1, {}, {1, 0}, {1, 0});
      r.first_velocity_after = {1.0, 0.0};  // both fly at unit speed for `length`
      r.second_velocity_after = {0.0, -1.0};
      paths.on_collision(r);
      t += length;
    }
    paths.on_collision(record(t, 0, 1, {}, {1, 0}, {1, 0}));
    return std::tuple{paths.total(), paths.by_speed()[0], paths.length_bins().high, paths.range_doublings()};
  };
  const auto [total, window, range, doublings] = histogram_of(1.0);
  const auto [reference, reference_window, reference_range, none] = histogram_of(64.0);
  EXPECT_DOUBLE_EQ(range, 64.0);
  EXPECT_EQ(doublings, 6);
  EXPECT_EQ(none, 0);
  EXPECT_EQ(total.counts, reference.counts);
  EXPECT_EQ(window.counts, reference_window.counts);
  EXPECT_EQ(total.overflow, std::vector<double>(4, 0.0));
  EXPECT_DOUBLE_EQ(reference_range, 64.0);
  EXPECT_DOUBLE_EQ(total.paths, 18.0);  // 9 flights of 2 disks
  double binned = 0.0;
  for (const double c : total.counts) binned += c;
  EXPECT_DOUBLE_EQ(binned, total.paths);
}

TEST(FreePathSummary, MatchedFormRecoversGammaHalfSamplesAndRejectsTheExponential) {
  // Samples of 𝒫(l) = exp(−l/l₀)/√(π l₀ l) (3.36): l = l₀ Z²/2 with Z standard normal.
  Random random(11);
  const double l0 = 0.4;
  FreePathSettings settings;
  settings.length_bins = 200;
  settings.angle_bins = 8;
  settings.max_length = 10.0;
  PathHistogram h;
  h.counts.assign(200 * 8, 0.0);
  h.overflow.assign(8, 0.0);
  const UniformBins lengths{0.0, 10.0, 200}, angles{0.0, 2.0 * std::numbers::pi, 8};
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double z = random.normal();
    const double l = 0.5 * l0 * z * z;
    const int k = lengths.bin(l);
    if (k < 0) {
      h.overflow[0] += 1;
    } else {
      h.counts[static_cast<std::size_t>(k) * 8] += 1;
    }
    h.paths += 1;
    h.sum_length += l;
  }
  const FreePathSummary s = summarize_free_paths(h, lengths, angles);
  EXPECT_NEAR(s.l0_matched, l0, 4.0 * l0 * std::sqrt(2.0 / n));  // l₀ = 2⟨l⟩, var(l) = l₀²/2
  EXPECT_NEAR(s.lbar, l0, 0.02 * l0);
  EXPECT_LT(s.ks_matched, 0.01);
  EXPECT_GT(s.ks_exponential, 0.05);
}

TEST(ImpactParameterSummary, UniformCountsHaveNoDeviation) {
  const UniformBins bins{0.0, 1.0, 10};
  const ImpactParameterSummary s = summarize_impact_parameters(std::vector<double>(10, 7.0), bins);
  EXPECT_DOUBLE_EQ(s.samples, 70.0);
  for (double d : s.density) EXPECT_NEAR(d, 1.0, 1e-12);
  EXPECT_NEAR(s.ks_uniform, 0.0, 1e-12);
}

}  // namespace
}  // namespace granule
