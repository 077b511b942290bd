// The engine renumbers its particles along the cells for speed (SystemParams::renumber_every);
// everything it hands out is by the user's id, and what happens does not depend on the numbering:
// the same collisions (partners, times, impulses, images), the same wall hits and boundary
// crossings, the same sizes, masses and TC history by id, a checkpoint that continues the same run
// and one that is refused when its numbering is damaged.  (The golden tier checks final states of
// every kind of run with and without renumbering, tests/golden.)
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>
#include <vector>

#include "init/particle_sizes.hpp"
#include "validation/simulation_setup.hpp"
#include "validation/surfaces_setup.hpp"

namespace granule {
namespace {

// Every event an observer sees, by user id, bit for bit.
template <int D>
struct Recorder final : EventObserver<D> {
  std::vector<std::tuple<double, std::int32_t, std::int32_t, double, int>> collisions;
  std::vector<std::tuple<double, std::int32_t, int, double>> crossings;
  std::vector<std::tuple<double, std::int32_t, int, int, double>> wall_hits;
  void on_collision(const CollisionRecord<D>& r) override {
    collisions.emplace_back(r.time, r.first, r.second, r.impulse, r.image_y);
  }
  void on_boundary_crossing(const BoundaryCrossingRecord& r) override {
    crossings.emplace_back(r.time, r.particle, r.direction, r.velocity_x_after);
  }
  void on_surface_hit(const SurfaceHitRecord<D>& r) override {
    if (!r.surface.wall()) return;
    wall_hits.emplace_back(r.time, r.particle, r.surface.axis(), r.surface.side(), r.energy_change);
  }
};

// A sheared bidisperse gas with the TC model, its engine renumbering every `every` events per particle.
Simulation<2> sheared_mixture(double every) {
  SystemParams p = make_system(800, 0.3, 0.8, 5.0);
  p.tc_duration = 1e-5;
  p.renumber_every = every;
  ParticleSizes sizes;
  for (int i = 0; i < p.particles; ++i) {  // the larger half first, the order of placement
    const bool large = i < p.particles / 2;
    sizes.diameter.push_back(large ? p.diameter : 0.7 * p.diameter);
    sizes.mass.push_back(large ? 1.0 : 0.49);
  }
  const auto grid = choose_cell_grid({p.length_x, p.length_y, p.diameter, p.particles, true, 0.6, std::nullopt});
  const auto init = make_initial_state(p, 1.0, 17, Placement::kAuto, std::nullopt, sizes);
  EXPECT_TRUE(init.error.empty()) << init.error;
  Simulation<2> sim(p, *grid.grid, init.state);
  sim.start_production(p.restitution);
  return sim;
}

TEST(Renumbering, ObserversSeeTheSameEventsByUserId) {
  Simulation<2> never = sheared_mixture(0.0);
  Simulation<2> often = sheared_mixture(1.0);
  Recorder<2> a, b;
  never.add_observer(&a);
  often.add_observer(&b);
  const std::int64_t target = 40 * 800;
  ASSERT_EQ(never.run(kInf, target), StopReason::kCollisionsReached);
  ASSERT_EQ(often.run(kInf, target), StopReason::kCollisionsReached);
  EXPECT_EQ(never.renumberings(), 0);
  EXPECT_GE(often.renumberings(), 50);
  ASSERT_EQ(a.collisions.size(), static_cast<std::size_t>(target));
  EXPECT_TRUE(a.collisions == b.collisions) << "the collisions differ";
  EXPECT_GT(a.crossings.size(), 100u);
  EXPECT_TRUE(a.crossings == b.crossings) << "the crossings of the sheared boundary differ";
  EXPECT_EQ(never.diameters(), often.diameters());
  EXPECT_EQ(never.masses(), often.masses());
  EXPECT_EQ(never.clock_state().last_collision, often.clock_state().last_collision);
  // The ids handed out are the user's: the sizes by id are those the run was given.
  const std::vector<double> diameters = often.diameters();
  for (std::size_t i = 0; i < diameters.size(); ++i) {
    ASSERT_EQ(diameters[i], i < 400 ? often.params().diameter : 0.7 * often.params().diameter) << i;
  }
}

// Rough spheres between walls under gravity: wall hits, by user id, are the same too.
TEST(Renumbering, WallHitsOfRoughSpheresUnderGravityAreTheSame) {
  const auto run = [](double every) {
    SystemParams p = surfaces_system<3>({8, 8, 8}, {1.0, 1.0, 1.0}, 0.06, 0.9);
    add_walls(p, 1, 0.9, 0.3);
    make_rough(p, 0.4, 0.4);
    p.gravity[1] = -1.0;
    p.tc_duration = 1e-5;  // against inelastic collapse on the floor
    p.renumber_every = every;
    Simulation<3> sim(p, surfaces_grid<3>(p, 0.6), lattice_gas<3>(p, {8, 8, 8}, 1.0, 4));
    sim.start_production(p);
    Recorder<3> recorder;
    sim.add_observer(&recorder);
    EXPECT_EQ(sim.run(kInf, 30 * p.particles), StopReason::kCollisionsReached);
    return std::make_tuple(recorder, sim.renumberings(), sim.state().wx);
  };
  const auto [never, none, spins_never] = run(0.0);
  const auto [often, some, spins_often] = run(1.0);
  EXPECT_EQ(none, 0);
  EXPECT_GE(some, 30);
  EXPECT_GT(never.wall_hits.size(), 1000u);
  EXPECT_TRUE(never.wall_hits == often.wall_hits) << "the wall hits differ";
  EXPECT_TRUE(never.collisions == often.collisions) << "the collisions differ";
  EXPECT_EQ(spins_never, spins_often);
}

TEST(Renumbering, ACheckpointHoldsTheNumberingAndADamagedOneIsRefused) {
  Simulation<2> sim = sheared_mixture(1.0);
  sim.run(kInf, 5 * 800);
  ASSERT_GT(sim.renumberings(), 0);
  StateArchive archive;
  sim.save(archive, "");
  auto ids = archive.get<std::int32_t>("particle_id");
  ASSERT_EQ(ids.size(), 800u);
  // A permutation, and not the identity after renumbering along the cells.
  std::vector<std::int32_t> sorted = ids;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], static_cast<std::int32_t>(i));
  EXPECT_NE(sorted, ids);
  ids[3] = ids[4];
  archive.put("particle_id", ids);
  try {
    Simulation<2>(sim.params(), sim.grid(), archive, "");
    ADD_FAILURE() << "a checkpoint with a particle id twice was accepted";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("particle_id"), std::string::npos) << error.what();
  }
}

// A checkpoint of an engine that never renumbered (every checkpoint written before renumbering
// existed) continues the same run in an engine that does.
TEST(Renumbering, ACheckpointWithoutNumberingContinuesTheSameRun) {
  Simulation<2> never = sheared_mixture(0.0);
  never.run(kInf, 3 * 800);
  StateArchive archive;
  never.save(archive, "");
  ASSERT_FALSE(archive.contains("particle_id"));
  SystemParams renumbering = never.params();
  renumbering.renumber_every = 1.0;
  Simulation<2> restored(renumbering, never.grid(), archive, "");
  never.run(kInf, 30 * 800);
  restored.run(kInf, 30 * 800);
  EXPECT_GE(restored.renumberings(), 30);
  const ParticleState a = never.state(), b = restored.state();
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.vx, b.vx);
  EXPECT_EQ(a.vy, b.vy);
  EXPECT_EQ(never.time(), restored.time());
}

}  // namespace
}  // namespace granule
