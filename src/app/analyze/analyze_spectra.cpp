// `granule analyze spectra SNAPSHOTS.h5`: Fourier spectra of the mass and momentum densities of
// each chosen frame (thesis §2.2, §3.2.1): the power maps R, P_x, P_y (, P_z), P, their annulus (2D) or
// shell (3D) integrals against |k| and averages S(k) with the statistical band of an ideal gas, and the
// dominant wavevector against L0 = l/√(1−ẽ²) (1.1) with its significance against uncorrelated positions
// (spectra/mode_significance.hpp), computed by io/spectra_from_snapshots.hpp.  3D maps are stored on the
// plane k_z = 0 only.  Schema: docs/spectra.md.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <memory>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/analyze/analysis_exit.hpp"
#include "app/analyze/analysis_memory.hpp"
#include "app/analyze/analyze_command.hpp"
#include "app/exit_codes.hpp"
#include "io/frame_selection.hpp"
#include "io/io_error.hpp"
#include "io/spectra_from_snapshots.hpp"
#include "spectra/power_spectra.hpp"
#include "spectra/reciprocal_lattice.hpp"
#include "spectra/spectra_memory.hpp"

namespace granule::app {

namespace {

// The analysis asked (its max_mode below), the frames and the modes as given.
struct SpectraOptions {
  SpectraRequest request;
  std::string frames = "all";
  std::optional<int> max_mode;  // default: default_max_mode of the run's dimension
};

int bad_spectra_input(const std::string& message) { return refuse_analysis_input("spectra", message); }

// The memory of a frame's spectra (its FFT grids, mode maps and rings) and of the frame read beside
// frame 0, against what the machine has: exit 5, its message naming --max-mode (and --dk).
std::optional<int> refuse_beyond_memory(const SpectraRequest& request, const SnapshotRead& first) {
  const SystemParams& system = first.metadata.system;
  const int dimension = system.dimension;
  spectra::TransformOptions transform;
  transform.max_mode = request.max_mode;
  transform.method = request.method == "exact" ? spectra::SpectralMethod::exact : spectra::SpectralMethod::fast;
  // The rings of the width asked, or of the default (io/spectra_from_snapshots.cpp); more than
  // kMaxAnnuli are refused as input by annulus_sums before it allocates them.
  const ShearFrame box{system.length_x, system.length_y, system.shear_velocity};
  const double dk = request.dk.value_or(
      spectra::default_annulus_width(spectra::lattice_for_frame(box, 0.0, dimension, system.length_z)));
  const double annuli =
      spectra::annulus_count(dk, spectra::complete_radius_at_any_strain(box, request.max_mode, dimension, system.length_z));
  const std::size_t particles = first.frame.particles.size();
  const double needed = frame_copy_bytes(first.frame) +
                        spectra::spectra_bytes(particles, dimension, transform, annuli <= spectra::kMaxAnnuli ? annuli : 0.0);
  return refused_for_memory("spectra", needed,
                            fmt::format("--max-mode {}{} (the {} spectra of N = {} in {}D)", request.max_mode,
                                        request.dk ? fmt::format(" with --dk {}", *request.dk) : "", request.method,
                                        particles, dimension));
}

int analyze_spectra(const SpectraOptions& options) {
  SpectraRequest request = options.request;
  // 1. Everything that can be wrong with the input is found before anything is written.
  if (request.dk && !(std::isfinite(*request.dk) && *request.dk > 0.0)) {
    return bad_spectra_input(fmt::format("--dk must be a positive finite wavenumber (got {})", *request.dk));
  }
  if (!(request.false_alarm > 0.0 && request.false_alarm < 1.0)) {
    return bad_spectra_input(fmt::format("--false-alarm must lie in (0, 1) (got {})", request.false_alarm));
  }
  if (request.method != "fast" && request.method != "exact") {
    return bad_spectra_input(fmt::format("--method must be 'fast' or 'exact' (got '{}')", request.method));
  }
  SnapshotRead first;
  try {
    first = read_snapshot(request.snapshots, 0);
  } catch (const std::exception& error) {
    return bad_spectra_input(fmt::format("cannot read snapshots '{}': {}", request.snapshots, error.what()));
  }
  std::vector<std::int64_t> frames;
  try {
    frames = parse_frame_selection(options.frames, first.frames);
  } catch (const InputError& error) {
    return bad_spectra_input(error.what());
  }
  const SystemParams& system = first.metadata.system;
  const int dimension = system.dimension;
  const int max_mode = options.max_mode.value_or(default_max_mode(dimension));
  if (max_mode < 1 || max_mode > max_mode_limit(dimension)) {
    return bad_spectra_input(
        fmt::format("--max-mode must be in [1, {}] for a {}D run (got {})", max_mode_limit(dimension), dimension, max_mode));
  }
  if (request.subtract_shear && !ShearFrame{system.length_x, system.length_y, system.shear_velocity}.sheared()) {
    return bad_spectra_input("--subtract-shear needs a Lees–Edwards run (this one is periodic, U = 0)");
  }
  request.max_mode = max_mode;
  // 2. What the machine cannot hold is refused before anything is allocated.
  if (const auto refused = refuse_beyond_memory(request, first)) return *refused;
  SpectraFromSnapshots analysis(request, first);

  // 3. Frame by frame, saying what each dominant mode is worth.
  return run_analysis("spectra", [&] {
    try {
      const double l0 = analysis.cluster_length();
      fmt::print("{}\n", spectra::describe_comparison(system, l0, request.false_alarm));
      const auto fields = spectra_file::fields_of(dimension);
      for (const std::int64_t index : frames) {
        const FrameSpectra frame = analysis.add_frame(index);
        fmt::print("frame {} (t = {:.6g}, c = {:.6g}):\n", index, frame.time, frame.collisions_per_particle);
        for (std::size_t f = 0; f < fields.size(); ++f) {
          if (fields[f].name == std::string("R") || fields[f].name == std::string("P")) {
            fmt::print("  {}\n", spectra::describe_dominant(fields[f].name, frame.dominant[f], l0, request.false_alarm));
          }
        }
      }
      for (std::size_t f = 0; f < fields.size(); ++f) {
        fmt::print("{}\n", analysis.tallies()[f].summary(fields[f].name, request.false_alarm));
      }
      analysis.publish();
    } catch (const std::length_error& refused) {  // an annulus width too small for the lattice
      return bad_spectra_input(fmt::format("--dk: {}", refused.what()));
    }
    fmt::print("wrote {} and {}\n", request.out, analysis.csv_path());
    return 0;
  });
}

}  // namespace

void add_analyze_spectra(CLI::App& analyze) {
  auto options = std::make_shared<SpectraOptions>();
  CLI::App* command = analyze.add_subcommand(
      "spectra", "Fourier spectra of the mass and momentum densities (thesis §2.2, §3.2.1), 2D or 3D runs: power maps, "
                 "annulus (shell) sums against |k| and the dominant wavevector against L0 = l/sqrt(1-e^2). Schema: "
                 "docs/spectra.md");
  command->add_option("snapshots", options->request.snapshots, "snapshots.h5 of a run")->required();
  command->add_option("--frames", options->frames,
                      "Frames: 'all', indices (negative from the end) and slices start:stop[:step], comma-separated")
      ->default_val("all");
  command->add_option("--max-mode", options->max_mode,
                      "Modes |l|, |m| (, |n|) <= M of the allowed lattice k = l k1 + m k2 (+ n k3); default 64 in 2D "
                      "(at most 2048), 32 in 3D (at most 256)");
  command->add_option("--dk", options->request.dk, "Annulus (shell) width (default 2*pi/max(Lx, Ly (, Lz)))");
  command->add_option("--method", options->request.method, "fast (gridded FFT, ~1e-6 relative) or exact (direct sums)")
      ->default_val("fast");
  command->add_flag("--subtract-shear", options->request.subtract_shear,
                    "Momentum relative to the linear shear profile, p'(k) of (3.17) (Lees-Edwards runs)");
  command->add_flag("--exclude-ky-axis", options->request.exclude_ky_axis,
                    "Leave the k_y axis (l = 0, and n = 0 in 3D) out of P_x and P, as the thesis does for p'_x (§3.2.1)");
  command->add_option("--out", options->request.out, "Output HDF5 file")->default_val("spectra.h5");
  command->add_option("--csv", options->request.csv, "Dominant-mode CSV (default: <out stem>_dominant.csv)");
  command->add_option("--false-alarm", options->request.false_alarm,
                      "False-alarm probability below which a dominant mode is significant against uncorrelated "
                      "positions, over all modes compared (0 < level < 1)")
      ->default_val(spectra::kDefaultFalseAlarm);
  command->callback([options] { throw CLI::RuntimeError(analyze_spectra(*options)); });
}

}  // namespace granule::app
