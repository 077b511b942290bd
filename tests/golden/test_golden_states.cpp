// Golden tier: the final state of a few fixed-seed runs, hashed bit for bit.  Any change that
// alters a trajectory — physics, round-off, initial state, random numbers, event order — changes a
// hash here and must be deliberate: then update the constants below in the same commit and say
// why in its message.  The hash covers the whole engine (every array of its checkpoint), so it is
// also the check that the same seed gives the same trajectory on another machine or compiler
// (README, "Same seed, same trajectory").
#include <gtest/gtest.h>

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "cells/cell_grid.hpp"
#include "engine/simulation.hpp"
#include "init/initial_state.hpp"
#include "init/particle_sizes.hpp"

namespace granule {
namespace {

// FNV-1a over bytes.
struct Fnv1a {
  std::uint64_t hash = 14695981039346656037ULL;
  void mix(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < size; ++k) hash = (hash ^ bytes[k]) * 1099511628211ULL;
  }
  template <typename T>
  void mix(const std::vector<T>& values) { mix(values.data(), values.size() * sizeof(T)); }
};

// Every entry of the archive, in name order.
std::uint64_t hash_of(const StateArchive& archive) {
  Fnv1a h;
  for (const auto& [name, values] : archive.arrays()) {
    h.mix(name.data(), name.size());
    std::visit([&](const auto& v) { h.mix(v.data(), v.size() * sizeof(v[0])); }, values);
  }
  return h.hash;
}

// What a user of the engine sees: the state by particle id, the clock and the counters.
template <int D>
std::uint64_t hash_of_state(const Simulation<D>& sim) {
  Fnv1a h;
  const ParticleState s = sim.state();
  for (const auto* values : {&s.x, &s.y, &s.z, &s.vx, &s.vy, &s.vz, &s.diameter, &s.mass, &s.wx, &s.wy, &s.wz}) h.mix(*values);
  const ClockState clock = sim.clock_state();
  for (const double t : {clock.time, clock.strain_reference, clock.strain_at_reference}) h.mix(&t, sizeof t);
  h.mix(clock.last_collision);
  for (const std::int64_t n : {clock.collisions, clock.events}) h.mix(&n, sizeof n);
  return h.hash;
}

struct GoldenRun {
  std::uint64_t checkpoint_hash;  // the whole engine, in its own numbering
  std::uint64_t state_hash;       // what the user sees (hash_of_state)
  std::int64_t renumberings;
};

struct GoldenCase {
  const char* name;
  int particles;
  double area_fraction, restitution, shear_velocity, tc_duration, collisions_per_particle;
  std::uint64_t seed;
  std::uint64_t expected;
  // A ramp with a sinusoidal kick (thesis §4.3) from production on: of the Lees–Edwards images, or
  // of the walls of a wall-driven shear.
  bool protocol = false;
  int dimension = 2;      // area_fraction is then the packing fraction
  double size_ratio = 1.0;                // ≠ 1: a binary mixture, half of the grains this much larger
  double tangential_restitution = -1.0;   // > −1: rough grains (β), with spin
  // Flat walls instead of images on some axes, and what they and a uniform gravity add.
  struct Surfaces {
    std::array<bool, 3> walls{};
    std::array<double, 3> gravity{};
    double wall_restitution = 1.0;
    double wall_tangential_restitution = -1.0;  // > −1: rough walls
    double wall_velocity = 0.0;                 // y walls moving along x at ∓U/2 (a wall-driven shear)
    double floor_amplitude = 0.0, floor_frequency = 0.0;  // A > 0: the floor y0 vibrates (WallMotion)
    VibrationShape floor_shape = VibrationShape::kSine;
  } surfaces{};
  RestitutionLaw speed_law{};  // how ẽ (and e_w) depend on the impact speed in production
  std::vector<Obstacle> obstacles{};  // fixed obstacles, with their production restitutions
};

// The run of a case, its engine renumbering its particles every `renumber_every` events per
// particle (0: never, the engine of the constants below).
template <int D>
GoldenRun final_state(const GoldenCase& k, double renumber_every) {
  SystemParams p;
  p.renumber_every = renumber_every;
  p.dimension = D;
  p.particles = k.particles;
  p.restitution = 1.0;
  p.shear_velocity = k.shear_velocity;
  p.tc_duration = k.tc_duration;
  const double unit_ball = D == 3 ? M_PI / 6.0 : M_PI / 4.0;
  const double half = 0.5 * k.particles;
  const double small = std::pow(k.area_fraction / (unit_ball * (half + half * std::pow(k.size_ratio, D))), 1.0 / D);
  p.diameter = std::max(small, k.size_ratio * small);
  ParticleSizes sizes;
  if (k.size_ratio != 1.0) {
    for (int i = 0; i < k.particles; ++i) {  // largest first, the order of placement
      const bool large = i < k.particles / 2;
      sizes.diameter.push_back(large ? k.size_ratio * small : small);
      sizes.mass.push_back(large ? std::pow(k.size_ratio, D) : 1.0);
    }
  }
  if (k.tangential_restitution > -1.0) {
    p.roughness.rough = true;
    p.roughness.inertia_factor = D == 3 ? 0.4 : 0.5;
  }
  p.walls = k.surfaces.walls;
  p.gravity = k.surfaces.gravity;
  for (std::size_t face = 0; face < p.wall.size(); ++face) {
    if (!p.walls[face / 2]) continue;
    p.wall[face].restitution = k.surfaces.wall_restitution;
    p.wall[face].tangential_restitution = k.surfaces.wall_tangential_restitution;
  }
  p.wall[2].velocity[0] = -0.5 * k.surfaces.wall_velocity;
  p.wall[3].velocity[0] = 0.5 * k.surfaces.wall_velocity;
  p.wall[2].motion = {k.surfaces.floor_amplitude, k.surfaces.floor_frequency, {}, k.surfaces.floor_shape};
  p.obstacles = k.obstacles;
  if (k.protocol) {
    const double u0 = p.walls[1] ? k.surfaces.wall_velocity : k.shear_velocity;
    ShearHistory history;
    history.ramp_time = 0.05;
    history.oscillation = ShearOscillation{0.3 * u0, 0.02, 0.05, 5.0};
    if (p.walls[1]) {
      p.wall[2].along = scaled(history, -0.5);
      p.wall[3].along = scaled(history, 0.5);
    } else {
      p.shear_history = history;
    }
  }
  CellGridRequest request{1.0, 1.0, p.diameter, p.particles, k.shear_velocity != 0.0, 1.0, std::nullopt};
  request.dimension = D;
  request.length_z = p.length_z;
  const auto grid = choose_cell_grid(request);
  EXPECT_TRUE(grid.grid) << grid.error;
  const auto init = make_initial_state(p, 1.0, k.seed, Placement::kAuto, std::nullopt, sizes);
  EXPECT_TRUE(init.error.empty()) << init.error;
  if (!grid.grid || !init.error.empty()) return {};
  Simulation<D> sim(elastic_prerun(p), *grid.grid, init.state);
  // As granule run does: an elastic pre-run, then the restitutions switched on.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  sim.run(kInf, 2L * k.particles);
  SystemParams production = p;
  production.restitution = k.restitution;
  production.roughness.tangential_restitution = k.tangential_restitution;
  production.restitution_law = k.speed_law;
  production.restitution_law.reference_radius = 0.5 * p.diameter;
  sim.start_production(production);
  const auto target = std::llround(k.collisions_per_particle * static_cast<double>(k.particles));
  EXPECT_EQ(sim.run(kInf, target), StopReason::kCollisionsReached);
  StateArchive archive;
  sim.save(archive, "");
  const std::uint64_t hash = hash_of(archive);
  std::printf("%s (renumbered every %g events per particle, %lld times): t = %.17g, events %lld, hash 0x%016" PRIx64 "\n",
              k.name, renumber_every, static_cast<long long>(sim.renumberings()), sim.time(), static_cast<long long>(sim.events()), hash);
  return {hash, hash_of_state(sim), sim.renumberings()};
}

GoldenRun final_state(const GoldenCase& k, double renumber_every) {
  return k.dimension == 3 ? final_state<3>(k, renumber_every) : final_state<2>(k, renumber_every);
}

class GoldenState : public ::testing::TestWithParam<GoldenCase> {};

// The engine that never renumbers its particles, bit for bit (its checkpoint is in user ids).
TEST_P(GoldenState, FinalStateHashIsUnchanged) {
  const GoldenCase k = GetParam();
  const std::uint64_t hash = final_state(k, 0.0).checkpoint_hash;
  EXPECT_EQ(hash, k.expected) << k.name << ": the trajectory changed (new hash 0x" << std::hex << hash << ")";
}

// Renumbering the particles along the cells (SystemParams::renumber_every) is a matter of memory
// order only: every case ends in the same state, bit for bit, by particle id, renumbered by
// default, at every event per particle, or never (past ≥ 30 collisions per particle and every
// re-base: 12 to 60 renumberings).
TEST_P(GoldenState, RenumberingLeavesTheTrajectoryUnchanged) {
  const GoldenCase k = GetParam();
  const GoldenRun never = final_state(k, 0.0);
  EXPECT_EQ(never.renumberings, 0);
  for (const double every : {kDefaultRenumberEvery, 1.0}) {
    const GoldenRun renumbered = final_state(k, every);
    EXPECT_GE(renumbered.renumberings, 10) << k.name;
    EXPECT_EQ(renumbered.state_hash, never.state_hash) << k.name << ": renumbering every " << every << " events per particle changed the run";
    EXPECT_NE(renumbered.checkpoint_hash, never.checkpoint_hash) << k.name << ": the engine's own order should have changed";
  }
}

INSTANTIATE_TEST_SUITE_P(
    Runs, GoldenState,
    ::testing::Values(GoldenCase{"free_cooling_tc", 2000, 0.05, 0.6, 0.0, 1e-7, 40.0, 1995, 0xed133ef0ca755353ULL},
                      GoldenCase{"lees_edwards_tc", 1500, 0.2, 0.8, 30.0, 1e-6, 40.0, 7, 0xe80eef488a67016cULL},
                      GoldenCase{"dense_elastic", 1200, 0.6, 1.0, 0.0, 0.0, 30.0, 3, 0x2516cc9840f1bf74ULL},
                      GoldenCase{"lees_edwards_protocol", 1500, 0.1, 0.7, 20.0, 1e-6, 40.0, 12, 0x4e880934045bdb47ULL, true},
                      // Spheres, a mixture of sizes, and rough grains with spin.
                      GoldenCase{"spheres_free_cooling_tc", 2000, 0.25, 0.8, 0.0, 1e-7, 30.0, 5, 0x580ce40736128058ULL, false, 3},
                      GoldenCase{"spheres_lees_edwards", 1500, 0.3, 0.9, 10.0, 1e-6, 30.0, 8, 0x0aaef081d0396e11ULL, false, 3},
                      GoldenCase{"spheres_bidisperse", 2000, 0.3, 0.9, 0.0, 1e-7, 30.0, 9, 0xcecba8abc3332889ULL, false, 3, 1.4},
                      GoldenCase{"rough_disks_shear", 1500, 0.3, 0.9, 20.0, 1e-6, 30.0, 10, 0xfc3df997c070cd9dULL, false, 2, 1.0, 0.5},
                      GoldenCase{"rough_spheres", 1500, 0.25, 0.9, 0.0, 1e-7, 30.0, 11, 0x646e4d9b927da56bULL, false, 3, 1.0, 0.3},
                      // Enough disks for the engine to prefetch records one event ahead
                      // (Simulation::kPrefetchRecordsFrom): a hint that must change nothing.
                      GoldenCase{"many_disks_free_cooling_tc", 66000, 0.05, 0.9, 0.0, 1e-7, 30.0, 17, 0xb07854f10a82be41ULL},
                      // Walls, gravity and rough walls: a closed box under gravity, a wall-driven
                      // shear of rough disks between rough walls, rough spheres on a rough floor.
                      GoldenCase{"disks_box_gravity_tc", 1500, 0.1, 0.95, 0.0, 1e-6, 30.0, 21, 0x9575a6888bcdae90ULL, false, 2, 1.0, -1.0,
                                 {{true, true, false}, {0.0, -0.5, 0.0}, 0.9}},
                      GoldenCase{"rough_disks_rough_walls_couette", 1500, 0.2, 0.9, 0.0, 1e-6, 30.0, 22, 0x74625fb342789f1bULL, false, 2, 1.0, 0.4,
                                 {{false, true, false}, {}, 0.9, 0.5, 5.0}},
                      GoldenCase{"rough_spheres_rough_floor_gravity", 1500, 0.2, 0.9, 0.0, 1e-7, 30.0, 23, 0xbe4693e8c492598cULL, false, 3, 1.0, 0.3,
                                 {{false, false, true}, {0.0, 0.0, -0.5}, 0.9, 0.2}},
                      // Restitution that depends on the impact speed: a viscoelastic mixture of
                      // disks on a floor under gravity (pairs and walls, other radii and masses),
                      // and spheres elastic below a threshold speed, with the TC model.
                      GoldenCase{"viscoelastic_disks_mixture_floor", 1500, 0.15, 1.0, 0.0, 0.0, 30.0, 31, 0xa8ad8b8001e193e0ULL, false, 2, 1.4, -1.0,
                                 {{false, true, false}, {0.0, -0.5, 0.0}, 1.0}, {RestitutionKind::kViscoelastic, 0.0, 0.1}},
                      GoldenCase{"threshold_spheres_tc", 1500, 0.2, 0.7, 0.0, 1e-7, 30.0, 32, 0xe2e959434348f31fULL, false, 3, 1.0, -1.0, {},
                                 {RestitutionKind::kThreshold, 0.3}},
                      // Walls that move: a vibrated floor under gravity (Γ ≈ 3.6), and rough
                      // spheres sheared by walls ramped and kicked as in Chapter 4.
                      GoldenCase{"vibrated_floor_disks_tc", 1500, 0.15, 0.9, 0.0, 1e-6, 30.0, 41, 0xcd41943094150aaaULL, false, 2, 1.0, -1.0,
                                 {{false, true, false}, {0.0, -1.0, 0.0}, 0.9, -1.0, 0.0, 0.01, 3.0}},
                      // Spheres on a floor vibrated in parabolic arcs (32Af² ≈ 2 g).
                      GoldenCase{"biparabolic_floor_spheres_tc", 1500, 0.15, 0.9, 0.0, 1e-6, 30.0, 44, 0x79f8d794141cdc4bULL, false, 3, 1.0, -1.0,
                                 {{false, true, false}, {0.0, -1.0, 0.0}, 0.9, -1.0, 0.0, 0.005, 3.5, VibrationShape::kBiparabolic}},
                      GoldenCase{"driven_walls_rough_spheres", 1500, 0.2, 0.9, 0.0, 1e-6, 30.0, 42, 0xe3d3b50856b01b20ULL, true, 3, 1.0, 0.4,
                                 {{false, true, false}, {}, 0.9, 0.3, 4.0}},
                      // A flow past obstacles: gravity along x between y walls, three obstacles
                      // (rough, smooth, and one seen through the periodic x face).
                      GoldenCase{"flow_past_obstacles_tc", 1500, 0.15, 0.9, 0.0, 1e-6, 30.0, 43, 0x3478975f24b705c4ULL, false, 2, 1.0, -1.0,
                                 {{false, true, false}, {0.5, 0.0, 0.0}, 0.9, 0.2}, {},
                                 {{{0.3, 0.5, 0.0}, 0.15, 0.8, 0.3}, {{0.7, 0.2, 0.0}, 0.1, 0.9, -1.0}, {{0.0, 0.8, 0.0}, 0.12, 1.0, -1.0}}}),
    [](const ::testing::TestParamInfo<GoldenCase>& run) { return std::string(run.param.name); });

}  // namespace
}  // namespace granule
