#include "io/hdf5_util.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "io/atomic_file.hpp"
#include "io/io_error.hpp"
#include "io/journaled_file_driver.hpp"

namespace granule::h5 {

namespace {

// HDF5 1.10 frees a file whose close failed (a full disk) but keeps its identifier, and its exit
// handler then closes it again and crashes.  Granule closes every file itself, so the handler is
// not installed (this must run before the library's first use: at static initialisation).
[[maybe_unused]] const herr_t kNoExitHandler = H5dont_atexit();

// Errors are reported through exceptions, not printed by HDF5 (stderr keeps one clear line).
void silence_hdf5_errors() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

// The reason of the failure just reported: the system's own words when HDF5 quotes them (its
// file drivers do, e.g. "No space left on device"), else the innermost HDF5 message.  Clears
// HDF5's error stack, so it must be called before any other HDF5 function.
std::string failure_reason() {
  struct Reason {
    std::string system, innermost;
  } reason;
  const auto collect = [](unsigned depth, const H5E_error2_t* error, void* data) -> herr_t {
    auto& r = *static_cast<Reason*>(data);
    const std::string text = error->desc ? error->desc : "";
    if (depth == 0) r.innermost = text;
    constexpr std::string_view marker = "error message = '";
    const std::size_t at = text.find(marker);
    if (r.system.empty() && at != std::string::npos) {
      const std::size_t from = at + marker.size();
      r.system = text.substr(from, text.find('\'', from) - from);
    }
    return 0;
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, collect, &reason);
  H5Eclear2(H5E_DEFAULT);
  if (!reason.system.empty()) return reason.system;
  return reason.innermost.empty() ? "HDF5 gave no reason" : "HDF5: " + reason.innermost;
}

template <typename Query>
std::string name_of(Query&& query) {
  const ssize_t length = query(nullptr, 0);
  if (length <= 0) return {};
  std::string name(static_cast<std::size_t>(length), '\0');
  query(name.data(), name.size() + 1);
  return name;
}

std::string file_name(hid_t object) {
  return name_of([&](char* buffer, std::size_t size) { return H5Fget_name(object, buffer, size); });
}

// The file an object belongs to, as " in <file>" (empty when it belongs to none).
std::string in_file(hid_t object) {
  const std::string file = file_name(object);
  return file.empty() ? std::string() : " in " + file;
}

// Throws IoError "cannot <action> <name> in <file>: <reason>" ("cannot <action> <file>: ..."
// without a name).
[[noreturn]] void fail(hid_t location, const char* action, const char* name) {
  const std::string reason = failure_reason();
  std::string where = name;
  const std::string file = file_name(location);
  if (!file.empty()) where += (where.empty() ? "" : " in ") + file;
  throw IoError("cannot " + std::string(action) + " " + where + ": " + reason);
}

[[noreturn]] void fail_path(const std::string& what, const std::string& path) {
  const std::string reason = failure_reason();
  throw IoError("cannot " + what + " " + path + ": " + reason);
}

// What a close would report: "file <f>", "dataset </name> in <f>", "group ...".
std::string describe(hid_t object) {
  const H5I_type_t type = H5Iget_type(object);
  const std::string path = name_of([&](char* buffer, std::size_t size) { return H5Iget_name(object, buffer, size); });
  switch (type) {
    case H5I_FILE: return "file " + file_name(object);
    case H5I_DATASET: return "dataset " + path + in_file(object);
    case H5I_GROUP: return "group " + path + in_file(object);
    default: return "HDF5 object";
  }
}

// File access with the "semi" close degree: closing a file with objects still open fails instead of
// leaving it open (and unflushed) behind a successful close, so a published file is a closed one.
// A file opened for writing goes through the journaled driver, whose flushes are atomic: a run
// killed while HDF5 flushed left chunk indices pointing to nodes never written
// (io/journaled_file_driver.hpp).
Handle access_properties(const std::string& path, bool writing) {
  Handle properties = owned(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, H5I_INVALID_HID, "create access properties of", path.c_str());
  check(H5Pset_fclose_degree(properties.get(), H5F_CLOSE_SEMI), H5I_INVALID_HID, "set the access properties of", path.c_str());
  if (writing) {
    check(H5Pset_driver(properties.get(), journaled_file_driver(), nullptr), H5I_INVALID_HID, "set the file driver of",
          path.c_str());
  }
  return properties;
}

hid_t open_existing(const std::string& path, unsigned flags) {
  silence_hdf5_errors();
  Handle properties = access_properties(path, flags == H5F_ACC_RDWR);
  const hid_t file = H5Fopen(path.c_str(), flags, properties.get());
  if (file < 0) fail_path("open", path);
  return file;
}

Handle open_dataset(hid_t file, const char* name) { return owned(H5Dopen2(file, name, H5P_DEFAULT), H5Dclose, file, "open dataset", name); }

std::vector<hsize_t> extent(hid_t dataset, const char* name, std::vector<hsize_t>* max = nullptr) {
  Handle space = owned(H5Dget_space(dataset), H5Sclose, dataset, "get the shape of", name);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) fail(dataset, "get the rank of", name);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (max) max->resize(dims.size());
  check(H5Sget_simple_extent_dims(space.get(), dims.data(), max ? max->data() : nullptr), dataset, "get the shape of", name);
  space.close();
  return dims;
}

// Paths of the per-frame datasets: those with an unlimited first dimension (create_frames).
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

}  // namespace

Handle owned(hid_t id, Handle::Closer closer, hid_t location, const char* action, const char* name) {
  return Handle(check_id(id, location, action, name), closer);
}

// Creation properties of a dataset, group or file without modification times (object headers
// otherwise hold the time of creation, and two equal runs would give different files).
Handle untimed_creation_properties(hid_t property_class, hid_t location, const char* name) {
  Handle properties = owned(H5Pcreate(property_class), H5Pclose, location, "create properties of", name);
  check(H5Pset_obj_track_times(properties.get(), false), location, "set the properties of", name);
  return properties;
}

Handle& Handle::operator=(Handle&& other) noexcept {
  if (this != &other) {
    discard();
    closer_ = other.closer_;
    id_ = other.release();
  }
  return *this;
}

void Handle::close() {
  if (id_ < 0) return;
  const std::string what = describe(id_);  // asked before: after a close the identifier is gone
  if (closer_(release()) < 0) {
    const std::string reason = failure_reason();
    throw IoError("cannot close " + what + ": " + reason);
  }
}

hid_t Handle::release() { return std::exchange(id_, -1); }

void Handle::discard() noexcept {
  if (id_ < 0) return;
  closer_(release());
  H5Eclear2(H5E_DEFAULT);
}

void check(herr_t status, hid_t location, const char* action, const char* name) {
  if (status < 0) fail(location, action, name);
}

hid_t check_id(hid_t id, hid_t location, const char* action, const char* name) {
  if (id < 0) fail(location, action, name);
  return id;
}

void write_attribute(hid_t object, const char* name, hid_t type, const void* data, hsize_t count) {
  Handle space = owned(count == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &count, nullptr), H5Sclose, object,
                       "describe attribute", name);
  Handle attribute = owned(H5Acreate2(object, name, type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose, object,
                           "create attribute", name);
  check(H5Awrite(attribute.get(), type, data), object, "write attribute", name);
  attribute.close();
  space.close();
}

void write_string_attribute(hid_t object, const char* name, const std::string& value) {
  Handle type = owned(H5Tcopy(H5T_C_S1), H5Tclose, object, "make the string type of", name);
  check(H5Tset_size(type.get(), value.size() + 1), object, "size the string type of", name);
  check(H5Tset_strpad(type.get(), H5T_STR_NULLTERM), object, "make the string type of", name);
  write_attribute(object, name, type.get(), value.c_str());
  type.close();
}

void read_attribute_values(hid_t object, const char* name, hid_t type, void* data) {
  Handle attribute = owned(H5Aopen(object, name, H5P_DEFAULT), H5Aclose, object, "open attribute", name);
  check(H5Aread(attribute.get(), type, data), object, "read attribute", name);
  attribute.close();
}

std::string read_string_attribute(hid_t object, const char* name) {
  Handle attribute = owned(H5Aopen(object, name, H5P_DEFAULT), H5Aclose, object, "open attribute", name);
  Handle stored = owned(H5Aget_type(attribute.get()), H5Tclose, object, "get the type of attribute", name);
  Handle memory = owned(H5Tcopy(H5T_C_S1), H5Tclose, object, "make the string type of", name);
  std::vector<char> buffer(H5Tget_size(stored.get()) + 1, '\0');
  check(H5Tset_size(memory.get(), buffer.size()), object, "size the string type of", name);
  check(H5Aread(attribute.get(), memory.get(), buffer.data()), object, "read attribute", name);
  memory.close();
  stored.close();
  attribute.close();
  return buffer.data();
}

Handle open_file(const std::string& path) { return Handle(open_existing(path, H5F_ACC_RDONLY), H5Fclose); }

hid_t create_partial_file(const std::string& path, const char* format, int format_version, const std::string& granule_version) {
  silence_hdf5_errors();
  const std::string partial = path + ".partial";
  Handle creation = untimed_creation_properties(H5P_FILE_CREATE, H5I_INVALID_HID, partial.c_str());
  Handle access = access_properties(partial, true);
  const hid_t id = H5Fcreate(partial.c_str(), H5F_ACC_TRUNC, creation.get(), access.get());
  if (id < 0) fail_path("create", partial);
  Handle file(id, H5Fclose);
  access.close();
  creation.close();
  write_string_attribute(file.get(), "format", format);
  write_attribute(file.get(), "format_version", H5T_NATIVE_INT, &format_version);
  write_string_attribute(file.get(), "granule_version", granule_version);
  return file.release();
}

void publish_partial_file(hid_t file, const std::string& path) {
  Handle(file, H5Fclose).close();
  publish_file(path + ".partial", path);
}

hid_t create_frames(hid_t file, const char* name, hid_t type, std::vector<hsize_t> row) {
  std::vector<hsize_t> dims{0}, max{H5S_UNLIMITED}, chunk{1};
  for (hsize_t d : row) {
    dims.push_back(d);
    max.push_back(d);
    chunk.push_back(d);
  }
  // A chunk holds at most kChunkEntries entries of a frame (1 MiB of doubles, HDF5's default chunk
  // cache): a frame of 10^8 disks written block by block then needs no buffer of a whole frame
  // inside HDF5, and no chunk reaches HDF5's limit of 4 GiB.
  constexpr hsize_t kChunkEntries = hsize_t{1} << 17;
  if (chunk.size() > 1) {
    hsize_t per_row = 1;
    for (std::size_t k = 2; k < chunk.size(); ++k) per_row *= chunk[k];
    chunk[1] = std::clamp<hsize_t>(kChunkEntries / std::max<hsize_t>(per_row, 1), 1, std::max<hsize_t>(chunk[1], 1));
  }
  Handle space = owned(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), max.data()), H5Sclose, file,
                       "describe dataset", name);
  Handle properties = untimed_creation_properties(H5P_DATASET_CREATE, file, name);
  check(H5Pset_chunk(properties.get(), static_cast<int>(chunk.size()), chunk.data()), file, "set the chunks of", name);
  Handle dataset = owned(H5Dcreate2(file, name, type, space.get(), H5P_DEFAULT, properties.get(), H5P_DEFAULT), H5Dclose,
                         file, "create dataset", name);
  properties.close();
  space.close();
  return dataset.release();
}

void add_frames(hid_t file, const char* name, hid_t type, std::vector<hsize_t> row) {
  Handle(create_frames(file, name, type, std::move(row)), H5Dclose).close();
}

void transfer_frame(hid_t file, const char* name, hid_t type, void* data, hsize_t frame, bool grow, hsize_t first_row,
                    hsize_t rows) {
  Handle dataset = open_dataset(file, name);
  std::vector<hsize_t> dims = extent(dataset.get(), name);
  if (grow) {
    dims[0] = frame + 1;
    check(H5Dset_extent(dataset.get(), dims.data()), file, "extend dataset", name);
  } else if (frame >= dims[0]) {
    throw std::out_of_range("dataset " + std::string(name) + " has no frame " + std::to_string(frame));
  }
  Handle space = owned(H5Dget_space(dataset.get()), H5Sclose, file, "get the shape of", name);
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
  check(H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr), file,
        "select a frame of", name);
  Handle memory = owned(H5Screate_simple(static_cast<int>(count.size()), count.data(), nullptr), H5Sclose, file,
                        "describe a frame of", name);
  if (grow) {
    check(H5Dwrite(dataset.get(), type, memory.get(), space.get(), H5P_DEFAULT, data), file, "write dataset", name);
  } else {
    check(H5Dread(dataset.get(), type, memory.get(), space.get(), H5P_DEFAULT, data), file, "read dataset", name);
  }
  memory.close();
  space.close();
  dataset.close();
}

std::vector<hsize_t> dataset_shape(hid_t location, const char* name) {
  Handle dataset = open_dataset(location, name);
  std::vector<hsize_t> dims = extent(dataset.get(), name);
  dataset.close();
  return dims;
}

void append_frame(hid_t file, const char* name, hid_t type, const void* data, hsize_t frame) {
  transfer_frame(file, name, type, const_cast<void*>(data), frame, true);
}

void append_frame_rows(hid_t file, const char* name, hid_t type, const void* data, hsize_t frame, hsize_t first_row,
                       hsize_t rows) {
  transfer_frame(file, name, type, const_cast<void*>(data), frame, true, first_row, rows);
}

void read_frame(hid_t file, const char* name, hid_t type, void* data, hsize_t frame) {
  transfer_frame(file, name, type, data, frame, false);
}

std::int64_t complete_frames(hid_t file) {
  const std::vector<std::string> datasets = frame_datasets(file);
  hsize_t frames = datasets.empty() ? 0 : std::numeric_limits<hsize_t>::max();
  for (const std::string& name : datasets) frames = std::min(frames, dataset_shape(file, name.c_str())[0]);
  return static_cast<std::int64_t>(frames);
}

std::int64_t complete_frames(const std::string& path) {
  Handle file = open_file(path);
  const std::int64_t frames = complete_frames(file.get());
  file.close();
  return frames;
}

PartialFile::PartialFile(const std::string& path, const char* format, int format_version, const std::string& granule_version)
    : path_(path), file_(create_partial_file(path, format, format_version, granule_version), H5Fclose) {}

PartialFile::PartialFile(const std::string& path, const char* format, std::int64_t keep_frames) : path_(path) {
  const std::string partial = path + ".partial";
  const bool published = !std::filesystem::exists(partial);
  const std::string current = published ? path : partial;
  if (!published) replay_journal(partial);  // the last flush of a killed run, before anything reads the file
  {
    Handle file = open_file(current);
    if (read_string_attribute(file.get(), "format") != format) {
      throw std::invalid_argument(current + " is not a " + format + " file");
    }
    frames_ = complete_frames(file.get());
    file.close();
  }
  if (keep_frames > frames_) {
    throw std::invalid_argument(current + " holds " + std::to_string(frames_) + " complete frames, not " +
                                std::to_string(keep_frames));
  }
  if (keep_frames >= 0) frames_ = keep_frames;
  // Renamed, not copied: a resumed run must not need the disk space of a second copy.
  if (published && std::rename(path.c_str(), partial.c_str()) != 0) {
    throw io_error("cannot rename " + path + " to " + partial, errno);
  }
  file_ = Handle(open_existing(partial, H5F_ACC_RDWR), H5Fclose);
  // HDF5's flushes do not always rewrite the superblock's end of the file: a killed run's chunk
  // index may point to chunks beyond it, which HDF5 then refuses ("addr overflow").  The end moves
  // to the bytes on disk, where every chunk an index on disk refers to lies.
  check(H5Fincrement_filesize(file_.get(), 0), file_.get(), "extend to its bytes on disk", partial.c_str());
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

void write_dataset(hid_t location, const char* name, const std::vector<hsize_t>& dims, const std::vector<double>& data) {
  Handle space = owned(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose, location,
                       "describe dataset", name);
  Handle properties = untimed_creation_properties(H5P_DATASET_CREATE, location, name);
  Handle dataset = owned(H5Dcreate2(location, name, H5T_NATIVE_DOUBLE, space.get(), H5P_DEFAULT, properties.get(), H5P_DEFAULT),
                         H5Dclose, location, "create dataset", name);
  // An empty dataset (a window that collected nothing) has no buffer to write: HDF5 refuses one.
  if (!data.empty()) {
    check(H5Dwrite(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), location, "write dataset", name);
  }
  dataset.close();
  properties.close();
  space.close();
}

void write_vector(hid_t location, const char* name, const std::vector<double>& data) {
  write_dataset(location, name, {static_cast<hsize_t>(data.size())}, data);
}

std::vector<double> read_vector(hid_t location, const char* name) {
  const std::vector<hsize_t> shape = dataset_shape(location, name);
  if (shape.size() != 1) throw IoError("dataset " + std::string(name) + " in " + file_name(location) + " is not one-dimensional");
  std::vector<double> values(static_cast<std::size_t>(shape[0]));
  Handle dataset = open_dataset(location, name);
  if (!values.empty()) {
    check(H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), location, "read dataset", name);
  }
  dataset.close();
  return values;
}

bool has_attribute(hid_t object, const char* name) { return H5Aexists(object, name) > 0; }
bool has_link(hid_t location, const char* name) { return H5Lexists(location, name, H5P_DEFAULT) > 0; }

hid_t create_group(hid_t location, const char* name) {
  Handle properties = untimed_creation_properties(H5P_GROUP_CREATE, location, name);
  Handle group = owned(H5Gcreate2(location, name, H5P_DEFAULT, properties.get(), H5P_DEFAULT), H5Gclose, location,
                       "create group", name);
  properties.close();
  return group.release();
}

}  // namespace granule::h5
