// What is computed from a configuration handed over in blocks (the engine's state of 10^8 disks,
// read 2^16 particles at a time) equals, to the bit, what is computed from the whole state: the
// time-series sample of every column, the cell moments and the local density.  Blocks of 7
// particles put a boundary inside every cell and every sum.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "analysis/cell_fields.hpp"
#include "analysis/density_windows.hpp"
#include "engine/state_blocks.hpp"
#include "init/random.hpp"
#include "observers/global_diagnostics.hpp"

namespace granule {
namespace {

constexpr std::size_t kSmallBlock = 7;

// Rough, polydisperse grains with random positions, velocities and spins (n of them, d = D).
ParticleState random_grains(int dimension, std::size_t n, std::uint64_t seed) {
  Random random(seed);
  ParticleState s;
  s.dimension = dimension;
  s.diameter.resize(n);
  s.mass.resize(n);
  for (int k = first_spin_axis(dimension); k < 3; ++k) s.spin(k).resize(n);
  s.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < dimension; ++a) {
      s.position(a)[i] = random.uniform();
      s.velocity(a)[i] = random.uniform() - 0.5;
    }
    s.diameter[i] = 0.002 * (1.0 + random.uniform());
    s.mass[i] = std::pow(s.diameter[i] / 0.002, dimension);
    for (int k = first_spin_axis(dimension); k < 3; ++k) s.spin(k)[i] = random.uniform() - 0.5;
  }
  return s;
}

SystemParams rough_sheared_params(int dimension, std::size_t n) {
  SystemParams p;
  p.dimension = dimension;
  p.particles = static_cast<std::int32_t>(n);
  p.diameter = 0.004;
  p.length_x = p.length_y = p.length_z = 1.0;
  p.shear_velocity = 2.0;
  p.roughness.rough = true;
  p.roughness.inertia_factor = 0.4;
  p.gravity = {0.3, 0.0, -0.2};
  return p;
}

StateBlocks in_small_blocks(const ParticleState& whole) {
  return StateBlocks(whole.size(), [&whole](std::size_t first, std::size_t count) { return whole.slice(first, count); },
                     kSmallBlock);
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

template <int D>
void expect_equal_samples() {
  const std::size_t n = 1000;
  const ParticleState whole = random_grains(D, n, 20261201);
  const SystemParams p = rough_sheared_params(D, n);
  const FieldGrid grid = D == 3 ? FieldGrid{4, 5, 1.0, 1.0, 3, 1.0, 3} : FieldGrid{6, 5, 1.0, 1.0};
  GlobalDiagnostics<D> from_whole(p, grid), from_blocks(p, grid);
  DiagnosticsSample a = from_whole.sample(whole, 1.0, 10, p.shear_velocity, 0.25);
  DiagnosticsSample b = from_blocks.sample(in_small_blocks(whole), 1.0, 10, p.shear_velocity, 0.25);
  std::vector<std::string> names;
  std::vector<double> values;
  for_each_column(a, [&](const char* name, double& value) {
    names.emplace_back(name);
    values.push_back(value);
  });
  std::size_t k = 0;
  for_each_column(b, [&](const char*, double& value) {
    ASSERT_LT(k, values.size());
    EXPECT_TRUE(same_bits(values[k], value)) << names[k] << ": " << values[k] << " whole, " << value << " in blocks";
    ++k;
  });
  EXPECT_EQ(k, values.size());
  // The sample has the columns of rough grains in gravity, and they are not trivially zero.
  ASSERT_TRUE(a.rotation.has_value());
  ASSERT_TRUE(a.gravity.has_value());
  EXPECT_GT(a.rotation->rotational_temperature, 0.0);
  EXPECT_NE(a.gravity->potential_energy, 0.0);
}

TEST(StateBlocks, DiskSampleInBlocksEqualsTheWholeState) { expect_equal_samples<2>(); }
TEST(StateBlocks, SphereSampleInBlocksEqualsTheWholeState) { expect_equal_samples<3>(); }

TEST(StateBlocks, CellMomentsAndLocalDensityInBlocksEqualTheWholeState) {
  const ParticleState whole = random_grains(2, 500, 7);
  const FieldGrid grid{5, 4, 1.0, 1.0};
  const ShearFrame frame{1.0, 1.0, 3.0};
  CellMoments a(grid, SpinInertia{0.5, 0.004}), b(grid, SpinInertia{0.5, 0.004});
  a.add(whole, frame, true);
  b.add(in_small_blocks(whole), frame, true);
  EXPECT_EQ(a.configurations, 1);
  EXPECT_EQ(b.configurations, 1);  // one configuration, however many blocks
  for (const auto& [x, y] : {std::pair{&a.count, &b.count}, std::pair{&a.px, &b.px}, std::pair{&a.pxy, &b.pxy},
                             std::pair{&a.energy_flux_y, &b.energy_flux_y}, std::pair{&a.mass, &b.mass},
                             std::pair{&a.spin_z, &b.spin_z}, std::pair{&a.spin_square, &b.spin_square}}) {
    ASSERT_EQ(x->size(), y->size());
    ASSERT_FALSE(x->empty());
    for (std::size_t c = 0; c < x->size(); ++c) EXPECT_TRUE(same_bits((*x)[c], (*y)[c])) << "cell " << c;
  }
  LocalDensity whole_density(grid), block_density(grid);
  whole_density.update(whole);
  block_density.update(in_small_blocks(whole));
  for (double x = 0.1; x < 1.0; x += 0.2) {
    for (double y = 0.1; y < 1.0; y += 0.25) EXPECT_EQ(whole_density.at(x, y), block_density.at(x, y));
  }
}

TEST(StateBlocks, VisitsEveryParticleOnceInOrder) {
  const ParticleState whole = random_grains(3, 23, 3);
  std::vector<double> seen;
  std::size_t expected_first = 0;
  in_small_blocks(whole).for_each([&](const ParticleState& block, std::size_t first) {
    EXPECT_EQ(first, expected_first);
    EXPECT_LE(block.size(), kSmallBlock);
    expected_first += block.size();
    seen.insert(seen.end(), block.z.begin(), block.z.end());
  });
  EXPECT_EQ(seen, whole.z);
}

}  // namespace
}  // namespace granule
