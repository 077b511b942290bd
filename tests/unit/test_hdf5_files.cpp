// Granule's HDF5 files and atomic files: resuming after a crash (reopen and truncate to the first
// K frames, without copying), detection of a frame left half-written, byte-identical files for
// identical content, and IoError messages that name the file.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

#include "io/atomic_file.hpp"
#include "io/export_field_source.hpp"
#include "io/fields_file.hpp"
#include "io/hdf5_util.hpp"
#include "io/io_error.hpp"
#include "io/snapshot_file.hpp"

namespace granule {
namespace {

namespace fs = std::filesystem;

constexpr int kParticles = 3;

// A fresh, empty directory for one test.
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("granule_test_hdf5_files_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

SnapshotMetadata metadata(double tc_duration = 0.0) {
  SnapshotMetadata m;
  m.system.particles = kParticles;
  m.system.diameter = 0.01;
  m.system.length_x = 100.0;  // every position of the labelled frames below lies inside
  m.system.length_y = 200.0;
  m.system.restitution = 0.8;
  m.system.tc_duration = tc_duration;
  m.packing_fraction = 0.1;
  m.boundary = "periodic";
  m.seed = 7;
  m.version = "test";
  return m;
}

// Frame `label`: every stored number is a distinct function of the label, so a frame read back
// tells which one was written.
SnapshotFrame frame(int label) {
  SnapshotFrame f;
  f.particles.resize(kParticles);
  for (int i = 0; i < kParticles; ++i) {
    const auto k = static_cast<std::size_t>(i);
    f.particles.x[k] = label + 0.1 * i;
    f.particles.y[k] = label + 0.2 * i;
    f.particles.vx[k] = -label - 0.3 * i;
    f.particles.vy[k] = -label - 0.4 * i;
  }
  f.clock.time = 10.0 * label;
  f.clock.collisions = 100 * label;
  f.clock.events = 1000 * label;
  f.clock.last_collision.assign(kParticles, -0.5 * label);
  f.collisions_per_particle = label / 3.0;
  f.shear_offset = 0.25 * label;
  return f;
}

void expect_frame(const std::string& path, std::int64_t index, int label) {
  const SnapshotRead read = read_snapshot(path, index);
  const SnapshotFrame expected = frame(label);
  EXPECT_EQ(read.frame.particles.x, expected.particles.x) << "frame " << index;
  EXPECT_EQ(read.frame.particles.vy, expected.particles.vy) << "frame " << index;
  EXPECT_EQ(read.frame.clock.time, expected.clock.time) << "frame " << index;
  EXPECT_EQ(read.frame.clock.events, expected.clock.events) << "frame " << index;
  EXPECT_EQ(read.frame.shear_offset, expected.shear_offset) << "frame " << index;
}

// Writes frames labelled 0..count-1 and "crashes": the writer goes away without finish().
void write_and_crash(const std::string& path, int count, double tc_duration = 0.0) {
  SnapshotWriter writer(path, metadata(tc_duration));
  for (int k = 0; k < count; ++k) writer.append(frame(k));
}

// Sets the length of one dataset of a file, as a crash in the middle of a frame leaves it.
void set_frames(const std::string& file_path, const char* dataset, hsize_t frames) {
  h5::Handle file(H5Fopen(file_path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose);
  ASSERT_GE(file.get(), 0);
  h5::Handle data(H5Dopen2(file.get(), dataset, H5P_DEFAULT), H5Dclose);
  std::vector<hsize_t> dims = h5::dataset_shape(file.get(), dataset);
  dims[0] = frames;
  ASSERT_GE(H5Dset_extent(data.get(), dims.data()), 0);
  data.close();
  file.close();
}

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(SnapshotFile, ResumesACrashedRunFromItsFirstFrames) {
  const std::string path = (scratch("crash") / "snapshots.h5").string();
  write_and_crash(path, 5);
  EXPECT_FALSE(fs::exists(path)) << "an unfinished file must not have its final name";
  ASSERT_TRUE(fs::exists(path + ".partial"));
  EXPECT_EQ(h5::complete_frames(path + ".partial"), 5);

  SnapshotWriter resumed(path, 3);
  EXPECT_EQ(resumed.frames(), 3);
  resumed.append(frame(13));
  resumed.append(frame(14));
  resumed.finish();
  EXPECT_FALSE(fs::exists(path + ".partial"));
  EXPECT_EQ(read_snapshot(path).frames, 5);
  for (int k = 0; k < 3; ++k) expect_frame(path, k, k);
  expect_frame(path, 3, 13);
  expect_frame(path, 4, 14);
}

// A flush's journal is renamed into place only when whole (io/journaled_file_driver.hpp): a
// temporary one was never applied and goes; a damaged one stops the resume with the file's name.
TEST(SnapshotFile, ResumeDiscardsAnUnfinishedJournalAndRefusesADamagedOne) {
  const std::string path = (scratch("journal") / "snapshots.h5").string();
  write_and_crash(path, 4);
  EXPECT_FALSE(fs::exists(path + ".partial.journal")) << "every flush was applied";
  std::ofstream(path + ".partial.journal.tmp") << "half a journal";
  {
    SnapshotWriter resumed(path, 2);
    EXPECT_EQ(resumed.frames(), 2);
  }
  EXPECT_FALSE(fs::exists(path + ".partial.journal.tmp"));
  expect_frame(path + ".partial", 1, 1);

  std::ofstream(path + ".partial.journal") << "GRNLJRN1 but not a journal";
  try {
    SnapshotWriter resumed(path, 2);
    ADD_FAILURE() << "a damaged journal was accepted";
  } catch (const IoError& error) {
    EXPECT_NE(std::string(error.what()).find("snapshots.h5.partial.journal is damaged"), std::string::npos) << error.what();
  }
}

TEST(SnapshotFile, ResumesAPublishedFileByRenamingItBack) {
  const std::string path = (scratch("published") / "snapshots.h5").string();
  {
    SnapshotWriter writer(path, metadata(0.1));  // with the TC model's last_collision dataset
    for (int k = 0; k < 4; ++k) writer.append(frame(k));
    writer.finish();
  }
  {
    SnapshotWriter resumed(path, 2);
    EXPECT_FALSE(fs::exists(path)) << "the published file is renamed back, not copied";
    EXPECT_TRUE(fs::exists(path + ".partial"));
    resumed.append(frame(22));
    resumed.finish();
  }
  const SnapshotRead last = read_snapshot(path, -1);
  EXPECT_EQ(last.frames, 3);
  EXPECT_EQ(last.frame.clock.last_collision, frame(22).clock.last_collision);
  expect_frame(path, 1, 1);
  expect_frame(path, 2, 22);
}

TEST(SnapshotFile, CountsOnlyFramesEveryDatasetHolds) {
  const std::string path = (scratch("unequal") / "snapshots.h5").string();
  write_and_crash(path, 5);
  const std::string partial = path + ".partial";
  set_frames(partial, "positions", 6);  // a sixth frame begun: positions written, the rest not
  EXPECT_EQ(h5::complete_frames(partial), 5);
  set_frames(partial, "time", 4);
  EXPECT_EQ(h5::complete_frames(partial), 4);
  EXPECT_EQ(read_snapshot(partial).frames, 4);

  SnapshotWriter resumed(path);  // every complete frame
  EXPECT_EQ(resumed.frames(), 4);
  for (const char* dataset : {"positions", "velocities", "time", "events"}) {
    h5::Handle file = h5::open_file(partial);
    EXPECT_EQ(h5::dataset_shape(file.get(), dataset)[0], 4u) << dataset;
    file.close();
  }
  resumed.append(frame(9));
  resumed.finish();
  expect_frame(path, 3, 3);
  expect_frame(path, 4, 9);
}

TEST(SnapshotFile, RefusesToKeepMoreFramesThanItHoldsAndRenamesNothing) {
  const std::string path = (scratch("too_many") / "snapshots.h5").string();
  {
    SnapshotWriter writer(path, metadata());
    writer.append(frame(0));
    writer.finish();
  }
  EXPECT_THROW(SnapshotWriter(path, 2), InputError);
  EXPECT_TRUE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".partial"));
}

TEST(SnapshotFile, IdenticalContentGivesIdenticalBytes) {
  // Object modification times have a resolution of one second: the second file is written after
  // the clock has moved on.
  const fs::path dir = scratch("identical");
  const auto write = [&](const char* name) {
    SnapshotWriter writer((dir / name).string(), metadata(0.1));
    for (int k = 0; k < 3; ++k) writer.append(frame(k));
    writer.finish();
  };
  write("a.h5");
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  write("b.h5");
  const std::string a = bytes_of(dir / "a.h5"), b = bytes_of(dir / "b.h5");
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(a == b) << "two files of the same frames differ";
}

TEST(SnapshotFile, FailuresNameTheFile) {
  const std::string path = (scratch("missing") / "no_such_directory" / "snapshots.h5").string();
  try {
    SnapshotWriter writer(path, metadata());
    FAIL() << "created a file in a missing directory";
  } catch (const IoError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(path + ".partial"), std::string::npos) << message;
    EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
  }
  EXPECT_THROW(read_snapshot(path), InputError);  // a missing input: refused, exit 2
}

FieldsFrame fields_frame(const FieldGrid& grid, int label) {
  FieldsFrame f;
  f.t = label;
  f.c = 2.0 * label;
  f.configurations = 1;
  for (CellFields* fields : {&f.instant, &f.average}) {
    fields->grid = grid;
    for_each_field(*fields, [&](const char*, std::vector<double>& v) { v.assign(grid.cells(), label + 0.5); });
  }
  f.collisional = CollisionalStress{std::vector<double>(grid.cells(), label), std::vector<double>(grid.cells(), 0.0),
                                    std::vector<double>(grid.cells(), label), std::vector<double>(grid.cells(), 1.0), 1.0, {}, {}, {}, {}, {}, {}, {}, {}, {}};
  f.heat_flux_collisional = HeatFlux{std::vector<double>(grid.cells(), -label), std::vector<double>(grid.cells(), 2.0 * label), {}};
  return f;
}

TEST(FieldsFile, ResumesACrashedRunFromItsFirstFrames) {
  const std::string path = (scratch("fields") / "fields.h5").string();
  const FieldGrid grid{3, 2, 1.0, 2.0};
  {
    FieldsWriter writer(path, grid, FieldsMetadata{metadata().system, "periodic", false, "run", "test"}, true);
    for (int k = 0; k < 5; ++k) writer.append(fields_frame(grid, k));
  }
  FieldsWriter resumed(path, 3);
  EXPECT_EQ(resumed.frames(), 3);
  FieldsFrame without_stress = fields_frame(grid, 30);
  without_stress.collisional.reset();
  EXPECT_THROW(resumed.append(without_stress), std::logic_error) << "the file's collisional stress was forgotten";
  FieldsFrame without_heat_flux = fields_frame(grid, 31);
  without_heat_flux.heat_flux_collisional.reset();
  EXPECT_THROW(resumed.append(without_heat_flux), std::logic_error) << "the file's collisional heat flux was forgotten";
  resumed.append(fields_frame(grid, 13));
  resumed.append(fields_frame(grid, 14));
  resumed.finish();

  const FieldFileFrame last = read_field_file_frame(path, -1);
  EXPECT_EQ(last.frames, 5);
  EXPECT_EQ(last.grid.nx, 3);
  EXPECT_EQ(last.grid.length_y, 2.0);
  EXPECT_EQ(last.time, 14.0);
  EXPECT_EQ(read_field_file_frame(path, 2).time, 2.0);
  EXPECT_EQ(read_field_file_frame(path, 3).time, 13.0);
}

TEST(AtomicFile, PublishesTheContentAndLeavesNoTemporary) {
  const fs::path dir = scratch("atomic");
  write_file_atomically((dir / "summary.json").string(), "{\"a\": 1}\n");
  EXPECT_EQ(bytes_of(dir / "summary.json"), "{\"a\": 1}\n");
  EXPECT_FALSE(fs::exists(dir / "summary.json.tmp"));
}

TEST(AtomicFile, FailuresNameTheFileAndTheReason) {
  const std::string path = (scratch("atomic_missing") / "no_such_directory" / "summary.json").string();
  try {
    write_file_atomically(path, "{}");
    FAIL() << "wrote into a missing directory";
  } catch (const IoError& error) {
    EXPECT_EQ(std::string(error.what()), "cannot create " + path + ".tmp: No such file or directory");
  }
}

}  // namespace
}  // namespace granule
