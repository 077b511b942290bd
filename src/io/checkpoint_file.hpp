// Checkpoint files (schema in README.md, "checkpoint.h5"): a StateArchive stored as one HDF5
// dataset per entry (the entry name is the dataset path, so "engine/x" lands in group engine).
// Written to `<path>.partial` and renamed, so a crash at any moment leaves the previous complete
// checkpoint in place.
#pragma once

#include <string>

#include "archive/state_archive.hpp"

namespace granule {

void write_checkpoint(const std::string& path, const StateArchive& archive, const std::string& granule_version);
// Throws InputError, naming the file and the entry, when the file is missing, damaged (a dataset
// whose values do not give the digest written with them) or not a checkpoint of this format.
StateArchive read_checkpoint(const std::string& path);

}  // namespace granule
