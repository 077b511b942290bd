#include "io/run_files.hpp"

#include <fmt/format.h>

#include <filesystem>

#include "io/hdf5_util.hpp"
#include "io/io_error.hpp"

namespace granule {

namespace fs = std::filesystem;

std::string locate_run_file(const std::string& run_dir_or_file, const std::string& name) {
  if (!fs::exists(run_dir_or_file)) throw InputError(fmt::format("{} does not exist (give a run directory or a file)", run_dir_or_file));
  if (!fs::is_directory(run_dir_or_file)) return run_dir_or_file;
  for (const std::string& candidate : {name, name + ".partial"}) {
    const fs::path path = fs::path(run_dir_or_file) / candidate;
    if (fs::exists(path)) return path.string();
  }
  throw InputError(fmt::format("{} has no {}", run_dir_or_file, name));
}

std::string output_beside(const std::string& run_dir_or_file, const std::string& name) {
  const fs::path base(run_dir_or_file);
  return ((fs::is_directory(base) ? base : base.parent_path()) / name).string();
}

std::string snapshots_beside(const std::string& path) {
  for (const char* name : {"snapshots.h5", "snapshots.h5.partial"}) {
    const fs::path candidate = fs::path(path).parent_path() / name;
    if (fs::exists(candidate)) return candidate.string();
  }
  return "";
}

// A file that is not HDF5, or a damaged one, is refused by the reading layer (InputError).
std::string hdf5_format(const std::string& path) {
  h5::Handle file = h5::open_file(path);
  const std::string format = h5::has_attribute(file.get(), "format") ? h5::read_string_attribute(file.get(), "format") : "";
  file.close();
  return format;
}

int hdf5_dimension(const std::string& path) {
  h5::Handle file = h5::open_file(path);
  const int dimension = h5::has_attribute(file.get(), "dimension") ? h5::read_attribute<int>(file.get(), "dimension", H5T_NATIVE_INT) : 2;
  file.close();
  return dimension;
}

void require_hdf5_format(const std::string& path, const char* format, const char* producer) {
  if (hdf5_format(path) != format) throw InputError(fmt::format("{} is not a {} file (written by {})", path, format, producer));
}

}  // namespace granule
