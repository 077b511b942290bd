// HDF5 snapshot files (schema in README.md, "snapshots.h5").  Frames are appended to
// `<name>.partial` during a run, flushed after each frame, and the file is renamed to `<name>`
// when the run ends, so a finished name is always a complete file.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "engine/system_params.hpp"

namespace granule {

struct SnapshotMetadata {
  SystemParams system;
  double area_fraction = 0.0;
  std::string boundary;  // "periodic" or "lees-edwards"
  std::uint64_t seed = 0;
  std::string version;
};

struct SnapshotFrame {
  ParticleState particles;
  ClockState clock;
  double collisions_per_particle = 0.0;
  double shear_offset = 0.0;  // Lees–Edwards image offset Δ ∈ [0, L_x)
  double strain = 0.0;        // strain of the sheared cell grid (restart state)
};

class SnapshotWriter {
 public:
  // Starts `path`.partial (replacing any earlier partial file).  Throws std::runtime_error.
  SnapshotWriter(const std::string& path, const SnapshotMetadata& metadata);
  // Continue the file of an interrupted or finished run after its first `keep_frames` frames
  // (hdf5_util.hpp, reopen_frames_file).
  static std::unique_ptr<SnapshotWriter> reopen(const std::string& path, std::int64_t keep_frames);
  ~SnapshotWriter();
  SnapshotWriter(const SnapshotWriter&) = delete;
  SnapshotWriter& operator=(const SnapshotWriter&) = delete;

  void append(const SnapshotFrame& frame);
  std::int64_t frames() const { return frames_; }
  // Close and rename to the final name.
  void finish();

 private:
  SnapshotWriter() = default;
  struct Handles;
  std::unique_ptr<Handles> handles_;
  std::string path_;
  std::int64_t frames_ = 0;
  std::int64_t particles_ = 0;
  bool tc_ = false;
};

struct SnapshotRead {
  SnapshotMetadata metadata;
  SnapshotFrame frame;
  std::int64_t frames = 0;
};

// Reads frame `index` (negative counts from the end) of a snapshot file.  Throws on error.
SnapshotRead read_snapshot(const std::string& path, std::int64_t index = -1);

}  // namespace granule
