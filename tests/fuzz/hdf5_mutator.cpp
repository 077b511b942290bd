#include "fuzz/hdf5_mutator.hpp"

#include <hdf5.h>
#include <xxhash.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace granule::fuzz {

namespace {

using Random = std::mt19937_64;

struct Attribute {
  std::string object;  // path of the object that holds it ("/" for the root)
  std::string name;
};

struct Objects {
  std::vector<std::string> datasets;
  std::vector<Attribute> attributes;
};

std::size_t pick(Random& random, std::size_t count) { return std::uniform_int_distribution<std::size_t>(0, count - 1)(random); }

// Values a damaged or hostile file may hold where a number is expected.
double special_value(Random& random, double original) {
  const double values[] = {std::numeric_limits<double>::quiet_NaN(), INFINITY, -INFINITY, -1.0, 0.0, 1.0, 1e300, -1e300,
                           2147483648.0, 9.3e18, 1e-300, -original, original * (1.0 + 1e-9), original * 2.0 + 1.0};
  return values[pick(random, std::size(values))];
}

void must(herr_t status, const char* what) {
  if (status < 0) throw std::runtime_error(std::string("mutator: cannot ") + what);
}

Objects objects_of(hid_t file) {
  Objects out;
  const auto collect_attributes = [&](const std::string& path) {
    const hid_t object = H5Oopen(file, path.c_str(), H5P_DEFAULT);
    if (object < 0) return;
    H5O_info_t info;
    if (H5Oget_info2(object, &info, H5O_INFO_NUM_ATTRS) >= 0) {
      for (hsize_t k = 0; k < info.num_attrs; ++k) {
        char name[256] = {};
        if (H5Aget_name_by_idx(object, ".", H5_INDEX_NAME, H5_ITER_INC, k, name, sizeof name, H5P_DEFAULT) > 0) {
          out.attributes.push_back({path, name});
        }
      }
    }
    H5Oclose(object);
  };
  std::vector<std::pair<std::string, H5O_type_t>> all;
  const auto visit = [](hid_t, const char* name, const H5O_info_t* info, void* data) -> herr_t {
    static_cast<std::vector<std::pair<std::string, H5O_type_t>>*>(data)->push_back({name, info->type});
    return 0;
  };
  must(H5Ovisit2(file, H5_INDEX_NAME, H5_ITER_INC, visit, &all, H5O_INFO_BASIC), "list the objects");
  for (const auto& [name, type] : all) {
    const std::string path = name == "." ? "/" : "/" + name;
    if (type == H5O_TYPE_DATASET) out.datasets.push_back(path);
    collect_attributes(path);
  }
  return out;
}

hid_t random_file_type(Random& random) {
  const hid_t types[] = {H5T_IEEE_F64LE, H5T_IEEE_F32LE, H5T_STD_I64LE, H5T_STD_I32LE, H5T_STD_U8LE, H5T_IEEE_F64BE};
  return types[pick(random, std::size(types))];
}

// A string type of `size` bytes (the caller closes it).
hid_t string_type(std::size_t size) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, size);
  return type;
}

// A conversion HDF5 refuses leaves the fill value: still a mutant.
void write_attribute_numbers(hid_t attribute, const std::vector<double>& values) {
  if (!values.empty()) H5Awrite(attribute, H5T_NATIVE_DOUBLE, values.data());
}

std::string mutate_attribute(hid_t file, const Attribute& a, Random& random) {
  const hid_t object = H5Oopen(file, a.object.c_str(), H5P_DEFAULT);
  if (object < 0) return "";
  double original = 1.0;
  if (const hid_t old = H5Aopen(object, a.name.c_str(), H5P_DEFAULT); old >= 0) {
    const hid_t space = H5Aget_space(old);
    const hid_t type = H5Aget_type(old);
    if (H5Tget_class(type) != H5T_STRING && H5Sget_simple_extent_npoints(space) >= 1) {
      std::vector<double> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
      if (H5Aread(old, H5T_NATIVE_DOUBLE, values.data()) >= 0) original = values[0];
    }
    H5Tclose(type);
    H5Sclose(space);
    H5Aclose(old);
  }
  H5Adelete(object, a.name.c_str());
  std::string what = "attribute " + a.object + "@" + a.name;
  const std::size_t choice = pick(random, 4);
  if (choice == 0) {
    what += " deleted";
  } else if (choice == 1) {  // a string where a number may be expected, or another string
    const std::string text = std::vector<std::string>{"", "x", "granule-snapshots", "granule-checkpoint", std::string(300, 'z')}[pick(random, 5)];
    const hid_t type = string_type(text.size() + 1);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t attribute = H5Acreate2(object, a.name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
    if (attribute >= 0) {
      H5Awrite(attribute, type, text.c_str());
      H5Aclose(attribute);
    }
    H5Sclose(space);
    H5Tclose(type);
    what += " = \"" + text.substr(0, 20) + "\"";
  } else {  // numbers: another count, type or value
    const hsize_t count = choice == 2 ? pick(random, 5) : 1;
    const hid_t type = random_file_type(random);
    const hid_t space = count == 1 && pick(random, 2) == 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &count, nullptr);
    const hid_t attribute = H5Acreate2(object, a.name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
    std::vector<double> values(count);
    for (double& v : values) v = special_value(random, original);
    if (attribute >= 0) {
      write_attribute_numbers(attribute, values);
      H5Aclose(attribute);
    }
    H5Sclose(space);
    what += " = " + std::to_string(count) + " values, first " + (values.empty() ? "none" : std::to_string(values[0]));
  }
  H5Oclose(object);
  return what;
}

std::vector<hsize_t> shape_of(hid_t dataset, std::vector<hsize_t>* max = nullptr) {
  const hid_t space = H5Dget_space(dataset);
  const int rank = std::max(0, H5Sget_simple_extent_ndims(space));
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (max) max->resize(dims.size());
  H5Sget_simple_extent_dims(space, dims.data(), max ? max->data() : nullptr);
  H5Sclose(space);
  return dims;
}

hsize_t elements(const std::vector<hsize_t>& dims) {
  hsize_t n = 1;
  for (const hsize_t d : dims) n *= d;
  return n;
}

// The edit of a hostile user: the digest of a checkpoint dataset made to match its new values.
void reseal(hid_t dataset) {
  if (H5Aexists(dataset, "xxh3_64") <= 0) return;
  const hid_t stored = H5Dget_type(dataset);
  const hid_t native = H5Tget_native_type(stored, H5T_DIR_ASCEND);
  const std::size_t size = H5Tget_size(native);
  std::vector<unsigned char> bytes(static_cast<std::size_t>(elements(shape_of(dataset))) * size);
  if (!bytes.empty()) H5Dread(dataset, native, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data());
  const std::uint64_t digest = XXH3_64bits(bytes.data(), bytes.size());
  const hid_t attribute = H5Aopen(dataset, "xxh3_64", H5P_DEFAULT);
  H5Awrite(attribute, H5T_NATIVE_UINT64, &digest);
  H5Aclose(attribute);
  H5Tclose(native);
  H5Tclose(stored);
}

std::string edit_values(hid_t dataset, const std::string& path, Random& random, const MutationOptions& options) {
  const std::vector<hsize_t> dims = shape_of(dataset);
  const hsize_t n = elements(dims);
  const hid_t type = H5Dget_type(dataset);
  const bool numeric = H5Tget_class(type) == H5T_INTEGER || H5Tget_class(type) == H5T_FLOAT;
  H5Tclose(type);
  if (!numeric || n == 0 || n > (hsize_t{1} << 24)) return "";
  std::vector<double> values(static_cast<std::size_t>(n));
  H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  const std::size_t edits = 1 + pick(random, 3);
  std::string what = "dataset " + path;
  for (std::size_t e = 0; e < edits; ++e) {
    const std::size_t at = pick(random, values.size());
    values[at] = special_value(random, values[at]);
    what += " [" + std::to_string(at) + "] = " + std::to_string(values[at]);
  }
  H5Dwrite(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  if (options.reseal_digests) {
    reseal(dataset);
    what += " (digest resealed)";
  }
  return what;
}

std::string reshape(hid_t file, const std::string& path, Random& random) {
  const hid_t old = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  if (old < 0) return "";
  std::vector<hsize_t> max;
  std::vector<hsize_t> dims = shape_of(old, &max);
  const bool frames = !max.empty() && max[0] == H5S_UNLIMITED;
  H5Dclose(old);
  H5Ldelete(file, path.c_str(), H5P_DEFAULT);
  std::string what = "dataset " + path;
  const std::size_t choice = pick(random, 7);
  if (choice == 0) return what + " deleted";
  const std::size_t axis = dims.empty() ? 0 : pick(random, dims.size());
  bool huge = false;
  switch (choice) {
    case 1: if (!dims.empty()) dims[axis] += 1; break;
    case 2: if (!dims.empty()) dims[axis] = dims[axis] > 0 ? dims[axis] - 1 : 0; break;
    case 3: if (!dims.empty()) dims[axis] *= 2; break;
    case 4: dims.push_back(3); break;
    case 5: if (!dims.empty()) dims.pop_back(); break;
    default: if (!dims.empty()) { dims[axis] = hsize_t{1} << 33; huge = true; } break;
  }
  std::vector<hsize_t> maxdims = dims;
  if (frames && !dims.empty()) maxdims[0] = H5S_UNLIMITED;
  const hid_t space = dims.empty() ? H5Screate(H5S_SCALAR) : H5Screate_simple(static_cast<int>(dims.size()), dims.data(), maxdims.data());
  const hid_t creation = H5Pcreate(H5P_DATASET_CREATE);
  if (!dims.empty() && (frames || huge)) {
    std::vector<hsize_t> chunk = dims;
    for (hsize_t& c : chunk) c = std::clamp<hsize_t>(c, 1, 64);
    H5Pset_chunk(creation, static_cast<int>(chunk.size()), chunk.data());
  }
  const bool text = pick(random, 8) == 0;
  const hid_t type = text ? string_type(8) : H5Tcopy(random_file_type(random));
  const hid_t dataset = H5Dcreate2(file, path.c_str(), type, space, H5P_DEFAULT, creation, H5P_DEFAULT);
  what += " reshaped to rank " + std::to_string(dims.size()) + (huge ? " with a huge axis (nothing stored)" : "");
  if (dataset >= 0) {
    const hsize_t n = elements(dims);
    if (!huge && n <= (hsize_t{1} << 22) && n > 0) {
      if (text) {
        std::vector<char> bytes(static_cast<std::size_t>(n) * 8, 'a');
        H5Dwrite(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data());
      } else {
        std::vector<double> values(static_cast<std::size_t>(n));
        for (double& v : values) v = pick(random, 4) == 0 ? special_value(random, 1.0) : std::uniform_real_distribution<double>(0.0, 2.0)(random);
        H5Dwrite(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
      }
    }
    H5Dclose(dataset);
  }
  H5Tclose(type);
  H5Pclose(creation);
  H5Sclose(space);
  return what;
}

std::string mutate_semantically(const std::string& mutant, Random& random, const MutationOptions& options) {
  const hid_t file = H5Fopen(mutant.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (file < 0) throw std::runtime_error("mutator: cannot open " + mutant);
  const Objects objects = objects_of(file);
  std::string what;
  const std::size_t operations = 1 + pick(random, 2);
  for (std::size_t k = 0; k < operations; ++k) {
    const std::size_t kind = pick(random, 3);
    std::string done;
    if (kind == 0 && !objects.attributes.empty()) {
      done = mutate_attribute(file, objects.attributes[pick(random, objects.attributes.size())], random);
    } else if (!objects.datasets.empty()) {
      const std::string& path = objects.datasets[pick(random, objects.datasets.size())];
      if (kind == 1) {
        done = reshape(file, path, random);
      } else if (const hid_t dataset = H5Dopen2(file, path.c_str(), H5P_DEFAULT); dataset >= 0) {
        done = edit_values(dataset, path, random, options);
        H5Dclose(dataset);
      }
    }
    if (!done.empty()) what += (what.empty() ? "" : "; ") + done;
  }
  H5Fclose(file);
  return what.empty() ? "unchanged" : what;
}

std::string mutate_bytes(const std::string& mutant, Random& random) {
  std::vector<char> bytes;
  {
    std::ifstream in(mutant, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  if (bytes.empty()) return "empty";
  std::string what;
  switch (pick(random, 4)) {
    case 0: {
      const std::size_t flips = 1 + pick(random, 16);
      for (std::size_t k = 0; k < flips; ++k) bytes[pick(random, bytes.size())] ^= static_cast<char>(1u << pick(random, 8));
      what = std::to_string(flips) + " bits flipped";
      break;
    }
    case 1: {
      const std::size_t at = pick(random, bytes.size());
      const std::size_t length = std::min(bytes.size() - at, 1 + pick(random, 64));
      std::fill_n(bytes.begin() + static_cast<std::ptrdiff_t>(at), length, '\0');
      what = std::to_string(length) + " bytes zeroed at " + std::to_string(at);
      break;
    }
    case 2: {
      const std::size_t length = pick(random, bytes.size());
      bytes.resize(length);
      what = "cut to " + std::to_string(length) + " bytes";
      break;
    }
    default: {
      const std::size_t at = pick(random, bytes.size());
      const std::size_t length = std::min(bytes.size() - at, 4 + pick(random, 5));
      std::fill_n(bytes.begin() + static_cast<std::ptrdiff_t>(at), length, '\xff');
      what = std::to_string(length) + " bytes set to 0xff at " + std::to_string(at);
    }
  }
  std::ofstream out(mutant, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return what;
}

}  // namespace

void reseal_digests(const std::string& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (file < 0) throw std::runtime_error("reseal: cannot open " + path);
  for (const std::string& name : objects_of(file).datasets) {
    const hid_t dataset = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
    if (dataset < 0) continue;
    reseal(dataset);
    H5Dclose(dataset);
  }
  H5Fclose(file);
}

std::string write_mutant(const std::string& original, const std::string& mutant, std::uint64_t seed, std::uint64_t index,
                         const MutationOptions& options) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  std::filesystem::copy_file(original, mutant, std::filesystem::copy_options::overwrite_existing);
  Random random(seed * 0x9E3779B97F4A7C15ull + index);
  // Two in three mutants are edits a tool like h5py makes, one in three damage to the bytes.
  if (pick(random, 3) != 0) return mutate_semantically(mutant, random, options);
  return mutate_bytes(mutant, random);
}

}  // namespace granule::fuzz
