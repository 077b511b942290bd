#include "io/checkpoint_file.hpp"

#include <fmt/format.h>
#include <hdf5.h>
#include <xxhash.h>

#include <algorithm>
#include <cstdint>
#include <new>
#include <span>
#include <stdexcept>
#include <type_traits>

#include "io/hdf5_util.hpp"
#include "io/io_error.hpp"

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
// 4: every dataset carries the digest of its values (kDigest), and a checkpoint without them is
// not trusted.
constexpr int kFormatVersion = 4;
// The attribute of each dataset that holds XXH3-64 of its values' little-endian bytes: a
// checkpoint is trusted only when every dataset's values still give their digest.
constexpr const char* kDigest = "xxh3_64";

// XXH3-64 of bytes given piece by piece (a streamed entry is written block by block).
class Digest {
 public:
  Digest() : state_(XXH3_createState()) {
    if (state_ == nullptr || XXH3_64bits_reset(state_) != XXH_OK) throw std::bad_alloc();
  }
  ~Digest() { XXH3_freeState(state_); }
  Digest(const Digest&) = delete;
  Digest& operator=(const Digest&) = delete;
  template <typename T>
  void add(std::span<const T> values) {
    if (!values.empty()) XXH3_64bits_update(state_, values.data(), values.size_bytes());
  }
  std::uint64_t value() const { return XXH3_64bits_digest(state_); }

 private:
  XXH3_state_t* state_;
};

void write_digest(hid_t dataset, const Digest& digest, const std::string& name) {
  const std::uint64_t value = digest.value();
  check(H5Aexists(dataset, kDigest) < 0 ? -1 : 0, dataset, "look for the digest of", name.c_str());
  write_attribute(dataset, kDigest, H5T_STD_U64LE, &value);
}

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
  Digest digest;
  digest.add(std::span<const T>(values));
  write_digest(dataset.get(), digest, name);
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
  Digest digest;
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
    digest.add(std::span<const T>(block.data(), count));
  }
  write_digest(dataset.get(), digest, name);
  dataset.close();
}

template <typename T>
void read_entry(hid_t dataset, const std::string& name, const std::string& path, StateArchive& archive) {
  const auto damaged = [&](const std::string& what) { return InputError(path + ": checkpoint entry " + name + " " + what); };
  const hid_t space = H5Dget_space(dataset);
  if (space < 0) throw damaged("has no shape");
  const Handle closes_space(space, H5Sclose);
  hsize_t size = 0;
  if (H5Sget_simple_extent_ndims(space) != 1 || H5Sget_simple_extent_dims(space, &size, nullptr) != 1) {
    throw damaged("is not one-dimensional");
  }
  require_stored(dataset, size, dataset, "checkpoint entry " + name);
  std::vector<T> values(static_cast<std::size_t>(size));
  if (!values.empty() && H5Dread(dataset, file_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
    throw damaged("cannot be read");
  }
  if (!has_attribute(dataset, kDigest)) throw damaged("has no digest: the checkpoint is not complete");
  Digest digest;
  digest.add(std::span<const T>(values));
  if (read_attribute<std::uint64_t>(dataset, kDigest, H5T_NATIVE_UINT64) != digest.value()) {
    throw damaged("is damaged: its values do not give the digest written with them");
  }
  archive.put(name, std::move(values));
}

// Reads the dataset `name` into the archive with the element type it was written with.
void read_dataset(hid_t file, const std::string& name, const std::string& path, StateArchive& archive) {
  const hid_t opened = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
  if (opened < 0) throw InputError(path + ": checkpoint entry " + name + " cannot be opened");
  const Handle dataset(opened, H5Dclose);
  const hid_t typed = H5Dget_type(dataset.get());
  if (typed < 0) throw InputError(path + ": checkpoint entry " + name + " has no type");
  const Handle type(typed, H5Tclose);
  const H5T_class_t type_class = H5Tget_class(type.get());
  const std::size_t size = H5Tget_size(type.get());
  const H5T_sign_t sign = H5Tget_sign(type.get());
  const hid_t d = dataset.get();
  if (type_class == H5T_FLOAT && size == 8) {
    read_entry<double>(d, name, path, archive);
  } else if (type_class == H5T_INTEGER && size == 8 && sign == H5T_SGN_2) {
    read_entry<std::int64_t>(d, name, path, archive);
  } else if (type_class == H5T_INTEGER && size == 4 && sign == H5T_SGN_2) {
    read_entry<std::int32_t>(d, name, path, archive);
  } else if (type_class == H5T_INTEGER && size == 4) {
    read_entry<std::uint32_t>(d, name, path, archive);
  } else if (type_class == H5T_INTEGER && size == 1 && sign == H5T_SGN_NONE) {
    read_entry<std::uint8_t>(d, name, path, archive);
  } else {
    throw InputError(path + ": checkpoint entry " + name + " has an unexpected type");
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
  if (read_string_attribute(file, "format") != kFormat) throw InputError(path + " is not a Granule checkpoint");
  if (const int version = read_attribute<int>(file, "format_version", H5T_NATIVE_INT); version != kFormatVersion) {
    throw InputError(fmt::format("{} is a checkpoint of format version {}, written by another version of Granule "
                                         "({}); this one continues runs from version {} only: continue it with the "
                                         "Granule that wrote it, or resume from a snapshot frame (--from-frame)",
                                         path, version, read_string_attribute(file, "granule_version"), kFormatVersion));
  }
  std::vector<std::string> names;
  if (H5Ovisit(file, H5_INDEX_NAME, H5_ITER_NATIVE, collect_dataset, &names) < 0) {
    throw InputError(path + ": the list of its datasets is damaged");
  }
  for (const std::string& name : names) read_dataset(file, name, path, archive);
  handle.close();
  return archive;
}

}  // namespace granule
