// `granule analyze spins RUN_DIR`: the spin correlation C(r) of neighbouring rough grains (thesis
// Fig C.4: under shear, grains close together spin in opposite senses) over the chosen frames of a
// run's snapshots, computed by io/spins_from_snapshots.hpp into spins.h5 (schema: README).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/analyze/analysis_exit.hpp"
#include "app/analyze/analysis_memory.hpp"
#include "app/analyze/analyze_command.hpp"
#include "app/exit_codes.hpp"
#include "io/frame_selection.hpp"
#include "io/io_error.hpp"
#include "io/run_files.hpp"
#include "io/spins_from_snapshots.hpp"

namespace granule::app {

namespace {

struct SpinsOptions {
  std::string run;
  std::string frames = "all";
  std::string out;  // default: spins.h5 beside the snapshots
  SpinCorrelationSettings settings;
};

int bad_spins_input(const std::string& message) { return refuse_analysis_input("spins", message); }

// A frame read beside frame 0, its cell list (a cell and a link per grain, the cells no more than
// the grains) and the bins, against what the machine has.
std::optional<int> refuse_beyond_memory(const SnapshotRead& first, const SpinCorrelationSettings& settings) {
  const double grains = static_cast<double>(first.frame.particles.size());
  const double needed = frame_copy_bytes(first.frame) + grains * 3.0 * sizeof(std::uint32_t) +
                        static_cast<double>(settings.bins) * 2.0 * kPairDirections * 2.0 * sizeof(double);
  return refused_for_memory("spins", needed, fmt::format("the spin correlation of N = {}", first.frame.particles.size()));
}

int analyze_spins(const SpinsOptions& o) {
  SpinsRequest request{"", o.out, o.settings};
  SnapshotRead first;
  try {
    request.snapshots = locate_run_file(o.run, "snapshots.h5");
    first = read_snapshot(request.snapshots, 0);
  } catch (const std::exception& error) {
    return bad_spins_input(fmt::format("cannot read the snapshots of '{}': {}", o.run, error.what()));
  }
  if (!first.frame.particles.rough()) {
    return bad_spins_input(fmt::format(
        "{} holds smooth grains: its frames carry no spins (angular velocities), so there is nothing to correlate.  Spin "
        "correlations need a run of rough grains: system.tangential_restitution = β in [-1, 1] in its configuration "
        "(examples/walls_spin_gravity/rough_shear_fig_c4.toml)",
        request.snapshots));
  }
  std::vector<std::int64_t> frames;
  try {
    frames = parse_frame_selection(o.frames, first.frames);
  } catch (const InputError& error) {
    return bad_spins_input(error.what());
  }
  if (!(std::isfinite(o.settings.contact_shell) && o.settings.contact_shell > 0.0 && o.settings.contact_shell < 1.0)) {
    return bad_spins_input(fmt::format("--contact-shell must lie in (0, 1) (got {})", o.settings.contact_shell));
  }
  if (!(std::isfinite(o.settings.max_distance) && o.settings.max_distance > 1.0 + o.settings.contact_shell &&
        o.settings.max_distance <= 100.0)) {
    return bad_spins_input(fmt::format("--max-distance must lie in (1 + --contact-shell, 100] contact distances (got {})",
                                       o.settings.max_distance));
  }
  if (o.settings.bins < 1 || o.settings.bins > 10000) return bad_spins_input(fmt::format("--bins must lie in [1, 10000] (got {})", o.settings.bins));
  if (request.out.empty()) request.out = output_beside(o.run, "spins.h5");
  if (const auto refused = refuse_beyond_memory(first, o.settings)) return *refused;

  SpinCorrelationAverage average;
  try {
    average = spins_from_snapshots(request, first, frames);
  } catch (const InputError& refused) {  // a smooth frame, a box too small, a damaged input: nothing written
    return bad_spins_input(refused.what());
  }
  const double contact = average.contact_mean(), error = average.contact_error();
  fmt::print("spin correlation of {} frame(s) of {} (spins relative to each frame's mean spin):\n", frames.size(), request.snapshots);
  fmt::print("  C_contact = {:.4g} ± {:.2g} (r < {:g} σ; the error is the standard error of the frames' values, frames taken as "
             "independent), {:.0f} pairs in contact\n",
             contact, error, 1.0 + o.settings.contact_shell, average.total.contact_pairs);
  double pairs = 0.0;
  for (const double p : average.total.pairs[0]) pairs += p;
  fmt::print("  {:.0f} pairs within {:g} contact distances; C(r) in {} bins\n", pairs, o.settings.max_distance, o.settings.bins);
  fmt::print("wrote {}\n", request.out);
  return 0;
}

}  // namespace

void add_analyze_spins(CLI::App& analyze) {
  auto o = std::make_shared<SpinsOptions>();
  CLI::App* command = analyze.add_subcommand(
      "spins", "Spin correlation C(r) = <dw_i.dw_j>/<dw^2> of neighbouring rough grains against their distance, overall and "
               "along the flow and the gradient, and C_contact (thesis Fig C.4). Schema: README, spins.h5");
  command->add_option("run", o->run, "Run directory or its snapshots.h5")->required();
  command->add_option("--frames", o->frames,
                      "Frames: 'all', indices (negative from the end) and slices start:stop[:step], comma-separated")
      ->default_val("all");
  command->add_option("--max-distance", o->settings.max_distance, "Largest centre distance binned, in contact distances σ_ij")
      ->default_val(3.0);
  command->add_option("--bins", o->settings.bins, "Bins of the distance over [1, --max-distance]")->default_val(20);
  command->add_option("--contact-shell", o->settings.contact_shell,
                      "Pairs closer than (1 + shell) σ_ij are in contact (C_contact)")
      ->default_val(0.1);
  command->add_option("--out", o->out, "Output HDF5 file (default: spins.h5 beside the snapshots)");
  command->callback([o] { throw CLI::RuntimeError(analyze_spins(*o)); });
}

}  // namespace granule::app
