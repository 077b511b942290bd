// Reading Granule's HDF5 files as untrusted input (io/hdf5_util.hpp, "Reading a file"): what the
// file holds is checked against what the caller expects before anything is copied or allocated,
// and every refusal is an InputError naming the file, the object and what was expected.
#include <hdf5.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "io/hdf5_internal.hpp"
#include "io/hdf5_util.hpp"
#include "io/io_error.hpp"

namespace granule::h5 {

namespace {

[[noreturn]] void refuse(hid_t location, const std::string& what) {
  const std::string file = file_name(location);
  throw InputError((file.empty() ? std::string("an HDF5 file") : file) + ": " + what);
}

void check_read(herr_t status, hid_t location, const std::string& action) {
  if (status < 0) {
    const std::string reason = failure_reason();
    refuse(location, "cannot " + action + ": " + reason);
  }
}

Handle read_owned(hid_t id, Handle::Closer closer, hid_t location, const std::string& action) {
  check_read(id < 0 ? -1 : 0, location, action);
  return Handle(id, closer);
}

// The number of elements of a shape, saturating far above anything a file can store.
hsize_t elements(const std::vector<hsize_t>& dims) {
  constexpr hsize_t kHuge = hsize_t{1} << 62;
  hsize_t count = 1;
  for (const hsize_t d : dims) {
    if (d != 0 && count > kHuge / d) return kHuge;
    count *= d;
  }
  return count;
}

// A numeric memory type reads a stored number; an integer memory type only a stored integer (a
// stored float would be rounded, and a NaN has no integer).
void require_numeric(hid_t stored, hid_t memory, hid_t location, const std::string& object) {
  const H5T_class_t have = H5Tget_class(stored);
  const bool integer = H5Tget_class(memory) == H5T_INTEGER;
  if (integer ? have == H5T_INTEGER : have == H5T_INTEGER || have == H5T_FLOAT) return;
  refuse(location, object + (integer ? " is not stored as integers" : " is not stored as numbers"));
}

// The largest ratio of values to stored bytes a filter can reach: deflate's limit is about 1032:1;
// the checksum filter (Fletcher-32) compresses nothing.
hsize_t stored_ratio(hid_t dataset, hid_t location, const std::string& object) {
  const Handle creation = read_owned(H5Dget_create_plist(dataset), H5Pclose, location, "read the layout of " + object);
  const int filters = H5Pget_nfilters(creation.get());
  check_read(filters, location, "read the filters of " + object);
  for (int k = 0; k < filters; ++k) {
    unsigned flags = 0;
    std::size_t values = 0;
    const H5Z_filter_t filter = H5Pget_filter2(creation.get(), static_cast<unsigned>(k), &flags, &values, nullptr, 0,
                                               nullptr, nullptr);
    if (filter != H5Z_FILTER_FLETCHER32) return 1100;
  }
  return 1;
}

std::string dataset_text(const char* name) { return std::string("dataset ") + name; }

// Opens per-frame dataset `name` for reading frame `frame` of shape `row` as `type`, after every check.
Handle checked_frame(hid_t file, const char* name, hid_t type, hsize_t frame, const std::vector<hsize_t>& row,
                     std::vector<hsize_t>& dims) {
  const std::string object = dataset_text(name);
  Handle dataset = read_owned(H5Dopen2(file, name, H5P_DEFAULT), H5Dclose, file, "open " + object);
  const Handle stored = read_owned(H5Dget_type(dataset.get()), H5Tclose, file, "read the type of " + object);
  require_numeric(stored.get(), type, file, object);
  dims = dataset_shape(file, name);
  const std::vector<hsize_t> have(dims.empty() ? dims.begin() : dims.begin() + 1, dims.end());
  if (dims.empty() || have != row) {
    refuse(file, object + " has shape " + shape_text(dims) + "; expected frames of shape " + shape_text(row));
  }
  if (frame >= dims[0]) refuse(file, object + " has " + std::to_string(dims[0]) + " frames: no frame " + std::to_string(frame));
  require_stored(dataset.get(), elements(row), file, object);
  return dataset;
}

void read_checked_frame(hid_t file, const char* name, hid_t type, void* data, hsize_t frame, const Handle& dataset,
                        const std::vector<hsize_t>& dims) {
  const std::string object = dataset_text(name);
  const Handle space = read_owned(H5Dget_space(dataset.get()), H5Sclose, file, "read the shape of " + object);
  const std::vector<hsize_t> count = select_frame(space.get(), dims, frame, 0, kAllRows, file, name);
  const Handle memory = read_owned(H5Screate_simple(static_cast<int>(count.size()), count.data(), nullptr), H5Sclose,
                                   file, "describe a frame of " + object);
  check_read(H5Dread(dataset.get(), type, memory.get(), space.get(), H5P_DEFAULT, data), file,
             "read frame " + std::to_string(frame) + " of " + object);
}

}  // namespace

std::string shape_text(const std::vector<hsize_t>& dims) {
  if (dims.empty()) return "a scalar";
  std::string text = "(";
  for (std::size_t k = 0; k < dims.size(); ++k) text += (k ? ", " : "") + std::to_string(dims[k]);
  return text + (dims.size() == 1 ? ",)" : ")");
}

void require_stored(hid_t dataset, hsize_t count, hid_t location, const std::string& object) {
  if (count == 0) return;
  const Handle type = read_owned(H5Dget_type(dataset), H5Tclose, location, "read the type of " + object);
  const hsize_t bytes = elements({count, H5Tget_size(type.get())});
  H5Eclear2(H5E_DEFAULT);
  const hsize_t stored = H5Dget_storage_size(dataset);
  // 0 is also how HDF5 reports a failed query (a chunk index it cannot read): say why.
  if (stored == 0 && H5Eget_num(H5E_DEFAULT) > 0) refuse(location, "cannot measure " + object + ": " + failure_reason());
  const hsize_t ratio = stored_ratio(dataset, location, object);
  if (bytes / ratio > stored) {
    refuse(location, object + " needs " + std::to_string(bytes) + " bytes for what its shape claims but stores " +
                         std::to_string(stored) + ": the file is damaged");
  }
}

Handle open_file(const std::string& path) { return Handle(open_existing(path, H5F_ACC_RDONLY), H5Fclose); }

namespace {

// An attribute that must exist, opened for reading.
Handle open_attribute(hid_t object, const char* name, const std::string& attribute_text) {
  const htri_t exists = H5Aexists(object, name);
  check_read(exists, object, "look for " + attribute_text);
  if (exists == 0) refuse(object, "has no " + attribute_text);
  return read_owned(H5Aopen(object, name, H5P_DEFAULT), H5Aclose, object, "open " + attribute_text);
}

}  // namespace

void read_attribute_values(hid_t object, const char* name, hid_t type, void* data, hsize_t count) {
  const std::string attribute_text = std::string("attribute ") + name;
  const Handle attribute = open_attribute(object, name, attribute_text);
  const Handle stored = read_owned(H5Aget_type(attribute.get()), H5Tclose, object, "read the type of " + attribute_text);
  require_numeric(stored.get(), type, object, attribute_text);
  const Handle space = read_owned(H5Aget_space(attribute.get()), H5Sclose, object, "read the shape of " + attribute_text);
  const hssize_t values = H5Sget_simple_extent_npoints(space.get());
  if (values < 0 || static_cast<hsize_t>(values) != count) {
    refuse(object, attribute_text + " holds " + std::to_string(values) + " values; expected " + std::to_string(count));
  }
  check_read(H5Aread(attribute.get(), type, data), object, "read " + attribute_text);
}

std::string read_string_attribute(hid_t object, const char* name) {
  const std::string attribute_text = std::string("attribute ") + name;
  const Handle attribute = open_attribute(object, name, attribute_text);
  const Handle stored = read_owned(H5Aget_type(attribute.get()), H5Tclose, object, "read the type of " + attribute_text);
  const Handle space = read_owned(H5Aget_space(attribute.get()), H5Sclose, object, "read the shape of " + attribute_text);
  if (H5Tget_class(stored.get()) != H5T_STRING || H5Sget_simple_extent_npoints(space.get()) != 1) {
    refuse(object, attribute_text + " is not one string");
  }
  const Handle memory = read_owned(H5Tcopy(H5T_C_S1), H5Tclose, object, "make the string type of " + attribute_text);
  check_read(H5Tset_cset(memory.get(), H5Tget_cset(stored.get())), object, "make the string type of " + attribute_text);
  if (H5Tis_variable_str(stored.get()) > 0) {  // as h5py writes a str
    check_read(H5Tset_size(memory.get(), H5T_VARIABLE), object, "make the string type of " + attribute_text);
    char* text = nullptr;
    check_read(H5Aread(attribute.get(), memory.get(), &text), object, "read " + attribute_text);
    std::string value = text ? text : "";
    H5free_memory(text);
    return value;
  }
  constexpr std::size_t kLongest = std::size_t{1} << 20;  // no name or version of Granule comes near
  const std::size_t size = H5Tget_size(stored.get());
  if (size == 0 || size > kLongest) refuse(object, attribute_text + " is not a string of at most 1 MiB");
  std::vector<char> buffer(size + 1, '\0');
  check_read(H5Tset_size(memory.get(), buffer.size()), object, "make the string type of " + attribute_text);
  check_read(H5Aread(attribute.get(), memory.get(), buffer.data()), object, "read " + attribute_text);
  return buffer.data();
}

std::vector<hsize_t> dataset_shape(hid_t location, const char* name) {
  const std::string object = dataset_text(name);
  const Handle dataset = read_owned(H5Dopen2(location, name, H5P_DEFAULT), H5Dclose, location, "open " + object);
  const Handle space = read_owned(H5Dget_space(dataset.get()), H5Sclose, location, "read the shape of " + object);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  check_read(rank, location, "read the rank of " + object);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  check_read(H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr), location, "read the shape of " + object);
  return dims;
}

std::vector<hsize_t> frame_row(hid_t file, const char* name) {
  const std::vector<hsize_t> dims = dataset_shape(file, name);
  if (dims.empty()) refuse(file, dataset_text(name) + " is a scalar, not a dataset of frames");
  std::vector<hsize_t> row(dims.begin() + 1, dims.end());
  const Handle dataset = read_owned(H5Dopen2(file, name, H5P_DEFAULT), H5Dclose, file, "open " + dataset_text(name));
  require_stored(dataset.get(), elements(row), file, dataset_text(name));
  return row;
}

void read_frame(hid_t file, const char* name, hid_t type, void* data, hsize_t frame, const std::vector<hsize_t>& row) {
  std::vector<hsize_t> dims;
  const Handle dataset = checked_frame(file, name, type, frame, row, dims);
  read_checked_frame(file, name, type, data, frame, dataset, dims);
}

std::vector<double> read_frame_values(hid_t file, const char* name, hsize_t frame, const std::vector<hsize_t>& row) {
  std::vector<hsize_t> dims;
  const Handle dataset = checked_frame(file, name, H5T_NATIVE_DOUBLE, frame, row, dims);
  std::vector<double> values(static_cast<std::size_t>(elements(row)));
  read_checked_frame(file, name, H5T_NATIVE_DOUBLE, values.data(), frame, dataset, dims);
  return values;
}

std::vector<double> read_values(hid_t location, const char* name) {
  const std::string object = dataset_text(name);
  const std::vector<hsize_t> dims = dataset_shape(location, name);
  const Handle dataset = read_owned(H5Dopen2(location, name, H5P_DEFAULT), H5Dclose, location, "open " + object);
  const Handle stored = read_owned(H5Dget_type(dataset.get()), H5Tclose, location, "read the type of " + object);
  require_numeric(stored.get(), H5T_NATIVE_DOUBLE, location, object);
  require_stored(dataset.get(), elements(dims), location, object);
  std::vector<double> values(static_cast<std::size_t>(elements(dims)));
  if (!values.empty()) {
    check_read(H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), location,
               "read " + object);
  }
  return values;
}

std::vector<double> read_vector(hid_t location, const char* name, hsize_t length) {
  const std::vector<hsize_t> dims = dataset_shape(location, name);
  if (dims.size() != 1 || (length != kAnyLength && dims[0] != length)) {
    refuse(location, dataset_text(name) + " has shape " + shape_text(dims) + "; expected " +
                         (length == kAnyLength ? std::string("one dimension") : shape_text({length})));
  }
  return read_values(location, name);
}

void require_whole(hid_t location, const char* name) {
  const std::vector<hsize_t> dims = dataset_shape(location, name);
  const Handle dataset = read_owned(H5Dopen2(location, name, H5P_DEFAULT), H5Dclose, location, "open " + dataset_text(name));
  require_stored(dataset.get(), elements(dims), location, dataset_text(name));
}

bool stored_as_integers(hid_t location, const char* name) {
  const std::string object = dataset_text(name);
  const Handle dataset = read_owned(H5Dopen2(location, name, H5P_DEFAULT), H5Dclose, location, "open " + object);
  const Handle stored = read_owned(H5Dget_type(dataset.get()), H5Tclose, location, "read the type of " + object);
  return H5Tget_class(stored.get()) == H5T_INTEGER;
}

std::int64_t complete_frames(hid_t file) { return complete_frames(file, -1); }

std::int64_t complete_frames(hid_t file, std::int64_t kept) {
  std::vector<std::string> datasets;
  try {
    datasets = frame_datasets(file);
  } catch (const IoError& error) {
    refuse(file, std::string("cannot list its datasets: ") + error.what());
  }
  hsize_t frames = datasets.empty() ? 0 : std::numeric_limits<hsize_t>::max();
  for (const std::string& name : datasets) {
    const std::vector<hsize_t> dims = dataset_shape(file, name.c_str());
    const hsize_t row = elements({dims.begin() + 1, dims.end()});
    // A killed run may leave one frame allocated but unwritten; more than that is damage.
    const hsize_t needed = kept >= 0 ? std::min<hsize_t>(dims[0], static_cast<hsize_t>(kept)) : dims[0] - 1;
    if (row > 0 && needed > 0) {
      const Handle dataset = read_owned(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose, file, "open " + dataset_text(name.c_str()));
      require_stored(dataset.get(), elements({needed, row}), file, dataset_text(name.c_str()));
    }
    frames = std::min(frames, dims[0]);
  }
  return static_cast<std::int64_t>(frames);
}

std::int64_t complete_frames(const std::string& path) {
  Handle file = open_file(path);
  const std::int64_t frames = complete_frames(file.get());
  file.close();
  return frames;
}

std::vector<double> read_frame_series(const std::string& path, const char* name) {
  Handle file = open_file(path);
  const htri_t exists = H5Lexists(file.get(), name, H5P_DEFAULT);
  std::vector<double> values(exists > 0 ? static_cast<std::size_t>(complete_frames(file.get())) : 0);
  for (std::size_t k = 0; k < values.size(); ++k) read_frame(file.get(), name, H5T_NATIVE_DOUBLE, &values[k], k, {});
  file.close();
  return values;
}

}  // namespace granule::h5
