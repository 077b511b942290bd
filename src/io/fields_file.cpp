#include "io/fields_file.hpp"

#include <array>
#include <stdexcept>

#include "io/hdf5_util.hpp"

namespace granule {

using namespace h5;

namespace {

constexpr const char* kFormat = "granule-fields";
constexpr int kFormatVersion = 1;

// The collisional and total stress and heat flux datasets of the interval average, in one list.
template <typename Visit>
void for_each_stress(Visit&& visit) {
  for (const char* name : {"collisional_xx", "collisional_xy", "collisional_yy", "pressure_collisional", "collisions",
                           "total_xx", "total_xy", "total_yy", "pressure_total", "heat_flux_collisional_x",
                           "heat_flux_collisional_y", "heat_flux_total_x", "heat_flux_total_y"}) {
    visit(name);
  }
}

// Streamwise profiles of the interval-averaged heat flux (runs only), in one list.
constexpr std::array<const char*, 4> kAverageFluxProfiles{
    "/profiles/average_heat_flux_collisional_x", "/profiles/average_heat_flux_collisional_y",
    "/profiles/average_heat_flux_total_x", "/profiles/average_heat_flux_total_y"};

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
    : file_(path, kFormat, kFormatVersion, m.version), grid_(grid), with_collisional_(with_collisional) {
  const hid_t f = file_.get();
  write_string_attribute(f, "source", m.source);
  write_string_attribute(f, "boundary", m.boundary);
  write_attribute(f, "nx", H5T_NATIVE_INT, &grid.nx);
  write_attribute(f, "ny", H5T_NATIVE_INT, &grid.ny);
  write_attribute(f, "length_x", H5T_NATIVE_DOUBLE, &grid.length_x);
  write_attribute(f, "length_y", H5T_NATIVE_DOUBLE, &grid.length_y);
  if (grid.dimension == 3) {  // a 2D file has exactly the attributes it had before 3D existed
    if (with_collisional) throw std::invalid_argument("the collisional stress is not yet written for 3D fields");
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
  for_each_scalar(shape, [&](const char* name, double&) { add_frames(f, name, H5T_NATIVE_DOUBLE, {}); });
  if (grid.dimension == 3) for_each_image_scalar(shape, [&](const char* name, double&) { add_frames(f, name, H5T_NATIVE_DOUBLE, {}); });
  add_frames(f, "/average/configurations", H5T_NATIVE_INT, {});
  for_each_field(shape.instant, [&](const char* name, std::vector<double>&) {
    add_frames(f, (std::string("/instant/") + name).c_str(), H5T_NATIVE_DOUBLE, cells);
    add_frames(f, (std::string("/average/") + name).c_str(), H5T_NATIVE_DOUBLE, cells);
  });
  if (with_collisional_) {
    for_each_stress([&](const char* name) { add_frames(f, (std::string("/average/") + name).c_str(), H5T_NATIVE_DOUBLE, cells); });
  }
  std::vector<double> y;
  for (int iy = 0; iy < grid.ny; ++iy) y.push_back(grid.center_y(iy));
  write_dataset(f, "/profiles/y", rows, y);
  StreamwiseProfiles profiles;
  for_each_profile(profiles, [&](const char* name, std::vector<double>&) { add_frames(f, name, H5T_NATIVE_DOUBLE, rows); });
  if (with_collisional_) {
    for (const char* name : kAverageFluxProfiles) add_frames(f, name, H5T_NATIVE_DOUBLE, rows);
  }
  file_.flush();
}

FieldsWriter::FieldsWriter(const std::string& path, std::int64_t keep_frames)
    : file_(path, kFormat, keep_frames), grid_(read_fields_grid(file_.get())) {
  const htri_t collisional = H5Lexists(file_.get(), "/average/collisional_xx", H5P_DEFAULT);
  check(collisional, file_.get(), "look for", "/average/collisional_xx");
  with_collisional_ = collisional > 0;
}

void FieldsWriter::append(const FieldsFrame& frame) {
  const hid_t f = file_.get();
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
    const CollisionalStress& c = *frame.collisional;
    const HeatFlux& qc = *frame.heat_flux_collisional;
    const CellFields& k = frame.average;
    const std::size_t n = grid_.cells();
    std::vector<double> pc(n), txx(n), txy(n), tyy(n), pt(n), qx(n), qy(n);
    for (std::size_t i = 0; i < n; ++i) {
      pc[i] = 0.5 * (c.xx[i] + c.yy[i]);
      txx[i] = k.kinetic_xx[i] + c.xx[i];  // total stress (1.7)
      txy[i] = k.kinetic_xy[i] + c.xy[i];
      tyy[i] = k.kinetic_yy[i] + c.yy[i];
      pt[i] = 0.5 * (txx[i] + tyy[i]);
      qx[i] = k.heat_flux_kinetic_x[i] + qc.x[i];  // total heat flux q^(k) + q^(c)
      qy[i] = k.heat_flux_kinetic_y[i] + qc.y[i];
    }
    const std::vector<const std::vector<double>*> data{&c.xx, &c.xy, &c.yy, &pc, &c.collisions, &txx, &txy,
                                                       &tyy, &pt,   &qc.x, &qc.y, &qx,           &qy};
    std::size_t next = 0;
    for_each_stress([&](const char* name) {
      append_frame(f, (std::string("/average/") + name).c_str(), H5T_NATIVE_DOUBLE, data[next++]->data(), at);
    });
    const std::array<std::vector<double>, 4> flux_profiles{row_means(grid_, qc.x), row_means(grid_, qc.y),
                                                           row_means(grid_, qx), row_means(grid_, qy)};
    for (std::size_t i = 0; i < flux_profiles.size(); ++i) {
      append_frame(f, kAverageFluxProfiles[i], H5T_NATIVE_DOUBLE, flux_profiles[i].data(), at);
    }
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
  for (std::size_t k = 0; k < c.size(); ++k) h5::read_frame(file.get(), "/frames/c", H5T_NATIVE_DOUBLE, &c[k], k);
  file.close();
  return c;
}

}  // namespace granule
