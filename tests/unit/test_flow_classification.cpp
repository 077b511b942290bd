// The Chapter 4 flow measures (analysis/flow_classification.hpp) on hand-built configurations with
// known answers, and the O(N) cluster labelling and densest band against brute-force O(N²) oracles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "analysis/flow_classification.hpp"
#include "unit/particle_rows.hpp"

namespace granule {
namespace {

// Oracle: every pair, every vertical image (shifted by ±Δ), nearest horizontal image; labels by
// repeated relaxation to the smallest connected id until nothing changes.
std::vector<std::int32_t> brute_force_labels(const ParticleState& s, double lx, double ly, double offset, double r) {
  const std::size_t n = s.size();
  std::vector<std::vector<std::size_t>> neighbours(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      for (int iy = -1; iy <= 1; ++iy) {
        double dx = s.x[j] + iy * offset - s.x[i];
        dx -= lx * std::round(dx / lx);
        const double dy = s.y[j] + iy * ly - s.y[i];
        if (std::hypot(dx, dy) < r) {
          neighbours[i].push_back(j);
          neighbours[j].push_back(i);
          break;
        }
      }
    }
  }
  std::vector<std::int32_t> label(n);
  std::iota(label.begin(), label.end(), 0);
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j : neighbours[i]) {
        if (label[j] < label[i]) label[i] = label[j], changed = true;
      }
    }
  }
  return label;
}

TEST(ClusterLabels, MatchBruteForceOnRandomConfigurations) {
  Random random(11);
  struct Case {
    std::size_t n;
    double lx, ly, r;
  };
  // From sparse to percolating, boxes only one or two cell-list cells wide included.
  for (const Case k : {Case{1500, 1.0, 1.0, 0.02}, Case{1500, 1.0, 1.0, 0.03}, Case{800, 2.0, 0.5, 0.04},
                       Case{300, 0.1, 1.0, 0.045}, Case{200, 1.0, 0.07, 0.05}, Case{60, 0.15, 0.15, 0.08}}) {
    for (int trial = 0; trial < 3; ++trial) {
      const ParticleState s = uniform_positions(random, k.n, k.lx, k.ly);
      const double offset = trial == 0 ? 0.0 : k.lx * random.uniform();
      const auto fast = cluster_labels(s, k.lx, k.ly, offset, k.r);
      const auto slow = brute_force_labels(s, k.lx, k.ly, offset, k.r);
      EXPECT_EQ(fast, slow) << "n " << k.n << " box " << k.lx << " × " << k.ly << " r " << k.r << " Δ " << offset;
      EXPECT_DOUBLE_EQ(largest_cluster_mass_fraction(fast), largest_cluster_mass_fraction(slow));
      std::printf("n %zu box %g × %g r %g Δ %.3f: largest cluster %.3f\n", k.n, k.lx, k.ly, k.r, offset,
                  largest_cluster_mass_fraction(fast));
    }
  }
}

TEST(ClusterLabels, HandBuiltChainsAcrossPeriodicAndLeesEdwardsBoundaries) {
  // σ = 0.1, δ = 0.1: contact distance 0.11.  A chain of three at spacing 0.105; a pair across
  // x = 0; a disk near the top whose partner near the bottom is 0.1 away only through the image
  // shifted by Δ = 0.3 (its image sits at x + Δ, y + L_y); a loner.
  const ParticleState s = particles_from_rows({{0.40, 0.50, 0, 0},    // 0 chain
                                               {0.505, 0.50, 0, 0},   // 1 chain
                                               {0.61, 0.50, 0, 0},    // 2 chain
                                               {0.98, 0.20, 0, 0},    // 3 pair across x
                                               {0.03, 0.21, 0, 0},    // 4 pair across x
                                               {0.70, 0.96, 0, 0},    // 5 top
                                               {0.40, 0.04, 0, 0},    // 6 bottom: image at (0.70, 1.04)
                                               {0.20, 0.80, 0, 0}});  // 7 alone
  const auto labels = cluster_labels(s, 1.0, 1.0, 0.3, 0.11);
  EXPECT_EQ(labels, (std::vector<std::int32_t>{0, 0, 0, 3, 3, 5, 5, 7}));
  EXPECT_DOUBLE_EQ(largest_cluster_mass_fraction(labels), 3.0 / 8.0);
  // Without the offset disks 5 and 6 are 0.3 apart across the boundary: not connected.
  const auto periodic = cluster_labels(s, 1.0, 1.0, 0.0, 0.11);
  EXPECT_NE(periodic[6], periodic[5]);
  // Spacing 0.105 is within (1 + δ)σ = 0.11 but not within 0.104.
  EXPECT_NE(cluster_labels(s, 1.0, 1.0, 0.3, 0.104)[1], 0);
}

TEST(DensestBand, PlantedBandAcrossTheTopIsFoundExactly) {
  // 500 disks in y ∈ [0.95, 1.05) mod 1 and 500 spread over [0.3, 0.7): a band 0.2 high holds at
  // most the 500 of the first group (any band over them ends below 1.15 and starts above 0.85).
  Random random(5);
  std::vector<double> y;
  for (int i = 0; i < 500; ++i) y.push_back(std::fmod(0.95 + 0.1 * random.uniform(), 1.0));
  for (int i = 0; i < 500; ++i) y.push_back(0.3 + 0.4 * random.uniform());
  EXPECT_DOUBLE_EQ(densest_band_mass_fraction(y, 1.0, 0.2), 0.5);
  EXPECT_DOUBLE_EQ(densest_band_mass_fraction(y, 1.0, 1.0), 1.0);
}

TEST(DensestBand, MatchesBruteForceOverEveryStart) {
  Random random(9);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<double> y(400);
    for (double& v : y) v = 2.0 * std::pow(random.uniform(), 1.0 + trial);  // increasingly clumped
    const double width = 0.1 + 0.2 * trial;
    std::size_t best = 0;
    for (double start : y) {
      std::size_t inside = 0;
      for (double v : y) inside += std::fmod(v - start + 2.0, 2.0) < width ? 1 : 0;
      best = std::max(best, inside);
    }
    EXPECT_DOUBLE_EQ(densest_band_mass_fraction(y, 2.0, width), static_cast<double>(best) / 400.0) << "trial " << trial;
  }
}

TEST(FlowClassification, HandBuiltProfiles) {
  // Four rows of a 1 × 1 box holding 1, 2, 3, 2 disks: ρ(y)/ρ̄ = 0.5, 1, 1.5, 1, contrast (3 − 1)/2
  // = 1, rms deviation √(0.5²·2/4).  V_x(y) = u(y) + (+½, −½, +½, −½) with U = 2: rms ½ = U/4.
  const double u = 2.0;
  const ShearFrame frame{1.0, 1.0, u};
  const auto vx = [&](double y, double d) { return frame.mean_flow(y) + d; };
  const ParticleState s = particles_from_rows({{0.1, 0.1, vx(0.125, 0.5), 0},
                                               {0.1, 0.3, vx(0.375, -0.5) - 1.0, 0}, {0.6, 0.3, vx(0.375, -0.5) + 1.0, 0},
                                               {0.1, 0.6, vx(0.625, 0.5), 0}, {0.4, 0.6, vx(0.625, 0.5), 0}, {0.7, 0.6, vx(0.625, 0.5), 0},
                                               {0.2, 0.8, vx(0.875, -0.5), 0}, {0.7, 0.8, vx(0.875, -0.5), 0}});
  FlowClassificationSettings settings;
  settings.rows = 4;
  const FlowClassification f = classify_flow(s, frame, 0.0, 0.01, settings);
  EXPECT_DOUBLE_EQ(f.density_contrast, 1.0);
  EXPECT_NEAR(f.density_rms_deviation, std::sqrt(0.125), 1e-15);
  EXPECT_NEAR(f.velocity_profile_deviation, 0.25, 1e-15);
  EXPECT_DOUBLE_EQ(f.largest_cluster_mass_fraction, 1.0 / 8.0);  // σ = 0.01: no contacts
  // Without shear the deviation is in absolute units (about V_x = 0).
  const ShearFrame still{1.0, 1.0, 0.0};
  ParticleState at_rest = s;
  for (std::size_t i = 0; i < s.size(); ++i) at_rest.vx[i] -= frame.mean_flow((std::floor(s.y[i] * 4) + 0.5) / 4);
  EXPECT_NEAR(classify_flow(at_rest, still, 0.0, 0.01, settings).velocity_profile_deviation, 0.5, 1e-15);
}

TEST(FlowClassification, UniformLatticeWithLinearProfileScoresZero) {
  // 20 × 20 square lattice, spacing 0.05 > (1 + δ)σ = 0.044: uniform rows, no clusters, V_x = u(y)
  // exactly at the row centres (one lattice row per profile row).
  ParticleState s;
  const ShearFrame frame{1.0, 1.0, 5.0};
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 20; ++j) {
      s.x.push_back(0.025 + 0.05 * i);
      s.y.push_back(0.025 + 0.05 * j);
      s.vx.push_back(frame.mean_flow(0.025 + 0.05 * j));
      s.vy.push_back(0.0);
    }
  }
  FlowClassificationSettings settings;
  settings.rows = 20;
  settings.band_fraction = 0.19;  // 4 lattice rows whatever the round-off at the band's edge
  const FlowClassification f = classify_flow(s, frame, 0.4, 0.04, settings);
  EXPECT_EQ(f.density_contrast, 0.0);
  EXPECT_EQ(f.density_rms_deviation, 0.0);
  EXPECT_NEAR(f.velocity_profile_deviation, 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(f.densest_band_mass_fraction, 0.2);  // 4 of the 20 lattice rows
  EXPECT_DOUBLE_EQ(f.largest_cluster_mass_fraction, 1.0 / 400.0);
}

}  // namespace
}  // namespace granule
