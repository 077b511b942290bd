// The batched pair test (physics/collision_batch.hpp) against collision_time() pair by pair: the
// same earliest time to the bit and the same partner, ties included, over random batches that mix
// every branch of the scalar test (receding, grazing, missing, touching, overlapping, far).  The
// file is compiled as the engine is (-march=native, -fno-math-errno: tests/CMakeLists.txt), so
// that the vector code the engine runs is the code tested here.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>

#include "physics/collision_batch.hpp"
#include "physics/collision_time.hpp"

namespace granule {
namespace {

template <int D>
struct Pair {
  Vec<D> r, v;
  double contact;
};

// A pair of one of the kinds the scalar test tells apart, at random.
template <int D>
Pair<D> random_pair(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Pair<D> p;
  p.contact = 0.5 + 0.5 * (unit(rng) + 1.0);
  for (int a = 0; a < D; ++a) {
    p.r[a] = 3.0 * unit(rng);
    p.v[a] = unit(rng);
  }
  switch (rng() % 6) {
    case 0:  // overlapping by round-off, approaching or receding
      p.r = (p.contact * (1.0 - 1e-13) / norm(p.r)) * p.r;
      break;
    case 1:  // grazing: v nearly perpendicular to r
      p.v = p.v - (dot(p.r, p.v) / norm2(p.r)) * p.r;
      p.v[0] += 1e-12 * unit(rng);
      break;
    case 2:  // head-on
      p.v = (-0.5 * (unit(rng) + 1.5)) * p.r;
      break;
    case 3:  // touching exactly, approaching
      p.r = (p.contact / norm(p.r)) * p.r;
      p.v = -1.0 * p.r;
      break;
    default:  // anything, far or near, hitting or missing
      break;
  }
  return p;
}

template <int D>
void check_random_batches(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  CollisionBatch<D> batch;
  int hits = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const int n = 1 + static_cast<int>(rng() % CollisionBatch<D>::kCapacity);
    // The best known before the batch: none, or a kept candidate that some pairs beat.
    const double known = rng() % 3 == 0 ? kNever : 2.0 * std::uniform_real_distribution<double>(0.0, 1.0)(rng);
    double scalar_best = known;
    std::int32_t scalar_partner = -7;
    batch.size = 0;
    for (int k = 0; k < n; ++k) {
      const Pair<D> p = random_pair<D>(rng);
      for (int a = 0; a < D; ++a) {
        batch.r[static_cast<std::size_t>(a)][static_cast<std::size_t>(k)] = p.r[a];
        batch.v[static_cast<std::size_t>(a)][static_cast<std::size_t>(k)] = p.v[a];
      }
      batch.contact[static_cast<std::size_t>(k)] = p.contact;
      batch.partner[static_cast<std::size_t>(k)] = 100 + k;
      ++batch.size;
      if (const double t = collision_time<D>(p.r, p.v, p.contact); t < scalar_best) {
        scalar_best = t;
        scalar_partner = 100 + k;
      }
    }
    double best = known;
    std::int32_t partner = -7;
    batch.take_earliest(best, partner);
    ASSERT_EQ(best, scalar_best) << "trial " << trial;  // bit for bit, +inf included
    ASSERT_EQ(partner, scalar_partner) << "trial " << trial;
    ASSERT_EQ(batch.size, 0);
    hits += partner != -7;
  }
  EXPECT_GT(hits, 5000);  // the batches did find collisions, not only misses
}

TEST(CollisionBatch, SameAsPairByPairForDisks) { check_random_batches<2>(11); }
TEST(CollisionBatch, SameAsPairByPairForSpheres) { check_random_batches<3>(12); }

TEST(CollisionBatch, TiesGoToTheFirstInBatchOrderAndToTheKnownCandidate) {
  CollisionBatch<3> batch;
  // Five copies of one head-on pair (τ = 1), the third and fifth sooner (τ = 0.5): the third wins.
  for (int k = 0; k < 5; ++k) {
    const double gap = (k == 2 || k == 4) ? 1.5 : 2.0;
    batch.r[0][static_cast<std::size_t>(k)] = gap;
    batch.r[1][static_cast<std::size_t>(k)] = batch.r[2][static_cast<std::size_t>(k)] = 0.0;
    batch.v[0][static_cast<std::size_t>(k)] = -1.0;
    batch.v[1][static_cast<std::size_t>(k)] = batch.v[2][static_cast<std::size_t>(k)] = 0.0;
    batch.contact[static_cast<std::size_t>(k)] = 1.0;
    batch.partner[static_cast<std::size_t>(k)] = k;
  }
  batch.size = 5;
  double best = kNever;
  std::int32_t partner = -1;
  batch.take_earliest(best, partner);
  EXPECT_EQ(best, 0.5);
  EXPECT_EQ(partner, 2);
  // A known candidate at the same time as the batch's best stays.
  batch.size = 5;
  best = 0.5;
  partner = 42;
  batch.take_earliest(best, partner);
  EXPECT_EQ(partner, 42);
}

}  // namespace
}  // namespace granule
