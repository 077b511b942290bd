// `granule analyze fields SNAPSHOTS.h5`: the coarse-grained fields of §1.4.3 from saved
// configurations (io/fields_from_snapshots.hpp), per frame and averaged over the chosen frames.
// The collisional stress is measured only during a run ([fields] in the config, fields.h5).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <memory>
#include <optional>

#include "analysis/cell_fields.hpp"
#include "app/analyze/analysis_memory.hpp"
#include "app/analyze/analysis_exit.hpp"
#include "app/analyze/analyze_command.hpp"
#include "app/exit_codes.hpp"
#include "granule/version.hpp"
#include "io/fields_from_snapshots.hpp"
#include "io/frame_selection.hpp"
#include "io/snapshot_file.hpp"

namespace granule::app {

namespace {

struct FieldsOptions {
  std::string snapshots;
  std::vector<int> cells;
  std::int64_t first = 0;
  std::int64_t last = -1;
  bool subtract_shear = false;
  std::string out = "fields_from_snapshots.h5";
};

int analyze_fields(const FieldsOptions& o) {
  SnapshotRead head;
  try {
    head = read_snapshot(o.snapshots, 0);
  } catch (const std::exception& error) {
    return refuse_analysis_input("fields", fmt::format("cannot read {}: {}", o.snapshots, error.what()));
  }
  const std::optional<FrameRange> frames = resolve_frame_range(o.first, o.last, head.frames);
  if (!frames) {
    return refuse_analysis_input("fields", fmt::format("--first {} --last {} select no frames: the file has frames 0..{} "
                                                       "(negative indices count from the end)", o.first, o.last, head.frames - 1));
  }
  FieldGrid grid;
  try {
    grid = fields_from_snapshots_grid(head.metadata.system, o.cells);
  } catch (const InputError& error) {
    return refuse_analysis_input("fields", error.what());
  }
  // io/fields_from_snapshots keeps a running and an instant set of moments and computes the fields
  // of both for every frame it reads beside frame 0: refused before any of it is allocated.
  const SystemParams& system = head.metadata.system;
  const bool masses = !head.frame.particles.mass.empty();
  const bool rough = system.roughness.rough && system.roughness.inertia_factor > 0.0;
  const double needed =
      frame_copy_bytes(head.frame) + 2.0 * (cell_moments_bytes(grid, masses, rough) + cell_fields_bytes(grid, rough));
  const std::string cells = grid.dimension == 3 ? fmt::format("{},{},{}", grid.nx, grid.ny, grid.nz)
                                                : fmt::format("{},{}", grid.nx, grid.ny);
  const std::string what = o.cells.empty() ? fmt::format("the default grid of {} cells", cells) : fmt::format("--cells {}", cells);
  if (const auto refused = refused_for_memory("fields", needed, fmt::format("{} (the fields of N = {})", what, head.frame.particles.size()))) {
    return *refused;
  }
  const auto [first, last] = *frames;
  write_fields_from_snapshots({o.snapshots, head.metadata, first, last, grid, o.subtract_shear, o.out, kVersion});
  fmt::print("fields of frames {}..{} on {} × {}{} cells written to {}\n", first, last, grid.nx, grid.ny,
             grid.dimension == 3 ? fmt::format(" × {}", grid.nz) : "", o.out);
  return 0;
}

}  // namespace

void add_analyze_fields(CLI::App& analyze) {
  auto o = std::make_shared<FieldsOptions>();
  CLI::App* command = analyze.add_subcommand(
      "fields", "Coarse-grained density, velocity, temperature, kinetic stress and vorticity (thesis §1.4.3) of saved "
                "snapshots, per frame and averaged over the frames (schema: README, fields.h5)");
  command->add_option("snapshots", o->snapshots, "snapshots.h5 of a run")->required()->check(CLI::ExistingFile);
  command->add_option("--cells", o->cells, "Coarse-graining cells nx,ny (3D: nx,ny,nz; default: about 20 particles per cell)")->delimiter(',');
  command->add_option("--first", o->first, "First frame (negative counts from the end)")->default_val(0);
  command->add_option("--last", o->last, "Last frame (negative counts from the end)")->default_val(-1);
  command->add_flag("--subtract-shear", o->subtract_shear,
                    "Take velocities relative to the Lees–Edwards profile u(y) = γ (y − L_y/2) before averaging");
  command->add_option("--out", o->out, "Output HDF5 file")->default_val("fields_from_snapshots.h5");
  command->callback([o] { throw CLI::RuntimeError(analyze_fields(*o)); });
}

}  // namespace granule::app
