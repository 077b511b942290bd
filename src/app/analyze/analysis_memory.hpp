// The memory check of an analysis of a run's snapshots, made before the analysis allocates
// anything: an analysis the machine cannot hold is refused with exit 5 (README, "Exit codes") by
// a message that names the option asking for it, instead of running until the kernel kills it.
#pragma once

#include <optional>
#include <string>

#include "io/snapshot_file.hpp"

namespace granule::app {

// What reading another frame like `frame` allocates: the analyses read each frame they use while
// the command keeps frame 0.
double frame_copy_bytes(const SnapshotFrame& frame);

// kExitOutOfMemory, after printing "granule analyze `command`: error: `what` needs about … GiB",
// when `needed_bytes` exceed the available memory (driver::require_memory); else nothing.
std::optional<int> refused_for_memory(const std::string& command, double needed_bytes, const std::string& what);

}  // namespace granule::app
