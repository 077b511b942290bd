#include "io/checkpoint_file.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <algorithm>
#include <span>
#include <stdexcept>
#include <type_traits>

#include "io/hdf5_util.hpp"

namespace granule {

namespace {

using namespace h5;

constexpr const char* kFormat = "granule-checkpoint";
// 2: the engine keeps each particle's collision candidate (time and partner) through crossings, in
// every run (version 1 kept the time only under time-dependent protocols): a version-1 checkpoint
// cannot continue its run bit for bit and is refused.
// 3: the particle records hold false positions at the clock base and no local time, and the
// collision candidate's time is computed again rather than stored (engine/particle_record.hpp); a
// version-2 checkpoint cannot continue its run bit for bit.
constexpr int kFormatVersion = 3;

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
Handle create_entry(hid_t file, const std::string& name, hsize_t size) {
  const Handle space = owned(H5Screate_simple(1, &size, nullptr), H5Sclose, file, "create the shape of", name.c_str());
  const Handle links = owned(H5Pcreate(H5P_LINK_CREATE), H5Pclose, file, "create link properties of", name.c_str());
  check(H5Pset_create_intermediate_group(links.get(), 1), file, "set link properties of", name.c_str());
  const Handle creation = untimed_creation_properties(H5P_DATASET_CREATE, file, name.c_str());
  return owned(H5Dcreate2(file, name.c_str(), file_type<T>(), space.get(), links.get(), creation.get(), H5P_DEFAULT),
               H5Dclose, file, "create", name.c_str());
}

template <typename T>
void write_entry(hid_t file, const std::string& name, const std::vector<T>& values) {
  Handle dataset = create_entry<T>(file, name, values.size());
  // The memory type is the file type: the archive's types are the little-endian fixed-size ones.
  if (!values.empty()) {
    check(H5Dwrite(dataset.get(), file_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), file, "write", name.c_str());
  }
  dataset.close();
}

// A streamed entry, through a buffer of at most kStreamBlock entries: the state of 10^8 disks is
// written without a copy of it (StateArchive::streaming).
template <typename T>
void write_entry(hid_t file, const std::string& name, const StateArchive::Producer<T>& producer) {
  constexpr std::size_t kStreamBlock = std::size_t{1} << 16;
  Handle dataset = create_entry<T>(file, name, producer.size);
  const hsize_t size = producer.size;
  const Handle file_space = owned(H5Screate_simple(1, &size, nullptr), H5Sclose, file, "create the shape of", name.c_str());
  std::vector<T> block(std::min(producer.size, kStreamBlock));
  for (std::size_t first = 0; first < producer.size; first += block.size()) {
    const std::size_t count = std::min(block.size(), producer.size - first);
    producer.fill(first, std::span<T>(block.data(), count));
    const hsize_t start = first;
    const hsize_t length = count;
    check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, &start, nullptr, &length, nullptr), file, "select part of",
          name.c_str());
    const Handle memory_space = owned(H5Screate_simple(1, &length, nullptr), H5Sclose, file, "create the shape of", name.c_str());
    check(H5Dwrite(dataset.get(), file_type<T>(), memory_space.get(), file_space.get(), H5P_DEFAULT, block.data()), file,
          "write", name.c_str());
  }
  dataset.close();
}

template <typename T>
void read_entry(hid_t dataset, const std::string& name, StateArchive& archive) {
  const Handle space = owned(H5Dget_space(dataset), H5Sclose, dataset, "get the shape of", name.c_str());
  const hssize_t size = H5Sget_simple_extent_npoints(space.get());
  if (size < 0) throw std::runtime_error("checkpoint entry " + name + " is damaged");
  std::vector<T> values(static_cast<std::size_t>(size));
  if (size > 0) {
    check(H5Dread(dataset, file_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), dataset, "read", name.c_str());
  }
  archive.put(name, std::move(values));
}

// Reads the dataset `name` into the archive with the element type it was written with.
void read_dataset(hid_t file, const std::string& name, StateArchive& archive) {
  const Handle dataset = owned(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose, file, "open", name.c_str());
  const Handle type = owned(H5Dget_type(dataset.get()), H5Tclose, file, "get the type of", name.c_str());
  const H5T_class_t type_class = H5Tget_class(type.get());
  const std::size_t size = H5Tget_size(type.get());
  const H5T_sign_t sign = H5Tget_sign(type.get());
  const hid_t d = dataset.get();
  if (type_class == H5T_FLOAT && size == 8) {
    read_entry<double>(d, name, archive);
  } else if (type_class == H5T_INTEGER && size == 8 && sign == H5T_SGN_2) {
    read_entry<std::int64_t>(d, name, archive);
  } else if (type_class == H5T_INTEGER && size == 4 && sign == H5T_SGN_2) {
    read_entry<std::int32_t>(d, name, archive);
  } else if (type_class == H5T_INTEGER && size == 4) {
    read_entry<std::uint32_t>(d, name, archive);
  } else if (type_class == H5T_INTEGER && size == 1 && sign == H5T_SGN_NONE) {
    read_entry<std::uint8_t>(d, name, archive);
  } else {
    throw std::runtime_error("checkpoint entry " + name + " has an unexpected type");
  }
}

herr_t collect_dataset(hid_t, const char* name, const H5O_info_t* info, void* names) {
  if (info->type == H5O_TYPE_DATASET) static_cast<std::vector<std::string>*>(names)->push_back(name);
  return 0;
}

}  // namespace

void write_checkpoint(const std::string& path, const StateArchive& archive, const std::string& granule_version) {
  Handle file(create_partial_file(path, kFormat, kFormatVersion, granule_version), H5Fclose);
  for (const auto& [name, values] : archive.arrays()) {
    std::visit([&, &entry = name](const auto& v) { write_entry(file.get(), entry, v); }, values);
  }
  for (const auto& [name, producer] : archive.deferred()) {
    std::visit([&, &entry = name](const auto& p) { write_entry(file.get(), entry, p); }, producer);
  }
  publish_partial_file(file.release(), path);
}

StateArchive read_checkpoint(const std::string& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  Handle handle = open_file(path);
  const hid_t file = handle.get();
  StateArchive archive;
  if (read_string_attribute(file, "format") != kFormat) throw std::runtime_error(path + " is not a Granule checkpoint");
  if (const int version = read_attribute<int>(file, "format_version", H5T_NATIVE_INT); version != kFormatVersion) {
    throw std::runtime_error(fmt::format("{} is a checkpoint of format version {}, written by another version of Granule "
                                         "({}); this one continues runs from version {} only: continue it with the "
                                         "Granule that wrote it, or resume from a snapshot frame (--from-frame)",
                                         path, version, read_string_attribute(file, "granule_version"), kFormatVersion));
  }
  std::vector<std::string> names;
  check(H5Ovisit(file, H5_INDEX_NAME, H5_ITER_NATIVE, collect_dataset, &names), file, "list the datasets of", path.c_str());
  for (const std::string& name : names) read_dataset(file, name, archive);
  handle.close();
  return archive;
}

}  // namespace granule
