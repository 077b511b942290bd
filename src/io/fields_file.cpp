#include "io/fields_file.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <utility>

#include "io/hdf5_util.hpp"
#include "io/input_ranges.hpp"
#include "io/io_error.hpp"

namespace granule {

using namespace h5;

namespace {

constexpr const char* kFormat = "granule-fields";
constexpr int kFormatVersion = 1;

// The collisional and total stress (1.6), (1.7), their pressures (trace/d) and the collisional and
// total heat flux of one interval average.
struct StressFrame {
  CollisionalStress collisional, total;
  std::vector<double> pressure_collisional, pressure_total;
  HeatFlux heat_flux_collisional, heat_flux_total;
};

StressFrame stress_frame(const FieldsFrame& frame, int dimension) {
  StressFrame s{*frame.collisional, *frame.collisional, {}, {}, *frame.heat_flux_collisional, *frame.heat_flux_collisional};
  CellFields kinetic = frame.average;
  const std::size_t n = s.collisional.xx.size();
  for (int a = 0; a < dimension; ++a) {
    for (int b = s.collisional.full() ? 0 : a; b < dimension; ++b) {
      for (std::size_t i = 0; i < n; ++i) s.total.component(a, b)[i] = kinetic.kinetic(a, b)[i] + s.collisional.component(a, b)[i];
    }
    for (std::size_t i = 0; i < n; ++i) {
      s.heat_flux_total.component(a)[i] = kinetic.heat_flux_kinetic(a)[i] + s.heat_flux_collisional.component(a)[i];
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    s.pressure_collisional.push_back(s.collisional.pressure(i));
    s.pressure_total.push_back(s.total.pressure(i));
  }
  return s;
}

// The datasets of a StressFrame, in one list: the 2D set, then in 3D the z components; then
// (for_each_stress) the entries below the diagonal of a full (rough grains') tensor.
template <typename Stress, typename Visit>
void for_each_symmetric_stress(Stress& s, int dimension, Visit& visit) {
  visit("collisional_xx", s.collisional.xx);
  visit("collisional_xy", s.collisional.xy);
  visit("collisional_yy", s.collisional.yy);
  visit("pressure_collisional", s.pressure_collisional);
  visit("collisions", s.collisional.collisions);
  visit("total_xx", s.total.xx);
  visit("total_xy", s.total.xy);
  visit("total_yy", s.total.yy);
  visit("pressure_total", s.pressure_total);
  visit("heat_flux_collisional_x", s.heat_flux_collisional.x);
  visit("heat_flux_collisional_y", s.heat_flux_collisional.y);
  visit("heat_flux_total_x", s.heat_flux_total.x);
  visit("heat_flux_total_y", s.heat_flux_total.y);
  if (dimension != 3) return;
  visit("collisional_xz", s.collisional.xz);
  visit("collisional_yz", s.collisional.yz);
  visit("collisional_zz", s.collisional.zz);
  visit("total_xz", s.total.xz);
  visit("total_yz", s.total.yz);
  visit("total_zz", s.total.zz);
  visit("heat_flux_collisional_z", s.heat_flux_collisional.z);
  visit("heat_flux_total_z", s.heat_flux_total.z);
}

template <typename Stress, typename Visit>
void for_each_stress(Stress& s, int dimension, bool full, Visit&& visit) {
  for_each_symmetric_stress(s, dimension, visit);
  if (!full) return;
  visit("collisional_yx", s.collisional.yx);
  visit("total_yx", s.total.yx);
  if (dimension != 3) return;
  visit("collisional_zx", s.collisional.zx);
  visit("collisional_zy", s.collisional.zy);
  visit("total_zx", s.total.zx);
  visit("total_zy", s.total.zy);
}

// Streamwise profiles of the interval-averaged heat flux (runs only), in one list.
template <typename Stress, typename Visit>
void for_each_flux_profile(Stress& s, int dimension, Visit&& visit) {
  visit("/profiles/average_heat_flux_collisional_x", s.heat_flux_collisional.x);
  visit("/profiles/average_heat_flux_collisional_y", s.heat_flux_collisional.y);
  visit("/profiles/average_heat_flux_total_x", s.heat_flux_total.x);
  visit("/profiles/average_heat_flux_total_y", s.heat_flux_total.y);
  if (dimension != 3) return;
  visit("/profiles/average_heat_flux_collisional_z", s.heat_flux_collisional.z);
  visit("/profiles/average_heat_flux_total_z", s.heat_flux_total.z);
}

// The streamwise profiles of the instantaneous fields, in one list.
template <typename Profiles, typename Visit>
void for_each_profile(Profiles& p, Visit&& visit) {
  visit("/profiles/density", p.density);
  visit("/profiles/velocity_x", p.velocity_x);
  visit("/profiles/velocity_y", p.velocity_y);
  visit("/profiles/temperature", p.temperature);
  visit("/profiles/heat_flux_kinetic_x", p.heat_flux_kinetic_x);
  visit("/profiles/heat_flux_kinetic_y", p.heat_flux_kinetic_y);
}

// The frame scalars, in one list.
template <typename Frame, typename Visit>
void for_each_scalar(Frame& f, Visit&& visit) {
  visit("/frames/t", f.t);
  visit("/frames/c", f.c);
  visit("/frames/t_start", f.t_start);
  visit("/frames/c_start", f.c_start);
}

// The Lees–Edwards state of a frame (3D files only), in one list.
template <typename Frame, typename Visit>
void for_each_image_scalar(Frame& f, Visit&& visit) {
  visit("/frames/shear_offset", f.shear_offset);
  visit("/frames/shear_velocity", f.shear_velocity);
}

}  // namespace

FieldsWriter::FieldsWriter(const std::string& path, const FieldGrid& grid, const FieldsMetadata& m, bool with_collisional)
    : file_(path, kFormat, kFormatVersion, m.version),
      grid_(grid),
      with_collisional_(with_collisional),
      rough_(m.system.roughness.rough) {
  const hid_t f = file_.get();
  write_string_attribute(f, "source", m.source);
  write_string_attribute(f, "boundary", m.boundary);
  write_attribute(f, "nx", H5T_NATIVE_INT, &grid.nx);
  write_attribute(f, "ny", H5T_NATIVE_INT, &grid.ny);
  write_attribute(f, "length_x", H5T_NATIVE_DOUBLE, &grid.length_x);
  write_attribute(f, "length_y", H5T_NATIVE_DOUBLE, &grid.length_y);
  if (grid.dimension == 3) {  // a 2D file has no 3D attribute, not even `dimension`
    write_attribute(f, "dimension", H5T_NATIVE_INT, &grid.dimension);
    write_attribute(f, "nz", H5T_NATIVE_INT, &grid.nz);
    write_attribute(f, "length_z", H5T_NATIVE_DOUBLE, &grid.length_z);
  }
  write_attribute(f, "diameter", H5T_NATIVE_DOUBLE, &m.system.diameter);
  write_attribute(f, "particles", H5T_NATIVE_INT64, &m.system.particles);
  write_attribute(f, "restitution", H5T_NATIVE_DOUBLE, &m.system.restitution);
  write_attribute(f, "shear_velocity", H5T_NATIVE_DOUBLE, &m.system.shear_velocity);
  const int subtract = m.subtract_shear_profile ? 1 : 0;
  write_attribute(f, "subtract_shear_profile", H5T_NATIVE_INT, &subtract);
  for (const char* group : {"/frames", "/instant", "/average", "/profiles"}) Handle(create_group(f, group), H5Gclose).close();

  const std::vector<hsize_t> cells = field_map_shape(grid);
  const std::vector<hsize_t> rows{static_cast<hsize_t>(grid.ny)};
  FieldsFrame shape;
  shape.instant.grid = grid;
  shape.instant.rough = rough_;
  for_each_scalar(shape, [&](const char* name, double&) { add_frames(f, name, H5T_NATIVE_DOUBLE, {}); });
  if (grid.dimension == 3) for_each_image_scalar(shape, [&](const char* name, double&) { add_frames(f, name, H5T_NATIVE_DOUBLE, {}); });
  add_frames(f, "/average/configurations", H5T_NATIVE_INT, {});
  for_each_field(shape.instant, [&](const char* name, std::vector<double>&) {
    add_frames(f, (std::string("/instant/") + name).c_str(), H5T_NATIVE_DOUBLE, cells);
    add_frames(f, (std::string("/average/") + name).c_str(), H5T_NATIVE_DOUBLE, cells);
  });
  StressFrame stress;
  if (with_collisional_) {
    for_each_stress(stress, grid.dimension, rough_, [&](const char* name, std::vector<double>&) {
      add_frames(f, (std::string("/average/") + name).c_str(), H5T_NATIVE_DOUBLE, cells);
    });
  }
  std::vector<double> y;
  for (int iy = 0; iy < grid.ny; ++iy) y.push_back(grid.center_y(iy));
  write_dataset(f, "/profiles/y", rows, y);
  StreamwiseProfiles profiles;
  for_each_profile(profiles, [&](const char* name, std::vector<double>&) { add_frames(f, name, H5T_NATIVE_DOUBLE, rows); });
  if (with_collisional_) {
    for_each_flux_profile(stress, grid.dimension, [&](const char* name, std::vector<double>&) { add_frames(f, name, H5T_NATIVE_DOUBLE, rows); });
  }
  file_.flush();
}

FieldsWriter::FieldsWriter(const std::string& path, std::int64_t keep_frames)
    : file_(path, kFormat, keep_frames), grid_(read_fields_grid(file_.get())) {
  const htri_t collisional = H5Lexists(file_.get(), "/average/collisional_xx", H5P_DEFAULT);
  check(collisional, file_.get(), "look for", "/average/collisional_xx");
  with_collisional_ = collisional > 0;
  const htri_t rough = H5Lexists(file_.get(), "/instant/rotational_temperature", H5P_DEFAULT);
  check(rough, file_.get(), "look for", "/instant/rotational_temperature");
  rough_ = rough > 0;
}

void FieldsWriter::append(const FieldsFrame& frame) {
  const hid_t f = file_.get();
  if (frame.instant.rough != rough_ || frame.average.rough != rough_) {
    throw std::logic_error("fields frame of rough grains in a file of smooth ones, or the reverse");
  }
  const auto at = static_cast<hsize_t>(file_.frames());
  const auto append_scalar = [&](const char* name, const double& value) { append_frame(f, name, H5T_NATIVE_DOUBLE, &value, at); };
  for_each_scalar(frame, append_scalar);
  if (grid_.dimension == 3) for_each_image_scalar(frame, append_scalar);
  append_frame(f, "/average/configurations", H5T_NATIVE_INT, &frame.configurations, at);
  for_each_field(frame.instant, [&](const char* name, const std::vector<double>& v) {
    append_frame(f, (std::string("/instant/") + name).c_str(), H5T_NATIVE_DOUBLE, v.data(), at);
  });
  for_each_field(frame.average, [&](const char* name, const std::vector<double>& v) {
    append_frame(f, (std::string("/average/") + name).c_str(), H5T_NATIVE_DOUBLE, v.data(), at);
  });
  if (with_collisional_) {
    if (!frame.collisional || !frame.heat_flux_collisional) {
      throw std::logic_error("fields frame without the collisional stress and heat flux");
    }
    if (frame.collisional->full() != rough_) throw std::logic_error("fields frame whose collisional stress is not full for rough grains");
    const StressFrame stress = stress_frame(frame, grid_.dimension);
    for_each_stress(stress, grid_.dimension, rough_, [&](const char* name, const std::vector<double>& v) {
      append_frame(f, (std::string("/average/") + name).c_str(), H5T_NATIVE_DOUBLE, v.data(), at);
    });
    for_each_flux_profile(stress, grid_.dimension, [&](const char* name, const std::vector<double>& v) {
      append_frame(f, name, H5T_NATIVE_DOUBLE, row_means(grid_, v).data(), at);
    });
  }
  const StreamwiseProfiles p = streamwise_profiles(frame.instant);
  for_each_profile(p, [&](const char* name, const std::vector<double>& v) { append_frame(f, name, H5T_NATIVE_DOUBLE, v.data(), at); });
  file_.end_frame();
}

FieldGrid read_fields_grid(hid_t file) {
  FieldGrid grid;
  grid.nx = read_attribute<int>(file, "nx", H5T_NATIVE_INT);
  grid.ny = read_attribute<int>(file, "ny", H5T_NATIVE_INT);
  grid.length_x = read_attribute<double>(file, "length_x", H5T_NATIVE_DOUBLE);
  grid.length_y = read_attribute<double>(file, "length_y", H5T_NATIVE_DOUBLE);
  const htri_t three_dimensional = H5Aexists(file, "dimension");
  check(three_dimensional, file, "look for", "dimension");
  if (three_dimensional > 0) {
    grid.dimension = read_attribute<int>(file, "dimension", H5T_NATIVE_INT);
    grid.nz = read_attribute<int>(file, "nz", H5T_NATIVE_INT);
    grid.length_z = read_attribute<double>(file, "length_z", H5T_NATIVE_DOUBLE);
  }
  // A damaged grid would size every map read from the file: its cells are checked first.
  const auto refuse = [&](const std::string& what) { throw InputError(h5::file_name(file) + ": " + what); };
  if (grid.dimension != 2 && grid.dimension != 3) refuse("attribute dimension is " + std::to_string(grid.dimension) + "; expected 2 or 3");
  for (const auto& [name, count] : {std::pair{"nx", grid.nx}, std::pair{"ny", grid.ny}, std::pair{"nz", grid.nz}}) {
    if (count < 1) refuse(fmt::format("attribute {} is {}; expected a count of cells ≥ 1", name, count));
  }
  for (const auto& [name, length] : {std::pair{"length_x", grid.length_x}, std::pair{"length_y", grid.length_y},
                                     std::pair{"length_z", grid.length_z}}) {
    if (!kLengthRange.contains(length)) refuse(fmt::format("attribute {} is {}; expected a length in {}", name, length, kLengthRange.text()));
  }
  return grid;
}

std::vector<hsize_t> field_map_shape(const FieldGrid& grid) {
  std::vector<hsize_t> shape{static_cast<hsize_t>(grid.ny), static_cast<hsize_t>(grid.nx)};
  if (grid.dimension == 3) shape.insert(shape.begin(), static_cast<hsize_t>(grid.nz));
  return shape;
}

std::vector<double> read_fields_frame_c(const std::string& path) {
  h5::Handle file = h5::open_file(path);
  std::vector<double> c(static_cast<std::size_t>(h5::complete_frames(file.get())));
  for (std::size_t k = 0; k < c.size(); ++k) h5::read_frame(file.get(), "/frames/c", H5T_NATIVE_DOUBLE, &c[k], k, {});
  file.close();
  return c;
}

}  // namespace granule
