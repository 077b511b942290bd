// Walls, gravity and spin against independent theory, with stated tolerances:
//  • an elastic gas in gravity above a floor: the floor carries the whole weight, P_floor = m g N_A
//    (momentum balance, exact on average), and the column's profile is the hydrostatic one of
//    the local-density theory (theory/hydrostatics.hpp: barometric in the dilute limit, Henderson
//    / Carnahan–Starling corrections) away from the floor's layering;
//  • the contact theorem: an elastic gas between flat walls pushes on them with its bulk pressure
//    n T Z(φ) (Henderson in 2D, Carnahan–Starling in 3D), n measured in the middle of the box;
//  • a wall-driven shear flow in its steady state carries one flux of x momentum from wall to wall:
//    the walls take equal and opposite shear stresses, equal to the bulk's kinetic + collisional
//    shear stress (eqs 1.4, 1.6) measured from the grains alone, and the mean profile is
//    antisymmetric about the middle;
//  • homogeneous cooling of rough grains: T_tr and T_rot against the Maxwellian kinetic theory of
//    Huthmann & Zippelius (1997) and Luding et al. (1998) (theory/rough_cooling.hpp), in 2D and 3D,
//    per collision (which removes the unknown contact value and collision frequency).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "observers/global_diagnostics.hpp"
#include "theory/hard_spheres.hpp"
#include "theory/hydrostatics.hpp"
#include "theory/rough_cooling.hpp"
#include "validation/surfaces_setup.hpp"

namespace granule {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Momentum the walls took, per face, and the number of hits.
template <int D>
struct WallMomentum final : EventObserver<D> {
  std::array<Vec<D>, 6> impulse{};
  void on_collision(const CollisionRecord<D>&) override {}
  void on_surface_hit(const SurfaceHitRecord<D>& r) override {
    if (!r.surface.wall()) return;
    auto& total = impulse[static_cast<std::size_t>(r.surface.face())];
    total = total + r.impulse_on_surface;
  }
};

double temperature_of(const ParticleState& s) {
  double sum = 0.0;
  for (int a = 0; a < s.dimension; ++a) {
    for (double v : s.velocity(a)) sum += v * v;
  }
  return sum / (s.dimension * static_cast<double>(s.size()));
}

template <int D>
std::array<double, D> box_of(double lx, double ly) {
  std::array<double, D> box{};
  box.fill(lx);
  box[1] = ly;
  return box;
}

// The floor's load and the column's profile (2D: 1600 disks, 3D: 1000 spheres), T ≈ 1, g such
// that the barometric height is a tenth of the box.
template <int D>
void check_column() {
  std::array<int, D> per_axis;
  per_axis.fill(D == 2 ? 40 : 10);
  const double width = D == 2 ? 2.0 : 0.5;
  const double height = D == 2 ? 3.0 : 2.0;
  const double sigma = D == 2 ? 0.01 : 0.02;
  SystemParams p = surfaces_system<D>(per_axis, box_of<D>(width, height), sigma, 1.0);
  add_walls(p, 1, 1.0, -1.0);
  const double g = 5.0;
  p.gravity[1] = -g;
  // The lattice squeezed into the lower 40 % of the box, so that the column that forms is about
  // 7 barometric heights below the ceiling.
  ParticleState initial = lattice_gas<D>(p, per_axis, 1.0, 3);
  for (double& y : initial.y) y = 0.5 * sigma + 0.4 * (y - 0.5 * sigma);
  Simulation<D> sim(p, surfaces_grid<D>(p), initial);
  sim.run(kInf, 30 * p.particles);  // equilibrate: energy goes from height into temperature
  WallMomentum<D> walls;
  sim.add_observer(&walls);
  const double t0 = sim.time();
  double momentum_y0 = 0.0;
  for (double v : sim.state().vy) momentum_y0 += v;
  const double floor_area = std::pow(width, D - 1);
  // Time averages over equally spaced samples: T and the heights of the centres.
  const int samples = 400;
  const double dt = 0.02;
  double temperature = 0.0;
  std::vector<double> heights;
  for (int k = 1; k <= samples; ++k) {
    sim.run(t0 + k * dt, std::numeric_limits<std::int64_t>::max());
    const ParticleState s = sim.state();
    temperature += temperature_of(s) / samples;
    for (double y : s.y) heights.push_back(y - 0.5 * sigma);
  }
  const double span = sim.time() - t0;
  // The walls carry the weight N m g (per unit area), the floor nearly all of it: exactly so up to
  // the change of the gas's own momentum over the span (a breathing column), which is measured.
  const double floor_pressure = -walls.impulse[2][1] / span / floor_area;
  const double ceiling_pressure = walls.impulse[3][1] / span / floor_area;
  const double weight = static_cast<double>(p.particles) * g / floor_area;
  double momentum_y1 = 0.0;
  for (double v : sim.state().vy) momentum_y1 += v;
  const double breathing = (momentum_y1 - momentum_y0) / span / floor_area;
  std::printf("[%dD] floor pressure / weight = %.4f, ceiling / weight = %.2e, d(P_y)/dt / weight = %.2e, T = %.4f, "
              "%lld collisions\n", D, floor_pressure / weight, ceiling_pressure / weight, breathing / weight, temperature,
              static_cast<long long>(sim.collisions()));
  EXPECT_NEAR(floor_pressure - ceiling_pressure, weight + breathing, 1e-9 * weight);  // momentum balance, exact
  EXPECT_NEAR(floor_pressure / weight, 1.0, 0.02);  // on average the floor holds the column
  EXPECT_LT(ceiling_pressure / weight, 0.005);
  // The column: fractions of grains above heights of 1, 2, 3 barometric heights, against the
  // hydrostatic profile at the measured T (integrated numerically on a fine grid).
  const theory::HydrostaticColumn column{D, sigma, 1.0, g, temperature, static_cast<double>(p.particles) / floor_area};
  const double h = theory::barometric_height(column);
  std::vector<double> grid;
  const double top = height - sigma;
  for (double y = 0.0; y <= top; y += h / 400.0) grid.push_back(y);
  const std::vector<double> phi = theory::hydrostatic_packing_fraction(column, grid);
  auto theory_fraction_above = [&](double y0) {
    double above = 0.0, total = 0.0;
    for (std::size_t k = 1; k < grid.size(); ++k) {
      const double slice = 0.5 * (phi[k] + phi[k - 1]) * (grid[k] - grid[k - 1]);
      total += slice;
      if (grid[k - 1] >= y0) above += slice;
    }
    return above / total;
  };
  for (double multiple : {1.0, 2.0, 3.0}) {
    const double y0 = multiple * h;
    double above = 0.0;
    for (double y : heights) above += y >= y0 ? 1.0 : 0.0;
    above /= static_cast<double>(heights.size());
    const double expected = theory_fraction_above(y0);
    std::printf("[%dD] fraction above %.0f h: measured %.4f, hydrostatic theory %.4f, barometric %.4f\n", D, multiple,
                above, expected, std::exp(-multiple));
    EXPECT_NEAR(above / expected, 1.0, 0.05 * multiple);
  }
}

TEST(SurfacesPhysics, DisksInGravityLoadTheFloorWithTheirWeightAndFormTheHydrostaticColumn) { check_column<2>(); }
TEST(SurfacesPhysics, SpheresInGravityLoadTheFloorWithTheirWeightAndFormTheHydrostaticColumn) { check_column<3>(); }

// Contact theorem: the walls feel the bulk pressure.
template <int D>
void check_wall_pressure() {
  std::array<int, D> per_axis;
  per_axis.fill(D == 2 ? 40 : 10);
  const double sigma = D == 2 ? 0.0127 : 0.07;  // ν ≈ 0.20 (disks), φ ≈ 0.18 (spheres)
  SystemParams p = surfaces_system<D>(per_axis, box_of<D>(1.0, 1.0), sigma, 1.0);
  add_walls(p, 1, 1.0, -1.0);
  Simulation<D> sim(p, surfaces_grid<D>(p), lattice_gas<D>(p, per_axis, 1.0, 17));
  sim.run(kInf, 20 * p.particles);
  WallMomentum<D> walls;
  sim.add_observer(&walls);
  const double t0 = sim.time();
  const int samples = 800;
  double temperature = 0.0, middle_density = 0.0;
  const double slab = 0.5;  // the middle half of the box in y
  for (int k = 1; k <= samples; ++k) {
    sim.run(t0 + k * 0.01, std::numeric_limits<std::int64_t>::max());
    const ParticleState s = sim.state();
    temperature += temperature_of(s) / samples;
    double inside = 0.0;
    for (double y : s.y) inside += std::abs(y - 0.5) < 0.5 * slab ? 1.0 : 0.0;
    middle_density += inside / slab / samples;  // per unit volume: the box is 1 wide (deep)
  }
  const double span = sim.time() - t0;
  const double wall_pressure = 0.5 * (-walls.impulse[2][1] + walls.impulse[3][1]) / span;
  const double v_d = D == 2 ? M_PI * sigma * sigma / 4.0 : M_PI * sigma * sigma * sigma / 6.0;
  const double phi = middle_density * v_d;
  const double bulk = theory::hard_sphere_pressure(D, middle_density, temperature, phi);
  std::printf("[%dD] wall pressure %.5g, bulk n T Z(φ = %.3f) %.5g: ratio %.4f\n", D, wall_pressure, phi, bulk,
              wall_pressure / bulk);
  EXPECT_NEAR(wall_pressure / bulk, 1.0, 0.02);
}

TEST(SurfacesPhysics, DisksPushOnAFlatWallWithTheirBulkPressure) { check_wall_pressure<2>(); }
TEST(SurfacesPhysics, SpheresPushOnAFlatWallWithTheirBulkPressure) { check_wall_pressure<3>(); }

// Inelastic smooth disks between rough inelastic walls moving at ∓U/2 (ν = 0.1, ẽ = e_w = 0.9,
// β_w = 0.5), over 200 collisions per disk after 300 of transient.
TEST(SurfacesPhysics, AWallDrivenShearFlowCarriesOneMomentumFluxFromWallToWall) {
  const std::array<int, 2> per_axis{50, 40};
  const double sigma = std::sqrt(4.0 * 0.1 / (M_PI * 2000.0));
  SystemParams p = surfaces_system<2>(per_axis, {1.0, 1.0}, sigma, 0.9);
  add_walls(p, 1, 0.9, 0.5);
  const double u = 10.0;
  p.wall[2].velocity[0] = -0.5 * u;
  p.wall[3].velocity[0] = 0.5 * u;
  // Started on the linear profile: momentum diffuses across the box in ~L²/(π² η/ρ) ≈ 10 time units
  // (~170 collisions per disk), far slower than the disks collide.
  ParticleState initial = lattice_gas<2>(p, per_axis, 0.3, 31);
  for (std::size_t i = 0; i < initial.size(); ++i) initial.vx[i] += u * (initial.y[i] - 0.5);
  Simulation<2> sim(p, surfaces_grid<2>(p), initial);
  sim.run(kInf, 300 * p.particles);
  GlobalDiagnostics<2> diagnostics(p, FieldGrid{8, 8, 1.0, 1.0});
  sim.add_observer(&diagnostics);
  diagnostics.restart_interval(sim.time(), sim.collisions());
  constexpr int kBins = 10;
  constexpr int kChunks = 200;
  std::array<double, kBins> momentum{}, count{};
  double kinetic = 0.0;  // Σ m v_x v_y / V averaged over the states (eq 1.4; ⟨V_x(y) v_y⟩ → 0)
  for (int chunk = 1; chunk <= kChunks; ++chunk) {
    sim.run(kInf, (300 + chunk) * p.particles);
    const ParticleState s = sim.state();
    for (std::size_t i = 0; i < s.size(); ++i) {
      kinetic += s.vx[i] * s.vy[i] / (p.length_x * p.length_y) / kChunks;
      const auto bin = static_cast<std::size_t>(std::min(kBins - 1, static_cast<int>(s.y[i] * kBins)));
      momentum[bin] += s.vx[i];
      count[bin] += 1.0;
    }
  }
  const DiagnosticsSample sample = diagnostics.sample(sim.state(), sim.time(), sim.collisions(), 0.0, 0.0);
  ASSERT_TRUE(sample.walls[2] && sample.walls[3]);
  const double bottom = sample.walls[2]->shear_stress, top = sample.walls[3]->shear_stress;
  // The time series' kinetic column is one state's; the time average is taken here.
  const double bulk = kinetic + sample.shear_stress_collisional;
  std::printf("wall shear stresses: bottom %.5g, top %.5g; bulk kinetic %.5g + collisional %.5g = %.5g\n", bottom, top,
              kinetic, sample.shear_stress_collisional, bulk);
  EXPECT_GT(bottom, 0.0);  // the lower wall pulls the gas towards −x: it takes +x momentum
  EXPECT_NEAR(-top / bottom, 1.0, 0.03);
  EXPECT_NEAR(-bulk / bottom, 1.0, 0.04);
  for (int k = 0; k < kBins / 2; ++k) {
    const double lower = momentum[static_cast<std::size_t>(k)] / count[static_cast<std::size_t>(k)];
    const double upper = momentum[static_cast<std::size_t>(kBins - 1 - k)] / count[static_cast<std::size_t>(kBins - 1 - k)];
    std::printf("  V_x in band %d: %.4f, mirrored %.4f\n", k, lower, upper);
    EXPECT_NEAR(lower, -upper, 0.03 * 0.5 * u) << "band " << k;
  }
}

// Rough homogeneous cooling, per collision: T_tr(c) and T_rot(c) from equipartition at c = 0, summed
// over 16 independent runs: one run's T_rot at β < 0 strays by up to 7 % (seen at c = 2, N = 2500),
// as far as the tolerance, and 4 runs by up to 6 %; 16 runs of two engines whose round-off
// differs agree within 1 % with each other.
template <int D>
void check_rough_cooling(double e, double beta) {
  std::array<int, D> per_axis;
  per_axis.fill(D == 2 ? 50 : 14);
  const double sigma = D == 2 ? 0.004 : 0.0216;  // ν ≈ 0.03 (2D), φ ≈ 0.03 (3D)
  SystemParams p = surfaces_system<D>(per_axis, box_of<D>(1.0, 1.0), sigma, 1.0);
  const double q = D == 2 ? 0.5 : 0.4;
  make_rough(p, -1.0, q);
  const double inertia = q * 0.25 * sigma * sigma;
  const theory::RoughGrains grains{e, beta, q};
  const std::array<double, 3> checkpoints{1.0, 2.0, 4.0};
  std::array<theory::RoughTemperatures, 3> measured{};
  std::array<theory::RoughTemperatures, 3> expected{};
  constexpr std::uint64_t kRuns = 16;
  for (std::uint64_t seed = 100; seed < 100 + kRuns; ++seed) {
    Simulation<D> sim(p, surfaces_grid<D>(p), lattice_gas<D>(p, per_axis, 1.0, seed));
    sim.run(kInf, 5 * p.particles);  // smooth elastic: melt the lattice, spins untouched
    SystemParams production = p;
    production.restitution = e;
    production.roughness.tangential_restitution = beta;
    sim.start_production(production);
    auto temperatures = [&]() {
      const ParticleState s = sim.state();
      double rot = 0.0;
      for (int k = 0; k < s.spin_components(); ++k) {
        for (double w : s.spin(k)) rot += inertia * w * w;
      }
      return theory::RoughTemperatures{temperature_of(s), rot / (s.spin_components() * static_cast<double>(s.size()))};
    };
    const theory::RoughTemperatures start = temperatures();
    // Early on, before the velocity correlations of the clustering instability grow (thesis
    // Chapter 2: these boxes are many L0 wide) and take the gas away from molecular chaos.
    for (std::size_t k = 0; k < checkpoints.size(); ++k) {
      sim.run(kInf, std::llround(checkpoints[k] * static_cast<double>(p.particles)));
      const theory::RoughTemperatures now = temperatures();
      const theory::RoughTemperatures theory_now = theory::rough_temperatures_after_collisions(D, grains, start, checkpoints[k]);
      measured[k].translational += now.translational;
      measured[k].rotational += now.rotational;
      expected[k].translational += theory_now.translational;
      expected[k].rotational += theory_now.rotational;
    }
  }
  for (std::size_t k = 0; k < checkpoints.size(); ++k) {
    const double c = checkpoints[k];
    std::printf("[%dD e=%.2f β=%+.2f] c=%4.1f  T_tr %.4f (theory %.4f)  T_rot %.4f (theory %.4f), sums of %d runs\n", D, e,
                beta, c, measured[k].translational, expected[k].translational, measured[k].rotational,
                expected[k].rotational, static_cast<int>(kRuns));
    // 3 % at first, 6 % by c = 4: the Maxwellian theory neglects the non-Gaussian parts of the
    // velocity and spin distributions and their correlations, known to grow to several per cent
    // in the cooling state of rough grains (Brilliantov, Pöschel et al., PRL 98, 128001 (2007)).
    const double tolerance = c <= 2.0 ? 0.03 : 0.06;
    EXPECT_NEAR(measured[k].translational / expected[k].translational, 1.0, tolerance) << "c = " << c;
    EXPECT_NEAR(measured[k].rotational / expected[k].rotational, 1.0, tolerance) << "c = " << c;
  }
}

// The cooling state: started with T_rot/T_tr at the kinetic theory's fixed point R (the positive
// root of its quadratic), the gas keeps it while it cools.  One run's mean T_rot/T_tr over c = 0.5
// … 4 (36 states) fluctuates by 2–3 % from seed to seed (measured over 12 seeds: sd 0.017–0.030
// for the disks, 0.020–0.024 for the spheres), so the check averages 12 independent runs (≈ 0.7 %).
// Means of 12 runs sat 1.8–2.5 % below R for the disks and 0.5–1.8 % for the spheres (two sets of
// seeds, two builds whose trajectories differ by round-off): the Maxwellian theory neglects the non-Gaussian parts of the
// distributions (Brilliantov, Pöschel et al., PRL 98, 128001 (2007)).  Tolerance 4 %: a wrong
// moment of inertia or tangential rule moves R by far more.
template <int D>
double cooling_state_ratio_of_run(double e, double beta, std::uint64_t seed) {
  std::array<int, D> per_axis;
  per_axis.fill(D == 2 ? 50 : 14);
  const double sigma = D == 2 ? 0.004 : 0.0216;
  SystemParams p = surfaces_system<D>(per_axis, box_of<D>(1.0, 1.0), sigma, 1.0);
  const double q = D == 2 ? 0.5 : 0.4;
  make_rough(p, -1.0, q);
  const theory::RoughGrains grains{e, beta, q};
  const double ratio = theory::rough_temperature_ratio(D, grains);
  ParticleState initial = lattice_gas<D>(p, per_axis, 1.0, seed);
  for (int k = 0; k < initial.spin_components(); ++k) {
    for (double& w : initial.spin(k)) w *= std::sqrt(ratio);
  }
  Simulation<D> sim(p, surfaces_grid<D>(p), initial);
  sim.run(kInf, 5 * p.particles);
  SystemParams production = p;
  production.restitution = e;
  production.roughness.tangential_restitution = beta;
  sim.start_production(production);
  const double inertia = q * 0.25 * sigma * sigma;
  double mean_ratio = 0.0;
  const int samples = 36;
  for (int k = 0; k < samples; ++k) {
    const double c = 0.5 + 0.1 * k;
    sim.run(kInf, std::llround(c * static_cast<double>(p.particles)));
    const ParticleState s = sim.state();
    double rot = 0.0;
    for (int m = 0; m < s.spin_components(); ++m) {
      for (double w : s.spin(m)) rot += inertia * w * w;
    }
    mean_ratio += rot / (s.spin_components() * static_cast<double>(s.size())) / temperature_of(s) / samples;
  }
  return mean_ratio / ratio;
}

template <int D>
void check_cooling_state(double e, double beta) {
  constexpr int kRuns = 12;
  std::vector<double> runs;
  for (int k = 0; k < kRuns; ++k) runs.push_back(cooling_state_ratio_of_run<D>(e, beta, 41 + static_cast<std::uint64_t>(k)));
  double mean = 0.0, square = 0.0;
  for (const double r : runs) mean += r / kRuns;
  for (const double r : runs) square += (r - mean) * (r - mean) / (kRuns - 1);
  std::printf("[%dD e=%.2f β=%+.2f] mean T_rot/T_tr over c = 0.5 … 4 / the theory's cooling state: %.4f ± %.4f (%d runs)\n",
              D, e, beta, mean, std::sqrt(square / kRuns), kRuns);
  EXPECT_NEAR(mean, 1.0, 0.04);
}

TEST(SurfacesPhysics, RoughDisksKeepTheCoolingStateRatio) { check_cooling_state<2>(0.9, 0.0); }
TEST(SurfacesPhysics, RoughSpheresKeepTheCoolingStateRatio) { check_cooling_state<3>(0.8, -0.4); }

TEST(SurfacesPhysics, RoughDisksCoolAsKineticTheorySays) {
  check_rough_cooling<2>(0.9, -0.4);
  check_rough_cooling<2>(0.95, 0.5);
}
TEST(SurfacesPhysics, RoughSpheresCoolAsKineticTheorySays) {
  check_rough_cooling<3>(0.9, -0.4);
  check_rough_cooling<3>(0.8, 0.5);
}

}  // namespace
}  // namespace granule
