#include "driver/run_directory.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <vector>

#include "io/fields_file.hpp"
#include "io/hdf5_util.hpp"
#include "io/io_error.hpp"
#include "io/timeseries_csv.hpp"
#include "observables/observables.hpp"

namespace granule::driver {

namespace fs = std::filesystem;

namespace {

// Everything a run writes (README.md, "Outputs"), with the temporary names of atomic writes.
const std::vector<std::string>& run_output_names() {
  static const std::vector<std::string> names = {
      "config.toml", "timeseries.csv", "summary.json", "snapshots.h5", "fields.h5", "collisions.h5",
      "checkpoint.h5", "impact_parameters.csv", "free_paths.csv", "configuration.png"};
  return names;
}

void remove_outputs(const std::string& out, const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    for (const char* suffix : {"", ".partial", ".tmp", ".partial.journal", ".partial.journal.tmp"}) {
      std::error_code error;
      fs::remove(fs::path(out) / (name + suffix), error);
      if (error) throw IoError(fmt::format("cannot remove {}/{}{}: {}", out, name, suffix, error.message()));
    }
  }
}

}  // namespace

double available_memory_bytes() {
  double available = 0.0;
  std::ifstream meminfo("/proc/meminfo");
  for (std::string key; meminfo >> key;) {
    double kib = 0.0;
    meminfo >> kib;
    if (key == "MemAvailable:") available = kib * 1024.0;
    meminfo.ignore(256, '\n');
  }
  std::ifstream limit("/sys/fs/cgroup/memory.max");
  double cgroup = 0.0;
  if (limit >> cgroup && cgroup > 0.0 && (available == 0.0 || cgroup < available)) available = cgroup;
  return available;
}

void prepare_new_output_directory(const std::string& out, bool force) {
  std::error_code error;
  // What no directory could be: refused as input (exit 2), before anything is created.
  if (out.empty()) throw RunDirectoryRefused("--out is empty: give the directory the run writes into");
  if (fs::is_symlink(fs::symlink_status(out, error)) && !fs::exists(out, error)) {
    throw RunDirectoryRefused(fmt::format("--out {} is a symbolic link to {}, which does not exist", out,
                                          fs::read_symlink(out, error).string()));
  }
  const fs::file_status status = fs::status(out, error);
  if (fs::exists(status) && !fs::is_directory(status)) {
    throw RunDirectoryRefused(fmt::format("--out {} exists and is not a directory", out));
  }
  if (fs::is_directory(status) && !fs::is_empty(out, error)) {
    if (!force) {
      throw RunDirectoryRefused(fmt::format("--out {} already holds files; give another directory, --force to replace "
                                            "the outputs of the run in it, or --resume {} to continue that run",
                                            out, out));
    }
    remove_outputs(out, run_output_names());
  }
  fs::create_directories(out, error);
  if (error) throw IoError(fmt::format("cannot create the output directory {}: {}", out, error.message()));
  // Root passes permission checks, an immutable directory or a read-only mount does not: try.
  const fs::path probe = fs::path(out) / ".granule-write-probe";
  bool written = false;
  {
    std::ofstream file(probe);
    file << "probe\n";
    file.flush();
    written = static_cast<bool>(file);
  }
  fs::remove(probe, error);
  if (!written) throw IoError(fmt::format("cannot write into the output directory {}", out));
}

void remove_end_of_run_outputs(const std::string& out) {
  remove_outputs(out, {"summary.json", "collisions.h5", "impact_parameters.csv", "free_paths.csv", "configuration.png"});
}

std::string set_aside_run_outputs(const std::string& out, std::int64_t frame) {
  fs::path aside = fs::path(out) / fmt::format("set_aside_after_frame_{}", frame);
  for (int copy = 2; fs::exists(aside); ++copy) aside = fs::path(out) / fmt::format("set_aside_after_frame_{}_{}", frame, copy);
  std::error_code error;
  fs::create_directory(aside, error);
  if (error) throw IoError(fmt::format("cannot create {}: {}", aside.string(), error.message()));
  for (const std::string& name : run_output_names()) {
    // A killed run's last flush first (h5::recover_partial_file), read from where it is set aside.
    const fs::path growing = fs::path(out) / (name + ".partial");
    if (fs::exists(growing)) h5::recover_partial_file(growing.string());
    for (const char* suffix : {"", ".partial"}) {
      const fs::path from = fs::path(out) / (name + suffix);
      if (!fs::exists(from)) continue;
      fs::rename(from, aside / (name + suffix), error);
      if (error) throw IoError(fmt::format("cannot move {} aside: {}", from.string(), error.message()));
    }
  }
  return aside.string();
}

std::string existing_run_output(const std::string& out, const std::string& name) {
  for (const char* suffix : {"", ".partial"}) {
    if (fs::exists(out + "/" + name + suffix)) return out + "/" + name + suffix;
  }
  return {};
}

std::vector<std::string> files_written_since(const std::string& out, fs::file_time_type since) {
  std::vector<std::string> files;
  std::error_code error;
  for (auto it = fs::recursive_directory_iterator(out, error); !error && it != fs::recursive_directory_iterator();
       it.increment(error)) {
    if (!it->is_regular_file(error) || it->last_write_time(error) < since) continue;
    files.push_back(fs::relative(it->path(), out, error).string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

BranchedOutputs branch_run_outputs(const std::string& out, std::int64_t frame, double c, bool fields) {
  BranchedOutputs branched;
  branched.aside = set_aside_run_outputs(out, frame);
  fs::copy_file(existing_run_output(branched.aside, "snapshots.h5"), out + "/snapshots.h5.partial");
  if (const std::string rows = existing_run_output(branched.aside, "timeseries.csv"); !rows.empty()) {
    for (const DiagnosticsSample& sample : read_timeseries(rows)) {
      if (sample.c <= c) branched.samples.push_back(sample);
    }
  }
  if (const std::string fields_file = existing_run_output(branched.aside, "fields.h5"); !fields_file.empty() && fields) {
    for (const double frame_c : read_fields_frame_c(fields_file)) {
      if (frame_c > c) break;
      ++branched.kept.fields_frames;
      branched.kept.fields_frame_at_start = frame_c == c;
    }
    fs::copy_file(fields_file, out + "/fields.h5.partial");
  }
  return branched;
}

double estimated_run_bytes(const RunConfig& config, const CellGrid& grid) {
  // Measured peaks (granule bench, /usr/bin/time, heaptrack; docs/performance.md): the engine
  // ~95 B per disk and ~111 per sphere, +8 with the TC model, +16 polydisperse, +8 (+24) for
  // spinning disks (spheres); beside it, at most the positions and cell binning of the flow
  // classification (32 B per disk) or a block-read output; a 2D run of 10^7 disks with every
  // default output peaked at 151 B per disk.  Per engine cell its list head.  Per cell of the
  // fields' grid (its moments, sums and averages) 673 B in 2D (fields.cells = [2000, 2000] of 1000
  // disks peaked at 2.73 GB, [1000, 1000] at 0.70 GB), 3D scaled by its 55 fields to 2D's 37, and
  // 13 B when fields are off; per cell of the diagnostics' grid 154 B ([2000, 2000]: 0.65 GB).
  const SystemParams& s = config.system;
  const bool spheres = s.dimension == 3;
  double per_particle = spheres ? 111.0 : 95.0;
  if (s.tc_duration > 0.0) per_particle += 8.0;
  if (!config.diameters.monodisperse()) per_particle += 16.0;
  if (s.roughness.rough) per_particle += spheres ? 24.0 : 8.0;
  per_particle += 48.0;  // the transients above, with a margin
  const auto n = static_cast<double>(s.particles);
  const double field_cells = static_cast<double>(fields_grid(config).cells());
  const double per_field_cell = !config.fields.enabled ? 16.0 : spheres ? 1000.0 : 680.0;
  const double diagnostic_cells = static_cast<double>(config.diagnostic_cells.first) * config.diagnostic_cells.second;
  return per_particle * n + 4.0 * static_cast<double>(grid.cell_count()) + per_field_cell * field_cells +
         160.0 * diagnostic_cells;
}

}  // namespace granule::driver
