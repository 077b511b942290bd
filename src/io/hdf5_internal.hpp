// The helpers that io/hdf5_util.cpp, io/hdf5_frames.cpp and io/hdf5_read.cpp share, private to
// those files: opening files and datasets, reading shapes, selecting a frame, naming what failed.
#pragma once

#include <string>
#include <vector>

#include "io/hdf5_util.hpp"

namespace granule::h5 {

// A file opened with Granule's access properties (the journaled driver when flags is
// H5F_ACC_RDWR); the caller owns the identifier.  Throws IoError (reading: InputError).
hid_t open_existing(const std::string& path, unsigned flags);
Handle open_dataset(hid_t file, const char* name);
// A dataset's dimensions, and its maximal dimensions into *max when given.
std::vector<hsize_t> extent(hid_t dataset, const char* name, std::vector<hsize_t>* max = nullptr);
// Creation properties of a chunked dataset without modification times, its chunks of shape
// `chunk` with axis `cut` shortened to hold at most 1 MiB of doubles, each chunk checksummed
// (Fletcher-32, verified by HDF5 on every read); plain properties when a dimension is 0.
Handle checksummed_creation_properties(std::vector<hsize_t> chunk, std::size_t cut, hid_t location, const char* name);
// Paths of the per-frame datasets: those with an unlimited first dimension (create_frames).
std::vector<std::string> frame_datasets(hid_t file);
// Selects in `space` (a dataset of shape `dims`) frame `frame`, or only its rows first_row ..
// first_row + rows - 1 (rows = kAllRows: the whole frame); returns the shape of the selection.
constexpr hsize_t kAllRows = 0;
std::vector<hsize_t> select_frame(hid_t space, const std::vector<hsize_t>& dims, hsize_t frame, hsize_t first_row,
                                  hsize_t rows, hid_t file, const char* name);
// Reads the file at `path` in a child process first and throws InputError when the child could not
// read it to the end (an error, a crash or a hang of the HDF5 library on a damaged file); once per
// process for an unchanged file (io/hdf5_preflight.cpp).
void preflight(const std::string& path);
// The reason of the failure HDF5 just reported (clears HDF5's error stack: call it first).
std::string failure_reason();

}  // namespace granule::h5
