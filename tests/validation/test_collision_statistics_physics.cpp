// Validation of the coarse-grained fields and collision statistics against independent
// results: the hard-disk equation of state, Enskog kinetic theory of the elastic gas, exact
// properties of equilibrium (isotropy, uniform impact parameters), and the imposed Lees–Edwards
// shear.  Each test prints what it measured.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "analysis/cell_fields.hpp"
#include "observers/collision_statistics_fits.hpp"
#include "observers/collisional_stress.hpp"
#include "observers/free_paths.hpp"
#include "observers/impact_parameters.hpp"
#include "observers/global_diagnostics.hpp"
#include "validation/simulation_setup.hpp"

namespace granule {
namespace {

// Free-path density of an elastic hard-disk gas under molecular chaos (Enskog): a disk of speed
// s collides at the rate ω(s) = 2σ n g(σ) ⟨|v − w|⟩_w (w Maxwellian), so its flights are
// exponential with mean s/ω(s); flights end at the rate f(s) ω(s).  Hence
//   𝒫(l) = ∫ f(s) ω(s)²/s · exp(−l ω(s)/s) ds / ∫ f(s) ω(s) ds,   f(s) = (s/T) exp(−s²/2T).
// ⟨|v − w|⟩ is the mean of a Rice distribution: √(πT/2) L_{1/2}(−s²/2T).
double enskog_free_path_density(double l, double n, double sigma, double g, double T) {
  const auto mean_relative_speed = [&](double s) {
    const double x = -s * s / (2.0 * T);
    const double laguerre = std::exp(x / 2.0) * ((1.0 - x) * std::cyl_bessel_i(0.0, -x / 2.0) - x * std::cyl_bessel_i(1.0, -x / 2.0));
    return std::sqrt(std::numbers::pi * T / 2.0) * laguerre;
  };
  double numerator = 0.0, denominator = 0.0;
  const int steps = 4000;
  const double ds = 10.0 * std::sqrt(T) / steps;
  for (int k = 0; k < steps; ++k) {
    const double s = (k + 0.5) * ds;
    const double f = s / T * std::exp(-s * s / (2.0 * T));
    const double omega = 2.0 * sigma * n * g * mean_relative_speed(s);
    numerator += f * omega * omega / s * std::exp(-l * omega / s) * ds;
    denominator += f * omega * ds;
  }
  return numerator / denominator;
}

// Least-squares slope of log y against x: the decay length is −1/slope.
double decay_length(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double m = static_cast<double>(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double ly = std::log(y[i]);
    sx += x[i];
    sy += ly;
    sxx += x[i] * x[i];
    sxy += x[i] * ly;
  }
  return -(m * sxx - sx * sx) / (m * sxy - sx * sy);
}

// One elastic equilibrium run at ν = 0.05 shared by the tests below (N = 3000, 30 collisions per
// particle after melting the lattice).
struct EquilibriumRun {
  static constexpr double kNu = 0.05;
  SystemParams params = make_system(3000, kNu, 1.0);
  FieldGrid grid{10, 10, 1.0, 1.0};
  double pressure_collisional_global = 0.0;
  CollisionalStress collisional;
  CellFields averaged;
  std::vector<CellFields> instants;
  std::vector<double> impact_counts;
  PathHistogram paths;
  UniformBins length_bins, angle_bins;
  double temperature = 0.0;

  EquilibriumRun() {
    Simulation<2> sim = make_simulation(params, 21);
    sim.run(kInf, collisions_for(params, 20.0));
    const ShearFrame frame{1.0, 1.0, 0.0};
    GlobalDiagnostics<2> diagnostics(params, 10, 10);
    CollisionalStressField<2> stress(grid, params.diameter);
    ImpactParameterStatistics<2> impacts(params.diameter, 1000, params.particles, {}, nullptr);
    FreePathSettings settings;
    settings.max_length = 12.0 / (2.0 * std::sqrt(2.0) * 3000.0 * params.diameter);
    settings.length_bins = 240;
    FreePathStatistics<2> free_paths(params.particles, settings, nullptr);
    for (EventObserver<2>* o : std::vector<EventObserver<2>*>{&diagnostics, &stress, &free_paths}) sim.add_observer(o);
    sim.run(kInf, sim.collisions() + collisions_for(params, 2.0));  // every disk's flight history known
    sim.add_observer(&impacts);
    free_paths.start();
    diagnostics.restart_interval(sim.time(), sim.collisions());
    stress.restart(sim.time());
    CellMoments moments(grid);
    for (int k = 0; k < 30; ++k) {
      sim.run(kInf, sim.collisions() + collisions_for(params, 1.0));
      const ParticleState state = sim.state();
      moments.add(state, frame, false);
      CellMoments one(grid);
      one.add(state, frame, false);
      instants.push_back(fields_from_moments(one, frame, 0.0, false));
    }
    const ParticleState state = sim.state();
    double energy = 0.0;
    for (std::size_t i = 0; i < state.size(); ++i) energy += 0.5 * (state.vx[i] * state.vx[i] + state.vy[i] * state.vy[i]);
    temperature = energy / static_cast<double>(state.size());  // elastic, no mean flow: T = ½⟨v²⟩ exactly
    pressure_collisional_global = diagnostics.sample(state, sim.time(), sim.collisions(), sim.image_velocity(), sim.shear_offset()).pressure_collisional;
    collisional = stress.stress(sim.time());
    averaged = fields_from_moments(moments, frame, 0.0, false);
    impact_counts = impacts.total();
    paths = free_paths.total();
    length_bins = free_paths.length_bins();
    angle_bins = free_paths.angle_bins();
  }
};

const EquilibriumRun& equilibrium() {
  static const EquilibriumRun run;
  return run;
}

TEST(FieldsValidation, CollisionalStressSummedOverCellsIsTheGlobalCollisionalPressure) {
  const EquilibriumRun& r = equilibrium();
  double sum = 0.0;
  for (std::size_t c = 0; c < r.grid.cells(); ++c) sum += 0.5 * (r.collisional.xx[c] + r.collisional.yy[c]) * r.grid.cell_area();
  std::printf("Σ cells P_c A_cell = %.9g, global P_c = %.9g\n", sum, r.pressure_collisional_global);
  EXPECT_NEAR(sum, r.pressure_collisional_global, 1e-10 * r.pressure_collisional_global);
}

// Collisional pressure (half trace of 1.6) against Henderson's equation of state:
// P_c = n T (Z − 1) = 2ν g(σ) n T.  Tolerance 3%: Henderson ≲1%, statistics of 90 000 collisions.
TEST(FieldsValidation, CollisionalPressureFollowsTheHardDiskEquationOfState) {
  const EquilibriumRun& r = equilibrium();
  double mean = 0.0;
  for (std::size_t c = 0; c < r.grid.cells(); ++c) mean += 0.5 * (r.collisional.xx[c] + r.collisional.yy[c]);
  mean /= static_cast<double>(r.grid.cells());
  const double n = static_cast<double>(r.params.particles);
  const double expected = n * r.temperature * (henderson_z(EquilibriumRun::kNu) - 1.0);
  std::printf("collisional pressure %.5g, Henderson %.5g (ratio %.4f)\n", mean, expected, mean / expected);
  EXPECT_NEAR(mean / expected, 1.0, 0.03);
}

// Kinetic stress (1.4) of the interval-averaged fields: isotropic and equal to ρT (ideal gas).
TEST(FieldsValidation, KineticStressIsIsotropicAndEqualsDensityTimesTemperature) {
  const EquilibriumRun& r = equilibrium();
  double xx = 0, yy = 0, xy = 0;
  for (std::size_t c = 0; c < r.grid.cells(); ++c) {
    xx += r.averaged.kinetic_xx[c];
    yy += r.averaged.kinetic_yy[c];
    xy += r.averaged.kinetic_xy[c];
  }
  const double cells = static_cast<double>(r.grid.cells());
  xx /= cells, yy /= cells, xy /= cells;
  const double rho_t = static_cast<double>(r.params.particles) * r.temperature;
  std::printf("τxx %.5g τyy %.5g τxy %.3g, ρT %.5g\n", xx, yy, xy, rho_t);
  EXPECT_NEAR(xx / rho_t, 1.0, 0.02);
  EXPECT_NEAR(yy / rho_t, 1.0, 0.02);
  EXPECT_NEAR(xy / rho_t, 0.0, 0.01);
}

// T(r) uniform within noise: for a Maxwellian, a cell of m disks has E[T̂] = T (m−1)/m and
// var T̂ = T² (m−1)/m²; the squared z-scores over all cells and snapshots average to 1 if the
// only variation is sampling noise (a real temperature gradient would inflate them).
TEST(FieldsValidation, TemperatureFieldIsUniformWithinSamplingNoise) {
  const EquilibriumRun& r = equilibrium();
  double z2 = 0.0;
  int used = 0;
  for (const CellFields& f : r.instants) {
    for (std::size_t c = 0; c < r.grid.cells(); ++c) {
      const double m = f.count[c];
      if (m < 5) continue;
      const double z = (f.temperature[c] - r.temperature * (m - 1) / m) / (r.temperature * std::sqrt(m - 1) / m);
      z2 += z * z;
      ++used;
    }
  }
  std::printf("mean squared z-score of T(r) over %d cells: %.4f\n", used, z2 / used);
  EXPECT_NEAR(z2 / used, 1.0, 0.1);
}

// In equilibrium every impact parameter is equally likely (§2.3, Fig 2.16(A)).  Kolmogorov–
// Smirnov distance on a 1000-bin histogram (bin error 10⁻³) against the 1% critical value.
TEST(CollisionStatisticsValidation, ImpactParametersAreUniformInEquilibrium) {
  const EquilibriumRun& r = equilibrium();
  const ImpactParameterSummary s = summarize_impact_parameters(r.impact_counts, UniformBins{0.0, 1.0, 1000});
  const double critical = 1.63 / std::sqrt(s.samples) + 1e-3;
  std::printf("impact parameters: %.0f collisions, KS distance %.5f (1%% critical %.5f)\n", s.samples, s.ks_uniform, critical);
  EXPECT_LT(s.ks_uniform, critical);
}

// Mean free path = distance travelled / flights = ⟨|v|⟩ / (2 dc/dt) = 1 / (2√2 n σ g(σ)) (Enskog).
TEST(CollisionStatisticsValidation, MeanFreePathMatchesEnskog) {
  const EquilibriumRun& r = equilibrium();
  const double n = static_cast<double>(r.params.particles);
  const double enskog = 1.0 / (2.0 * std::sqrt(2.0) * n * r.params.diameter * henderson_contact(EquilibriumRun::kNu));
  const double measured = r.paths.sum_length / r.paths.paths;
  std::printf("mean free path %.6g, Enskog %.6g (ratio %.4f), %.0f paths\n", measured, enskog, measured / enskog, r.paths.paths);
  EXPECT_NEAR(measured / enskog, 1.0, 0.02);
}

// The distribution of free paths: its exponential tail (3.35) decays with the length predicted
// by molecular chaos (fast disks fly further: the decay length exceeds the mean free path).
TEST(CollisionStatisticsValidation, FreePathTailDecaysAsEnskogPredicts) {
  const EquilibriumRun& r = equilibrium();
  const FreePathSummary s = summarize_free_paths(r.paths, r.length_bins, r.angle_bins);
  const double n = static_cast<double>(r.params.particles);
  const double g = henderson_contact(EquilibriumRun::kNu);
  std::vector<double> x, measured, theory;
  for (int k = 0; k < r.length_bins.bins; ++k) {
    const double l = r.length_bins.center(k);
    if (l < 2.0 * s.mean_length || l > 5.0 * s.mean_length) continue;
    x.push_back(l);
    measured.push_back(s.magnitude_density[static_cast<std::size_t>(k)]);
    theory.push_back(enskog_free_path_density(l, n, r.params.diameter, g, r.temperature));
  }
  const double measured_decay = decay_length(x, measured), theory_decay = decay_length(x, theory);
  std::printf("free-path tail decay length over [2, 5] λ: measured %.5g, Enskog %.5g, mean free path %.5g; "
              "KS distance to exp(−l/λ) %.4f, to the matched form (3.36) %.4f\n",
              measured_decay, theory_decay, s.mean_length, s.ks_exponential, s.ks_matched);
  EXPECT_NEAR(measured_decay / theory_decay, 1.0, 0.05);
  EXPECT_GT(theory_decay / s.mean_length, 1.1);
}

// Lees–Edwards: the streamwise profile V_x(y) is linear with slope γ = U/L_y and both shear
// stresses transport x-momentum down the gradient (τ_xy < 0 for γ > 0).
TEST(FieldsValidation, LeesEdwardsProfileIsLinearWithSlopeGammaAndShearStressesAreNegative) {
  const SystemParams p = make_system(2000, 0.05, 0.9, 20.0);
  Simulation<2> sim = make_simulation(p, 5);
  const ShearFrame frame{1.0, 1.0, p.shear_velocity};
  const FieldGrid grid{8, 16, 1.0, 1.0};
  sim.run(kInf, collisions_for(p, 20.0));
  CollisionalStressField<2> stress(grid, p.diameter);
  sim.add_observer(&stress);
  stress.restart(sim.time());
  CellMoments moments(grid);
  for (int k = 0; k < 40; ++k) {
    sim.run(kInf, sim.collisions() + collisions_for(p, 0.5));
    moments.add(sim.state(), frame, false);
  }
  const CellFields f = fields_from_moments(moments, frame, sim.shear_offset(), false);
  const StreamwiseProfiles profile = streamwise_profiles(f);
  double sy = 0, sv = 0, syy = 0, syv = 0;
  const double m = static_cast<double>(profile.y.size());
  for (std::size_t i = 0; i < profile.y.size(); ++i) {
    sy += profile.y[i];
    sv += profile.velocity_x[i];
    syy += profile.y[i] * profile.y[i];
    syv += profile.y[i] * profile.velocity_x[i];
  }
  const double slope = (m * syv - sy * sv) / (m * syy - sy * sy);
  const CollisionalStress c = stress.stress(sim.time());
  double kinetic_xy = 0, collisional_xy = 0;
  for (std::size_t i = 0; i < grid.cells(); ++i) {
    kinetic_xy += f.kinetic_xy[i];
    collisional_xy += c.xy[i];
  }
  std::printf("V_x(y) slope %.4f (γ = %.4f); Σ τxy kinetic %.4g, collisional %.4g\n", slope, p.shear_velocity,
              kinetic_xy, collisional_xy);
  EXPECT_NEAR(slope / p.shear_velocity, 1.0, 0.05);
  EXPECT_LT(kinetic_xy, 0.0);
  EXPECT_LT(collisional_xy, 0.0);
}

// Measuring must not change the trajectory: the same seed with and without every observer gives
// bit-identical states.
TEST(FieldsValidation, ObserversDoNotChangeTheTrajectory) {
  const SystemParams p = make_system(1000, 0.2, 0.8, 5.0);
  Simulation<2> plain = make_simulation(p, 9);
  Simulation<2> measured = make_simulation(p, 9);
  const FieldGrid grid{6, 6, 1.0, 1.0};
  LocalDensity density(grid);
  density.update(measured.state());
  CollisionalStressField<2> stress(grid, p.diameter);
  ImpactParameterStatistics<2> impacts(p.diameter, 50, 100, {{0.0, 1e9}}, &density);
  FreePathStatistics<2> paths(p.particles, FreePathSettings{}, &density);
  paths.start();
  for (EventObserver<2>* o : std::vector<EventObserver<2>*>{&stress, &impacts, &paths}) measured.add_observer(o);
  plain.run(kInf, collisions_for(p, 5.0));
  measured.run(kInf, collisions_for(p, 5.0));
  const ParticleState a = plain.state(), b = measured.state();
  ASSERT_GT(impacts.windows().size(), 0u);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.vx, b.vx);
  EXPECT_EQ(a.vy, b.vy);
}

}  // namespace
}  // namespace granule
