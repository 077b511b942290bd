// The trajectory of a seed is a property of the physics, not of how the run is driven: stopping
// run() anywhere, reading the state, attaching observers, or saving the engine and continuing in
// a new one restored from the checkpoint changes no bit.  Checked under Lees–Edwards with the TC
// model over ≥ 30 collisions per particle and ≥ 100 N events, so that every periodic action
// (clock re-base every 16 N events, grid realignment) happens many times on the way; once with a
// constant drive and once under a shear protocol (a ramp with a sinusoidal kick, thesis §4.3),
// whose changes of U are global actions too.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "validation/simulation_setup.hpp"
#include "validation/same_engine.hpp"

namespace granule {
namespace {

class ExactContinuation : public ::testing::TestWithParam<bool> {
 protected:
  // GetParam(): driven by a protocol.
  SystemParams sheared_tc_system() const {
    SystemParams p = make_system(500, 0.25, 0.8, 4.0);
    p.tc_duration = 1e-5;
    if (GetParam()) {
      p.shear_history.ramp_time = 0.02;
      p.shear_history.oscillation = ShearOscillation{1.5, 0.013, 0.01, 1e6};
      p.shear_history.tolerance = 1e-2;
    }
    return p;
  }
  // In production from the start, so that the protocol runs.
  Simulation<2> make_driven(const SystemParams& p, std::uint64_t seed) const {
    Simulation<2> sim = make_simulation(p, seed);
    sim.start_production(p.restitution);
    return sim;
  }
};

struct Counter final : EventObserver<2> {
  std::int64_t collisions = 0, crossings = 0;
  void on_collision(const CollisionRecord<2>&) override { ++collisions; }
  void on_boundary_crossing(const BoundaryCrossingRecord&) override { ++crossings; }
};

constexpr double kSpan = 120.0;  // collisions per particle

TEST_P(ExactContinuation, SameSeedSameTrajectory) {
  const SystemParams p = sheared_tc_system();
  Simulation<2> a = make_driven(p, 99);
  Simulation<2> b = make_driven(p, 99);
  a.run(kInf, collisions_for(p, kSpan));
  b.run(kInf, collisions_for(p, kSpan));
  expect_same_engine(a, b);
}

TEST_P(ExactContinuation, StopsReadsAndObserversChangeNothing) {
  const SystemParams p = sheared_tc_system();
  Simulation<2> reference = make_driven(p, 7);
  ASSERT_EQ(reference.run(kInf, collisions_for(p, kSpan)), StopReason::kCollisionsReached);
  ASSERT_GE(reference.events(), 100 * p.particles) << "the span must cover many clock re-bases";

  Simulation<2> driven = make_driven(p, 7);
  Counter counter;
  driven.add_observer(&counter);
  std::mt19937_64 random(3);
  std::int64_t stops = 0;
  while (driven.collisions() < reference.collisions()) {
    // Alternate stops at random collision counts and at random times, as outputs would.
    const std::int64_t target =
        std::min(reference.collisions(), driven.collisions() + 1 + static_cast<std::int64_t>(random() % 400));
    const double until = random() % 2 ? driven.time() + 1e-4 * static_cast<double>(random() % 100) : kInf;
    driven.run(until, target);
    static_cast<void>(driven.state());
    ++stops;
  }
  std::printf("stops %lld, events %lld (%.1f N), crossings of the sheared boundary %lld\n",
              static_cast<long long>(stops), static_cast<long long>(driven.events()),
              static_cast<double>(driven.events()) / static_cast<double>(p.particles),
              static_cast<long long>(counter.crossings));
  EXPECT_GT(stops, 100);
  EXPECT_GT(counter.crossings, 0);
  expect_same_engine(reference, driven);
}

TEST_P(ExactContinuation, RestoredCheckpointsContinueTheSameRun) {
  const SystemParams p = sheared_tc_system();
  Simulation<2> reference = make_driven(p, 11);
  reference.run(kInf, collisions_for(p, kSpan));

  auto current = std::make_unique<Simulation<2>>(make_driven(p, 11));
  const CellGrid grid = current->grid();
  int restores = 0;
  for (double c = 0.37; c < kSpan; c += 3.1, ++restores) {
    current->run(kInf, collisions_for(p, c));
    StateArchive archive;
    current->save(archive, "engine/");
    current = std::make_unique<Simulation<2>>(p, grid, archive, "engine/");
  }
  current->run(kInf, collisions_for(p, kSpan));
  EXPECT_GE(restores, 12);
  expect_same_engine(reference, *current);
}

TEST_P(ExactContinuation, CheckpointOfAnotherSystemIsRefused) {
  const SystemParams p = sheared_tc_system();
  Simulation<2> sim = make_driven(p, 1);
  sim.run(kInf, collisions_for(p, 1.0));
  StateArchive archive;
  sim.save(archive, "");
  SystemParams other = p;
  other.shear_velocity = 5.0;
  EXPECT_THROW(Simulation<2>(other, sim.grid(), archive, ""), std::runtime_error);
  // A damaged checkpoint (one disk moved onto another) fails the engine's invariants.  The records
  // hold positions at the clock base: disk 0 is placed so that it sits 0.1 σ from disk 1 now.
  auto x = archive.get<double>("x");
  auto y = archive.get<double>("y");
  const auto vx = archive.get<double>("vx"), vy = archive.get<double>("vy");
  const double t_now = archive.scalar("t_now");
  x[0] = x[1] + (vx[1] - vx[0]) * t_now + 0.1 * p.diameter;
  y[0] = y[1] + (vy[1] - vy[0]) * t_now;
  archive.put("x", x);
  archive.put("y", y);
  EXPECT_THROW(Simulation<2>(p, sim.grid(), archive, ""), std::runtime_error);
}

TEST_P(ExactContinuation, InvariantsHoldAlongARun) {
  const SystemParams p = sheared_tc_system();
  Simulation<2> sim = make_driven(p, 5);
  for (int k = 1; k <= 20; ++k) {
    sim.run(kInf, collisions_for(p, 0.5 * k));
    ASSERT_NO_THROW(sim.check_invariants()) << "after c = " << 0.5 * k;
  }
}

INSTANTIATE_TEST_SUITE_P(Drives, ExactContinuation, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& drive) { return drive.param ? "Protocol" : "Constant"; });

}  // namespace
}  // namespace granule
