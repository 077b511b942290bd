// Per-frame datasets (snapshots, fields, collision statistics, spectra): their creation, one frame
// written or read at a time, the count of complete frames, and the `<path>.partial` file that a
// run grows frame by frame and a resumed run reopens and cuts back (io/hdf5_util.hpp).
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <utility>

#include "io/hdf5_internal.hpp"
#include "io/hdf5_util.hpp"
#include "io/io_error.hpp"

namespace granule::h5 {

std::vector<std::string> frame_datasets(hid_t file) {
  std::vector<std::string> datasets;
  const auto visit = [](hid_t, const char* name, const H5O_info_t* info, void* data) -> herr_t {
    if (info->type == H5O_TYPE_DATASET) static_cast<std::vector<std::string>*>(data)->push_back(name);
    return 0;
  };
  check(H5Ovisit2(file, H5_INDEX_NAME, H5_ITER_INC, visit, &datasets, H5O_INFO_BASIC), file, "list the datasets", "");
  std::erase_if(datasets, [&](const std::string& name) {
    Handle dataset = open_dataset(file, name.c_str());
    std::vector<hsize_t> max;
    const std::vector<hsize_t> dims = extent(dataset.get(), name.c_str(), &max);
    dataset.close();
    return dims.empty() || max[0] != H5S_UNLIMITED;
  });
  return datasets;
}

hid_t create_frames(hid_t file, const char* name, hid_t type, std::vector<hsize_t> row) {
  std::vector<hsize_t> dims{0}, max{H5S_UNLIMITED}, chunk{1};
  for (hsize_t d : row) {
    dims.push_back(d);
    max.push_back(d);
    chunk.push_back(d);
  }
  Handle space = owned(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), max.data()), H5Sclose, file,
                       "describe dataset", name);
  // One frame per chunk at most, its rows cut to fit.
  Handle properties = checksummed_creation_properties(chunk, chunk.size() > 1 ? 1 : 0, file, name);
  Handle dataset = owned(H5Dcreate2(file, name, type, space.get(), H5P_DEFAULT, properties.get(), H5P_DEFAULT), H5Dclose,
                         file, "create dataset", name);
  properties.close();
  space.close();
  return dataset.release();
}

void add_frames(hid_t file, const char* name, hid_t type, std::vector<hsize_t> row) {
  Handle(create_frames(file, name, type, std::move(row)), H5Dclose).close();
}

void append_frame_rows(hid_t file, const char* name, hid_t type, const void* data, hsize_t frame, hsize_t first_row,
                       hsize_t rows) {
  Handle dataset = open_dataset(file, name);
  std::vector<hsize_t> dims = extent(dataset.get(), name);
  dims[0] = frame + 1;
  check(H5Dset_extent(dataset.get(), dims.data()), file, "extend dataset", name);
  Handle space = owned(H5Dget_space(dataset.get()), H5Sclose, file, "get the shape of", name);
  const std::vector<hsize_t> count = select_frame(space.get(), dims, frame, first_row, rows, file, name);
  Handle memory = owned(H5Screate_simple(static_cast<int>(count.size()), count.data(), nullptr), H5Sclose, file,
                        "describe a frame of", name);
  check(H5Dwrite(dataset.get(), type, memory.get(), space.get(), H5P_DEFAULT, data), file, "write dataset", name);
  memory.close();
  space.close();
  dataset.close();
}

void append_frame(hid_t file, const char* name, hid_t type, const void* data, hsize_t frame) {
  append_frame_rows(file, name, type, data, frame, 0, kAllRows);
}

std::vector<hsize_t> select_frame(hid_t space, const std::vector<hsize_t>& dims, hsize_t frame, hsize_t first_row,
                                  hsize_t rows, hid_t file, const char* name) {
  std::vector<hsize_t> start(dims.size(), 0), count = dims;
  start[0] = frame;
  count[0] = 1;
  if (rows != kAllRows) {
    if (dims.size() < 2 || first_row + rows > dims[1]) {
      throw std::out_of_range("dataset " + std::string(name) + " has no rows " + std::to_string(first_row) + " + " +
                              std::to_string(rows));
    }
    start[1] = first_row;
    count[1] = rows;
  }
  check(H5Sselect_hyperslab(space, H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr), file,
        "select a frame of", name);
  return count;
}

PartialFile::PartialFile(const std::string& path, const char* format, int format_version, const std::string& granule_version)
    : path_(path), file_(create_partial_file(path, format, format_version, granule_version), H5Fclose) {}

namespace {

// Opens a partial file for growing.  The driver applies a journal a killed run left behind
// (io/journaled_file_driver.hpp).  HDF5's flushes do not always rewrite the superblock's end of
// allocated space, so a killed run's chunk index may point beyond the end the superblock states
// ("addr overflow": H5Dget_storage_size then reports 0 bytes).  The end moves to the bytes on
// disk, where everything an index on disk refers to lies.
Handle open_for_growth(const std::string& partial) {
  Handle file(open_existing(partial, H5F_ACC_RDWR), H5Fclose);
  check(H5Fincrement_filesize(file.get(), 0), file.get(), "extend to its bytes on disk", partial.c_str());
  return file;
}

}  // namespace

void recover_partial_file(const std::string& partial) { open_for_growth(partial).close(); }

PartialFile::PartialFile(const std::string& path, const char* format, std::int64_t keep_frames) : path_(path) {
  const std::string partial = path + ".partial";
  const bool published = !std::filesystem::exists(partial);
  const std::string current = published ? path : partial;
  if (!published) recover_partial_file(partial);
  {
    Handle file = open_file(current);
    if (read_string_attribute(file.get(), "format") != format) {
      throw InputError(current + " is not a " + format + " file");
    }
    frames_ = complete_frames(file.get(), keep_frames);
    file.close();
  }
  if (keep_frames > frames_) {
    throw InputError(current + " holds " + std::to_string(frames_) + " complete frames, not " +
                                std::to_string(keep_frames));
  }
  if (keep_frames >= 0) frames_ = keep_frames;
  // Renamed, not copied: a resumed run must not need the disk space of a second copy.
  if (published && std::rename(path.c_str(), partial.c_str()) != 0) {
    throw io_error("cannot rename " + path + " to " + partial, errno);
  }
  file_ = open_for_growth(partial);
  for (const std::string& name : frame_datasets(file_.get())) {
    Handle dataset = open_dataset(file_.get(), name.c_str());
    std::vector<hsize_t> dims = extent(dataset.get(), name.c_str());
    if (dims[0] != static_cast<hsize_t>(frames_)) {
      dims[0] = static_cast<hsize_t>(frames_);
      check(H5Dset_extent(dataset.get(), dims.data()), file_.get(), "truncate dataset", name.c_str());
    }
    dataset.close();
  }
  flush();
}

void PartialFile::flush() { check(H5Fflush(file_.get(), H5F_SCOPE_GLOBAL), file_.get(), "flush", ""); }

void PartialFile::end_frame() {
  flush();
  ++frames_;
}

void PartialFile::publish() {
  if (file_.get() < 0) return;
  publish_partial_file(file_.release(), path_);
}

}  // namespace granule::h5
