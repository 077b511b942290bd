// Validation tier for spheres and mixtures: the 3D engine and the polydisperse engine against
// independent kinetic theory (src/theory, derivations in docs/theory.md).  Temperature per degree
// of freedom, T = m⟨|v − V|²⟩/d; c = collisions / N (each collision counted once).
//
// The measurements here are the test's own (an observer summing impulses and counting collisions
// by species pair), not Granule's diagnostics, so that a slip in either shows.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "cells/cell_grid.hpp"
#include "engine/simulation.hpp"
#include "init/initial_state.hpp"
#include "theory/enskog_mixture.hpp"
#include "theory/hard_spheres.hpp"
#include "theory/homogeneous_cooling.hpp"

namespace granule {
namespace {

constexpr double kForever = std::numeric_limits<double>::infinity();

// A unit box (square or cube) holding `particles` at packing fraction `nu`: half of them of
// diameter σ_A and half of σ_B = ratio σ_A (ratio 1: monodisperse), masses ∝ σ^d.
struct Mixture {
  SystemParams params;
  ParticleSizes sizes;
  double sigma_small = 0.0;
  double sigma_large = 0.0;
  double mass_large = 1.0;
};

Mixture make_mixture(int d, int particles, double nu, double restitution, double ratio = 1.0) {
  Mixture m;
  SystemParams& p = m.params;
  p.dimension = d;
  p.particles = particles;
  p.restitution = restitution;
  const double unit_ball = d == 3 ? M_PI / 6.0 : M_PI / 4.0;
  const double half = 0.5 * particles;
  m.sigma_small = std::pow(nu / (unit_ball * (half + half * std::pow(ratio, d))), 1.0 / d);
  m.sigma_large = ratio * m.sigma_small;
  p.diameter = std::max(m.sigma_small, m.sigma_large);
  if (ratio != 1.0) {
    m.mass_large = std::pow(ratio, d);
    // Largest first (the order random addition places them in); the large ones have ids < N/2.
    for (int i = 0; i < particles; ++i) {
      const bool large = i < particles / 2;
      m.sizes.diameter.push_back(large ? m.sigma_large : m.sigma_small);
      m.sizes.mass.push_back(large ? m.mass_large : 1.0);
    }
  }
  return m;
}

template <int D>
Simulation<D> start(const Mixture& m, std::uint64_t seed) {
  const SystemParams& p = m.params;
  CellGridRequest request{p.length_x, p.length_y, p.diameter, p.particles, false, 1.0, std::nullopt};
  request.dimension = D;
  request.length_z = p.length_z;
  const auto grid = choose_cell_grid(request);
  EXPECT_TRUE(grid.grid) << grid.error;
  const auto init = make_initial_state(p, 1.0, seed, Placement::kAuto, std::nullopt, m.sizes);
  EXPECT_TRUE(init.error.empty()) << init.error;
  return Simulation<D>(p, *grid.grid, init.state);
}

// Σ J σ_ij over collisions (the collisional virial) and collisions by species pair
// (0: small–small, 1: small–large, 2: large–large; species from the particle's mass).
template <int D>
struct VirialAndCounts final : EventObserver<D> {
  double virial = 0.0;
  std::array<std::int64_t, 3> pairs{};
  void on_collision(const CollisionRecord<D>& r) override {
    virial += r.impulse * contact(r);
    ++pairs[static_cast<std::size_t>((r.first_mass > 1.0 ? 1 : 0) + (r.second_mass > 1.0 ? 1 : 0))];
  }
  // σ_ij from the masses (m ∝ σ^d), independently of the engine's own σ_ij.
  double contact(const CollisionRecord<D>& r) const {
    const double radius_first = std::pow(r.first_mass, 1.0 / D) * sigma_unit_mass * 0.5;
    const double radius_second = std::pow(r.second_mass, 1.0 / D) * sigma_unit_mass * 0.5;
    return radius_first + radius_second;
  }
  double sigma_unit_mass = 0.0;  // the diameter of a particle of unit mass (masses ∝ σ^d)
};

// Kinetic temperature per degree of freedom and flatness ⟨c⁴⟩/⟨c²⟩² of a state (zero total momentum).
struct Kinetics {
  double temperature = 0.0;
  double flatness = 0.0;
};
Kinetics kinetics(const ParticleState& s) {
  double sum2 = 0.0, sum4 = 0.0, mass2 = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    double c2 = 0.0;
    for (int a = 0; a < s.dimension; ++a) c2 += s.velocity(a)[i] * s.velocity(a)[i];
    sum2 += s.mass_of(i) * c2;
    mass2 += c2;
    sum4 += c2 * c2;
  }
  const auto n = static_cast<double>(s.size());
  return {sum2 / (s.dimension * n), (sum4 / n) / ((mass2 / n) * (mass2 / n))};
}

struct EquilibriumMeasurement {
  double compressibility = 0.0;   // Z = P / (n T)
  double collision_rate = 0.0;    // c per unit time
  double flatness = 0.0;
  double temperature = 0.0;
  std::array<double, 3> pair_rate_density{};  // collisions per unit volume and time by pair
};

// An elastic run melted for 10 c, then measured for `c` collisions per particle in 40 samples.
template <int D>
EquilibriumMeasurement measure_equilibrium(const Mixture& m, double c, std::uint64_t seed) {
  Simulation<D> sim = start<D>(m, seed);
  const auto n = m.params.particles;
  sim.run(kForever, 10 * n);
  VirialAndCounts<D> observer;
  observer.sigma_unit_mass = m.sigma_small;
  sim.add_observer(&observer);
  const double t0 = sim.time();
  const std::int64_t c0 = sim.collisions();
  constexpr int kSamples = 40;
  double temperature = 0.0, flatness = 0.0;
  for (int k = 1; k <= kSamples; ++k) {
    sim.run(kForever, c0 + std::llround(c * static_cast<double>(n) * k / kSamples));
    const Kinetics now = kinetics(sim.state());
    temperature += now.temperature / kSamples;
    flatness += now.flatness / kSamples;
  }
  const double span = sim.time() - t0;
  const double volume = 1.0;
  const double density = static_cast<double>(n) / volume;
  // Virial pressure P = n T + Σ J σ_ij / (d V τ); T is constant in an elastic run.
  const double pressure = density * temperature + observer.virial / (D * volume * span);
  EquilibriumMeasurement out;
  out.compressibility = pressure / (density * temperature);
  out.collision_rate = static_cast<double>(sim.collisions() - c0) / static_cast<double>(n) / span;
  out.flatness = flatness;
  out.temperature = temperature;
  for (std::size_t k = 0; k < 3; ++k) out.pair_rate_density[k] = static_cast<double>(observer.pairs[k]) / (volume * span);
  return out;
}

// Hard spheres in equilibrium: Z against Carnahan–Starling (accurate to ≤ 0.3% in the fluid up to
// φ = 0.45), the collision rate against Enskog with the Carnahan–Starling contact value
// (dc/dt = ω/2, ω = 4nσ²χ√(πT)), κ = 5/3 for the 3D Maxwellian.  2000 spheres over 30 c give a
// statistical error of ≈ 0.5% on Z and the rate: tolerance 2%.
class SphereEquilibrium : public ::testing::TestWithParam<double> {};

TEST_P(SphereEquilibrium, PressureCollisionRateAndFlatness) {
  const double phi = GetParam();
  const Mixture m = make_mixture(3, 2000, phi, 1.0);
  const EquilibriumMeasurement r = measure_equilibrium<3>(m, 30.0, 21);
  const double n = static_cast<double>(m.params.particles);
  const double z_cs = theory::carnahan_starling_compressibility(phi);
  const double enskog = 0.5 * theory::hard_sphere_collision_frequency(3, n, m.params.diameter,
                                                                       theory::carnahan_starling_contact_value(phi),
                                                                       r.temperature, 1.0);
  std::printf("phi=%.2f  Z=%.4f (Carnahan-Starling %.4f)  dc/dt=%.4f (Enskog %.4f, ratio %.4f)  kappa=%.4f (5/3)\n", phi,
              r.compressibility, z_cs, r.collision_rate, enskog, r.collision_rate / enskog, r.flatness);
  EXPECT_NEAR(r.compressibility / z_cs, 1.0, 0.02);
  EXPECT_NEAR(r.collision_rate / enskog, 1.0, 0.02);
  EXPECT_NEAR(r.flatness, 5.0 / 3.0, 0.03);
}

INSTANTIATE_TEST_SUITE_P(VolumeFractions, SphereEquilibrium, ::testing::Values(0.05, 0.2, 0.35));

// Binary mixtures (σ_B = 1.5 σ_A, m ∝ σ^d, equal numbers) in equilibrium: collisions per unit
// volume and time of each species pair against Enskog theory for mixtures (BMCSL contact values
// in 3D, Santos–Yuste–López de Haro in 2D), and the pressure against the same equations of state.
// 4000 particles over 20 c give one run's pair rates to 0.6–1.6 % (sd over 12 seeds, 2D φ = 0.3;
// more than the counting error, ≈ 1 %, as the composition fluctuates slowly): four runs are
// averaged (≤ 0.8 %); tolerance 3 % (the contact values' own accuracy at these densities is ~1 %).
struct MixtureCase {
  int dimension;
  double packing_fraction;
};
class MixtureEquilibrium : public ::testing::TestWithParam<MixtureCase> {};

TEST_P(MixtureEquilibrium, PairCollisionRatesAndPressure) {
  const MixtureCase k = GetParam();
  const Mixture m = make_mixture(k.dimension, 4000, k.packing_fraction, 1.0, 1.5);
  const double half = 0.5 * static_cast<double>(m.params.particles);
  const std::vector<theory::MixtureSpecies> species{{m.sigma_small, 1.0, half}, {m.sigma_large, m.mass_large, half}};
  ASSERT_NEAR(theory::mixture_packing_fraction(k.dimension, species), k.packing_fraction, 1e-12);
  const char* names[] = {"small-small", "small-large", "large-large"};
  const std::size_t first[] = {0, 0, 1}, second[] = {0, 1, 1};
  // Each run against the theory at its own temperature, the ratios averaged.
  constexpr int kRuns = 4;
  std::array<double, 3> rate_ratio{};
  double z_ratio = 0.0;
  for (std::uint64_t seed = 5; seed < 5 + kRuns; ++seed) {
    const EquilibriumMeasurement r =
        k.dimension == 3 ? measure_equilibrium<3>(m, 20.0, seed) : measure_equilibrium<2>(m, 20.0, seed);
    for (std::size_t pair = 0; pair < 3; ++pair) {
      const double expected = theory::pair_collision_rate_density(k.dimension, species, first[pair], second[pair], r.temperature);
      rate_ratio[pair] += r.pair_rate_density[pair] / expected / kRuns;
    }
    z_ratio += r.compressibility / (theory::mixture_pressure(k.dimension, species, r.temperature) / (2.0 * half * r.temperature)) / kRuns;
  }
  for (std::size_t pair = 0; pair < 3; ++pair) {
    std::printf("%dD phi=%.2f %s: collisions per volume and time / Enskog %.4f (%d runs)\n", k.dimension,
                k.packing_fraction, names[pair], rate_ratio[pair], kRuns);
    EXPECT_NEAR(rate_ratio[pair], 1.0, 0.03) << names[pair];
  }
  std::printf("%dD phi=%.2f mixture Z / equation of state %.4f\n", k.dimension, k.packing_fraction, z_ratio);
  EXPECT_NEAR(z_ratio, 1.0, 0.02);
}

INSTANTIATE_TEST_SUITE_P(Mixtures, MixtureEquilibrium,
                         ::testing::Values(MixtureCase{3, 0.05}, MixtureCase{3, 0.25}, MixtureCase{2, 0.3}),
                         [](const ::testing::TestParamInfo<MixtureCase>& test) {
                           return std::to_string(test.param.dimension) + "D_phi" +
                                  std::to_string(static_cast<int>(100 * test.param.packing_fraction));
                         });

// Free cooling of spheres before clustering (homogeneous cooling state): T(c) = T₀ exp(−2 f c) with
// f = (1 − e²)/d (1 + 3a₂/16)/(1 − a₂/16) the fraction of the pair's kinetic energy lost per
// collision (van Noije & Ernst's Sonine a₂; derivation in docs/theory.md).  4000 spheres at φ = 0.05,
// e = 0.9, the slope of ln T over c ∈ [2, 12] (after the Maxwellian start has relaxed): tolerance
// 1.5% (≈ 4 standard errors of the slope; the Sonine term itself is 0.4% here and not resolved).
TEST(SphereCooling, CoolingRatePerCollision) {
  const double e = 0.9;
  Mixture m = make_mixture(3, 4000, 0.05, 1.0);
  Simulation<3> sim = start<3>(m, 31);
  const auto n = m.params.particles;
  sim.run(kForever, 5 * n);
  sim.start_production(e);
  std::vector<double> cs, logs;
  for (int k = 0; k <= 40; ++k) {
    const double c = 2.0 + 0.25 * k;
    sim.run(kForever, std::llround(c * static_cast<double>(n)));
    cs.push_back(static_cast<double>(sim.collisions()) / static_cast<double>(n));
    logs.push_back(std::log(kinetics(sim.state()).temperature));
  }
  double mc = 0.0, ml = 0.0;
  for (std::size_t i = 0; i < cs.size(); ++i) {
    mc += cs[i] / static_cast<double>(cs.size());
    ml += logs[i] / static_cast<double>(cs.size());
  }
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t i = 0; i < cs.size(); ++i) {
    sxy += (cs[i] - mc) * (logs[i] - ml);
    sxx += (cs[i] - mc) * (cs[i] - mc);
  }
  const double slope = sxy / sxx;
  const double expected = -2.0 * theory::energy_loss_per_collision(3, e, theory::sonine_a2(e, 3));
  std::printf("3D e=%.2f: d ln T / dc = %.5f (homogeneous cooling with Sonine a2: %.5f, Maxwellian %.5f; ratio %.4f)\n", e,
              slope, expected, -2.0 * (1.0 - e * e) / 3.0, slope / expected);
  EXPECT_NEAR(slope / expected, 1.0, 0.015);
}

}  // namespace
}  // namespace granule
