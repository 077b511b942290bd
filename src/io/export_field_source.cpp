#include "io/export_field_source.hpp"

#include <stdexcept>

#include "io/fields_file.hpp"
#include "io/hdf5_util.hpp"
#include "io/io_error.hpp"

namespace granule {

namespace {

using h5::Handle;

// The (K, ny, nx) maps (3D: (K, nz, ny, nx)) of one group, frame k.
void read_group_maps(hid_t file, const std::string& group_name, const FieldGrid& grid, hsize_t k,
                     std::vector<NamedCellArray>& arrays) {
  if (H5Lexists(file, group_name.c_str(), H5P_DEFAULT) <= 0) return;
  Handle group(h5::check_id(H5Gopen2(file, group_name.c_str(), H5P_DEFAULT), file, "open group", group_name.c_str()), H5Gclose);
  H5G_info_t info;
  h5::check(H5Gget_info(group.get(), &info), file, "list group", group_name.c_str());
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t length = H5Lget_name_by_idx(group.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    h5::check(length < 0 ? -1 : 0, file, "list group", group_name.c_str());
    std::string name(static_cast<std::size_t>(length), '\0');
    H5Lget_name_by_idx(group.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size() + 1, H5P_DEFAULT);
    const std::string path = group_name + "/" + name;
    std::vector<hsize_t> map = h5::dataset_shape(file, path.c_str());
    if (!map.empty()) map.erase(map.begin());  // the frames axis
    if (map != field_map_shape(grid)) continue;
    arrays.push_back({group_name + "_" + name, h5::read_frame_values(file, path.c_str(), k, map)});
  }
  group.close();
}

}  // namespace

FieldFileFrame read_field_file_frame(const std::string& path, std::int64_t index) {
  Handle opened = h5::open_file(path);
  const hid_t file = opened.get();
  FieldFileFrame out;
  out.grid = read_fields_grid(file);
  const std::vector<hsize_t> times = h5::dataset_shape(file, "frames/t");
  if (times.size() != 1) throw InputError(path + ": dataset frames/t is not one time per frame");
  out.frames = static_cast<std::int64_t>(times[0]);
  const std::int64_t k = index < 0 ? out.frames + index : index;
  if (k < 0 || k >= out.frames) {
    throw std::runtime_error(path + " has " + std::to_string(out.frames) + " frames: no frame " + std::to_string(index));
  }
  const auto frame = static_cast<hsize_t>(k);
  h5::read_frame(file, "frames/t", H5T_NATIVE_DOUBLE, &out.time, frame, {});
  h5::read_frame(file, "frames/c", H5T_NATIVE_DOUBLE, &out.collisions_per_particle, frame, {});
  read_group_maps(file, "instant", out.grid, frame, out.arrays);
  read_group_maps(file, "average", out.grid, frame, out.arrays);
  opened.close();
  return out;
}

}  // namespace granule
