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

namespace granule {
namespace {

// FNV-1a over the bytes of every entry of the archive, in name order.
std::uint64_t hash_of(const StateArchive& archive) {
  std::uint64_t hash = 14695981039346656037ULL;
  const auto mix = [&](const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < size; ++k) hash = (hash ^ bytes[k]) * 1099511628211ULL;
  };
  for (const auto& [name, values] : archive.arrays()) {
    mix(name.data(), name.size());
    std::visit([&](const auto& v) { mix(v.data(), v.size() * sizeof(v[0])); }, values);
  }
  return hash;
}

struct GoldenCase {
  const char* name;
  int particles;
  double area_fraction, restitution, shear_velocity, tc_duration, collisions_per_particle;
  std::uint64_t seed;
  std::uint64_t expected;
  bool protocol = false;  // a ramp with a sinusoidal kick (thesis §4.3) from production on
};

class GoldenState : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(GoldenState, FinalStateHashIsUnchanged) {
  const GoldenCase k = GetParam();
  SystemParams p;
  p.particles = k.particles;
  p.diameter = std::sqrt(4.0 * k.area_fraction / (M_PI * k.particles));
  p.restitution = 1.0;
  p.shear_velocity = k.shear_velocity;
  p.tc_duration = k.tc_duration;
  if (k.protocol) {
    p.shear_history.ramp_time = 0.05;
    p.shear_history.oscillation = ShearOscillation{0.3 * k.shear_velocity, 0.02, 0.05, 5.0};
  }
  const auto grid = choose_cell_grid({1.0, 1.0, p.diameter, p.particles, k.shear_velocity != 0.0, 1.0, std::nullopt});
  ASSERT_TRUE(grid.grid) << grid.error;
  const auto init = make_initial_state(p, 1.0, k.seed, Placement::kAuto);
  ASSERT_TRUE(init.error.empty()) << init.error;
  Simulation<2> sim(p, *grid.grid, init.state);
  // As granule run does: an elastic pre-run, then the restitution switched on.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  sim.run(kInf, 2L * k.particles);
  sim.start_production(k.restitution);
  const auto target = std::llround(k.collisions_per_particle * static_cast<double>(k.particles));
  ASSERT_EQ(sim.run(kInf, target), StopReason::kCollisionsReached);
  StateArchive archive;
  sim.save(archive, "");
  const std::uint64_t hash = hash_of(archive);
  std::printf("%s: t = %.17g, events %lld, hash 0x%016" PRIx64 "\n", k.name, sim.time(),
              static_cast<long long>(sim.events()), hash);
  EXPECT_EQ(hash, k.expected) << k.name << ": the trajectory changed (new hash 0x" << std::hex << hash << ")";
}

INSTANTIATE_TEST_SUITE_P(
    Runs, GoldenState,
    ::testing::Values(GoldenCase{"free_cooling_tc", 2000, 0.05, 0.6, 0.0, 1e-7, 40.0, 1995, 0xd3297e4829867e50ULL},
                      GoldenCase{"lees_edwards_tc", 1500, 0.2, 0.8, 30.0, 1e-6, 40.0, 7, 0x605329950098a518ULL},
                      GoldenCase{"dense_elastic", 1200, 0.6, 1.0, 0.0, 0.0, 30.0, 3, 0x86706d463aed0ef9ULL},
                      GoldenCase{"lees_edwards_protocol", 1500, 0.1, 0.7, 20.0, 1e-6, 40.0, 12, 0x0ea69a738738344fULL, true}),
    [](const ::testing::TestParamInfo<GoldenCase>& run) { return std::string(run.param.name); });

}  // namespace
}  // namespace granule
