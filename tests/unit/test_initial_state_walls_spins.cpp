// Initial states with walls and rough grains, built from configuration keys: every
// centre at least its own radius from each wall and no overlap (brute force over all particles and
// pairs, no periodic image across a wall), the linear profile between moving y walls (least-squares
// slope against the wall velocities), and Gaussian spins of variance T_rot/I_i, I_i = q m_i σ_i²/4
// (exact T_rot, mean and per-component temperatures within their statistical errors, χ² of the
// normalised spins), drawn after everything else so that positions and velocities are those of the
// smooth run of the same seed, bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "chi_square.hpp"
#include "init/initial_state.hpp"
#include "io/config.hpp"

namespace granule {
namespace {

RunConfig config(const std::vector<std::string>& overrides) {
  const ConfigResult r = parse_config("", overrides);
  EXPECT_TRUE(r.config) << r.error;
  return r.config.value_or(RunConfig{});
}

// As `granule run` builds a new gas from its configuration.
ParticleState initial_state(const RunConfig& c) {
  const InitialStateResult r = make_initial_state(c.system, c.initial_temperature, c.seed, c.placement, std::nullopt,
                                                  particle_sizes(c), {c.initial_shear_profile, c.initial_rotational_temperature});
  EXPECT_TRUE(r.error.empty()) << r.error;
  return r.state;
}

double side(const SystemParams& p, std::size_t axis) { return axis == 0 ? p.length_x : axis == 1 ? p.length_y : p.length_z; }

// Particles closer than their radius to a wall or outside the box, and overlapping pairs
// (σ_ij = (σ_i + σ_j)/2, nearest image along periodic axes only): O(N²).
int violations(const SystemParams& p, const ParticleState& s) {
  int count = 0;
  const auto d = static_cast<std::size_t>(p.dimension);
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double radius = 0.5 * s.diameter_of(i, p.diameter);
    for (std::size_t a = 0; a < d; ++a) {
      const double r = s.position(static_cast<int>(a))[i];
      const bool inside = p.walls[a] ? r >= radius && side(p, a) - r >= radius : r >= 0.0 && r < side(p, a);
      if (!inside) ++count;
    }
    for (std::size_t j = 0; j < i; ++j) {
      const double contact = 0.5 * (s.diameter_of(i, p.diameter) + s.diameter_of(j, p.diameter));
      double distance_sq = 0.0;
      for (std::size_t a = 0; a < d; ++a) {
        double delta = std::fabs(s.position(static_cast<int>(a))[i] - s.position(static_cast<int>(a))[j]);
        if (!p.walls[a]) delta = std::min(delta, side(p, a) - delta);
        distance_sq += delta * delta;
      }
      if (distance_sq < contact * contact) ++count;
    }
  }
  return count;
}

TEST(InitialStateWalls, EveryCentreARadiusFromEachWallAndNoOverlaps) {
  const std::string walls = "boundary.kind=\"walls\"";
  const std::vector<std::vector<std::string>> cases = {
      {walls, "system.particles=2000", "system.area_fraction=0.3"},
      {walls, "system.particles=1500", "system.area_fraction=0.45", "system.box=[2.0, 0.5]", "initial.placement=\"random\""},
      {walls, "boundary.wall_axes=[\"x\", \"y\"]", "system.particles=1500", "system.area_fraction=0.6"},  // lattice
      {walls, "system.particles=1500", "system.area_fraction=0.2", "system.diameters={ distribution = \"uniform\", width = 0.6 }"},
      {walls, "system.particles=1000", "system.area_fraction=0.35",
       "system.diameters={ distribution = \"bidisperse\", ratio = 2.0, fraction = 0.3 }", "initial.placement=\"lattice\""},
      {"system.dimension=3", walls, "boundary.wall_axes=[\"y\", \"z\"]", "system.particles=1500", "system.packing_fraction=0.25"},
      {"system.dimension=3", walls, "system.particles=1200", "system.packing_fraction=0.45"},  // FCC lattice
      {"system.dimension=3", walls, "boundary.wall_axes=[\"x\", \"y\", \"z\"]", "system.particles=1000",
       "system.packing_fraction=0.15", "system.diameters={ distribution = \"lognormal\", width = 0.3 }"},
  };
  for (const auto& overrides : cases) {
    const RunConfig c = config(overrides);
    const ParticleState s = initial_state(c);
    ASSERT_EQ(s.size(), static_cast<std::size_t>(c.system.particles));
    EXPECT_EQ(violations(c.system, s), 0) << overrides.back();
    // The lowest centre of the first wall axis: a radius or a little more from the wall.
    std::size_t axis = 0;
    while (!c.system.walls[axis]) ++axis;
    const auto& r = s.position(static_cast<int>(axis));
    std::printf("walls, %s: lowest centre %.4g σ_max from the wall\n", overrides.back().c_str(),
                *std::min_element(r.begin(), r.end()) / c.system.diameter);
  }
}

// Least-squares slope and mean of v_x against y.
struct Fit {
  double slope, mean, slope_error;
};
Fit fit_vx_against_y(const ParticleState& s) {
  const auto n = static_cast<double>(s.size());
  double my = 0.0, mv = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    my += s.y[i] / n;
    mv += s.vx[i] / n;
  }
  double syy = 0.0, syv = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    syy += (s.y[i] - my) * (s.y[i] - my);
    syv += (s.y[i] - my) * (s.vx[i] - mv);
  }
  const double slope = syv / syy;
  double residual = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) residual += std::pow(s.vx[i] - mv - slope * (s.y[i] - my), 2);
  return {slope, mv, std::sqrt(residual / (n - 2.0) / syy)};
}

TEST(InitialStateWalls, ProfileRunsLinearlyBetweenTheWallVelocities) {
  // Thermal speed 0.01 beside a profile from −2 to +2 along L_y = 2: slope γ = U/L_y = 2.
  const RunConfig c = config({"boundary.kind=\"walls\"", "boundary.shear_velocity=4", "system.particles=4000",
                              "system.box=[1.0, 2.0]", "initial.temperature=1e-4"});
  const Fit sheared = fit_vx_against_y(initial_state(c));
  std::printf("wall-driven profile: slope %.6f ± %.1e (γ = 2), mean v_x %.2e\n", sheared.slope, sheared.slope_error, sheared.mean);
  EXPECT_NEAR(sheared.slope, 2.0, 5.0 * sheared.slope_error);
  EXPECT_LT(sheared.slope_error, 1e-3);
  EXPECT_NEAR(sheared.mean, 0.0, 1e-12);  // the mean of the walls' velocities

  // Walls at 1 and 3: the profile keeps their mean velocity 2 (not the zero total momentum of a periodic box).
  SystemParams moving = c.system;
  moving.wall[2].velocity[0] = 1.0;
  moving.wall[3].velocity[0] = 3.0;
  const InitialStateResult plug = make_initial_state(moving, c.initial_temperature, c.seed, c.placement);
  const Fit offset = fit_vx_against_y(plug.state);
  EXPECT_NEAR(offset.slope, 1.0, 5.0 * offset.slope_error);
  EXPECT_NEAR(offset.mean, 2.0, 1e-12);

  // initial.shear_profile = false: a static gas between the moving walls.
  const Fit still = fit_vx_against_y(initial_state(config({"boundary.kind=\"walls\"", "boundary.shear_velocity=4",
                                                           "system.particles=4000", "system.box=[1.0, 2.0]",
                                                           "initial.temperature=1e-4", "initial.shear_profile=false"})));
  EXPECT_NEAR(still.slope, 0.0, 5.0 * still.slope_error);
  EXPECT_NEAR(still.mean, 0.0, 1e-12);
}

// Spins normalised by their standard deviation √(T_rot/I_i) against the standard normal: χ² over
// 14 bins of width ½ on [−3, 3] and two tails.
double normal_chi_square(const std::vector<double>& z) {
  std::vector<double> edges{-INFINITY};
  for (double e = -3.0; e <= 3.0 + 1e-12; e += 0.5) edges.push_back(e);
  edges.push_back(INFINITY);
  const auto cdf = [](double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); };
  double chi2 = 0.0;
  for (std::size_t b = 0; b + 1 < edges.size(); ++b) {
    const double expected = static_cast<double>(z.size()) * (cdf(edges[b + 1]) - cdf(edges[b]));
    const auto observed = static_cast<double>(std::count_if(z.begin(), z.end(), [&](double v) { return v >= edges[b] && v < edges[b + 1]; }));
    chi2 += (observed - expected) * (observed - expected) / expected;
  }
  return chi2;
}

struct SpinFigures {
  std::vector<double> temperature_per_component;  // Σ I ω_k² / N
  double total_temperature = 0.0;                 // Σ I |ω|² / (d_rot N)
  double largest_mean_in_errors = 0.0;            // |mean ω_k| / its standard error
  double chi_square = 0.0;
};

SpinFigures spin_figures(const RunConfig& c, const ParticleState& s, double t_rot) {
  SpinFigures f;
  const auto n = static_cast<double>(s.size());
  std::vector<double> z;
  for (int k = 0; k < s.spin_components(); ++k) {
    double twice = 0.0, mean = 0.0, mean_variance = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const double sigma = s.diameter_of(i, c.system.diameter);
      const double inertia = c.system.roughness.inertia_factor * s.mass_of(i) * sigma * sigma / 4.0;
      const double w = s.spin(k)[i];
      twice += inertia * w * w;
      mean += w / n;
      mean_variance += t_rot / inertia / (n * n);
      z.push_back(w * std::sqrt(inertia / t_rot));
    }
    f.temperature_per_component.push_back(twice / n);
    f.total_temperature += twice / (n * s.spin_components());
    f.largest_mean_in_errors = std::max(f.largest_mean_in_errors, std::fabs(mean) / std::sqrt(mean_variance));
  }
  f.chi_square = normal_chi_square(z);
  return f;
}

TEST(InitialStateSpins, RoughDisksGetGaussianSpinsOfExactlyTRot) {
  const RunConfig c = config({"system.particles=20000", "system.tangential_restitution=-0.8", "initial.temperature=1.5",
                              "initial.rotational_temperature=2"});
  const ParticleState s = initial_state(c);
  ASSERT_TRUE(s.rough());
  ASSERT_EQ(s.wz.size(), s.size());
  EXPECT_TRUE(s.wx.empty() && s.wy.empty());  // a disk spins about z only
  const SpinFigures f = spin_figures(c, s, 2.0);
  std::printf("rough disks, N = 20000: T_rot %.15g (2), |mean ω| %.2f standard errors, χ² %.1f (16 bins)\n",
              f.total_temperature, f.largest_mean_in_errors, f.chi_square);
  EXPECT_NEAR(f.total_temperature, 2.0, 2e-12);
  EXPECT_LT(f.largest_mean_in_errors, test_statistics::kNormal9995);
  EXPECT_LT(f.chi_square, test_statistics::chi_square_quantile(15.0, test_statistics::kNormal9995));
}

TEST(InitialStateSpins, RoughPolydisperseSpheresShareTRotOverAxesAndSizes) {
  const RunConfig c = config({"system.dimension=3", "system.particles=12000", "system.packing_fraction=0.1",
                              "system.diameters={ distribution = \"uniform\", width = 0.5 }", "system.tangential_restitution=0.5",
                              "initial.temperature=1.5"});
  const ParticleState s = initial_state(c);
  ASSERT_EQ(s.wx.size(), s.size());
  ASSERT_EQ(s.wy.size(), s.size());
  ASSERT_EQ(s.wz.size(), s.size());
  const SpinFigures f = spin_figures(c, s, 1.5);  // T_rot defaults to T_i
  std::printf("rough polydisperse spheres, N = 12000: T_rot %.15g (1.5), per axis %.4f %.4f %.4f (± %.4f), |mean ω| %.2f "
              "standard errors, χ² %.1f\n", f.total_temperature, f.temperature_per_component[0],
              f.temperature_per_component[1], f.temperature_per_component[2], 1.5 * std::sqrt(2.0 / 12000.0),
              f.largest_mean_in_errors, f.chi_square);
  EXPECT_NEAR(f.total_temperature, 1.5, 2e-12);
  for (const double t : f.temperature_per_component) EXPECT_NEAR(t, 1.5, 4.0 * 1.5 * std::sqrt(2.0 / 12000.0));
  EXPECT_LT(f.largest_mean_in_errors, test_statistics::kNormal9995);
  EXPECT_LT(f.chi_square, test_statistics::chi_square_quantile(15.0, test_statistics::kNormal9995));
}

TEST(InitialStateSpins, SpinsComeLastSoTheRestIsTheSmoothRunsBitForBit) {
  for (const std::string placement : {"\"random\"", "\"lattice\""}) {
    const std::vector<std::string> smooth = {"system.dimension=3", "system.particles=3000", "system.packing_fraction=0.2",
                                             "initial.placement=" + placement};
    std::vector<std::string> rough = smooth;
    rough.push_back("system.tangential_restitution=-0.5");
    const ParticleState a = initial_state(config(smooth));
    const ParticleState b = initial_state(config(rough));
    EXPECT_FALSE(a.rough());
    EXPECT_TRUE(b.rough());
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_EQ(a.position(axis), b.position(axis)) << placement << " axis " << axis;
      EXPECT_EQ(a.velocity(axis), b.velocity(axis)) << placement << " axis " << axis;
    }
  }
}

TEST(InitialStateSpins, SameSeedSameSpinsOtherSeedOthersAndZeroTRotNoSpin) {
  const std::vector<std::string> rough = {"system.particles=2000", "system.tangential_restitution=0"};
  std::vector<std::string> other = rough;
  other.push_back("seed=2");
  std::vector<std::string> still = rough;
  still.push_back("initial.rotational_temperature=0");
  const ParticleState a = initial_state(config(rough));
  EXPECT_EQ(a.wz, initial_state(config(rough)).wz);
  EXPECT_NE(a.wz, initial_state(config(other)).wz);
  const ParticleState s = initial_state(config(still));
  ASSERT_EQ(s.wz.size(), s.size());
  EXPECT_TRUE(std::all_of(s.wz.begin(), s.wz.end(), [](double w) { return w == 0.0; }));
}

}  // namespace
}  // namespace granule
