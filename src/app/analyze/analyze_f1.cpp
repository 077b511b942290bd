// `granule analyze f1 SNAPSHOTS.h5 --density-window C±W --temperature-window C±W`: the
// single-particle velocity distribution of thesis Chapter 5 in each (ρ, T) window, by the
// cumulative sampling algorithm of §5.2, as the Appendix B table.  Docs: docs/f1.md.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <memory>
#include <new>
#include <optional>

#include "app/analyze/analysis_exit.hpp"
#include "app/analyze/analysis_memory.hpp"
#include "app/analyze/analyze_command.hpp"
#include "app/exit_codes.hpp"
#include "distribution/f1_report.hpp"
#include "io/f1_file.hpp"
#include "io/f1_from_snapshots.hpp"
#include "io/f1_thesis_csv.hpp"
#include "io/io_error.hpp"
#include "io/snapshot_file.hpp"

namespace granule::app {

namespace {

using namespace granule::distribution;

constexpr int kExitNoWindow = 1;

struct F1CommandOptions {
  std::string snapshots;
  std::vector<std::string> density_windows, temperature_windows;
  std::string cells;
  std::int64_t from_frame = 0;
  bool subtract_shear_profile = false;
  bool thesis_windows = false;
  std::optional<double> profile_speed;
  double profile_angle = M_PI;
  std::string out = "f1.h5";
  F1Options f1;
};

int bad_input(const std::string& message) { return refuse_analysis_input("f1", message); }

int analyze_f1(const F1CommandOptions& o) {
  // 1. Every input error is found before anything is read at length or written.
  std::vector<ValueWindow> densities, temperatures;
  for (const auto& [texts, parsed, name] : {std::tuple{&o.density_windows, &densities, "--density-window"},
                                            std::tuple{&o.temperature_windows, &temperatures, "--temperature-window"}}) {
    for (const std::string& text : *texts) {
      const auto w = parse_value_window(text);
      if (!w) return bad_input(fmt::format("{} '{}' must be CENTER±HALFWIDTH (or CENTER+-HALFWIDTH) with HALFWIDTH > 0", name, text));
      parsed->push_back(*w);
    }
  }
  const F1Options& f = o.f1;
  if (f.speed_bins < 8 || f.speed_bins > 4096) return bad_input(fmt::format("--speed-bins must be in [8, 4096] (got {})", f.speed_bins));
  if (f.angle_bins < 16 || f.angle_bins > 4096 || f.angle_bins % 8 != 0)
    return bad_input(fmt::format("--angle-bins must be a multiple of 8 in [16, 4096] (got {})", f.angle_bins));
  if (!(f.fit_quantile >= 0.5 && f.fit_quantile <= 1.0)) return bad_input(fmt::format("--fit-quantile must be in [0.5, 1] (got {})", f.fit_quantile));
  if (f.bootstrap < 0 || f.bootstrap == 1 || f.bootstrap > 10000)
    return bad_input(fmt::format("--bootstrap must be 0 or in [2, 10000] (got {})", f.bootstrap));
  if (!(f.speed_max >= 0.0) || !std::isfinite(f.speed_max)) return bad_input(fmt::format("--speed-max must be ≥ 0 (got {})", f.speed_max));
  if (o.profile_speed && !(*o.profile_speed > 0.0)) return bad_input(fmt::format("--profile-speed must be > 0 (got {})", *o.profile_speed));
  SnapshotRead first;
  try {
    first = read_snapshot(o.snapshots, 0);
  } catch (const std::exception& error) {
    return bad_input(fmt::format("cannot read snapshots '{}': {}", o.snapshots, error.what()));
  }
  const SystemParams& system = first.metadata.system;
  if (o.thesis_windows) {
    if (!add_thesis_windows(system, densities, temperatures)) {
      return bad_input(fmt::format("--thesis-windows needs a Lees–Edwards run with restitution 0.6, 0.7, 0.8 or 0.9 "
                                   "(Appendix B's); this one has ẽ = {:g}, U = {:g}", system.restitution,
                                   system.shear_velocity));
    }
    fmt::print("{}\n", describe_thesis_units(system));
  }
  if (densities.empty() || temperatures.empty()) {
    return bad_input("give --density-window and --temperature-window (each at least once), or --thesis-windows");
  }
  // Cumulative sampling of Chapter 5 is written for the velocity plane of disks.
  if (system.dimension != 2) {
    return bad_input(fmt::format("'{}' is a {}D run: the velocity distribution f1 is measured in 2D runs only", o.snapshots,
                                 system.dimension));
  }
  if (o.from_frame < 0 || o.from_frame >= first.frames)
    return bad_input(fmt::format("--from-frame must be in [0, {}) for this file (got {})", first.frames, o.from_frame));
  SamplingOptions sampling;
  sampling.grid = default_field_grid(system.length_x, system.length_y, system.particles);
  if (!o.cells.empty()) {
    int nx = 0, ny = 0;
    char comma = 0, extra = 0;
    if (std::sscanf(o.cells.c_str(), "%d %c %d %c", &nx, &comma, &ny, &extra) != 3 || comma != ',' || nx < 1 || ny < 1 ||
        nx > 4096 || ny > 4096)
      return bad_input(fmt::format("--cells must be NX,NY with each in [1, 4096] (got '{}')", o.cells));
    sampling.grid.nx = nx;
    sampling.grid.ny = ny;
  }
  if (o.subtract_shear_profile && !ShearFrame{system.length_x, system.length_y, system.shear_velocity}.sheared())
    return bad_input("--subtract-shear-profile needs a Lees–Edwards run (this one has U = 0)");
  sampling.subtract_shear_profile = o.subtract_shear_profile;

  // 2. Sample every window in every frame from --from-frame on, then analyse each window.
  F1RunDescription run{o.snapshots, first.metadata, sampling.grid.nx, sampling.grid.ny, o.from_frame,
                       first.frames - o.from_frame, o.subtract_shear_profile, o.profile_angle,
                       o.profile_speed.value_or(0.0), f};
  const std::size_t window_count = densities.size() * temperatures.size();
  const double needed = frame_copy_bytes(first.frame) +
                        f1_analysis_bytes(static_cast<std::size_t>(system.particles), static_cast<std::size_t>(run.frames_used),
                                          window_count, f);
  if (const std::optional<int> refused = refused_for_memory(
          "f1", needed, fmt::format("{} windows over {} frames of N = {} with --speed-bins {} --angle-bins {}", window_count,
                                    run.frames_used, system.particles, f.speed_bins, f.angle_bins))) {
    return *refused;
  }
  return run_analysis("f1", [&] {
    const std::vector<WindowSamples> windows =
        sample_snapshot_windows(o.snapshots, first, o.from_frame, sampling, densities, temperatures);
    fmt::print("sampled {} frames ({} to {}) on {} x {} cells\n", run.frames_used, o.from_frame, first.frames - 1,
               sampling.grid.nx, sampling.grid.ny);
    std::vector<WindowResult> results;
    for (const WindowSamples& w : windows) {
      WindowResult r = analyse_window(w, f);
      if (!r.analysed) {
        fmt::print(stderr, "granule analyze f1: warning: {}\n", r.warning);
        continue;
      }
      fmt::print("{}\n", describe_window(r));
      if (const auto match = nearest_thesis_window(system, r)) fmt::print("{}\n", describe_thesis_comparison(*match, r));
      results.push_back(std::move(r));
    }
    if (results.empty()) {
      fmt::print(stderr, "granule analyze f1: error: no window had enough samples; nothing written\n");
      return kExitNoWindow;
    }
    for (const std::string& path : write_f1_outputs(o.out, run, results, thesis_comparison_csv(system, results))) fmt::print("wrote {}\n", path);
    return 0;
  });
}

}  // namespace

void add_analyze_f1(CLI::App& analyze) {
  auto o = std::make_shared<F1CommandOptions>();
  CLI::App* command = analyze.add_subcommand(
      "f1", "Single-particle velocity distribution by cumulative sampling (thesis §5.2): the Appendix B table of "
            "b^(i)(theta) in each density x temperature window. Docs: docs/f1.md");
  command->add_option("snapshots", o->snapshots, "snapshots.h5 of a (steady) run")->required();
  command->add_option("--density-window", o->density_windows,
                      "rho window C±W in particles per unit area (repeatable; every rho x T pair is analysed)");
  command->add_option("--temperature-window", o->temperature_windows, "T window C±W, T = ½<v'²> (repeatable)");
  command->add_flag("--thesis-windows", o->thesis_windows,
                    "Add Appendix B's 4 x 4 windows of the run's restitution, mapped to the run's units (docs/f1.md)");
  command->add_option("--cells", o->cells, "Coarse-graining cells NX,NY (default: ~20 particles per cell)");
  command->add_option("--from-frame", o->from_frame, "First frame used (the steady state)")->default_val(0);
  command->add_flag("--subtract-shear-profile", o->subtract_shear_profile,
                    "Lees-Edwards: velocities relative to the linear profile u(y) before the cell mean (docs/f1.md)");
  command->add_option("--speed-bins", o->f1.speed_bins, "Polar bins in the speed")->default_val(64);
  command->add_option("--angle-bins", o->f1.angle_bins, "Polar bins in the angle (multiple of 8)")->default_val(64);
  command->add_option("--speed-max", o->f1.speed_max, "Last speed edge (0: the largest sampled speed)")->default_val(0.0);
  command->add_option("--fit-quantile", o->f1.fit_quantile, "Twice fit (5.27) up to this quantile of the speed")
      ->default_val(0.999);
  command->add_option("--bootstrap", o->f1.bootstrap, "Bootstrap replicates over snapshots (0: none)")->default_val(20);
  command->add_option("--seed", o->f1.seed, "Seed of the bootstrap")->default_val(1);
  command->add_option("--min-samples", o->f1.min_samples, "Skip (with a warning) windows with fewer samples")
      ->default_val(10000);
  command->add_option("--profile-angle", o->profile_angle, "Angle of the f(v) profiles (Fig 5.10)")->default_val(M_PI);
  command->add_option("--profile-speed", o->profile_speed, "Speed of the f(theta) profiles (Fig 5.11; default sqrt(2T))");
  command->add_option("--out", o->out, "Output HDF5 file; CSV tables are written beside it")->default_val("f1.h5");
  command->callback([o] { throw CLI::RuntimeError(analyze_f1(*o)); });
}

}  // namespace granule::app
