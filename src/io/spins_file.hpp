// The file of `granule analyze spins` (format "granule-spins", schema in the README): the spin
// correlation C(r) of neighbouring grains (analysis/spin_correlation.hpp, thesis Fig C.4) per frame
// of a run's snapshots and over them all, overall and split along the flow and the gradient, with
// C_contact and its frame-to-frame error.  Written as `<path>.partial`, published once complete.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

#include "analysis/spin_correlation.hpp"
#include "io/file_schema.hpp"
#include "io/hdf5_util.hpp"
#include "io/snapshot_file.hpp"

namespace granule {

namespace spins_file {

// The split of the pairs by direction: the suffix of its datasets, in PairDirection's order.
inline constexpr const char* kDirectionSuffixes[kPairDirections] = {"", "_flow", "_gradient"};

// What spins.h5 holds (io/file_schema.hpp), checked before a figure script or a study reads it.
const h5::FileSchema& spins_schema();

}  // namespace spins_file

// Where the pairs of a frame of a run have their images: the box, its walls, the frame's
// Lees–Edwards offset (none across y walls, which replace the sheared images).
PairImages pair_images_of(const SystemParams& system, const SnapshotFrame& frame);

class SpinsFile {
 public:
  SpinsFile(const std::string& path, const std::string& source, const SnapshotMetadata& metadata,
            const SpinCorrelationSettings& settings);
  void append(std::int64_t index, const SnapshotFrame& frame, const SpinPairSums& sums);
  // The average over the frames, C_contact with its error, then the file under its final name.
  void publish(const SpinCorrelationAverage& average);

 private:
  h5::PartialFile partial_;
  hid_t file_;  // partial_'s identifier, owned by it
  std::size_t bins_;
};

// What a study reads of a spins.h5 (checked against its schema first; InputError otherwise).
struct SpinsSummary {
  double contact = 0.0, contact_error = 0.0, contact_pairs = 0.0;
  std::int64_t frames = 0;
  std::vector<double> r;  // bin centres, in contact distances
  std::vector<double> correlation[kPairDirections];  // the average C(r) of each direction
};
SpinsSummary read_spins_summary(const std::string& path);

}  // namespace granule
