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
  int dimension = 2;      // area_fraction is then the packing fraction
  double size_ratio = 1.0;                // ≠ 1: a binary mixture, half of the grains this much larger
  double tangential_restitution = -1.0;   // > −1: rough grains (β), with spin
};

template <int D>
std::uint64_t final_state_hash(const GoldenCase& k) {
  SystemParams p;
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
  if (k.protocol) {
    p.shear_history.ramp_time = 0.05;
    p.shear_history.oscillation = ShearOscillation{0.3 * k.shear_velocity, 0.02, 0.05, 5.0};
  }
  CellGridRequest request{1.0, 1.0, p.diameter, p.particles, k.shear_velocity != 0.0, 1.0, std::nullopt};
  request.dimension = D;
  request.length_z = p.length_z;
  const auto grid = choose_cell_grid(request);
  EXPECT_TRUE(grid.grid) << grid.error;
  const auto init = make_initial_state(p, 1.0, k.seed, Placement::kAuto, std::nullopt, sizes);
  EXPECT_TRUE(init.error.empty()) << init.error;
  if (!grid.grid || !init.error.empty()) return 0;
  Simulation<D> sim(elastic_prerun(p), *grid.grid, init.state);
  // As granule run does: an elastic pre-run, then the restitutions switched on.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  sim.run(kInf, 2L * k.particles);
  SystemParams production = p;
  production.restitution = k.restitution;
  production.roughness.tangential_restitution = k.tangential_restitution;
  sim.start_production(production);
  const auto target = std::llround(k.collisions_per_particle * static_cast<double>(k.particles));
  EXPECT_EQ(sim.run(kInf, target), StopReason::kCollisionsReached);
  StateArchive archive;
  sim.save(archive, "");
  const std::uint64_t hash = hash_of(archive);
  std::printf("%s: t = %.17g, events %lld, hash 0x%016" PRIx64 "\n", k.name, sim.time(),
              static_cast<long long>(sim.events()), hash);
  return hash;
}

class GoldenState : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(GoldenState, FinalStateHashIsUnchanged) {
  const GoldenCase k = GetParam();
  const std::uint64_t hash = k.dimension == 3 ? final_state_hash<3>(k) : final_state_hash<2>(k);
  EXPECT_EQ(hash, k.expected) << k.name << ": the trajectory changed (new hash 0x" << std::hex << hash << ")";
}

INSTANTIATE_TEST_SUITE_P(
    Runs, GoldenState,
    ::testing::Values(GoldenCase{"free_cooling_tc", 2000, 0.05, 0.6, 0.0, 1e-7, 40.0, 1995, 0xd3297e4829867e50ULL},
                      GoldenCase{"lees_edwards_tc", 1500, 0.2, 0.8, 30.0, 1e-6, 40.0, 7, 0x605329950098a518ULL},
                      GoldenCase{"dense_elastic", 1200, 0.6, 1.0, 0.0, 0.0, 30.0, 3, 0x86706d463aed0ef9ULL},
                      GoldenCase{"lees_edwards_protocol", 1500, 0.1, 0.7, 20.0, 1e-6, 40.0, 12, 0x0ea69a738738344fULL, true},
                      // The generic core (issue 14) and rough grains (issue 15): spheres, a mixture, spin.
                      GoldenCase{"spheres_free_cooling_tc", 2000, 0.25, 0.8, 0.0, 1e-7, 30.0, 5, 0xa61b14aa52cb401aULL, false, 3},
                      GoldenCase{"spheres_lees_edwards", 1500, 0.3, 0.9, 10.0, 1e-6, 30.0, 8, 0x9d65e40edb575e83ULL, false, 3},
                      GoldenCase{"spheres_bidisperse", 2000, 0.3, 0.9, 0.0, 1e-7, 30.0, 9, 0x9a735fe18d28219fULL, false, 3, 1.4},
                      GoldenCase{"rough_disks_shear", 1500, 0.3, 0.9, 20.0, 1e-6, 30.0, 10, 0x9ffdafdc6a41a22cULL, false, 2, 1.0, 0.5},
                      GoldenCase{"rough_spheres", 1500, 0.25, 0.9, 0.0, 1e-7, 30.0, 11, 0x775fbab178969dc6ULL, false, 3, 1.0, 0.3}),
    [](const ::testing::TestParamInfo<GoldenCase>& run) { return std::string(run.param.name); });

}  // namespace
}  // namespace granule
