// Exact laws of walls, gravity and spin, to round-off:
//  • a free grain under gravity follows its parabola through any number of cell crossings;
//  • a grain dropped on a floor of restitution e_w bounces at the times and speeds of the
//    geometric series (t₁ = √(2h/g), then flights 2 e_wᵏ g t₁ / g), and a moving rough floor
//    multiplies its slip by −β_w at each bounce;
//  • elastic grains (smooth, or rough with β = 1) between elastic smooth walls in gravity conserve
//    kinetic + rotational + potential energy, and the periodic components of momentum;
//  • in any run the state's momentum and energy change exactly by what the wall and collision
//    records say (the measured wall stress and heat input are the true ones);
//  • a grain coming to rest on a floor without the TC model is stopped as inelastic collapse, with
//    the TC model it micro-bounces and the run goes on.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "validation/same_engine.hpp"
#include "validation/surfaces_setup.hpp"

namespace granule {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

template <int D>
void check_free_parabola() {
  SystemParams p = one_grain_box<D>(0.01);
  Vec<D> g, r0, v0;
  for (int a = 0; a < D; ++a) {
    g[a] = -0.7 + 0.9 * a;
    r0[a] = 0.3 + 0.1 * a;
    v0[a] = 2.3 - 1.1 * a;
  }
  for (int a = 0; a < D; ++a) p.gravity[static_cast<std::size_t>(a)] = g[a];
  Simulation<D> sim = single_grain<D>(p, r0, v0);
  const double t_end = 3.7;
  sim.run(t_end, std::numeric_limits<std::int64_t>::max());
  ASSERT_GT(sim.events(), 150);  // many cell crossings, several box periods
  const ParticleState s = sim.state();
  for (int a = 0; a < D; ++a) {
    const double exact = r0[a] + v0[a] * t_end + 0.5 * g[a] * t_end * t_end;
    const double wrapped = exact - std::floor(exact);  // unit box
    EXPECT_NEAR(s.position(a)[0], wrapped, 1e-12) << "axis " << a;
    EXPECT_NEAR(s.velocity(a)[0], v0[a] + g[a] * t_end, 1e-13) << "axis " << a;
  }
}

TEST(GravityExact, AFreeDiskFollowsItsParabolaThroughEveryCellCrossing) { check_free_parabola<2>(); }
TEST(GravityExact, AFreeSphereFollowsItsParabolaThroughEveryCellCrossing) { check_free_parabola<3>(); }

template <int D>
void check_bounces(bool rough_grain) {
  SystemParams p = one_grain_box<D>(0.02, 2.0);
  const double e_w = 0.8, beta_w = 0.4, wall_speed = -0.3, g = 9.0;
  add_walls(p, 1, e_w, beta_w);
  p.wall[2].velocity[0] = wall_speed;  // the floor slides along x
  p.gravity[1] = -g;
  if (rough_grain) make_rough(p, -1.0, 0.5);
  Vec<D> r0, v0;
  r0[0] = 0.5;
  r0[1] = 1.51;
  if constexpr (D == 3) r0[2] = 0.5;
  v0[0] = 0.9;
  Simulation<D> sim = single_grain<D>(p, r0, v0);
  WallLog<D> log;
  sim.add_observer(&log);
  const double radius = 0.5 * p.diameter;
  const double t1 = std::sqrt(2.0 * (r0[1] - radius) / g);
  // Bounce k (k = 0, 1, …) at t_k = t1 + Σ_{j<k} 2 e_w^{j+1} g t1 / g, coming down at e_w^k g t1.
  const int bounces = 25;
  double horizon = t1;
  for (int k = 0; k < bounces - 1; ++k) horizon += 2.0 * std::pow(e_w, k + 1) * t1;
  sim.run(horizon + 0.5 * std::pow(e_w, bounces) * t1, std::numeric_limits<std::int64_t>::max());
  ASSERT_EQ(static_cast<int>(log.hits.size()), bounces);
  double t = t1;
  double slip = v0[0] - wall_speed;
  // A smooth grain meets the rough floor as a grain of infinite moment of inertia: its slip is
  // multiplied by −β_w; a rough disk (q = ½) by 1 − (1 + β_w) q/(1 + q) on its first bounce.
  for (int k = 0; k < bounces; ++k) {
    const SurfaceHitRecord<D>& hit = log.hits[static_cast<std::size_t>(k)];
    EXPECT_EQ(hit.surface.axis(), 1);
    EXPECT_EQ(hit.surface.side(), 0);
    EXPECT_NEAR(hit.time, t, 1e-12 * (1.0 + t)) << "bounce " << k;
    EXPECT_NEAR(hit.velocity_before[1], -std::pow(e_w, k) * g * t1, 1e-11) << "bounce " << k;
    EXPECT_NEAR(hit.velocity_after[1], std::pow(e_w, k + 1) * g * t1, 1e-11) << "bounce " << k;
    EXPECT_NEAR(hit.position[1], radius, 1e-12);
    if (!rough_grain) {
      EXPECT_NEAR(hit.velocity_before[0] - wall_speed, slip, 1e-13);
      slip *= -beta_w;
      EXPECT_NEAR(hit.velocity_after[0] - wall_speed, slip, 1e-13);
    } else if (k == 0) {
      const double q = 0.5;
      EXPECT_NEAR(hit.velocity_after[0] - wall_speed, slip * (1.0 - (1.0 + beta_w) * q / (1.0 + q)), 1e-13);
    }
    t += 2.0 * std::pow(e_w, k + 1) * t1;
  }
  sim.check_invariants();
}

TEST(WallsExact, ADiskDroppedOnASlidingRoughFloorBouncesAsTheGeometricSeries) { check_bounces<2>(false); }
TEST(WallsExact, ASphereDroppedOnASlidingRoughFloorBouncesAsTheGeometricSeries) { check_bounces<3>(false); }
TEST(WallsExact, ARoughDiskTakesUpSpinFromTheFloor) { check_bounces<2>(true); }

// 400 disks or 512 spheres in the unit box.
template <int D>
std::array<int, D> small_lattice() {
  std::array<int, D> per_axis;
  per_axis.fill(D == 2 ? 20 : 8);
  return per_axis;
}
template <int D>
std::array<double, D> unit_box() {
  std::array<double, D> box;
  box.fill(1.0);
  return box;
}

// Elastic grains (smooth, or perfectly rough) in a box with elastic smooth walls on y (and z in
// 3D), gravity tilted: kinetic + rotational + potential energy conserved to round-off; momentum
// along x (periodic, no wall, no gravity) conserved.
template <int D>
void check_conservation(bool rough) {
  const std::array<int, D> per_axis = small_lattice<D>();
  SystemParams p = surfaces_system<D>(per_axis, unit_box<D>(), D == 2 ? 0.02 : 0.05, 1.0);
  add_walls(p, 1, 1.0, -1.0);
  if constexpr (D == 3) add_walls(p, 2, 1.0, -1.0);
  p.gravity[1] = -2.0;  // along wall axes only: −m g·r is then a potential energy
  if constexpr (D == 3) p.gravity[2] = 0.5;
  if (rough) make_rough(p, 1.0, D == 2 ? 0.5 : 0.4);
  const ParticleState initial = lattice_gas<D>(p, per_axis, 1.0, 5);
  Simulation<D> sim(p, surfaces_grid<D>(p), initial);
  WallLog<D> log;
  sim.add_observer(&log);
  const double e0 = total_energy(p, sim.state());
  double px0 = 0.0;
  for (double v : initial.vx) px0 += v;
  for (int chunk = 1; chunk <= 4; ++chunk) {
    sim.run(kInf, static_cast<std::int64_t>(chunk * 10 * p.particles));  // 40 collisions per grain
    sim.check_invariants();
  }
  const ParticleState s = sim.state();
  double px = 0.0;
  for (double v : s.vx) px += v;
  EXPECT_NEAR(total_energy(p, s), e0, 1e-10 * std::abs(e0)) << "after " << sim.collisions() << " collisions";
  EXPECT_NEAR(px, px0, 1e-10 * static_cast<double>(p.particles));
  EXPECT_GT(log.hits.size(), static_cast<std::size_t>(p.particles));
  std::printf("[%dD %s] %lld collisions, %zu wall hits, energy drift %.2e (relative)\n", D, rough ? "rough" : "smooth",
              static_cast<long long>(sim.collisions()), log.hits.size(), total_energy(p, s) / e0 - 1.0);
}

TEST(WallsExact, ElasticDisksInGravityBetweenWallsConserveEnergy) { check_conservation<2>(false); }
TEST(WallsExact, ElasticSpheresInGravityBetweenWallsConserveEnergy) { check_conservation<3>(false); }
TEST(WallsExact, PerfectlyRoughElasticDisksConserveTranslationalPlusRotationalEnergy) { check_conservation<2>(true); }
TEST(WallsExact, PerfectlyRoughElasticSpheresConserveTranslationalPlusRotationalEnergy) { check_conservation<3>(true); }

// Inelastic rough grains between moving rough inelastic walls (a wall-driven Couette flow): the
// state's energy and momentum change by exactly the sums of the records.
template <int D>
void check_budgets() {
  const std::array<int, D> per_axis = small_lattice<D>();
  SystemParams p = surfaces_system<D>(per_axis, unit_box<D>(), D == 2 ? 0.02 : 0.05, 0.9);
  add_walls(p, 1, 0.8, -0.8);
  p.wall[2].velocity[0] = -1.0;
  p.wall[3].velocity[0] = 1.0;
  make_rough(p, -0.5, D == 2 ? 0.5 : 0.4, 0.3);
  // A cold gas (T = 0.01 against walls moving at ±1): the walls must heat it.
  const ParticleState initial = lattice_gas<D>(p, per_axis, 0.01, 9);
  Simulation<D> sim(p, surfaces_grid<D>(p), initial);
  WallLog<D> log;
  log.rough = true;
  sim.add_observer(&log);
  const double e0 = total_energy(p, sim.state());
  sim.run(kInf, 30 * p.particles);
  const ParticleState s = sim.state();
  const double e1 = total_energy(p, s);
  EXPECT_NEAR(e1 - e0, log.wall_energy + log.collision_energy, 1e-12 * log.magnitude);
  for (int a = 0; a < D; ++a) {
    double p0 = 0.0, p1 = 0.0;
    for (double v : initial.velocity(a)) p0 += v;
    for (double v : s.velocity(a)) p1 += v;
    EXPECT_NEAR(p1 - p0, -log.impulse_on_walls[a], 1e-10 * static_cast<double>(p.particles)) << "axis " << a;
  }
  EXPECT_GT(log.wall_energy, 0.0);
  sim.check_invariants();
  std::printf("[%dD] wall work %.4g, collisional loss %.4g, %zu wall hits\n", D, log.wall_energy, -log.collision_energy,
              log.hits.size());
}

TEST(WallsExact, WallDrivenRoughDisksChangeEnergyAndMomentumExactlyAsTheRecordsSay) { check_budgets<2>(); }
TEST(WallsExact, WallDrivenRoughSpheresChangeEnergyAndMomentumExactlyAsTheRecordsSay) { check_budgets<3>(); }

TEST(WallsExact, AGrainComingToRestOnAFloorIsCollapseWithoutTcAndMicroBouncesWithIt) {
  for (const double tc : {0.0, 1e-4}) {
    SystemParams p = one_grain_box<2>(0.02);
    add_walls(p, 1, 0.5, -1.0);
    p.gravity[1] = -10.0;
    p.tc_duration = tc;
    Simulation<2> sim = single_grain<2>(p, {0.5, 0.3}, {0.0, 0.0});
    WallLog<2> log;
    sim.add_observer(&log);
    const StopReason reason = sim.run(1.0, std::numeric_limits<std::int64_t>::max());
    if (tc == 0.0) {
      EXPECT_EQ(reason, StopReason::kInelasticCollapse);
      EXPECT_EQ(sim.collapse().second, -1);  // at a wall
    } else {
      EXPECT_EQ(reason, StopReason::kTimeReached);
      // At rest within the TC window: flights of ≈ t_c, i.e. speeds ≈ g t_c / 2.
      EXPECT_LT(std::abs(sim.state().vy[0]), 10.0 * 1e-4);
      sim.check_invariants();
    }
  }
}

}  // namespace
}  // namespace granule

namespace granule {
namespace {

// A checkpoint of a run with rough grains, moving walls and gravity continues it bit for bit:
// the engine restored from the archive, run on, saves exactly the archive of the uninterrupted run
// (≥ 30 collisions per grain after the save, past several clock re-bases).
template <int D>
void check_exact_continuation() {
  const std::array<int, D> per_axis = small_lattice<D>();
  SystemParams p = surfaces_system<D>(per_axis, unit_box<D>(), D == 2 ? 0.02 : 0.05, 0.9);
  add_walls(p, 1, 0.8, 0.3);
  p.wall[2].velocity[0] = -1.0;
  p.wall[3].velocity[0] = 1.0;
  p.gravity[1] = -1.0;
  p.tc_duration = 1e-5;
  make_rough(p, 0.4, D == 2 ? 0.5 : 0.4, 0.5);
  const CellGrid grid = surfaces_grid<D>(p);
  Simulation<D> straight(p, grid, lattice_gas<D>(p, per_axis, 1.0, 13));
  straight.run(kInf, 10 * p.particles);
  StateArchive saved;
  straight.save(saved, "");
  Simulation<D> restored(p, grid, saved, "");
  straight.run(kInf, 45 * p.particles);
  restored.run(kInf, 45 * p.particles);
  expect_same_engine(straight, restored);
  EXPECT_TRUE(saved.contains("spin_z"));
  EXPECT_TRUE(saved.contains("wall_2_restitution"));
}

TEST(WallsExact, ARoughWalledRunInGravityContinuesFromItsCheckpointBitForBit2D) { check_exact_continuation<2>(); }
TEST(WallsExact, ARoughWalledRunInGravityContinuesFromItsCheckpointBitForBit3D) { check_exact_continuation<3>(); }

}  // namespace
}  // namespace granule
