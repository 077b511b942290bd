#include "io/hdf5_util.hpp"

#include <algorithm>
#include <string_view>
#include <utility>

#include "io/atomic_file.hpp"
#include "io/hdf5_internal.hpp"
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

}  // namespace

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

namespace {

template <typename Query>
std::string name_of(Query&& query) {
  const ssize_t length = query(nullptr, 0);
  if (length <= 0) return {};
  std::string name(static_cast<std::size_t>(length), '\0');
  query(name.data(), name.size() + 1);
  return name;
}

}  // namespace

std::string file_name(hid_t object) {
  return name_of([&](char* buffer, std::size_t size) { return H5Fget_name(object, buffer, size); });
}

namespace {

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

}  // namespace

hid_t open_existing(const std::string& path, unsigned flags) {
  silence_hdf5_errors();
  preflight(path);
  Handle properties = access_properties(path, flags == H5F_ACC_RDWR);
  const hid_t file = H5Fopen(path.c_str(), flags, properties.get());
  if (file < 0 && flags == H5F_ACC_RDONLY) throw InputError("cannot open " + path + ": " + failure_reason());
  if (file < 0) fail_path("open", path);
  return file;
}

Handle open_dataset(hid_t file, const char* name) { return owned(H5Dopen2(file, name, H5P_DEFAULT), H5Dclose, file, "open dataset", name); }

std::vector<hsize_t> extent(hid_t dataset, const char* name, std::vector<hsize_t>* max) {
  Handle space = owned(H5Dget_space(dataset), H5Sclose, dataset, "get the shape of", name);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) fail(dataset, "get the rank of", name);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (max) max->resize(dims.size());
  check(H5Sget_simple_extent_dims(space.get(), dims.data(), max ? max->data() : nullptr), dataset, "get the shape of", name);
  space.close();
  return dims;
}

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

Handle checksummed_creation_properties(std::vector<hsize_t> chunk, std::size_t cut, hid_t location, const char* name) {
  Handle properties = untimed_creation_properties(H5P_DATASET_CREATE, location, name);
  if (std::find(chunk.begin(), chunk.end(), 0) != chunk.end()) return properties;  // nothing to store
  // A chunk holds at most kChunkEntries entries (1 MiB of doubles, HDF5's default chunk cache): a
  // frame of 10^8 disks written block by block then needs no buffer of a whole frame inside HDF5,
  // and no chunk reaches HDF5's limit of 4 GiB.
  constexpr hsize_t kChunkEntries = hsize_t{1} << 17;
  hsize_t per_row = 1;
  for (std::size_t k = cut + 1; k < chunk.size(); ++k) per_row *= chunk[k];
  chunk[cut] = std::clamp<hsize_t>(kChunkEntries / std::max<hsize_t>(per_row, 1), 1, chunk[cut]);
  check(H5Pset_chunk(properties.get(), static_cast<int>(chunk.size()), chunk.data()), location, "set the chunks of", name);
  // Fletcher-32 per chunk, verified by HDF5 on every read: a flipped bit in the values is refused.
  check(H5Pset_fletcher32(properties.get()), location, "set the checksum of", name);
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

hid_t create_partial_file(const std::string& path, const char* format, int format_version, const std::string& granule_version) {
  silence_hdf5_errors();
  const std::string partial = path + ".partial";
  Handle creation = untimed_creation_properties(H5P_FILE_CREATE, H5I_INVALID_HID, partial.c_str());
  Handle access = access_properties(partial, true);
  // The file format of HDF5 1.8 and later: every piece of metadata (superblock, object headers,
  // chunk indices) carries a checksum that the library verifies when it reads it, so a damaged
  // file is refused rather than misread (h5py and every HDF5 ≥ 1.8 read it).
  check(H5Pset_libver_bounds(access.get(), H5F_LIBVER_V18, H5F_LIBVER_LATEST), H5I_INVALID_HID,
        "set the format bounds of", partial.c_str());
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

void write_dataset(hid_t location, const char* name, const std::vector<hsize_t>& dims, const std::vector<double>& data) {
  Handle space = owned(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose, location,
                       "describe dataset", name);
  Handle properties = dims.empty() ? untimed_creation_properties(H5P_DATASET_CREATE, location, name)
                                   : checksummed_creation_properties(dims, 0, location, name);
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
