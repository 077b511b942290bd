// A run's files as the analyses and pictures find them: a run directory or one of its files, the
// name of an output beside it, and what an HDF5 file declares in its root attributes (its format,
// its dimension).  What cannot be found or read as asked throws InputError.
#pragma once

#include <string>

#include "io/io_error.hpp"

namespace granule {

// RUN_DIR_or_FILE → the file: a directory gives `<dir>/<name>` (or `<name>.partial` while the run
// is still going), a file is itself.  Throws InputError when there is no such file.
std::string locate_run_file(const std::string& run_dir_or_file, const std::string& name);

// Default output: `<dir>/<name>` for a run directory, `<file's folder>/<name>` for a file.
std::string output_beside(const std::string& run_dir_or_file, const std::string& name);

// The snapshot file beside another file of a run (snapshots.h5, or its .partial), "" if none.
std::string snapshots_beside(const std::string& path);

// The root attribute `format` of an HDF5 file ("" without one); throws InputError when `path` is not HDF5.
std::string hdf5_format(const std::string& path);
// The root attribute `dimension` of a snapshot or fields file: 3 for a run of spheres, 2 (also when
// absent: 2D files need not carry it) for disks.  Throws InputError when `path` is not HDF5.
int hdf5_dimension(const std::string& path);
// Throws InputError unless `path` is an HDF5 file whose root attribute `format` is `format`.
void require_hdf5_format(const std::string& path, const char* format, const char* producer);

}  // namespace granule
