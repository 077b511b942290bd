// Initial states of 3D and polydisperse runs, built end to end from configuration keys:
// no overlaps (brute force over all pairs, σ_ij = (σ_i + σ_j)/2), the requested packing fraction
// realised, exact bidisperse counts, the analytic moments of the diameter distributions, masses
// ∝ σ^d, zero total momentum Σ m_i v_i, the temperature T = Σ m_i |v_i − u|² / (d N) and its
// equipartition over species and axes, the FCC lattice, and the lean placement grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "boundary/shear_frame.hpp"
#include "init/initial_state.hpp"
#include "init/placement.hpp"
#include "io/config.hpp"

namespace granule {
namespace {

RunConfig config(const std::vector<std::string>& overrides) {
  const ConfigResult r = parse_config("", overrides);
  EXPECT_TRUE(r.config) << r.error;
  return r.config.value_or(RunConfig{});
}

ParticleState initial_state(const RunConfig& c, double temperature = 1.0) {
  const InitialStateResult r =
      make_initial_state(c.system, temperature, c.seed, c.placement, std::nullopt, particle_sizes(c));
  EXPECT_TRUE(r.error.empty()) << r.error;
  return r.state;
}

double side(const SystemParams& p, int axis) { return axis == 0 ? p.length_x : axis == 1 ? p.length_y : p.length_z; }

// O(N²) reference: pairs closer than (σ_i + σ_j)/2 at the nearest periodic image, and particles
// outside the box.
int overlapping_pairs(const SystemParams& p, const ParticleState& s) {
  int pairs = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    for (int a = 0; a < p.dimension; ++a) {
      EXPECT_TRUE(s.position(a)[i] >= 0.0 && s.position(a)[i] < side(p, a)) << "particle " << i << " axis " << a;
    }
    for (std::size_t j = 0; j < i; ++j) {
      double distance_sq = 0.0;
      for (int a = 0; a < p.dimension; ++a) {
        double delta = std::fabs(s.position(a)[i] - s.position(a)[j]);
        delta = std::min(delta, side(p, a) - delta);
        distance_sq += delta * delta;
      }
      const double contact = 0.5 * (s.diameter_of(i, p.diameter) + s.diameter_of(j, p.diameter));
      if (distance_sq < contact * contact) ++pairs;
    }
  }
  return pairs;
}

// π Σ σ_i^d / (4 A) or / (6 V), summed here with std::pow.
double measured_packing_fraction(const SystemParams& p, const ParticleState& s) {
  double covered = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) covered += std::pow(s.diameter_of(i, p.diameter), p.dimension);
  const double volume = p.dimension == 3 ? p.length_x * p.length_y * p.length_z : p.length_x * p.length_y;
  return M_PI * covered / ((p.dimension == 3 ? 6.0 : 4.0) * volume);
}

struct PlacementCase {
  std::vector<std::string> keys;
  double nu;
};

const std::vector<PlacementCase> kPlacementCases = {
    {{"system.dimension=3", "system.box=[1.0, 1.0, 1.0]"}, 0.05},
    {{"system.dimension=3", "system.box=[2.0, 1.0, 1.0]"}, 0.28},
    {{"system.dimension=3", "system.box=[1.0, 1.0, 1.0]"}, 0.70},  // FCC 8 × 8 × 8 with 48 vacancies
    {{"system.dimension=3", "system.box=[1.0, 1.0, 1.0]", "system.diameters={distribution=\"bidisperse\", ratio=2.0, fraction=0.3}"}, 0.25},
    {{"system.dimension=3", "system.box=[1.0, 1.0, 1.0]", "system.diameters={distribution=\"bidisperse\", ratio=1.25, fraction=0.3}"}, 0.42},
    {{"system.dimension=3", "system.box=[1.0, 2.0, 1.0]", "system.diameters={distribution=\"uniform\", width=0.3}"}, 0.25},
    {{"system.dimension=3", "system.box=[1.0, 1.0, 1.0]", "system.diameters={distribution=\"lognormal\", width=0.3}"}, 0.2},
    {{"system.box=[1.0, 1.0]", "system.diameters={distribution=\"bidisperse\", ratio=1.4, fraction=0.5}"}, 0.4},
    {{"system.box=[2.0, 1.0]", "system.diameters={distribution=\"uniform\", width=0.5}"}, 0.45},
    {{"system.box=[1.0, 1.0]", "system.diameters={distribution=\"lognormal\", width=0.5}"}, 0.3},
    {{"system.box=[1.0, 1.0]", "system.diameters={distribution=\"uniform\", width=0.1}"}, 0.6},  // lattice
};

TEST(InitialState3dPoly, NoOverlapsAndTheRequestedPackingFraction) {
  for (const PlacementCase& k : kPlacementCases) {
    std::vector<std::string> keys = k.keys;
    keys.push_back("system.particles=2000");
    keys.push_back("system.packing_fraction=" + std::to_string(k.nu));
    const RunConfig c = config(keys);
    const ParticleState s = initial_state(c);
    ASSERT_EQ(s.size(), 2000u);
    const double nu = measured_packing_fraction(c.system, s);
    std::printf("%s: d = %d, requested nu = %.2f, realised %.15f, overlaps %d\n", keys[keys.size() - 3].c_str(),
                c.system.dimension, k.nu, nu, overlapping_pairs(c.system, s));
    EXPECT_EQ(overlapping_pairs(c.system, s), 0) << keys[keys.size() - 3];
    EXPECT_NEAR(nu, k.nu, 1e-12 * k.nu) << keys[keys.size() - 3];
    EXPECT_EQ(s.dimension, c.system.dimension);
    if (s.polydisperse()) {  // sorted largest first, the largest in SystemParams
      EXPECT_TRUE(std::is_sorted(s.diameter.rbegin(), s.diameter.rend()));
      EXPECT_EQ(s.diameter.front(), c.system.diameter);
    }
  }
}

// round(x_B N), not sampled: 0.3 · 2001 = 600.3 → 600, 0.25 · 2002 = 500.5 → 501.
TEST(InitialState3dPoly, BidisperseCountsAreExact) {
  for (auto [n, fraction, expected] : {std::tuple{2001, 0.3, 600}, std::tuple{2002, 0.25, 501}}) {
    const RunConfig c = config({"system.particles=" + std::to_string(n), "system.diameter=0.001",
                                "system.diameters={distribution=\"bidisperse\", ratio=0.5, fraction=" +
                                    std::to_string(fraction) + "}"});
    const ParticleSizes sizes = particle_sizes(c);
    const auto small = std::count(sizes.diameter.begin(), sizes.diameter.end(), 0.0005);
    const auto large = std::count(sizes.diameter.begin(), sizes.diameter.end(), 0.001);
    EXPECT_EQ(small, expected) << "N = " << n;
    EXPECT_EQ(large, n - expected) << "N = " << n;
  }
}

// Sample mean and variance of σ against the distribution's: uniform on [σ̄(1 − w), σ̄(1 + w)]:
// variance σ̄² w²/3, central fourth moment σ̄⁴ w⁴/5; log-normal with mean σ̄ and ω = e^{s²}:
// variance σ̄²(ω − 1), fourth moment variance² (ω⁴ + 2ω³ + 3ω² − 3).  Within 4 standard errors.
TEST(InitialState3dPoly, DiameterDistributionsHaveTheirAnalyticMoments) {
  const int n = 40000;
  const double mean = 0.002;
  struct Case {
    std::string table;
    double variance, fourth_moment;
  };
  const double w = 0.4, s = 0.35, omega = std::exp(s * s);
  const double lognormal_variance = mean * mean * (omega - 1.0);
  for (const Case& k : {Case{"{distribution=\"uniform\", width=0.4}", mean * mean * w * w / 3.0, std::pow(mean * w, 4) / 5.0},
                        Case{"{distribution=\"lognormal\", width=0.35}", lognormal_variance,
                             lognormal_variance * lognormal_variance *
                                 (std::pow(omega, 4) + 2.0 * std::pow(omega, 3) + 3.0 * omega * omega - 3.0)}}) {
    for (int dimension : {2, 3}) {
      const RunConfig c = config({"system.dimension=" + std::to_string(dimension),
                                  dimension == 3 ? "system.box=[1.0, 1.0, 1.0]" : "system.box=[1.0, 1.0]",
                                  "system.particles=" + std::to_string(n), "system.diameter=0.002",
                                  "system.diameters=" + k.table, "seed=77"});
      const std::vector<double> sigma = particle_sizes(c).diameter;
      double sample_mean = 0.0;
      for (double x : sigma) sample_mean += x / n;
      double sample_variance = 0.0;
      for (double x : sigma) sample_variance += (x - sample_mean) * (x - sample_mean) / (n - 1);
      const double mean_error = std::sqrt(k.variance / n);
      const double variance_error = std::sqrt((k.fourth_moment - k.variance * k.variance) / n);
      std::printf("%s, d = %d: mean %.4f SE from sigma_bar, variance %.4f SE from analytic\n", k.table.c_str(), dimension,
                  (sample_mean - mean) / mean_error, (sample_variance - k.variance) / variance_error);
      EXPECT_NEAR(sample_mean, mean, 4.0 * mean_error) << k.table;
      EXPECT_NEAR(sample_variance, k.variance, 4.0 * variance_error) << k.table;
    }
  }
}

// m_i ∝ σ_i^d with mean 1 by default; explicit species masses for bidisperse runs.
TEST(InitialState3dPoly, MassesFollowTheVolumeOrTheSpecies) {
  for (int dimension : {2, 3}) {
    const RunConfig c = config({"system.dimension=" + std::to_string(dimension),
                                dimension == 3 ? "system.box=[1.0, 1.0, 1.0]" : "system.box=[1.0, 1.0]",
                                "system.particles=3000", "system.diameters={distribution=\"lognormal\", width=0.4}"});
    const ParticleSizes sizes = particle_sizes(c);
    double total = 0.0;
    for (double m : sizes.mass) total += m;
    EXPECT_NEAR(total / 3000.0, 1.0, 1e-13) << "d = " << dimension;
    for (std::size_t i = 1; i < sizes.mass.size(); i += 97) {
      EXPECT_NEAR(sizes.mass[i] / sizes.mass[0], std::pow(sizes.diameter[i] / sizes.diameter[0], dimension), 1e-13);
    }
  }
  const RunConfig c = config({"system.particles=1000", "system.masses=[1.0, 8.0]",
                              "system.diameters={distribution=\"bidisperse\", ratio=0.5, fraction=0.2}"});
  const ParticleSizes sizes = particle_sizes(c);
  for (std::size_t i = 0; i < sizes.mass.size(); ++i) {
    EXPECT_EQ(sizes.mass[i], sizes.diameter[i] == sizes.diameter.front() ? 1.0 : 8.0) << i;
  }
  EXPECT_EQ(std::count(sizes.mass.begin(), sizes.mass.end(), 8.0), 200);
  EXPECT_TRUE(particle_sizes(config({"system.particles=100"})).monodisperse());
}

// Σ m_i v_i = 0 to round-off; Σ m_i |v_i − u(y_i)|² / (d N) = T_i + M ū² / (d N) exactly (the
// velocities are rescaled to T_i before the profile u is added and its mass-weighted mean ū
// removed); and each species' temperature on each axis, Σ m v_a² / n_s (mean T, variance 2T²
// for Gaussian velocities of variance T/m), within 4 standard errors of T_i — a mass ignored
// in the draw would put the heavy species 8 times hotter.
TEST(InitialState3dPoly, ZeroMomentumTemperatureAndEquipartition) {
  const double temperature = 1.7;
  for (int dimension : {2, 3}) {
    for (double shear_velocity : {0.0, 5.0}) {
      std::vector<std::string> keys = {"system.dimension=" + std::to_string(dimension), "system.particles=6000",
                                       dimension == 3 ? "system.box=[1.0, 1.0, 1.0]" : "system.box=[1.0, 1.0]",
                                       "system.packing_fraction=0.1", "system.masses=[1.0, 8.0]",
                                       "system.diameters={distribution=\"bidisperse\", ratio=2.0, fraction=0.5}"};
      if (shear_velocity != 0.0) {
        keys.push_back("boundary.kind=\"lees-edwards\"");
        keys.push_back("boundary.shear_velocity=" + std::to_string(shear_velocity));
      }
      const RunConfig c = config(keys);
      const ParticleState s = initial_state(c, temperature);
      const ShearFrame frame{c.system.length_x, c.system.length_y, c.system.shear_velocity};
      const double n = static_cast<double>(s.size());
      double momentum[3] = {0, 0, 0}, mass = 0.0, mean_flow = 0.0, peculiar = 0.0, scale = 0.0;
      double species_temperature[2][3] = {}, species_count[2] = {};
      for (std::size_t i = 0; i < s.size(); ++i) {
        const double m = s.mass[i];
        mass += m;
        mean_flow += m * frame.mean_flow(s.y[i]);
        const int species = m == 8.0 ? 1 : 0;
        species_count[species] += 1.0;
        for (int a = 0; a < dimension; ++a) {
          const double v = s.velocity(a)[i];
          const double w = a == 0 ? v - frame.mean_flow(s.y[i]) : v;
          momentum[a] += m * v;
          peculiar += m * w * w;
          scale += m * v * v;
          species_temperature[species][a] += m * w * w;
        }
      }
      mean_flow /= mass;
      for (int a = 0; a < dimension; ++a) EXPECT_NEAR(momentum[a], 0.0, 1e-13 * std::sqrt(scale * mass)) << a;
      const double measured = peculiar / (dimension * n);
      EXPECT_NEAR(measured, temperature + mass * mean_flow * mean_flow / (dimension * n), 1e-12 * temperature);
      for (int species : {0, 1}) {
        for (int a = 0; a < dimension; ++a) {
          const double t = species_temperature[species][a] / species_count[species];
          const double error = temperature * std::sqrt(2.0 / species_count[species]);
          // The profile's mean ū adds M ū²-order terms along x only when sheared: far below the error.
          std::printf("d = %d, U = %g, species %d, axis %d: T = %.4f (%.2f SE from T_i)\n", dimension, shear_velocity,
                      species, a, t, (t - temperature) / error);
          EXPECT_NEAR(t, temperature, 4.0 * error) << "species " << species << ", axis " << a;
        }
      }
    }
  }
}

TEST(InitialState3dPoly, SameSeedSameStateOtherSeedAnother) {
  const std::vector<std::string> keys = {"system.dimension=3", "system.box=[1.0, 1.0, 1.0]", "system.particles=500",
                                         "system.diameters={distribution=\"uniform\", width=0.2}"};
  std::vector<std::string> other = keys;
  other.push_back("seed=2");
  const ParticleState a = initial_state(config(keys)), b = initial_state(config(keys)), c = initial_state(config(other));
  EXPECT_TRUE(a.x == b.x && a.z == b.z && a.vz == b.vz && a.diameter == b.diameter && a.mass == b.mass);
  EXPECT_NE(a.diameter, c.diameter);
  EXPECT_NE(a.z, c.z);
}

// FCC cells of edge a carry 4 sites, nearest neighbours at a/√2: 500 sites fill 5 × 5 × 5 cells of
// a unit cube (spacing 0.2/√2); in a 1 × 1 × 2 box 4 × 4 × 8 cubic cells (512 sites, a = 0.25)
// beat the 5 × 5 × 5 cells stretched along z (spacing ½√(0.2² + 0.2²) = 0.141).
TEST(InitialState3dPoly, DensestFccLattice) {
  SystemParams p;
  p.dimension = 3;
  p.particles = 500;
  Lattice cube = densest_lattice(p);
  EXPECT_EQ(cube.cells, (std::array<std::int64_t, 3>{5, 5, 5}));
  EXPECT_NEAR(cube.spacing, 0.2 / std::sqrt(2.0), 1e-15);
  p.length_z = 2.0;
  Lattice tall = densest_lattice(p);
  EXPECT_EQ(tall.cells, (std::array<std::int64_t, 3>{4, 4, 8}));
  EXPECT_NEAR(tall.spacing, 0.25 / std::sqrt(2.0), 1e-15);
  // A full lattice of touching spheres is the FCC packing fraction: placed without overlaps just
  // below it, refused (naming the lattice) just above.
  p.length_z = 1.0;
  for (double factor : {1.0 - 1e-8, 1.0 + 1e-8}) {
    p.diameter = factor * 0.2 / std::sqrt(2.0);
    const InitialStateResult r = make_initial_state(p, 1.0, 3, Placement::kAuto);
    if (factor < 1.0) {
      EXPECT_TRUE(r.error.empty()) << r.error;
      EXPECT_EQ(overlapping_pairs(p, r.state), 0);
    } else {
      EXPECT_NE(r.error.find("FCC lattice"), std::string::npos) << r.error;
    }
  }
}

// One int32 per cell (at most N cells) and one per particle, cells at least the largest diameter
// wide, in 3D too.
TEST(InitialState3dPoly, PlacementGridIsLeanIn3d) {
  for (std::int64_t n : {2, 4000, 1'000'000}) {
    for (double phi : {1e-9, 1e-5, 0.05, 0.3}) {
      SystemParams p;
      p.dimension = 3;
      p.particles = n;
      p.length_x = 4.0;
      p.length_z = 0.5;
      p.diameter = std::cbrt(6.0 * phi * 2.0 / (M_PI * static_cast<double>(n)));
      const PlacementGrid grid(p);
      EXPECT_LE(grid.head.size(), static_cast<std::size_t>(n)) << "N = " << n << ", φ = " << phi;
      EXPECT_EQ(grid.next.size(), static_cast<std::size_t>(n));
      for (int a = 0; a < 3; ++a) EXPECT_TRUE(grid.width[a] >= p.diameter || grid.count[a] == 1) << a;
    }
  }
}

}  // namespace
}  // namespace granule
