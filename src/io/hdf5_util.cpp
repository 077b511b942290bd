#include "io/hdf5_util.hpp"

#include <filesystem>
#include <stdexcept>

namespace granule::h5 {

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5 error while " + what);
}
hid_t check_id(hid_t id, const std::string& what) {
  if (id < 0) throw std::runtime_error("HDF5 error while " + what);
  return id;
}

void write_attribute(hid_t object, const char* name, hid_t type, const void* data, hsize_t count) {
  const hid_t space = count == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &count, nullptr);
  const hid_t attribute = check_id(H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT), name);
  check(H5Awrite(attribute, type, data), name);
  H5Aclose(attribute);
  H5Sclose(space);
}

void write_string_attribute(hid_t object, const char* name, const std::string& value) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.size() + 1);
  H5Tset_strpad(type, H5T_STR_NULLTERM);
  write_attribute(object, name, type, value.c_str());
  H5Tclose(type);
}

std::string read_string_attribute(hid_t object, const char* name) {
  const hid_t attribute = check_id(H5Aopen(object, name, H5P_DEFAULT), std::string("reading attribute ") + name);
  const hid_t type = H5Aget_type(attribute);
  const hid_t memory = H5Tcopy(H5T_C_S1);
  std::vector<char> buffer(H5Tget_size(type) + 1, '\0');
  H5Tset_size(memory, buffer.size());
  check(H5Aread(attribute, memory, buffer.data()), name);
  H5Tclose(memory);
  H5Tclose(type);
  H5Aclose(attribute);
  return buffer.data();
}

hid_t create_frames(hid_t file, const char* name, hid_t type, std::vector<hsize_t> row) {
  std::vector<hsize_t> dims{0}, max{H5S_UNLIMITED}, chunk{1};
  for (hsize_t d : row) {
    dims.push_back(d);
    max.push_back(d);
    chunk.push_back(d);
  }
  const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), max.data());
  const hid_t properties = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(properties, static_cast<int>(chunk.size()), chunk.data());
  const hid_t dataset = check_id(H5Dcreate2(file, name, type, space, H5P_DEFAULT, properties, H5P_DEFAULT), name);
  H5Pclose(properties);
  H5Sclose(space);
  return dataset;
}

void transfer_frame(hid_t file, const char* name, hid_t type, void* data, hsize_t frame, bool grow) {
  const hid_t dataset = check_id(H5Dopen2(file, name, H5P_DEFAULT), name);
  hid_t space = H5Dget_space(dataset);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  if (grow) {
    H5Sclose(space);
    dims[0] = frame + 1;
    check(H5Dset_extent(dataset, dims.data()), name);
    space = H5Dget_space(dataset);
  }
  std::vector<hsize_t> start(dims.size(), 0), count = dims;
  start[0] = frame;
  count[0] = 1;
  H5Sselect_hyperslab(space, H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr);
  const hid_t memory = H5Screate_simple(rank, count.data(), nullptr);
  const herr_t status = grow ? H5Dwrite(dataset, type, memory, space, H5P_DEFAULT, data)
                             : H5Dread(dataset, type, memory, space, H5P_DEFAULT, data);
  H5Sclose(memory);
  H5Sclose(space);
  H5Dclose(dataset);
  check(status, name);
}

void append_frame(hid_t file, const char* name, hid_t type, const void* data, hsize_t frame) {
  transfer_frame(file, name, type, const_cast<void*>(data), frame, true);
}

void read_frame(hid_t file, const char* name, hid_t type, void* data, hsize_t frame) {
  transfer_frame(file, name, type, data, frame, false);
}

void write_dataset(hid_t location, const char* name, const std::vector<hsize_t>& dims, const std::vector<double>& data) {
  const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
  const hid_t dataset = check_id(H5Dcreate2(location, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), name);
  const herr_t status = H5Dwrite(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
  H5Dclose(dataset);
  H5Sclose(space);
  check(status, name);
}

void write_vector(hid_t location, const char* name, const std::vector<double>& data) {
  write_dataset(location, name, {static_cast<hsize_t>(data.size())}, data);
}

hid_t create_partial_file(const std::string& path, const char* format, int format_version, const std::string& granule_version) {
  const std::string partial = path + ".partial";
  const hid_t file = check_id(H5Fcreate(partial.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), "creating " + partial);
  write_string_attribute(file, "format", format);
  write_attribute(file, "format_version", H5T_NATIVE_INT, &format_version);
  write_string_attribute(file, "granule_version", granule_version);
  return file;
}

void publish_partial_file(hid_t file, const std::string& path) {
  check(H5Fclose(file), "closing " + path + ".partial");
  std::filesystem::rename(path + ".partial", path);
}

hid_t create_group(hid_t location, const char* name) {
  return check_id(H5Gcreate2(location, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), name);
}

namespace {
herr_t truncate_extendible(hid_t file, const char* name, const H5O_info_t* info, void* keep_frames) {
  if (info->type != H5O_TYPE_DATASET) return 0;
  const hid_t dataset = H5Dopen2(file, name, H5P_DEFAULT);
  if (dataset < 0) return -1;
  const hid_t space = H5Dget_space(dataset);
  const int rank = H5Sget_simple_extent_ndims(space);
  herr_t status = rank < 0 ? -1 : 0;
  if (rank > 0) {
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank)), max(static_cast<std::size_t>(rank));
    H5Sget_simple_extent_dims(space, dims.data(), max.data());
    const auto keep = *static_cast<const hsize_t*>(keep_frames);
    if (max[0] == H5S_UNLIMITED && dims[0] != keep) {
      if (dims[0] < keep) {
        status = -1;  // fewer frames than the checkpoint knew of: the file is not this run's
      } else {
        dims[0] = keep;
        status = H5Dset_extent(dataset, dims.data());
      }
    }
  }
  H5Sclose(space);
  H5Dclose(dataset);
  return status;
}
}  // namespace

hid_t reopen_frames_file(const std::string& path, std::int64_t keep_frames) {
  const std::string partial = path + ".partial";
  if (!std::filesystem::exists(partial)) std::filesystem::rename(path, partial);
  const hid_t file = check_id(H5Fopen(partial.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), "opening " + partial);
  hsize_t keep = static_cast<hsize_t>(keep_frames);
  if (H5Ovisit(file, H5_INDEX_NAME, H5_ITER_NATIVE, truncate_extendible, &keep) < 0) {
    H5Fclose(file);
    throw std::runtime_error(partial + " does not hold the " + std::to_string(keep_frames) +
                             " frames its run's checkpoint expects");
  }
  return file;
}

}  // namespace granule::h5
