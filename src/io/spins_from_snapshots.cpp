#include "io/spins_from_snapshots.hpp"

#include <memory>
#include <stdexcept>

#include "io/io_error.hpp"
#include "io/spins_file.hpp"

namespace granule {

SpinCorrelationAverage spins_from_snapshots(const SpinsRequest& request, const SnapshotRead& first,
                                            const std::vector<std::int64_t>& frames) {
  const SystemParams& system = first.metadata.system;
  SpinCorrelationAverage average;
  std::unique_ptr<SpinsFile> file;  // made after the first frame's sums: a refusal writes nothing
  for (const std::int64_t index : frames) {
    const SnapshotRead snapshot = index == 0 ? first : read_snapshot(request.snapshots, index);
    SpinPairSums sums;
    try {
      sums = spin_pair_sums(snapshot.frame.particles, pair_images_of(system, snapshot.frame), system.diameter, request.settings);
    } catch (const std::invalid_argument& refused) {
      throw InputError(request.snapshots + ": " + refused.what());
    }
    if (!file) file = std::make_unique<SpinsFile>(request.out, request.snapshots, first.metadata, request.settings);
    file->append(index, snapshot.frame, sums);
    average.add(sums);
  }
  if (file) file->publish(average);
  return average;
}

}  // namespace granule
