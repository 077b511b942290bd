// Snapshots of runs with rough grains, walls or gravity: the spins of rough grains are written
// with every frame and read back (a restart from a frame gets them), and the roughness, wall and
// gravity parameters travel as attributes; a smooth run's file has none of them.
#include <gtest/gtest.h>

#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "io/hdf5_util.hpp"
#include "io/snapshot_file.hpp"

namespace granule {
namespace {

namespace fs = std::filesystem;

std::string scratch_file(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "granule_test_snapshot_spins";
  fs::create_directories(dir);
  fs::remove(dir / name);
  return (dir / name).string();
}

SnapshotMetadata rough_walled_metadata(int dimension) {
  SnapshotMetadata m;
  m.system.particles = 3;
  m.system.diameter = 0.05;
  m.system.dimension = dimension;
  m.system.roughness = {true, 0.4, 0.35, std::numeric_limits<double>::infinity()};
  m.system.walls = {false, true, false};
  m.system.wall[2] = {0.9, 0.5, {-1.5, 0.0, 0.0}};
  m.system.wall[3] = {0.8, -1.0, {1.5, 0.0, 0.25}};
  m.system.gravity = {0.0, -9.81, 0.0};
  m.boundary = "walls";
  m.version = "test";
  return m;
}

// Frame `label` of n grains with spins that tell frame, grain and component apart.
SnapshotFrame spinning_frame(int dimension, int label) {
  SnapshotFrame f;
  f.particles.dimension = dimension;
  f.particles.resize(3);
  f.particles.make_rough();
  for (std::size_t i = 0; i < 3; ++i) {
    for (int a = 0; a < dimension; ++a) {
      f.particles.position(a)[i] = 0.1 * (label + 1) + 0.01 * static_cast<double>(i) + 0.001 * a;
      f.particles.velocity(a)[i] = -f.particles.position(a)[i];
    }
    const int first = dimension == 3 ? 0 : 2;
    for (int k = first; k < 3; ++k) f.particles.spin(k)[i] = 100.0 * label + 10.0 * static_cast<double>(i) + k;
  }
  f.clock.time = label;
  return f;
}

void expect_spins_round_trip(int dimension) {
  const std::string path = scratch_file("rough" + std::to_string(dimension) + ".h5");
  {
    SnapshotWriter writer(path, rough_walled_metadata(dimension));
    for (int label = 0; label < 3; ++label) writer.append(spinning_frame(dimension, label));
    writer.finish();
  }
  const SnapshotRead read = read_snapshot(path, 1);
  const SnapshotFrame expected = spinning_frame(dimension, 1);
  ASSERT_TRUE(read.frame.particles.rough());
  for (int k = dimension == 3 ? 0 : 2; k < 3; ++k) EXPECT_EQ(read.frame.particles.spin(k), expected.particles.spin(k)) << k;
  EXPECT_EQ(read.frame.particles.vx, expected.particles.vx);

  const SystemParams& p = read.metadata.system;
  const SystemParams& written = rough_walled_metadata(dimension).system;
  EXPECT_TRUE(p.roughness.rough);
  EXPECT_EQ(p.roughness.tangential_restitution, 0.4);
  EXPECT_EQ(p.roughness.inertia_factor, 0.35);
  EXPECT_TRUE(std::isinf(p.roughness.friction));
  EXPECT_EQ(p.walls, written.walls);
  for (std::size_t face = 0; face < 6; ++face) {
    EXPECT_EQ(p.wall[face].restitution, written.wall[face].restitution) << face;
    EXPECT_EQ(p.wall[face].tangential_restitution, written.wall[face].tangential_restitution) << face;
    EXPECT_EQ(p.wall[face].velocity, written.wall[face].velocity) << face;
  }
  EXPECT_EQ(p.gravity, written.gravity);

  // The dataset's shape: (S, N) for disks, (S, N, 3) for spheres.
  h5::Handle file = h5::open_file(path);
  const std::vector<hsize_t> shape = h5::dataset_shape(file.get(), "spins");
  file.close();
  EXPECT_EQ(shape, dimension == 3 ? (std::vector<hsize_t>{3, 3, 3}) : (std::vector<hsize_t>{3, 3}));
}

TEST(SnapshotSpins, DisksRoundTrip) { expect_spins_round_trip(2); }
TEST(SnapshotSpins, SpheresRoundTrip) { expect_spins_round_trip(3); }

TEST(SnapshotSpins, SmoothRunsHaveNoneOfTheNewData) {
  const std::string path = scratch_file("smooth.h5");
  SnapshotMetadata m = rough_walled_metadata(2);
  m.system.roughness = {};
  m.system.walls = {};
  m.system.gravity = {};
  {
    SnapshotWriter writer(path, m);
    SnapshotFrame f = spinning_frame(2, 0);
    f.particles.wz.clear();
    writer.append(f);
    writer.finish();
  }
  const SnapshotRead read = read_snapshot(path);
  EXPECT_FALSE(read.frame.particles.rough());
  EXPECT_FALSE(read.metadata.system.roughness.rough);
  EXPECT_FALSE(read.metadata.system.has_walls());
  EXPECT_FALSE(read.metadata.system.has_gravity());
  h5::Handle file = h5::open_file(path);
  for (const char* name : {"inertia_factor", "walls", "gravity", "wall_velocity"}) EXPECT_FALSE(h5::has_attribute(file.get(), name)) << name;
  EXPECT_FALSE(h5::has_link(file.get(), "spins"));
  file.close();
}

TEST(SnapshotSpins, ASmoothFrameInARoughFileIsABug) {
  const std::string path = scratch_file("mismatch.h5");
  SnapshotWriter writer(path, rough_walled_metadata(2));
  SnapshotFrame f = spinning_frame(2, 0);
  f.particles.wz.clear();
  EXPECT_THROW(writer.append(f), std::logic_error);
}

}  // namespace
}  // namespace granule
