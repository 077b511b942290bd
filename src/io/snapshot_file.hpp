// HDF5 snapshot files (schema in README.md, "snapshots.h5").  Frames are appended to
// `<name>.partial` during a run, flushed after each frame, and the file is renamed to `<name>`
// when the run ends, so a finished name is always a complete file.  Every failure throws IoError
// (src/io/io_error.hpp) and leaves `<name>.partial`, never an incomplete `<name>`.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "engine/state_blocks.hpp"
#include "engine/system_params.hpp"

namespace granule {

namespace h5 {
class PartialFile;
}

struct SnapshotMetadata {
  // With its dimension and L_z, and the roughness, walls and gravity (rough runs
  // write spins with every frame: the frame's ParticleState is then rough).
  SystemParams system;
  double packing_fraction = 0.0;  // area fraction (2D) or volume fraction (3D)
  std::string boundary;  // "periodic" or "lees-edwards"
  std::uint64_t seed = 0;
  std::string version;
  // Per-particle diameters and masses of a polydisperse run (empty otherwise); a read fills them
  // into the frame's ParticleState instead and sets `polydisperse`.
  std::vector<double> diameters, masses;
  bool polydisperse = false;
};

struct SnapshotFrame {
  ParticleState particles;
  ClockState clock;
  double collisions_per_particle = 0.0;
  double shear_offset = 0.0;  // Lees–Edwards image offset Δ ∈ [0, L_x)
  double strain = 0.0;        // strain of the sheared cell grid (restart state)
  double shear_velocity = 0.0;  // U(t): the images' velocity at this frame (shear protocol)
};

class SnapshotWriter {
 public:
  static constexpr std::int64_t kCompleteFrames = -1;

  // Starts `path`.partial (replacing any earlier partial file).
  SnapshotWriter(const std::string& path, const SnapshotMetadata& metadata);
  // Continues `path` (resume): reopens `path`.partial, or the published `path` renamed back to
  // `path`.partial (not copied), keeping its first `keep_frames` frames (kCompleteFrames: every
  // frame all datasets hold); later frames are appended after them and finish() publishes the
  // file again.  Throws InputError when the file holds fewer complete frames.
  explicit SnapshotWriter(const std::string& path, std::int64_t keep_frames = kCompleteFrames);
  ~SnapshotWriter();  // a writer not finished leaves `path`.partial, closed
  SnapshotWriter(const SnapshotWriter&) = delete;
  SnapshotWriter& operator=(const SnapshotWriter&) = delete;

  void append(const SnapshotFrame& frame);
  // A frame whose particles (frame.particles is not read) come in blocks (a frame of 10^8 disks
  // needs no copy of the whole state).
  void append(const SnapshotFrame& frame, const StateBlocks& particles);
  std::int64_t frames() const;
  // Close and rename to the final name.
  void finish();

 private:
  std::unique_ptr<h5::PartialFile> file_;
  std::int64_t particles_ = 0;
  bool tc_ = false;
  bool rough_ = false;
};

struct SnapshotRead {
  SnapshotMetadata metadata;
  SnapshotFrame frame;
  std::int64_t frames = 0;  // complete frames in the file
};

// Reads frame `index` (negative counts from the end) of a snapshot file, `.partial` or published.
// Throws IoError when the file cannot be read, std::runtime_error when it is not a snapshot file
// or has no such frame.
SnapshotRead read_snapshot(const std::string& path, std::int64_t index = -1);

}  // namespace granule
