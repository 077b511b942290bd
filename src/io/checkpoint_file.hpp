// Checkpoint files (schema in README.md, "checkpoint.h5"): a StateArchive stored as one HDF5
// dataset per entry (the entry name is the dataset path, so "engine/x" lands in group engine).
// Written to `<path>.partial` and renamed, so a crash at any moment leaves the previous complete
// checkpoint in place.
#pragma once

#include <string>

#include "archive/state_archive.hpp"

namespace granule {

void write_checkpoint(const std::string& path, const StateArchive& archive, const std::string& granule_version);
// Throws std::runtime_error when the file is missing, damaged or not a Granule checkpoint.
StateArchive read_checkpoint(const std::string& path);

}  // namespace granule
