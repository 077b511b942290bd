// `granule analyze spectra SNAPSHOTS.h5`: Fourier spectra of the mass and momentum densities of
// each chosen frame (thesis §2.2, §3.2.1): the power maps R, P_x, P_y (, P_z), P, their annulus (2D) or
// shell (3D) integrals against |k| and averages S(k) with the statistical band of an ideal gas, and the
// dominant wavevector against L0 = l/√(1−ẽ²) (1.1) with its significance against uncorrelated positions
// (spectra/mode_significance.hpp).  3D maps are stored on the plane k_z = 0 only.  Schema: docs/spectra.md.
#include <fmt/format.h>
#include <hdf5.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <new>
#include <numbers>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/exit_codes.hpp"
#include "app/analyze_command.hpp"
#include "granule/version.hpp"
#include "io/atomic_file.hpp"
#include "io/io_error.hpp"
#include "io/hdf5_util.hpp"
#include "io/snapshot_file.hpp"
#include "app/spectra_console.hpp"
#include "spectra/dominant_mode.hpp"
#include "spectra/power_spectra.hpp"
#include "spectra/shell_structure_factor.hpp"

namespace granule::app {

namespace {

using namespace granule::spectra;

constexpr int kMaxModeLimit = 2048;
constexpr int kMaxModeLimit3d = 256;  // an n³ FFT grid of 16 n³ bytes per pair of fields: 20 GB at M = 256
constexpr int kDefaultMaxMode = 64, kDefaultMaxMode3d = 32;
constexpr const char* kFormat = "granule-spectra";
constexpr int kFormatVersion = 2;  // 2: every run has S(k), its band and the significance of dominant modes

struct SpectraOptions {
  std::string snapshots;
  std::string frames = "all";
  std::optional<int> max_mode;  // default kDefaultMaxMode (2D), kDefaultMaxMode3d (3D)
  std::optional<double> dk;
  std::string method = "fast";
  bool subtract_shear = false;
  bool exclude_ky_axis = false;
  std::string out = "spectra.h5";
  std::string csv;
  double false_alarm = kDefaultFalseAlarm;
};

// "all", or comma-separated items: an index (negative counts from the end) or a Python-style slice
// start:stop[:step] with optional parts.  Returns the frame indices, or an error message.
std::vector<std::int64_t> parse_frames(const std::string& spec, std::int64_t total, std::string& error) {
  std::vector<std::int64_t> frames;
  const auto resolve = [&](std::int64_t i) { return i < 0 ? total + i : i; };
  std::size_t start = 0;
  while (error.empty() && start <= spec.size()) {
    const std::size_t comma = std::min(spec.find(',', start), spec.size());
    const std::string item = spec.substr(start, comma - start);
    start = comma + 1;
    try {
      if (item == "all") {
        for (std::int64_t i = 0; i < total; ++i) frames.push_back(i);
      } else if (item.find(':') == std::string::npos) {
        std::size_t used = 0;
        const std::int64_t i = resolve(std::stoll(item, &used));
        if (used != item.size() || i < 0 || i >= total) throw std::out_of_range(item);
        frames.push_back(i);
      } else {
        std::vector<std::string> parts;
        for (std::size_t p = 0, colon = 0; colon != std::string::npos; p = colon + 1) {
          colon = item.find(':', p);
          parts.push_back(item.substr(p, colon == std::string::npos ? std::string::npos : colon - p));
        }
        if (parts.size() > 3) throw std::invalid_argument(item);
        const std::int64_t step = parts.size() == 3 && !parts[2].empty() ? std::stoll(parts[2]) : 1;
        if (step <= 0) throw std::invalid_argument(item);
        const std::int64_t first = parts[0].empty() ? 0 : std::clamp<std::int64_t>(resolve(std::stoll(parts[0])), 0, total);
        const std::int64_t last = parts[1].empty() ? total : std::clamp<std::int64_t>(resolve(std::stoll(parts[1])), 0, total);
        for (std::int64_t i = first; i < last; i += step) frames.push_back(i);
      }
    } catch (const std::exception&) {
      error = fmt::format("--frames: '{}' is not a frame index in [-{}, {}) or a slice start:stop[:step] (step > 0)",
                          item, total, total);
    }
  }
  if (error.empty() && frames.empty()) error = fmt::format("--frames '{}' selects no frame (the file has {})", spec, total);
  return frames;
}

// The spectra, in output order: name in the file, the map of PowerMaps and the sum of AnnulusSpectrum
// it comes from, and its power for uncorrelated positions.
struct FieldChoice {
  const char* name;
  const std::vector<double> PowerMaps::*map;
  const std::vector<double> AnnulusSpectrum::*annulus;
  ModeNoise (*noise)(const PowerMaps&);
};
constexpr FieldChoice kFields[] = {
    {"R", &PowerMaps::density, &AnnulusSpectrum::density, [](const PowerMaps& p) { return p.density_noise(); }},
    {"Px", &PowerMaps::momentum_x, &AnnulusSpectrum::momentum_x, [](const PowerMaps& p) { return p.momentum_component_noise(0); }},
    {"Py", &PowerMaps::momentum_y, &AnnulusSpectrum::momentum_y, [](const PowerMaps& p) { return p.momentum_component_noise(1); }},
    {"P", &PowerMaps::momentum, &AnnulusSpectrum::momentum, [](const PowerMaps& p) { return p.momentum_noise(); }}};
constexpr FieldChoice kFields3d[] = {
    kFields[0], kFields[1], kFields[2],
    {"Pz", &PowerMaps::momentum_z, &AnnulusSpectrum::momentum_z, [](const PowerMaps& p) { return p.momentum_component_noise(2); }},
    kFields[3]};

// The columns of a dominant mode after its indices, in the file (dominant/<field>/<column>) and the CSV.
constexpr std::pair<const char*, double DominantMode::*> kDominantColumns[] = {
    {"kx", &DominantMode::kx}, {"ky", &DominantMode::ky}, {"kz", &DominantMode::kz}, {"k", &DominantMode::k},
    {"angle_deg", &DominantMode::angle_deg}, {"length", &DominantMode::length}, {"power", &DominantMode::power},
    {"power_over_ideal_gas", &DominantMode::power_over_ideal_gas}, {"independent_modes", &DominantMode::independent_modes},
    {"noise_p_value", &DominantMode::noise_p_value}, {"noise_threshold", &DominantMode::noise_threshold}};

std::span<const FieldChoice> fields_of(int dimension) {
  return dimension == 3 ? std::span<const FieldChoice>(kFields3d) : std::span<const FieldChoice>(kFields);
}

// The shell-averaged spectra: name, and the member of ShellStructureFactor.
constexpr std::pair<const char*, const std::vector<double> ShellStructureFactor::*> kShellAverages[] = {
    {"S_R", &ShellStructureFactor::density}, {"S_R_sd", &ShellStructureFactor::density_sd},
    {"S_P", &ShellStructureFactor::momentum}, {"S_P_sd", &ShellStructureFactor::momentum_sd}};

// The spectra file as it grows: `<out>.partial`, flushed after its layout and after every frame,
// given its final name only once its close succeeded (h5::PartialFile); a failure leaves the
// `.partial` with the frames done so far.  Every HDF5 call is checked and throws IoError.
class SpectraFile {
 public:
  SpectraFile(const std::string& path, const SpectraOptions& options, const SnapshotMetadata& metadata,
              const TransformOptions& transform, double dk, const AnnulusSpectrum& bins)
      : partial_(path, kFormat, kFormatVersion, kVersion),
        file_(partial_.get()),
        depth_(metadata.system.dimension == 3),
        rings_(depth_ ? "shell_" : "annulus_") {
    write_layout(options, metadata, transform, dk, bins);
    partial_.flush();
  }

  // Root attributes (parameters of the analysis and of the run) and the empty per-frame datasets.
  void write_layout(const SpectraOptions& options, const SnapshotMetadata& metadata, const TransformOptions& transform,
                    double dk, const AnnulusSpectrum& bins) {
    using namespace h5;
    const SystemParams& s = metadata.system;
    write_string_attribute(file_, "source", std::filesystem::absolute(options.snapshots).string());
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

  void append(std::int64_t index, const SnapshotFrame& frame, const PowerMaps& maps, const AnnulusSpectrum& annulus,
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
  void publish() { partial_.publish(); }

 private:
  h5::PartialFile partial_;
  hid_t file_;  // partial_'s identifier, owned by it
  bool depth_;         // a 3D run
  std::string rings_;  // "annulus_" (2D) or "shell_" (3D)
};

int bad_input(const std::string& message) {
  fmt::print(stderr, "granule analyze spectra: error: {}\n", message);
  return kExitBadInput;
}

int analyze_spectra(const SpectraOptions& options) {
  // 1. Everything that can be wrong with the input is found before anything is written.
  if (options.dk && !(std::isfinite(*options.dk) && *options.dk > 0.0)) {
    return bad_input(fmt::format("--dk must be a positive finite wavenumber (got {})", *options.dk));
  }
  if (!(options.false_alarm > 0.0 && options.false_alarm < 1.0)) {
    return bad_input(fmt::format("--false-alarm must lie in (0, 1) (got {})", options.false_alarm));
  }
  if (options.method != "fast" && options.method != "exact") {
    return bad_input(fmt::format("--method must be 'fast' or 'exact' (got '{}')", options.method));
  }
  SnapshotRead first;
  try {
    first = read_snapshot(options.snapshots, 0);
  } catch (const std::exception& error) {
    return bad_input(fmt::format("cannot read snapshots '{}': {}", options.snapshots, error.what()));
  }
  std::string error;
  const std::vector<std::int64_t> frames = parse_frames(options.frames, first.frames, error);
  if (!error.empty()) return bad_input(error);
  const SnapshotMetadata& metadata = first.metadata;
  const int dimension = metadata.system.dimension;
  const double length_z = metadata.system.length_z;
  const int max_mode = options.max_mode.value_or(dimension == 3 ? kDefaultMaxMode3d : kDefaultMaxMode);
  const int max_mode_limit = dimension == 3 ? kMaxModeLimit3d : kMaxModeLimit;
  if (max_mode < 1 || max_mode > max_mode_limit) {
    return bad_input(fmt::format("--max-mode must be in [1, {}] for a {}D run (got {})", max_mode_limit, dimension, max_mode));
  }
  const ShearFrame box{metadata.system.length_x, metadata.system.length_y, metadata.system.shear_velocity};
  if (options.subtract_shear && !box.sheared()) {
    return bad_input("--subtract-shear needs a Lees–Edwards run (this one is periodic, U = 0)");
  }
  TransformOptions transform;
  transform.max_mode = max_mode;
  transform.method = options.method == "exact" ? SpectralMethod::exact : SpectralMethod::fast;
  transform.subtract_shear_profile = options.subtract_shear;
  const double dk = options.dk.value_or(default_annulus_width(lattice_for_frame(box, 0.0, dimension, length_z)));
  const double radius = complete_radius_at_any_strain(box, max_mode, dimension, length_z);
  const std::string csv_path = !options.csv.empty() ? options.csv
                               : std::filesystem::path(options.out).replace_extension("").string() + "_dominant.csv";
  const double l0 = cluster_length(metadata.system);

  // 2. Frame by frame into <out>.partial; the CSV and the final name only when all frames are done.
  try {
    std::unique_ptr<SpectraFile> file;
    std::string csv = "frame,t,c,shear_offset,field,l,m,n";
    for (const auto& [column, member] : kDominantColumns) csv += fmt::format(",{}", column);
    csv += ",length_over_L0,significant\n";
    std::vector<SignificanceTally> tallies(fields_of(dimension).size());
    fmt::print("{}\n", describe_comparison(metadata.system, l0, options.false_alarm));
    for (const std::int64_t index : frames) {
      const SnapshotRead snapshot = index == 0 ? first : read_snapshot(options.snapshots, index);
      const SnapshotFrame& frame = snapshot.frame;
      const ReciprocalLattice lattice = lattice_for_frame(box, frame.shear_offset, dimension, length_z);
      const PowerMaps maps = power_maps(transform_fields(frame.particles, box, lattice, transform), options.exclude_ky_axis);
      const AnnulusSpectrum annulus = annulus_sums(maps, dk, radius);
      if (!file) file = std::make_unique<SpectraFile>(options.out, options, metadata, transform, dk, annulus);
      std::vector<DominantMode> dominant;
      for (const FieldChoice& field : fields_of(dimension)) {
        const DominantMode& d =
            dominant.emplace_back(dominant_mode(maps, maps.*field.map, field.noise(maps), options.false_alarm));
        csv += fmt::format("{},{:.17g},{:.17g},{:.17g},{},{},{},{}", index, frame.clock.time, frame.collisions_per_particle,
                           frame.shear_offset, field.name, d.l, d.m, d.n);
        for (const auto& [column, member] : kDominantColumns) csv += fmt::format(",{:.17g}", d.*member);
        csv += fmt::format(",{:.17g},{}\n", d.length / l0, d.significant ? 1 : 0);
      }
      file->append(index, frame, maps, annulus, dominant, l0);
      fmt::print("frame {} (t = {:.6g}, c = {:.6g}):\n", index, frame.clock.time, frame.collisions_per_particle);
      for (std::size_t f = 0; f < dominant.size(); ++f) {
        const char* name = fields_of(dimension)[f].name;
        if (name == std::string("R") || name == std::string("P")) {
          fmt::print("  {}\n", describe_dominant(name, dominant[f], l0, options.false_alarm));
        }
        tallies[f].add(dominant[f], l0);
      }
    }
    for (std::size_t f = 0; f < tallies.size(); ++f) {
      fmt::print("{}\n", tallies[f].summary(fields_of(dimension)[f].name, options.false_alarm));
    }
    write_file_atomically(csv_path, csv);
    file->publish();
  } catch (const IoError&) {  // a file that cannot be written: main reports it, exit 4
    throw;
  } catch (const std::bad_alloc&) {  // exit 5, by main
    throw;
  } catch (const std::exception& failure) {
    fmt::print(stderr, "granule analyze spectra: error: {}\n", failure.what());
    return 1;
  }
  fmt::print("wrote {} and {}\n", options.out, csv_path);
  return 0;
}

}  // namespace

void add_analyze_spectra(CLI::App& analyze) {
  auto options = std::make_shared<SpectraOptions>();
  CLI::App* command = analyze.add_subcommand(
      "spectra", "Fourier spectra of the mass and momentum densities (thesis §2.2, §3.2.1), 2D or 3D runs: power maps, "
                 "annulus (shell) sums against |k| and the dominant wavevector against L0 = l/sqrt(1-e^2). Schema: "
                 "docs/spectra.md");
  command->add_option("snapshots", options->snapshots, "snapshots.h5 of a run")->required();
  command->add_option("--frames", options->frames,
                      "Frames: 'all', indices (negative from the end) and slices start:stop[:step], comma-separated")
      ->default_val("all");
  command->add_option("--max-mode", options->max_mode,
                      "Modes |l|, |m| (, |n|) <= M of the allowed lattice k = l k1 + m k2 (+ n k3); default 64 in 2D "
                      "(at most 2048), 32 in 3D (at most 256)");
  command->add_option("--dk", options->dk, "Annulus (shell) width (default 2*pi/max(Lx, Ly (, Lz)))");
  command->add_option("--method", options->method, "fast (gridded FFT, ~1e-6 relative) or exact (direct sums)")
      ->default_val("fast");
  command->add_flag("--subtract-shear", options->subtract_shear,
                    "Momentum relative to the linear shear profile, p'(k) of (3.17) (Lees-Edwards runs)");
  command->add_flag("--exclude-ky-axis", options->exclude_ky_axis,
                    "Leave the k_y axis (l = 0, and n = 0 in 3D) out of P_x and P, as the thesis does for p'_x (§3.2.1)");
  command->add_option("--out", options->out, "Output HDF5 file")->default_val("spectra.h5");
  command->add_option("--csv", options->csv, "Dominant-mode CSV (default: <out stem>_dominant.csv)");
  command->add_option("--false-alarm", options->false_alarm,
                      "False-alarm probability below which a dominant mode is significant against uncorrelated "
                      "positions, over all modes compared (0 < level < 1)")
      ->default_val(kDefaultFalseAlarm);
  command->callback([options] { throw CLI::RuntimeError(analyze_spectra(*options)); });
}

}  // namespace granule::app
