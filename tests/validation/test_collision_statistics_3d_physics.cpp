// Validation of the collision measurements of spheres against independent results: the
// Carnahan–Starling equation of state and the test's own virial sum for the collisional stress
// (1.6), molecular chaos for the impact parameters ((b/σ)² uniform on [0, 1] in 3D), Enskog theory
// for the mean free path, isotropy for the free-path directions; and for a binary mixture the same
// identity and law with each pair's σ_ij.  Each test prints what it measured.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include "observers/collision_statistics_fits.hpp"
#include "observers/collisional_stress.hpp"
#include "observers/free_paths.hpp"
#include "observers/impact_parameters.hpp"
#include "cells/cell_grid.hpp"
#include "init/initial_state.hpp"
#include "theory/hard_spheres.hpp"
#include "validation/simulation_setup.hpp"

namespace granule {
namespace {

// Spheres in the unit cube at volume fraction φ, elastic; `sizes` empty: monodisperse of σ.
Simulation<3> spheres(const SystemParams& p, const ParticleSizes& sizes, std::uint64_t seed) {
  CellGridRequest request{p.length_x, p.length_y, p.diameter, p.particles, false, 1.0, std::nullopt};
  request.dimension = 3;
  request.length_z = p.length_z;
  const auto grid = choose_cell_grid(request);
  EXPECT_TRUE(grid.grid) << grid.error;
  const auto init = make_initial_state(p, 1.0, seed, Placement::kAuto, std::nullopt, sizes);
  EXPECT_TRUE(init.error.empty()) << init.error;
  return Simulation<3>(p, *grid.grid, init.state);
}

SystemParams sphere_system(int n, double largest_diameter) {
  SystemParams p;
  p.dimension = 3;
  p.particles = n;
  p.diameter = largest_diameter;
  return p;
}

// The test's own collisional virial Σ J σ_ij, σ_ij from the masses (m ∝ σ³, unit mass for σ_unit),
// independently of the engine's σ_ij and of the stress field.
struct Virial final : EventObserver<3> {
  double sigma_unit_mass = 0.0;
  double sum = 0.0;
  void on_collision(const CollisionRecord<3>& r) override {
    sum += r.impulse * 0.5 * sigma_unit_mass * (std::cbrt(r.first_mass) + std::cbrt(r.second_mass));
  }
};

// Temperature per degree of freedom of a state of zero total momentum, T = Σ m v² / (3N).
double temperature(const ParticleState& s) {
  double sum = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) sum += s.mass_of(i) * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i] + s.vz[i] * s.vz[i]);
  return sum / (3.0 * static_cast<double>(s.size()));
}

// The measurements of one elastic run: melted for 10 c, flights known after 2 c more, then measured
// for `c` collisions per particle.
struct Measured {
  CollisionalStress stress;
  double virial_pressure_collisional = 0.0;  // Σ J σ_ij / (3 V t) from the test's own sum
  double temperature = 0.0;
  double collisions = 0.0;
  std::vector<double> impact_counts;
  UniformBins impact_bins;
  PathHistogram paths;
  UniformBins length_bins, angle_bins;
};

Measured measure(const SystemParams& p, const ParticleSizes& sizes, double sigma_unit_mass, double c, double max_length,
                 std::uint64_t seed) {
  Simulation<3> sim = spheres(p, sizes, seed);
  const auto n = p.particles;
  sim.run(kInf, 10 * n);
  const FieldGrid grid{5, 5, 1.0, 1.0, 5, 1.0, 3};
  const std::optional<double> diameter = sizes.monodisperse() ? std::optional<double>(p.diameter) : std::nullopt;
  CollisionalStressField<3> stress(grid, diameter);
  ImpactParameterStatistics<3> impacts(diameter, 1000, n, {}, nullptr);
  FreePathSettings settings;
  settings.max_length = max_length;
  settings.length_bins = 240;
  FreePathStatistics<3> free_paths(n, settings, nullptr);
  Virial virial;
  virial.sigma_unit_mass = sigma_unit_mass;
  sim.add_observer(&free_paths);
  sim.run(kInf, sim.collisions() + 2 * n);  // every particle's flight history known
  for (EventObserver<3>* o : std::vector<EventObserver<3>*>{&stress, &impacts, &virial}) sim.add_observer(o);
  free_paths.start();
  stress.restart(sim.time());
  const double t0 = sim.time();
  const std::int64_t c0 = sim.collisions();
  sim.run(kInf, c0 + std::llround(c * static_cast<double>(n)));
  Measured m;
  m.stress = stress.stress(sim.time());
  m.virial_pressure_collisional = virial.sum / (3.0 * 1.0 * (sim.time() - t0));
  m.temperature = temperature(sim.state());  // elastic, no mean flow: constant
  m.collisions = static_cast<double>(sim.collisions() - c0);
  m.impact_counts = impacts.total();
  m.impact_bins = impacts.bins();
  m.paths = free_paths.total();
  m.length_bins = free_paths.length_bins();
  m.angle_bins = free_paths.angle_bins();
  return m;
}

// Box average of the collisional pressure field (trace/3 per cell; cells of equal volume).
double box_pressure(const CollisionalStress& s) {
  double sum = 0.0;
  for (std::size_t c = 0; c < s.xx.size(); ++c) sum += s.pressure(c);
  return sum / static_cast<double>(s.xx.size());
}
double box_mean(const std::vector<double>& field) {
  double sum = 0.0;
  for (double v : field) sum += v;
  return sum / static_cast<double>(field.size());
}

// Monodisperse spheres at φ = 0.05: N = 2000 over 30 c (60 000 collisions).
constexpr double kPhi = 0.05;
constexpr int kSpheres = 2000;
double sphere_diameter() { return std::cbrt(6.0 * kPhi / (M_PI * kSpheres)); }
double enskog_mean_free_path() {
  return theory::hard_sphere_mean_free_path(3, kSpheres, sphere_diameter(), theory::carnahan_starling_contact_value(kPhi));
}

const Measured& equilibrium() {
  static const Measured m = measure(sphere_system(kSpheres, sphere_diameter()), {}, sphere_diameter(), 30.0,
                                    12.0 * enskog_mean_free_path(), 41);
  return m;
}

// The stress field summed over its cells is the box's collisional virial, collision by collision:
// an identity (to round-off), against the test's own Σ J σ_ij.
TEST(CollisionalStress3DValidation, SummedOverCellsIsTheVirialOfTheBox) {
  const Measured& m = equilibrium();
  const double field = box_pressure(m.stress);  // unit volume: the box average is the box total
  std::printf("3D: box-averaged collisional pressure %.9g, own virial Σ J σ / (3 V t) %.9g\n", field, m.virial_pressure_collisional);
  EXPECT_NEAR(field / m.virial_pressure_collisional, 1.0, 1e-10);
}

// P_c = n T (Z − 1) with Carnahan–Starling Z (≤ 0.3% from MD here); 60 000 collisions give ≈ 0.5%
// statistics: tolerance 2%.  The normal stresses are equal and the shear stresses vanish
// (isotropy) within 3% of P_c.
TEST(CollisionalStress3DValidation, PressureFollowsCarnahanStarlingAndTheStressIsIsotropic) {
  const Measured& m = equilibrium();
  const double expected = kSpheres * m.temperature * (theory::carnahan_starling_compressibility(kPhi) - 1.0);
  const double pc = box_pressure(m.stress);
  std::printf("3D phi=%.2f: collisional pressure %.5g, Carnahan-Starling n T (Z - 1) %.5g (ratio %.4f); "
              "xx %.4f yy %.4f zz %.4f xy %.4f xz %.4f yz %.4f (in units of P_c)\n",
              kPhi, pc, expected, pc / expected, box_mean(m.stress.xx) / pc, box_mean(m.stress.yy) / pc,
              box_mean(m.stress.zz) / pc, box_mean(m.stress.xy) / pc, box_mean(m.stress.xz) / pc, box_mean(m.stress.yz) / pc);
  EXPECT_NEAR(pc / expected, 1.0, 0.02);
  for (const auto* diagonal : {&m.stress.xx, &m.stress.yy, &m.stress.zz}) EXPECT_NEAR(box_mean(*diagonal) / pc, 1.0, 0.03);
  for (const auto* shear : {&m.stress.xy, &m.stress.xz, &m.stress.yz}) EXPECT_NEAR(box_mean(*shear) / pc, 0.0, 0.03);
}

// Molecular chaos: (b/σ)² uniform on [0, 1].  Kolmogorov–Smirnov distance on 1000 bins (bin
// resolution 10⁻³) within the 95% band 1.36/√n.
TEST(CollisionStatistics3DValidation, SquaredImpactParametersAreUniformInEquilibrium) {
  const Measured& m = equilibrium();
  const ImpactParameterSummary s = summarize_impact_parameters(m.impact_counts, m.impact_bins);
  const double critical = 1.36 / std::sqrt(s.samples) + 1e-3;
  std::printf("3D (b/sigma)^2: %.0f collisions, KS distance from uniform %.5f (95%% band %.5f)\n", s.samples, s.ks_uniform,
              critical);
  EXPECT_LT(s.ks_uniform, critical);
}

// Mean free path = distance flown / flights = ⟨|v|⟩ / ω = 1/(√2 π n σ² χ) with the Carnahan–Starling
// χ (Enskog; the collision rate is within 0.6% of Enskog here, test_hard_sphere_physics): tolerance
// 2%.  The Boltzmann value (χ = 1) is 14% longer at this density and is printed for comparison.
TEST(CollisionStatistics3DValidation, MeanFreePathMatchesEnskog) {
  const Measured& m = equilibrium();
  const double measured = m.paths.sum_length / m.paths.paths;
  const double boltzmann = theory::hard_sphere_mean_free_path(3, kSpheres, sphere_diameter(), 1.0);
  std::printf("3D mean free path %.6g over %.0f paths: Enskog (CS) %.6g (ratio %.4f), Boltzmann %.6g (ratio %.4f)\n", measured,
              m.paths.paths, enskog_mean_free_path(), measured / enskog_mean_free_path(), boltzmann, measured / boltzmann);
  EXPECT_NEAR(measured / enskog_mean_free_path(), 1.0, 0.02);
}

// Flights in an equilibrium gas have no preferred direction: cos θ to the x axis uniform on
// [−1, 1], within the 1% Kolmogorov band (consecutive flights of one sphere are nearly independent).
TEST(CollisionStatistics3DValidation, FreePathDirectionsAreIsotropic) {
  const Measured& m = equilibrium();
  const FreePathSummary s = summarize_free_paths(m.paths, m.length_bins, m.angle_bins, 3);
  const double below_max = s.paths * s.length_cumulative.back();
  const double critical = 1.63 / std::sqrt(below_max);
  std::printf("3D free-path cos(theta): KS distance from uniform %.5f over %.0f paths (1%% band %.5f)\n", s.ks_isotropic,
              below_max, critical);
  EXPECT_LT(s.ks_isotropic, critical);
}

// A binary mixture (σ_B = 1.6 σ_A, m ∝ σ³, equal numbers) at φ = 0.05: the stress field with each
// pair's σ_ij sums to the test's own virial (an identity), and (b/σ_ij)² is uniform.  N = 2000
// over 15 c (30 000 collisions).
TEST(CollisionStatistics3DValidation, MixtureStressIsTheVirialAndImpactParametersAreUniformInSigmaIJ) {
  const int n = 2000;
  const double ratio = 1.6;
  const double sigma_small = std::cbrt(6.0 * kPhi / (M_PI * (0.5 * n) * (1.0 + ratio * ratio * ratio)));
  ParticleSizes sizes;
  for (int i = 0; i < n; ++i) {
    const bool large = i < n / 2;  // the largest first, as placement orders them
    sizes.diameter.push_back(large ? ratio * sigma_small : sigma_small);
    sizes.mass.push_back(large ? ratio * ratio * ratio : 1.0);
  }
  const Measured m = measure(sphere_system(n, ratio * sigma_small), sizes, sigma_small, 15.0, 1.0, 7);
  const ImpactParameterSummary b = summarize_impact_parameters(m.impact_counts, m.impact_bins);
  const double critical = 1.36 / std::sqrt(b.samples) + 1e-3;
  std::printf("3D mixture: box-averaged collisional pressure %.9g, own virial %.9g; (b/sigma_ij)^2 KS %.5f over %.0f "
              "collisions (95%% band %.5f)\n",
              box_pressure(m.stress), m.virial_pressure_collisional, b.ks_uniform, b.samples, critical);
  EXPECT_NEAR(box_pressure(m.stress) / m.virial_pressure_collisional, 1.0, 1e-10);
  EXPECT_LT(b.ks_uniform, critical);
}

}  // namespace
}  // namespace granule
