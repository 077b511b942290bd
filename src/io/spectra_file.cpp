#include "io/spectra_file.hpp"

#include <fmt/format.h>

#include <filesystem>

#include "granule/version.hpp"
#include "io/file_schema.hpp"

namespace granule {

using namespace granule::spectra;
using namespace granule::spectra_file;

namespace {

constexpr const char* kFormat = "granule-spectra";
constexpr int kFormatVersion = 2;  // 2: every run has S(k), its band and the significance of dominant modes

}  // namespace

const h5::FileSchema& spectra_file::spectra_schema(int dimension) {
  using h5::Values;
  const auto describe = [](int d) {
    const bool depth = d == 3;
    const std::string rings = depth ? "shell_" : "annulus_";
    h5::FileSchema s{kFormat, kFormatVersion, kFormatVersion, {}, {}, {}};
    for (const char* name : {"source", "method", "normalization", "boundary", "length_over_L0_compares", "null_hypothesis"}) {
      s.attributes.push_back({".", name, Values::kText});
    }
    for (const char* name : {"max_mode", "subtract_shear_profile", "exclude_ky_axis_from_Px", "kernel_width", "fft_grid", "particles"}) {
      s.attributes.push_back({".", name, Values::kIntegers});
    }
    for (const char* name : {"dk", "diameter", depth ? "packing_fraction" : "area_fraction", "restitution", "shear_velocity",
                             "false_alarm"}) {
      s.attributes.push_back({".", name, Values::kFinite});
    }
    s.attributes.push_back({".", "box", Values::kFinite, depth ? 3 : 2});
    if (depth) s.attributes.push_back({".", "dimension", Values::kIntegers});
    for (const char* name : {"mean_free_path", "L0"}) s.attributes.push_back({".", name, Values::kNumbers});

    // F frames, maps of S × S modes (the plane k_z = 0 in 3D), K rings of |k|.
    s.datasets.push_back({rings + "k", "K"});
    s.datasets.push_back({"frame_index", "F", Values::kIntegers});
    for (const char* name : {"collisions_per_particle", "time", "shear_offset", "tilt"}) s.datasets.push_back({name, "F"});
    for (const char* name : {"kx", "ky"}) s.datasets.push_back({name, "F,S,S"});
    for (const char* name : {"modes", "P_modes"}) s.datasets.push_back({rings + name, "F,K", Values::kIntegers});
    for (const auto& [name, member] : kShellAverages) s.datasets.push_back({name, "F,K", Values::kNumbers});
    for (const char* name : {"ideal_R", "ideal_P"}) s.datasets.push_back({name, "F", Values::kNumbers});
    s.groups.push_back("dominant");
    for (const FieldChoice& field : fields_of(d)) {
      const std::string group = std::string("dominant/") + field.name;
      s.groups.push_back(group);
      s.datasets.push_back({field.name, "F,S,S", Values::kNumbers});
      s.datasets.push_back({rings + field.name, "F,K", Values::kNumbers});
      for (const char* column : {"l", "m", "n", "significant"}) {
        if (depth || column[0] != 'n') s.datasets.push_back({group + "/" + column, "F", Values::kIntegers});
      }
      for (const auto& [column, member] : kDominantColumns) {
        if (depth || std::string(column) != "kz") s.datasets.push_back({group + "/" + column, "F", Values::kNumbers});
      }
      s.datasets.push_back({group + "/length_over_L0", "F", Values::kNumbers});
    }
    return s;
  };
  static const h5::FileSchema planar = describe(2), spatial = describe(3);
  return dimension == 3 ? spatial : planar;
}

std::string spectra_file::dominant_csv_header() {
  std::string csv = "frame,t,c,shear_offset,field,l,m,n";
  for (const auto& [column, member] : kDominantColumns) csv += fmt::format(",{}", column);
  return csv + ",length_over_L0,significant\n";
}

std::string spectra_file::dominant_csv_row(std::int64_t index, const SnapshotFrame& frame, const char* field,
                                           const DominantMode& d, double l0) {
  std::string csv = fmt::format("{},{:.17g},{:.17g},{:.17g},{},{},{},{}", index, frame.clock.time,
                                frame.collisions_per_particle, frame.shear_offset, field, d.l, d.m, d.n);
  for (const auto& [column, member] : kDominantColumns) csv += fmt::format(",{:.17g}", d.*member);
  return csv + fmt::format(",{:.17g},{}\n", d.length / l0, d.significant ? 1 : 0);
}

SpectraFile::SpectraFile(const std::string& path, const SpectraFileSettings& settings, const SnapshotMetadata& metadata,
                         const TransformOptions& transform, double dk, const AnnulusSpectrum& bins)
    : partial_(path, kFormat, kFormatVersion, kVersion),
      file_(partial_.get()),
      depth_(metadata.system.dimension == 3),
      rings_(depth_ ? "shell_" : "annulus_") {
  write_layout(settings, metadata, transform, dk, bins);
  partial_.flush();
}

void SpectraFile::write_layout(const SpectraFileSettings& options, const SnapshotMetadata& metadata,
                               const TransformOptions& transform, double dk, const AnnulusSpectrum& bins) {
  using namespace h5;
  const SystemParams& s = metadata.system;
  write_string_attribute(file_, "source", std::filesystem::absolute(options.source).string());
  write_string_attribute(file_, "method", options.method);
  write_attribute(file_, "max_mode", H5T_NATIVE_INT, &transform.max_mode);
  write_attribute(file_, "dk", H5T_NATIVE_DOUBLE, &dk);
  const int subtract = options.subtract_shear ? 1 : 0, exclude = options.exclude_ky_axis ? 1 : 0;
  write_attribute(file_, "subtract_shear_profile", H5T_NATIVE_INT, &subtract);
  write_attribute(file_, "exclude_ky_axis_from_Px", H5T_NATIVE_INT, &exclude);
  const int grid = fft_grid_size(transform.max_mode, transform.gridding);
  write_attribute(file_, "kernel_width", H5T_NATIVE_INT, &transform.gridding.kernel_width);
  write_attribute(file_, "fft_grid", H5T_NATIVE_INT, &grid);
  write_string_attribute(file_, "normalization", "rho(k) = (1/2pi) sum_j exp(i k.r_j), p(k) = (1/2pi) sum_j v_j exp(i k.r_j) (thesis 3.4-3.5)");
  write_attribute(file_, "particles", H5T_NATIVE_INT64, &s.particles);
  write_attribute(file_, "diameter", H5T_NATIVE_DOUBLE, &s.diameter);
  const double box[3] = {s.length_x, s.length_y, s.length_z};
  write_attribute(file_, "box", H5T_NATIVE_DOUBLE, box, depth_ ? 3 : 2);
  write_attribute(file_, depth_ ? "packing_fraction" : "area_fraction", H5T_NATIVE_DOUBLE, &metadata.packing_fraction);
  if (depth_) write_attribute(file_, "dimension", H5T_NATIVE_INT, &s.dimension);
  write_attribute(file_, "restitution", H5T_NATIVE_DOUBLE, &s.restitution);
  write_string_attribute(file_, "boundary", metadata.boundary);
  write_attribute(file_, "shear_velocity", H5T_NATIVE_DOUBLE, &s.shear_velocity);
  const double l = mean_free_path(s), l0 = cluster_length(s);
  write_attribute(file_, "mean_free_path", H5T_NATIVE_DOUBLE, &l);
  write_attribute(file_, "L0", H5T_NATIVE_DOUBLE, &l0);
  write_string_attribute(file_, "length_over_L0_compares",
                         depth_ ? "2pi/|k| of the dominant mode over L0 = l/sqrt(1-e^2) (1.1), l = 1/(sqrt2 pi n sigma^2)"
                                : "2pi/|k| of the dominant mode over L0 = l/sqrt(1-e^2) (1.1), l = LxLy/(2 N sigma) (3.1.2)");
  write_attribute(file_, "false_alarm", H5T_NATIVE_DOUBLE, &options.false_alarm);
  write_string_attribute(file_, "null_hypothesis",
                         "uncorrelated positions: power/level of one mode ~ sum_i share_i Exp(1); "
                         "noise_p_value = 1 - (1 - Q(s))^K over K independent modes (+-k once)");

  const auto side = static_cast<hsize_t>(2 * transform.max_mode + 1);
  const auto rings = static_cast<hsize_t>(bins.k.size());
  write_dataset(file_, (rings_ + "k").c_str(), {rings}, bins.k);
  for (const char* name : {"frame_index", "collisions_per_particle", "time", "shear_offset", "tilt"}) {
    add_frames(file_, name, std::string(name) == "frame_index" ? H5T_STD_I64LE : H5T_IEEE_F64LE, {});
  }
  add_frames(file_, "kx", H5T_IEEE_F64LE, {side, side});
  add_frames(file_, "ky", H5T_IEEE_F64LE, {side, side});
  add_frames(file_, (rings_ + "modes").c_str(), H5T_STD_I64LE, {rings});
  add_frames(file_, (rings_ + "P_modes").c_str(), H5T_STD_I64LE, {rings});
  for (const auto& [name, member] : kShellAverages) add_frames(file_, name, H5T_IEEE_F64LE, {rings});
  for (const char* name : {"ideal_R", "ideal_P"}) add_frames(file_, name, H5T_IEEE_F64LE, {});
  Handle(create_group(file_, "dominant"), H5Gclose).close();
  for (const FieldChoice& field : fields_of(s.dimension)) {
    add_frames(file_, field.name, H5T_IEEE_F64LE, {side, side});
    add_frames(file_, (rings_ + field.name).c_str(), H5T_IEEE_F64LE, {rings});
    const std::string group = std::string("dominant/") + field.name;
    Handle(create_group(file_, group.c_str()), H5Gclose).close();
    for (const char* column : {"l", "m", "n", "significant"}) {
      if (depth_ || column[0] != 'n') add_frames(file_, (group + "/" + column).c_str(), H5T_STD_I32LE, {});
    }
    for (const auto& [column, member] : kDominantColumns) {
      if (depth_ || std::string(column) != "kz") add_frames(file_, (group + "/" + column).c_str(), H5T_IEEE_F64LE, {});
    }
    add_frames(file_, (group + "/length_over_L0").c_str(), H5T_IEEE_F64LE, {});
  }
}

void SpectraFile::append(std::int64_t index, const SnapshotFrame& frame, const PowerMaps& maps, const AnnulusSpectrum& annulus,
                         const std::vector<DominantMode>& dominant, double l0) {
  using namespace h5;
  const auto k = static_cast<hsize_t>(partial_.frames());
  // The plane n = 0 (k_z = 0) of a 3D map; the whole map in 2D.
  const std::size_t plane = static_cast<std::size_t>(maps.modes.max_mode_z()) * maps.modes.plane_count();
  append_frame(file_, "frame_index", H5T_NATIVE_INT64, &index, k);
  append_frame(file_, "time", H5T_NATIVE_DOUBLE, &frame.clock.time, k);
  append_frame(file_, "collisions_per_particle", H5T_NATIVE_DOUBLE, &frame.collisions_per_particle, k);
  append_frame(file_, "shear_offset", H5T_NATIVE_DOUBLE, &frame.shear_offset, k);
  append_frame(file_, "tilt", H5T_NATIVE_DOUBLE, &maps.lattice.tilt, k);
  append_frame(file_, "kx", H5T_NATIVE_DOUBLE, maps.kx.data() + plane, k);
  append_frame(file_, "ky", H5T_NATIVE_DOUBLE, maps.ky.data() + plane, k);
  append_frame(file_, (rings_ + "modes").c_str(), H5T_NATIVE_INT64, annulus.modes.data(), k);
  append_frame(file_, (rings_ + "P_modes").c_str(), H5T_NATIVE_INT64, annulus.momentum_modes.data(), k);
  const ShellStructureFactor averages = shell_structure_factor(annulus, maps);
  for (const auto& [name, member] : kShellAverages) append_frame(file_, name, H5T_NATIVE_DOUBLE, (averages.*member).data(), k);
  const double ideal_momentum = maps.ideal_momentum();
  append_frame(file_, "ideal_R", H5T_NATIVE_DOUBLE, &maps.ideal_density, k);
  append_frame(file_, "ideal_P", H5T_NATIVE_DOUBLE, &ideal_momentum, k);
  const std::span<const FieldChoice> fields = fields_of(maps.lattice.dimension);
  for (std::size_t f = 0; f < fields.size(); ++f) {
    const FieldChoice& field = fields[f];
    append_frame(file_, field.name, H5T_NATIVE_DOUBLE, (maps.*field.map).data() + plane, k);
    append_frame(file_, (rings_ + field.name).c_str(), H5T_NATIVE_DOUBLE, (annulus.*field.annulus).data(), k);
    const std::string group = std::string("dominant/") + field.name + "/";
    const DominantMode& d = dominant[f];
    const double ratio = d.length / l0;
    const int significant = d.significant ? 1 : 0;
    append_frame(file_, (group + "l").c_str(), H5T_NATIVE_INT, &d.l, k);
    append_frame(file_, (group + "m").c_str(), H5T_NATIVE_INT, &d.m, k);
    if (depth_) append_frame(file_, (group + "n").c_str(), H5T_NATIVE_INT, &d.n, k);
    append_frame(file_, (group + "significant").c_str(), H5T_NATIVE_INT, &significant, k);
    for (const auto& [column, member] : kDominantColumns) {
      if (depth_ || std::string(column) != "kz") append_frame(file_, (group + column).c_str(), H5T_NATIVE_DOUBLE, &(d.*member), k);
    }
    append_frame(file_, (group + "length_over_L0").c_str(), H5T_NATIVE_DOUBLE, &ratio, k);
  }
  partial_.end_frame();
}

}  // namespace granule
