// Oracle tier: the cell engine against the O(N²) reference of brute_force.hpp.
//
// Hard-disk dynamics is chaotic, so two correct codes drift apart after a few dozen collisions
// per particle from round-off alone.  The comparison is therefore made event by event from the
// engine's own state: before each of ≥ 10^4 collisions (a quarter under AddressSanitizer) the reference predicts, from the
// engine's configuration, which pair collides next and when; the engine must execute exactly
// that pair at that time (to 1e-9), across periodic and Lees–Edwards boxes, densities and seeds,
// disks and spheres, equal and unequal sizes and masses, and leave both particles with the
// velocities the reference's own collision rule gives.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "cells/cell_grid.hpp"
#include "engine/simulation.hpp"
#include "init/initial_state.hpp"
#include "oracle/brute_force.hpp"
#include "physics/collision_batch.hpp"

namespace granule {
namespace {

struct OracleCase {
  int dimension;
  int particles;
  double packing_fraction;
  double restitution;
  double shear_velocity;
  std::uint64_t seed;
  double size_ratio = 1.0;  // ≠ 1: a binary mixture, half the particles this much larger, m ∝ σ^d
  // The engine's cells: with many particles each, a block holds more neighbours than one batch of
  // pair tests (CollisionBatch::kCapacity), and the batches must give the pair-by-pair order.
  double particles_per_cell = 1.0;
};

// Box 1 × 1.3 (× 0.9): not square, so that axis mix-ups show.
SystemParams box_for(const OracleCase& k) {
  SystemParams p;
  p.dimension = k.dimension;
  p.particles = k.particles;
  p.length_x = 1.0;
  p.length_y = 1.3;
  p.length_z = 0.9;
  p.restitution = k.restitution;
  p.shear_velocity = k.shear_velocity;
  return p;
}

// The reference's own initial state: random sequential addition tested against every placed
// particle, Gaussian velocities, no cells (independent of src/init); dense monodisperse disks
// come from src/init's lattice, melted by the run.  Sets p.diameter to the largest diameter.
ParticleState random_gas(SystemParams& p, const OracleCase& k) {
  const int d = k.dimension;
  if (d == 2 && k.size_ratio == 1.0 && k.packing_fraction > 0.45) {
    p.diameter = std::sqrt(4.0 * k.packing_fraction * p.length_x * p.length_y / (M_PI * k.particles));
    return make_initial_state(p, 1.0, k.seed, Placement::kAuto).state;
  }
  const double volume = p.length_x * p.length_y * (d == 3 ? p.length_z : 1.0);
  const double unit_ball = d == 3 ? M_PI / 6.0 : M_PI / 4.0;  // volume of a ball of diameter 1
  // Σ σ_i^d = ν V / unit_ball, with half the particles of diameter σ and half of ratio·σ.
  const double half = 0.5 * k.particles;
  const double sum_unit = half + half * std::pow(k.size_ratio, d);
  const double sigma = std::pow(k.packing_fraction * volume / unit_ball / sum_unit, 1.0 / d);
  ParticleState s;
  s.dimension = d;
  if (k.size_ratio != 1.0) {
    s.diameter.resize(static_cast<std::size_t>(k.particles));
    s.mass.resize(static_cast<std::size_t>(k.particles));
  }
  s.resize(static_cast<std::size_t>(k.particles));
  std::mt19937_64 rng(k.seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  p.diameter = sigma * std::max(1.0, k.size_ratio);
  const SystemParams periodic = [&] { SystemParams q = p; q.shear_velocity = 0.0; return q; }();
  for (int i = 0; i < k.particles; ++i) {
    if (s.polydisperse()) {
      s.diameter[i] = i % 2 == 1 ? sigma * k.size_ratio : sigma;
      s.mass[i] = std::pow(s.diameter[i] / sigma, d);
    }
    for (int attempt = 0;; ++attempt) {
      if (attempt > 100000) throw std::runtime_error("oracle gas: cannot place");
      s.x[i] = uniform(rng) * p.length_x;
      s.y[i] = uniform(rng) * p.length_y;
      if (d == 3) s.z[i] = uniform(rng) * p.length_z;
      bool free = true;
      for (int j = 0; j < i && free; ++j) {
        oracle::for_each_image(periodic, s, 0.0, i, j, [&](const oracle::Point& r, const oracle::Point&, int) {
          free = free && oracle::dot(r, r) > std::pow(oracle::contact(p, s, i, j), 2);
        });
      }
      if (free) break;
    }
    s.vx[i] = normal(rng);
    s.vy[i] = normal(rng);
    if (d == 3) s.vz[i] = normal(rng);
  }
  return s;
}

template <int D>
void check_against_brute_force(const OracleCase& k) {
  SystemParams p = box_for(k);
  const ParticleState initial = random_gas(p, k);
  CellGridRequest request{p.length_x, p.length_y, p.diameter, p.particles, k.shear_velocity != 0.0, k.particles_per_cell, std::nullopt};
  request.dimension = D;
  request.length_z = p.length_z;
  const auto grid = choose_cell_grid(request);
  ASSERT_TRUE(grid.grid) << grid.error;
  if (k.particles_per_cell != 1.0) {  // the case is there to fill more than one batch per block
    const double block = std::pow(3.0, D) * k.particles / static_cast<double>(grid.grid->cell_count());
    ASSERT_GT(block, CollisionBatch<D>::kCapacity);
  }
  Simulation<D> sim(p, *grid.grid, initial);

  struct Recorder final : EventObserver<D> {
    CollisionRecord<D> last;
    void on_collision(const CollisionRecord<D>& r) override { last = r; }
  } recorder;
  sim.add_observer(&recorder);

  // 10⁴ collisions; a quarter under AddressSanitizer (CI's second tier, which looks for memory
  // errors and runs the engine's invariant checks at every re-base: a quarter still passes several
  // re-bases), where the reference's O(N²) search made these cases 270 s of the tier's 960.
#ifdef __SANITIZE_ADDRESS__
  constexpr int kCollisions = 2500;
#else
  constexpr int kCollisions = 10000;
#endif
  int ties = 0;
  for (int n = 1; n <= kCollisions; ++n) {
    const ParticleState state = sim.state();
    const double t = sim.time();
    const auto expected = oracle::brute_force_next_collision(p, state, t);
    ASSERT_TRUE(std::isfinite(expected.delay));
    ASSERT_EQ(sim.run(std::numeric_limits<double>::infinity(), n), StopReason::kCollisionsReached);
    const double tolerance = 1e-9 * std::max(1.0, t);
    const int a = std::min(recorder.last.first, recorder.last.second);
    const int b = std::max(recorder.last.first, recorder.last.second);
    ASSERT_NEAR(recorder.last.time, t + expected.delay, tolerance) << "collision " << n;
    const CollisionRecord<D>& r = recorder.last;
    const auto after = oracle::brute_force_collide(p, state, t, r.first, r.second, r.time - t, r.restitution);
    double speed = 0.0;
    for (int axis = 0; axis < D; ++axis) {
      speed = std::max({speed, std::abs(r.first_velocity_before[axis]), std::abs(r.second_velocity_before[axis])});
    }
    for (int axis = 0; axis < D; ++axis) {
      ASSERT_NEAR(r.first_velocity_after[axis], after.v1[axis], 1e-9 * speed) << "collision " << n << " axis " << axis;
      ASSERT_NEAR(r.second_velocity_after[axis], after.v2[axis], 1e-9 * speed) << "collision " << n << " axis " << axis;
    }
    EXPECT_EQ(r.restitution, p.restitution);
    if (expected.runner_up_delay - expected.delay < tolerance) {
      ++ties;  // two collisions at the same time to 1e-9: either order is correct
      continue;
    }
    ASSERT_EQ(a, expected.first) << "collision " << n << " at t = " << t;
    ASSERT_EQ(b, expected.second) << "collision " << n << " at t = " << t;
    if (n % 500 == 0) {
      ASSERT_GT(oracle::min_distance_ratio(p, sim.state(), sim.time()), 1.0 - 1e-9);
    }
  }
  EXPECT_LT(ties, kCollisions / 100);
}

class EngineVsBruteForce : public ::testing::TestWithParam<OracleCase> {};

TEST_P(EngineVsBruteForce, SameNextCollisionEveryTime) {
  const OracleCase& k = GetParam();
  if (k.dimension == 2) {
    check_against_brute_force<2>(k);
  } else {
    check_against_brute_force<3>(k);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Boxes, EngineVsBruteForce,
    ::testing::Values(OracleCase{2, 100, 0.05, 1.0, 0.0, 1}, OracleCase{2, 100, 0.3, 0.9, 0.0, 2},
                      OracleCase{2, 120, 0.6, 1.0, 0.0, 3}, OracleCase{2, 100, 0.05, 0.8, 3.0, 4},
                      OracleCase{2, 100, 0.3, 1.0, 2.0, 5}, OracleCase{2, 80, 0.5, 0.9, -4.0, 6},
                      OracleCase{2, 100, 0.3, 1.0, 2.0, 7, 1.6},  // binary mixture
                      // 3×3 cells of about 11 disks: every block is the whole box, two batches
                      OracleCase{2, 100, 0.3, 0.9, 2.0, 13, 1.6, 12.0},
                      // 3D: 27 images per pair make the reference slow, hence fewer spheres
                      OracleCase{3, 60, 0.05, 1.0, 0.0, 8}, OracleCase{3, 60, 0.25, 0.9, 0.0, 9},
                      OracleCase{3, 60, 0.1, 0.8, 3.0, 10}, OracleCase{3, 60, 0.2, 1.0, -2.0, 11, 1.5},
                      OracleCase{3, 60, 0.15, 0.9, 0.0, 12, 2.0}),
    [](const ::testing::TestParamInfo<OracleCase>& test) {
      const OracleCase& k = test.param;
      return std::to_string(k.dimension) + "D_" + (k.shear_velocity != 0.0 ? "LeesEdwards" : "Periodic") + "_nu" +
             std::to_string(static_cast<int>(100 * k.packing_fraction)) + (k.size_ratio != 1.0 ? "_mixture" : "") + (k.particles_per_cell != 1.0 ? "_crowded" : "") +
             "_seed" + std::to_string(k.seed);
    });

}  // namespace
}  // namespace granule
