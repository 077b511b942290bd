// Walls that move, against results computed here independently of the engine:
//  • a grain on a floor vibrated as a sine, a triangle or bi-parabolically, under gravity: each bounce of the engine is where an
//    independent root search (dense sampling of the gap, then bisection) puts it, starting from the
//    engine's previous bounce, and leaves at u − e_w (v − u), u the floor's velocity then (the
//    bounce map of the vibrated bed, free of the chaos that amplifies round-off over many bounces);
//  • a vibrated inelastic gas (each shape): the energy changes by exactly the work the floor did plus what the
//    collisions took, the momentum by the walls' impulses plus gravity's, to round-off, and no
//    grain is ever in the moving floor (the engine's invariants at every stop);
//  • a floor raised by a schedule several cells into a gas (a piston): the same, with the floor's
//    exact position checked;
//  • walls sliding at ±U(t)/2 under the ramp and oscillation drives of Chapter 4: a grain leaving a
//    perfectly rough wall has v_x = 2 w(t) − v_x, w from the closed form of U(t);
//  • a dilute vibro-fluidised bed has the temperature and height of kinetic theory;
//  • a run with moving walls continues bit for bit from its checkpoint.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <vector>

#include "validation/same_engine.hpp"
#include "validation/surfaces_setup.hpp"

namespace granule {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::int64_t kNoCollisionLimit = std::numeric_limits<std::int64_t>::max();

// The floor's displacement h and velocity, written out here from the phase x of the cycle: the sine
// A (1 − cos 2πx); the triangle 4Ax up to ½ and 4A(1 − x) after; the bi-parabolic 16Ax² up to ¼,
// 8A(2x − 2x² − ¼) up to ¾ and 16A(1 − x)² after (arcs of acceleration ±32Af²).
struct Vibration {
  double amplitude, frequency;
  VibrationShape shape = VibrationShape::kSine;
  double phase(double t) const { return frequency * t - std::floor(frequency * t); }
  double h(double t) const {
    const double x = phase(t), a = amplitude;
    switch (shape) {
      case VibrationShape::kSine: return a * (1.0 - std::cos(2.0 * std::numbers::pi * frequency * t));
      case VibrationShape::kTriangle: return x < 0.5 ? 4.0 * a * x : 4.0 * a * (1.0 - x);
      default: return x < 0.25 ? 16.0 * a * x * x : x < 0.75 ? 8.0 * a * (2.0 * x - 2.0 * x * x - 0.25) : 16.0 * a * (1.0 - x) * (1.0 - x);
    }
  }
  double u(double t) const {
    const double x = phase(t), af = amplitude * frequency;
    switch (shape) {
      case VibrationShape::kSine: return 2.0 * std::numbers::pi * af * std::sin(2.0 * std::numbers::pi * frequency * t);
      case VibrationShape::kTriangle: return x < 0.5 ? 4.0 * af : -4.0 * af;
      default: return x < 0.25 ? 32.0 * af * x : x < 0.75 ? 16.0 * af * (1.0 - 2.0 * x) : 32.0 * af * (x - 1.0);
    }
  }
};

// The first time after t0 at which a grain leaving the floor at height y0 with velocity v0 (in
// gravity −g) meets it again: the gap sampled every `step` until it is negative, then bisected.
double next_landing(const Vibration& floor, double radius, double g, double t0, double y0, double v0, double step) {
  const auto gap = [&](double t) {
    const double s = t - t0;
    return y0 + v0 * s - 0.5 * g * s * s - radius - floor.h(t);
  };
  double a = t0 + 1e-9;
  double b = a;
  while (gap(b) >= 0.0) {
    a = b;
    b += step;
  }
  for (int k = 0; k < 200 && b - a > 1e-15 * b; ++k) {
    const double m = 0.5 * (a + b);
    (gap(m) >= 0.0 ? a : b) = m;
  }
  return 0.5 * (a + b);
}

// One grain at the middle of the unit box's x (and z), at height y with velocity (v_x, v_y),
// its walls' drives started (production from t = 0), watched by `log`.
template <int D>
Simulation<D> driven_grain(const SystemParams& p, double y, std::array<double, 2> velocity, WallLog<D>& log) {
  Vec<D> r0, v0;
  for (int a = 0; a < D; ++a) r0[a] = 0.5;
  r0[1] = y;
  v0[0] = velocity[0];
  v0[1] = velocity[1];
  Simulation<D> sim = single_grain<D>(p, r0, v0);
  sim.start_production(p);
  sim.add_observer(&log);
  return sim;
}

// Γ = (2πf)² A / g ≈ 2 for the sine, 32Af²/g ≈ 1.1 for the bi-parabolic: the grain is thrown every
// cycle or two, never as high as the lid.
template <int D>
void check_bounce_map(VibrationShape shape = VibrationShape::kSine) {
  SystemParams p = one_grain_box<D>(0.02, 1.0);
  p.renumber_every = 0.0;  // one grain in a fine grid: nothing to gain
  const double e_w = 0.85, g = 1.0;
  const Vibration floor{shape == VibrationShape::kBiparabolic ? 0.02 : 0.03, 1.3, shape};
  add_walls(p, 1, e_w, -1.0);
  p.gravity[1] = -g;
  p.wall[2].motion = {floor.amplitude, floor.frequency, {}, shape};
  const double y_start = 0.4, vx = 0.07;
  WallLog<D> log;
  Simulation<D> sim = driven_grain<D>(p, y_start, {vx, 0.0}, log);
  sim.run(40.0, kNoCollisionLimit);
  const double radius = 0.5 * p.diameter;
  ASSERT_GE(log.hits.size(), 30u);
  double t0 = 0.0, y0 = y_start, u0 = 0.0;
  const double step = 1e-4 / floor.frequency;
  for (std::size_t k = 0; k < log.hits.size(); ++k) {
    const SurfaceHitRecord<D>& hit = log.hits[k];
    ASSERT_EQ(hit.surface.axis() * 2 + hit.surface.side(), 2) << "bounce " << k;
    const double t = next_landing(floor, radius, g, t0, y0, u0, step);
    EXPECT_NEAR(hit.time, t, 1e-9) << "bounce " << k;
    EXPECT_NEAR(hit.position[1], radius + floor.h(hit.time), 1e-11) << "bounce " << k;
    EXPECT_NEAR(hit.velocity_before[1], u0 - g * (hit.time - t0), 1e-9) << "bounce " << k;
    const double u = floor.u(hit.time);
    EXPECT_NEAR(hit.velocity_after[1], u - e_w * (hit.velocity_before[1] - u), 1e-12) << "bounce " << k;
    EXPECT_NEAR(hit.velocity_after[0], vx, 1e-15) << "a smooth floor leaves v_x alone";
    t0 = hit.time;
    y0 = hit.position[1];
    u0 = hit.velocity_after[1];
  }
  sim.check_invariants();
  std::printf("[%dD, shape %d] %zu bounces on the vibrated floor, each where the independent search puts it\n", D,
              static_cast<int>(shape), log.hits.size());
}

TEST(MovingWalls, ADiskOnAVibratedFloorBouncesAsTheIndependentBounceMapSays) { check_bounce_map<2>(); }
TEST(MovingWalls, ASphereOnAVibratedFloorBouncesAsTheIndependentBounceMapSays) { check_bounce_map<3>(); }
TEST(MovingWalls, ADiskOnATriangleDrivenFloorBouncesAsTheIndependentBounceMapSays) {
  check_bounce_map<2>(VibrationShape::kTriangle);
}
TEST(MovingWalls, ADiskOnABiparabolicFloorBouncesAsTheIndependentBounceMapSays) {
  check_bounce_map<2>(VibrationShape::kBiparabolic);
}
TEST(MovingWalls, ASphereOnABiparabolicFloorBouncesAsTheIndependentBounceMapSays) {
  check_bounce_map<3>(VibrationShape::kBiparabolic);
}

// Σ m v over the grains along `axis`.
double momentum(const ParticleState& s, int axis) {
  double sum = 0.0;
  for (double v : s.velocity(axis)) sum += v;
  return sum;
}

// An inelastic gas in gravity on a moving floor: the budgets close to round-off, the invariants hold
// at every stop (no grain in the floor, wherever it is).
template <int D>
void check_driven_gas_budgets(const WallMotion& motion, int chunks, double collisions_per_chunk) {
  std::array<int, D> per_axis;
  per_axis.fill(D == 2 ? 16 : 6);
  per_axis[1] = D == 2 ? 12 : 8;
  std::array<double, D> box;
  box.fill(1.0);
  box[1] = 2.0;
  SystemParams p = surfaces_system<D>(per_axis, box, D == 2 ? 0.03 : 0.07, 0.9);
  add_walls(p, 1, 0.9, -1.0);
  p.gravity[1] = -1.0;
  p.tc_duration = 1e-5;
  p.wall[2].motion = motion;
  const ParticleState initial = lattice_gas<D>(p, per_axis, 0.2, 21);
  Simulation<D> sim(p, surfaces_grid<D>(p), initial);
  sim.start_production(p);
  WallLog<D> log;
  sim.add_observer(&log);
  const double e0 = total_energy(p, initial);
  const double radius = 0.5 * p.diameter;
  for (int chunk = 1; chunk <= chunks; ++chunk) {
    sim.run(kInf, static_cast<std::int64_t>(chunk * collisions_per_chunk * static_cast<double>(p.particles)));
    sim.check_invariants();
  }
  const ParticleState s = sim.state();
  const double t = sim.time();
  const double h = motion.velocity().integral(0.0, t);
  double lowest = kInf;
  for (double y : s.y) lowest = std::min(lowest, y - radius - h);
  EXPECT_GE(lowest, -1e-12) << "a grain below the floor";
  EXPECT_NEAR(total_energy(p, s) - e0, log.wall_energy + log.collision_energy, 1e-12 * log.magnitude);
  const auto n = static_cast<double>(p.particles);
  for (int a = 0; a < D; ++a) {
    const double gravity_impulse = n * p.gravity[static_cast<std::size_t>(a)] * t;
    EXPECT_NEAR(momentum(s, a) - momentum(initial, a), gravity_impulse - log.impulse_on_walls[a], 1e-10 * n) << "axis " << a;
  }
  EXPECT_GT(log.wall_energy, 0.0) << "the moving floor must do work on the gas";
  std::printf("[%dD] t = %.3g, h = %.4g: floor work %.4g, collisional loss %.4g, %zu wall hits, lowest gap %.2e\n", D, t,
              h, log.wall_energy, -log.collision_energy, log.hits.size(), lowest);
}

TEST(MovingWalls, AVibratedGasOfDisksKeepsExactBudgetsAndNeverEntersTheFloor) {
  check_driven_gas_budgets<2>({0.02, 3.0, {}}, 4, 10.0);
}
TEST(MovingWalls, AVibratedGasOfSpheresKeepsExactBudgetsAndNeverEntersTheFloor) {
  check_driven_gas_budgets<3>({0.04, 2.0, {}}, 3, 10.0);
}
TEST(MovingWalls, ABiparabolicallyVibratedGasKeepsExactBudgetsAndNeverEntersTheFloor) {
  check_driven_gas_budgets<2>({0.02, 3.0, {}, VibrationShape::kBiparabolic}, 4, 10.0);
}
TEST(MovingWalls, ATriangleDrivenGasKeepsExactBudgetsAndNeverEntersTheFloor) {
  check_driven_gas_budgets<2>({0.02, 3.0, {}, VibrationShape::kTriangle}, 4, 10.0);
}
// A piston: the floor rises 0.6 (several cells) in one time unit and stays there.
TEST(MovingWalls, AFloorRaisedByASchedulePushesTheGasUpWithExactBudgets) {
  check_driven_gas_budgets<2>({0.0, 0.0, {{0.0, 0.0}, {1.0, 0.6}}}, 4, 8.0);
}

// A dilute, nearly elastic gas of disks above a floor vibrating fast at a small amplitude, against
// the leading order of kinetic theory (Kumaran, J. Fluid Mech. 364, 163 (1998); McNamara & Luding,
// Phys. Rev. E 58, 813 (1998)), whose assumptions this case meets: an isothermal Maxwell–Boltzmann
// gas, n(y) = n₀ e^{−gy/T} (ε = 1 − ẽ² = 0.02 ≪ 1; ν ≤ 0.04 at the floor, χ ≈ 1); a floor velocity
// V = Aω sin φ small beside the thermal speed (V² ≪ T) and fast beside the flights (ω ≫ g/√T),
// so that grains meet it at phases spread evenly, weighted by their approach speed c + V.  An
// elastic floor then gives ½((2V + c)² − c²) per hit; averaged over φ and the Maxwellian flux
// n₀ √(T/2π), the input per unit length is 2 n₀ (Aω)² √(T/2π).  The collisions of 2D disks take
// (1 − ẽ²) √π σ n² T^{3/2} per unit area, ∫ n² dy = n₀² T/(2g), and n₀ = N g/(L_x T): the balance
// gives T = 2√2 (Aω)² L_x / (π (1 − ẽ²) N σ), and ⟨y⟩ − σ/2 = T/g.
TEST(MovingWalls, ADiluteVibrofluidisedBedHasTheTemperatureOfKineticTheory) {
  const std::array<int, 2> per_axis{50, 20};
  SystemParams p = surfaces_system<2>(per_axis, {10.0, 3.0}, 0.01, 0.99);
  add_walls(p, 1, 1.0, -1.0);
  p.gravity[1] = -1.0;
  const double speed = 0.07, frequency = 10.0;  // Aω and f: A = 0.11σ, a tenth of a flight's time per cycle
  p.wall[2].motion = {speed / (2.0 * std::numbers::pi * frequency), frequency, {}};
  Simulation<2> sim(p, surfaces_grid<2>(p), lattice_gas<2>(p, per_axis, 0.2, 31));
  sim.start_production(p);
  const auto n = static_cast<double>(p.particles);
  const double predicted = 2.0 * std::sqrt(2.0) * speed * speed * p.length_x /
                           (std::numbers::pi * (1.0 - p.restitution * p.restitution) * n * p.diameter);
  // Relaxed from the start by t = 200 (the cooling time 1/((1 − ẽ²)√π σ n₀ √T) is ≈ 25); then sampled
  // once per time unit.
  double temperature = 0.0, height = 0.0;
  int samples = 0;
  for (int t = 1; t <= 1200; ++t) {
    sim.run(static_cast<double>(t), kNoCollisionLimit);
    if (t <= 200) continue;
    const ParticleState s = sim.state();
    const double mean_x = momentum(s, 0) / n, mean_y = momentum(s, 1) / n;
    double sum = 0.0, heights = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      sum += (s.vx[i] - mean_x) * (s.vx[i] - mean_x) + (s.vy[i] - mean_y) * (s.vy[i] - mean_y);
      heights += s.y[i];
    }
    temperature += 0.5 * sum / n;
    height += heights / n - 0.5 * p.diameter;
    ++samples;
  }
  temperature /= samples;
  height /= samples;
  std::printf("vibrofluidised bed: T = %.4f against %.4f (ratio %.3f); <y> - σ/2 = %.4f against T/g = %.4f (ratio %.3f)\n",
              temperature, predicted, temperature / predicted, height, temperature, height / temperature);
  // The theory's next order is O(ε^{1/2}) ≈ 0.14 in the worst case; measured 2–3 %.
  EXPECT_NEAR(temperature / predicted, 1.0, 0.08);
  EXPECT_NEAR(height / temperature, 1.0, 0.08);
}

// U(t) of the drives, written out here: a ramp U₀ (1 − e^{−t/τ}) and U₀ + a sin(2πt/P).
template <int D>
void check_tangential_drive(const ShearHistory& history, double steady, const std::function<double(double)>& wall_speed) {
  SystemParams p = one_grain_box<D>(0.02, 1.0);
  p.renumber_every = 0.0;
  add_walls(p, 1, 1.0, 1.0);  // elastic and perfectly rough: a smooth grain leaves with 2 w − v_x
  p.wall[2].velocity[0] = -0.5 * steady;
  p.wall[3].velocity[0] = 0.5 * steady;
  p.wall[2].along = scaled(history, -0.5);
  p.wall[3].along = scaled(history, 0.5);
  WallLog<D> log;
  Simulation<D> sim = driven_grain<D>(p, 0.5, {0.2, 3.1}, log);
  sim.run(12.0, kNoCollisionLimit);
  ASSERT_GE(log.hits.size(), 30u);
  for (const SurfaceHitRecord<D>& hit : log.hits) {
    const double w = (hit.surface.side() == 0 ? -0.5 : 0.5) * wall_speed(hit.time);
    EXPECT_NEAR(hit.velocity_after[0], 2.0 * w - hit.velocity_before[0], 1e-13) << "t = " << hit.time;
    EXPECT_NEAR(std::abs(hit.velocity_after[1]), 3.1, 1e-13);
  }
}

TEST(MovingWalls, WallsRampedAsInChapter4MoveAtHalfTheRampsVelocity) {
  ShearHistory ramp;
  ramp.ramp_time = 1.5;
  check_tangential_drive<2>(ramp, 2.0, [](double t) { return 2.0 * (1.0 - std::exp(-t / 1.5)); });
}
TEST(MovingWalls, WallsOscillatedAsInChapter4MoveAtHalfTheOscillatingVelocity) {
  ShearHistory kick;
  kick.oscillation = ShearOscillation{0.7, 0.8, 1.0, 3.0};
  check_tangential_drive<3>(kick, 2.0, [](double t) {
    return 2.0 + (t >= 1.0 && t <= 3.4 ? 0.7 * std::sin(2.0 * std::numbers::pi * (t - 1.0) / 0.8) : 0.0);
  });
}

// A run with a vibrated floor and oscillating side walls continues from its checkpoint bit for bit
// (≥ 30 collisions per grain after the save, past several re-bases).
TEST(MovingWalls, AVibratedRunContinuesFromItsCheckpointBitForBit) {
  const std::array<int, 2> per_axis{16, 12};
  SystemParams p = surfaces_system<2>(per_axis, {1.0, 2.0}, 0.03, 0.9);
  add_walls(p, 1, 0.9, 0.3);
  p.gravity[1] = -1.0;
  p.tc_duration = 1e-5;
  p.wall[2].motion = {0.02, 3.0, {}};
  p.wall[3].velocity[0] = 0.5;
  p.wall[3].along.oscillation = ShearOscillation{0.2, 0.5, 0.0, 100.0};
  const CellGrid grid = surfaces_grid<2>(p);
  Simulation<2> straight(p, grid, lattice_gas<2>(p, per_axis, 0.2, 17));
  straight.start_production(p);
  straight.run(kInf, 10 * p.particles);
  StateArchive saved;
  straight.save(saved, "");
  Simulation<2> restored(p, grid, saved, "");
  straight.run(kInf, 45 * p.particles);
  restored.run(kInf, 45 * p.particles);
  expect_same_engine(straight, restored);
  // A configuration whose floor vibrates otherwise cannot take the checkpoint over.
  SystemParams other = p;
  other.wall[2].motion.frequency = 2.0;
  EXPECT_THROW(Simulation<2>(other, grid, saved, ""), std::runtime_error);
}

}  // namespace
}  // namespace granule
