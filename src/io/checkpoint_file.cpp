#include "io/checkpoint_file.hpp"

#include <hdf5.h>

#include <stdexcept>
#include <type_traits>

#include "io/hdf5_util.hpp"

namespace granule {

namespace {

using namespace h5;

constexpr const char* kFormat = "granule-checkpoint";
constexpr int kFormatVersion = 1;

// The HDF5 file type of each element type an archive can hold (little-endian, fixed size).
template <typename T>
hid_t file_type() {
  if constexpr (std::is_same_v<T, double>) return H5T_IEEE_F64LE;
  if constexpr (std::is_same_v<T, std::int64_t>) return H5T_STD_I64LE;
  if constexpr (std::is_same_v<T, std::int32_t>) return H5T_STD_I32LE;
  if constexpr (std::is_same_v<T, std::uint32_t>) return H5T_STD_U32LE;
  if constexpr (std::is_same_v<T, std::uint8_t>) return H5T_STD_U8LE;
}

template <typename T>
void write_entry(hid_t file, const std::string& name, const std::vector<T>& values) {
  const hsize_t size = values.size();
  const hid_t space = check_id(H5Screate_simple(1, &size, nullptr), name);
  const hid_t links = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(links, 1);
  const hid_t dataset = H5Dcreate2(file, name.c_str(), file_type<T>(), space, links, H5P_DEFAULT, H5P_DEFAULT);
  H5Pclose(links);
  H5Sclose(space);
  check_id(dataset, "creating checkpoint entry " + name);
  // The memory type is the file type: the archive's types are the little-endian fixed-size ones.
  const herr_t written = values.empty() ? 0 : H5Dwrite(dataset, file_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  const herr_t closed = H5Dclose(dataset);
  check(written, "writing checkpoint entry " + name);
  check(closed, "closing checkpoint entry " + name);
}

template <typename T>
void read_entry(hid_t dataset, const std::string& name, StateArchive& archive) {
  const hid_t space = check_id(H5Dget_space(dataset), name);
  const hssize_t size = H5Sget_simple_extent_npoints(space);
  H5Sclose(space);
  if (size < 0) throw std::runtime_error("checkpoint entry " + name + " is damaged");
  std::vector<T> values(static_cast<std::size_t>(size));
  if (size > 0) check(H5Dread(dataset, file_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "reading " + name);
  archive.put(name, std::move(values));
}

// Reads the dataset `name` into the archive with the element type it was written with.
void read_dataset(hid_t file, const std::string& name, StateArchive& archive) {
  const hid_t dataset = check_id(H5Dopen2(file, name.c_str(), H5P_DEFAULT), "opening " + name);
  const hid_t type = H5Dget_type(dataset);
  const H5T_class_t type_class = H5Tget_class(type);
  const std::size_t size = H5Tget_size(type);
  const H5T_sign_t sign = H5Tget_sign(type);
  H5Tclose(type);
  try {
    if (type_class == H5T_FLOAT && size == 8) {
      read_entry<double>(dataset, name, archive);
    } else if (type_class == H5T_INTEGER && size == 8 && sign == H5T_SGN_2) {
      read_entry<std::int64_t>(dataset, name, archive);
    } else if (type_class == H5T_INTEGER && size == 4 && sign == H5T_SGN_2) {
      read_entry<std::int32_t>(dataset, name, archive);
    } else if (type_class == H5T_INTEGER && size == 4) {
      read_entry<std::uint32_t>(dataset, name, archive);
    } else if (type_class == H5T_INTEGER && size == 1 && sign == H5T_SGN_NONE) {
      read_entry<std::uint8_t>(dataset, name, archive);
    } else {
      throw std::runtime_error("checkpoint entry " + name + " has an unexpected type");
    }
  } catch (...) {
    H5Dclose(dataset);
    throw;
  }
  H5Dclose(dataset);
}

herr_t collect_dataset(hid_t, const char* name, const H5O_info_t* info, void* names) {
  if (info->type == H5O_TYPE_DATASET) static_cast<std::vector<std::string>*>(names)->push_back(name);
  return 0;
}

}  // namespace

void write_checkpoint(const std::string& path, const StateArchive& archive, const std::string& granule_version) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are reported through exceptions
  const hid_t file = create_partial_file(path, kFormat, kFormatVersion, granule_version);
  try {
    for (const auto& [name, values] : archive.arrays()) {
      std::visit([&, &entry = name](const auto& v) { write_entry(file, entry, v); }, values);
    }
  } catch (...) {
    H5Fclose(file);
    throw;
  }
  publish_partial_file(file, path);
}

StateArchive read_checkpoint(const std::string& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t file = check_id(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "opening " + path);
  StateArchive archive;
  try {
    if (read_string_attribute(file, "format") != kFormat) throw std::runtime_error(path + " is not a Granule checkpoint");
    std::vector<std::string> names;
    check(H5Ovisit(file, H5_INDEX_NAME, H5_ITER_NATIVE, collect_dataset, &names), "listing " + path);
    for (const std::string& name : names) read_dataset(file, name, archive);
  } catch (...) {
    H5Fclose(file);
    throw;
  }
  H5Fclose(file);
  return archive;
}

}  // namespace granule
