#include "app/analyze/analysis_memory.hpp"

#include <fmt/format.h>

#include "app/exit_codes.hpp"
#include "driver/run_beginnings.hpp"

namespace granule::app {

double frame_copy_bytes(const SnapshotFrame& frame) {
  const std::size_t collision_times = frame.clock.last_collision.size() * sizeof(double);  // the TC model's
  return static_cast<double>(frame.particles.array_bytes() + collision_times);
}

std::optional<int> refused_for_memory(const std::string& command, double needed_bytes, const std::string& what) {
  try {
    driver::require_memory(needed_bytes, what);
  } catch (const driver::NotEnoughMemory& refused) {
    fmt::print(stderr, "granule analyze {}: error: {}\n", command, refused.what());
    return kExitOutOfMemory;
  }
  return std::nullopt;
}

}  // namespace granule::app
