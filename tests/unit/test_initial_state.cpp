// Initial states of thesis §1.4.2 (src/init): no overlaps (brute-force pair check), scratch memory
// bounded by N at any area fraction, uniform positions (χ² over cells), Gaussian velocities with
// exactly zero total momentum and exactly the requested temperature.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "boundary/shear_frame.hpp"
#include "init/initial_state.hpp"
#include "init/placement.hpp"

namespace granule {
namespace {

SystemParams system_at(std::int64_t n, double nu, double length_x = 1.0, double length_y = 1.0) {
  SystemParams p;
  p.particles = n;
  p.length_x = length_x;
  p.length_y = length_y;
  p.diameter = std::sqrt(4.0 * nu * length_x * length_y / (M_PI * static_cast<double>(n)));
  return p;
}

ParticleState initial_state(const SystemParams& p, Placement placement, double temperature = 1.0, std::uint64_t seed = 1) {
  const InitialStateResult r = make_initial_state(p, temperature, seed, placement);
  EXPECT_TRUE(r.error.empty()) << r.error;
  return r.state;
}

// O(N²) reference: pairs closer than σ (nearest periodic image), and disks outside the box.
int overlapping_pairs(const SystemParams& p, const ParticleState& s) {
  int pairs = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_TRUE(s.x[i] >= 0.0 && s.x[i] < p.length_x && s.y[i] >= 0.0 && s.y[i] < p.length_y) << "disk " << i;
    for (std::size_t j = 0; j < i; ++j) {
      double dx = std::fabs(s.x[i] - s.x[j]), dy = std::fabs(s.y[i] - s.y[j]);
      dx = std::min(dx, p.length_x - dx);
      dy = std::min(dy, p.length_y - dy);
      if (dx * dx + dy * dy < p.diameter * p.diameter) ++pairs;
    }
  }
  return pairs;
}

TEST(InitialState, NoOverlapsFromDiluteToDense) {
  struct Case {
    double nu, length_x, length_y;
    Placement placement;
  };
  for (const Case& c : {Case{0.05, 1.0, 1.0, Placement::kAuto}, Case{0.3, 2.0, 1.0, Placement::kAuto},
                        Case{0.45, 1.0, 3.0, Placement::kAuto}, Case{0.5, 1.0, 1.0, Placement::kRandom},
                        Case{0.6, 1.0, 1.0, Placement::kAuto}, Case{0.8, 2.0, 1.0, Placement::kLattice}}) {
    const SystemParams p = system_at(1500, c.nu, c.length_x, c.length_y);
    EXPECT_EQ(overlapping_pairs(p, initial_state(p, c.placement)), 0) << "ν = " << c.nu;
  }
}

// The overlap-test grid has at most N cells (O(N) memory whatever ν), each at least σ wide so
// that the 3 × 3 neighbourhood holds every disk a new one could overlap.
TEST(InitialState, PlacementGridHasAtMostNCellsOfSideAtLeastSigma) {
  for (std::int64_t n : {2, 4000, 1'000'000}) {
    for (double nu : {1e-9, 1e-7, 1e-5, 0.05, 0.3, 0.45}) {
      for (auto [lx, ly] : {std::pair{1.0, 1.0}, std::pair{4.0, 1.0}, std::pair{1.0, 0.25}}) {
        const SystemParams p = system_at(n, nu, lx, ly);
        const PlacementGrid grid(p);
        EXPECT_LE(grid.head.size(), static_cast<std::size_t>(n)) << "N = " << n << ", ν = " << nu;
        EXPECT_EQ(grid.next.size(), static_cast<std::size_t>(n));
        EXPECT_TRUE(grid.width[0] >= p.diameter || grid.count[0] == 1) << "N = " << n << ", ν = " << nu;
        EXPECT_TRUE(grid.width[1] >= p.diameter || grid.count[1] == 1) << "N = " << n << ", ν = " << nu;
      }
    }
  }
}

// Before the grid was sized by N, ν = 10⁻⁵ needed L²/σ² ≈ 3·10⁸ cell lists for N = 4000.
TEST(InitialState, ExtremelyDiluteSystemsArePlacedQuickly) {
  for (double nu : {1e-5, 1e-7}) {
    const SystemParams p = system_at(4000, nu);
    const auto start = std::chrono::steady_clock::now();
    const ParticleState s = initial_state(p, Placement::kAuto);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("N = 4000, nu = %g: placed in %.3f s\n", nu, seconds);
    EXPECT_EQ(overlapping_pairs(p, s), 0);
  }
}

// Pearson's χ² of the counts in the cells of a cols × rows grid against equal expectations.
double chi_square_over_cells(const SystemParams& p, const ParticleState& s, int cols, int rows) {
  std::vector<double> counts(static_cast<std::size_t>(cols * rows));
  for (std::size_t i = 0; i < s.size(); ++i) {
    const int cx = std::min(cols - 1, static_cast<int>(s.x[i] / p.length_x * cols));
    const int cy = std::min(rows - 1, static_cast<int>(s.y[i] / p.length_y * rows));
    counts[static_cast<std::size_t>(cx + cy * cols)] += 1.0;
  }
  const double expected = static_cast<double>(s.size()) / static_cast<double>(counts.size());
  double chi2 = 0.0;
  for (double c : counts) chi2 += (c - expected) * (c - expected) / expected;
  return chi2;
}

// Uniform positions: χ² over a 2-d grid and over thin strips in x and in y (which would see a
// deficit at the box edges or at the placement grid's last row or column).  In a dilute system
// the counts are nearly multinomial, χ² ≈ df ± √(2 df) (checked at 4 standard deviations); the
// excluded volume of a dense system only lowers the variance of the counts, so there only the
// upper bound applies.
TEST(InitialState, PositionsAreUniform) {
  struct Case {
    double nu;
    bool nearly_ideal;
  };
  for (const Case& c : {Case{0.01, true}, Case{0.4, false}}) {
    const SystemParams p = system_at(20000, c.nu, 2.0, 1.0);
    const ParticleState s = initial_state(p, Placement::kAuto, 1.0, 5);
    for (auto [cols, rows] : {std::pair{20, 10}, std::pair{200, 1}, std::pair{1, 200}}) {
      const double df = cols * rows - 1.0;
      const double chi2 = chi_square_over_cells(p, s, cols, rows);
      std::printf("nu = %g, %d x %d cells: chi^2 = %.1f (df %.0f +- %.1f)\n", c.nu, cols, rows, chi2, df,
                  std::sqrt(2.0 * df));
      EXPECT_LT(chi2, df + 4.0 * std::sqrt(2.0 * df)) << "ν = " << c.nu << ", " << cols << " × " << rows;
      if (c.nearly_ideal) {
        EXPECT_GT(chi2, df - 4.0 * std::sqrt(2.0 * df)) << cols << " × " << rows;
      }
    }
  }
}

// Thesis §1.4.2: Gaussian velocities at temperature T_i, the total momentum P subtracted (P/N from
// each disk).  The code rescales the peculiar velocities w (mean removed) to ½⟨w²⟩ = T_i exactly,
// so in a periodic box ½⟨v²⟩ = T_i; under Lees–Edwards v_x = w_x + u(y) − ū with ū = ⟨u(y_i)⟩,
// hence ½⟨(v − u(y))²⟩ = T_i + ½ ū² exactly.
TEST(InitialState, ZeroMomentumAndRequestedTemperature) {
  const double temperature = 2.5;
  for (double shear_velocity : {0.0, 10.0}) {
    SystemParams p = system_at(5000, 0.1);
    p.shear_velocity = shear_velocity;
    const ParticleState s = initial_state(p, Placement::kAuto, temperature);
    const ShearFrame frame{p.length_x, p.length_y, p.shear_velocity};
    const double n = static_cast<double>(s.size());
    double px = 0.0, py = 0.0, mean_flow = 0.0, fluctuation = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      px += s.vx[i];
      py += s.vy[i];
      mean_flow += frame.mean_flow(s.y[i]) / n;
      const double wx = s.vx[i] - frame.mean_flow(s.y[i]);
      fluctuation += 0.5 * (wx * wx + s.vy[i] * s.vy[i]) / n;
    }
    const double speed = std::sqrt(2.0 * temperature) + std::fabs(shear_velocity);
    EXPECT_NEAR(px, 0.0, 1e-13 * n * speed) << "U = " << shear_velocity;
    EXPECT_NEAR(py, 0.0, 1e-13 * n * speed) << "U = " << shear_velocity;
    EXPECT_NEAR(fluctuation, temperature + 0.5 * mean_flow * mean_flow, 1e-12 * temperature) << "U = " << shear_velocity;
  }
}

// The velocity components are normal with variance T_i: KS at the 1% level (√n D < 1.63).
TEST(InitialState, VelocitiesAreGaussian) {
  const double temperature = 0.7;
  const ParticleState s = initial_state(system_at(20000, 0.05), Placement::kAuto, temperature);
  for (const std::vector<double>* component : {&s.vx, &s.vy}) {
    std::vector<double> z = *component;
    std::sort(z.begin(), z.end());
    const double n = static_cast<double>(z.size());
    double d = 0.0;
    for (std::size_t i = 0; i < z.size(); ++i) {
      const double f = 0.5 * std::erfc(-z[i] / std::sqrt(2.0 * temperature));
      d = std::max({d, f - static_cast<double>(i) / n, static_cast<double>(i + 1) / n - f});
    }
    std::printf("initial velocities: KS sqrt(n) D = %.3f\n", d * std::sqrt(n));
    EXPECT_LT(d * std::sqrt(n), 1.63);
  }
}

TEST(InitialState, SameSeedSameStateOtherSeedAnother) {
  const SystemParams p = system_at(1000, 0.2);
  const ParticleState a = initial_state(p, Placement::kAuto, 1.0, 9), b = initial_state(p, Placement::kAuto, 1.0, 9);
  const ParticleState c = initial_state(p, Placement::kAuto, 1.0, 10);
  EXPECT_TRUE(a.x == b.x && a.y == b.y && a.vx == b.vx && a.vy == b.vy);
  EXPECT_NE(a.x, c.x);
  EXPECT_NE(a.vx, c.vx);
}

// Random sequential addition jams near ν ≈ 0.547: asked for more, it gives up with advice.
TEST(InitialState, RandomPlacementBeyondJammingIsRefused) {
  const InitialStateResult r = make_initial_state(system_at(300, 0.6), 1.0, 1, Placement::kRandom);
  EXPECT_NE(r.error.find("lattice"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace granule
