#include "io/export_field_source.hpp"

#include <stdexcept>

#include "io/hdf5_util.hpp"

namespace granule {

namespace {

std::vector<hsize_t> dataset_shape(hid_t file, const std::string& name) {
  const hid_t dataset = h5::check_id(H5Dopen2(file, name.c_str(), H5P_DEFAULT), "opening " + name);
  const hid_t space = H5Dget_space(dataset);
  std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  H5Sclose(space);
  H5Dclose(dataset);
  return dims;
}

// The (K, ny, nx) maps of one group, frame k.
void read_group_maps(hid_t file, const std::string& group_name, const FieldGrid& grid, hsize_t k,
                     std::vector<NamedCellArray>& arrays) {
  if (H5Lexists(file, group_name.c_str(), H5P_DEFAULT) <= 0) return;
  const hid_t group = h5::check_id(H5Gopen2(file, group_name.c_str(), H5P_DEFAULT), "opening " + group_name);
  H5G_info_t info;
  h5::check(H5Gget_info(group, &info), "listing " + group_name);
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t length = H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    std::string name(static_cast<std::size_t>(length), '\0');
    H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size() + 1, H5P_DEFAULT);
    const std::string path = group_name + "/" + name;
    const std::vector<hsize_t> dims = dataset_shape(file, path);
    if (dims.size() != 3 || dims[1] != static_cast<hsize_t>(grid.ny) || dims[2] != static_cast<hsize_t>(grid.nx)) continue;
    NamedCellArray array{group_name + "_" + name, std::vector<double>(grid.cells())};
    h5::read_frame(file, path.c_str(), H5T_NATIVE_DOUBLE, array.values.data(), k);
    arrays.push_back(std::move(array));
  }
  H5Gclose(group);
}

}  // namespace

FieldFileFrame read_field_file_frame(const std::string& path, std::int64_t index) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t file = h5::check_id(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "opening " + path);
  FieldFileFrame out;
  try {
    FieldGrid& g = out.grid;
    g.nx = static_cast<int>(h5::read_attribute<std::int64_t>(file, "nx", H5T_NATIVE_INT64));
    g.ny = static_cast<int>(h5::read_attribute<std::int64_t>(file, "ny", H5T_NATIVE_INT64));
    g.length_x = h5::read_attribute<double>(file, "length_x", H5T_NATIVE_DOUBLE);
    g.length_y = h5::read_attribute<double>(file, "length_y", H5T_NATIVE_DOUBLE);
    out.frames = static_cast<std::int64_t>(dataset_shape(file, "frames/t").at(0));
    const std::int64_t k = index < 0 ? out.frames + index : index;
    if (k < 0 || k >= out.frames) {
      throw std::runtime_error(path + " has " + std::to_string(out.frames) + " frames: no frame " + std::to_string(index));
    }
    const auto frame = static_cast<hsize_t>(k);
    h5::read_frame(file, "frames/t", H5T_NATIVE_DOUBLE, &out.time, frame);
    h5::read_frame(file, "frames/c", H5T_NATIVE_DOUBLE, &out.collisions_per_particle, frame);
    read_group_maps(file, "instant", g, frame, out.arrays);
    read_group_maps(file, "average", g, frame, out.arrays);
  } catch (...) {
    H5Fclose(file);
    throw;
  }
  H5Fclose(file);
  return out;
}

}  // namespace granule
