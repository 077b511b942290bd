// The helpers that io/hdf5_util.cpp and io/hdf5_frames.cpp share, private to those two files:
// opening files and datasets and reading shapes, every failure an IoError naming the object.
#pragma once

#include <string>
#include <vector>

#include "io/hdf5_util.hpp"

namespace granule::h5 {

// A file opened with Granule's access properties (the journaled driver when flags is
// H5F_ACC_RDWR); the caller owns the identifier.
hid_t open_existing(const std::string& path, unsigned flags);
Handle open_dataset(hid_t file, const char* name);
// A dataset's dimensions, and its maximal dimensions into *max when given.
std::vector<hsize_t> extent(hid_t dataset, const char* name, std::vector<hsize_t>* max = nullptr);

}  // namespace granule::h5
