#include "io/export_series.hpp"

#include <fmt/format.h>

#include <utility>

#include "io/export_field_source.hpp"
#include "io/export_file.hpp"
#include "io/export_vtk.hpp"
#include "io/export_xyz.hpp"
#include "io/snapshot_file.hpp"

namespace granule {

namespace fs = std::filesystem;

namespace {

// `<stem>_<k>.<extension>` beside the series file.
std::string frame_file(const fs::path& series, std::int64_t k, const std::string& extension) {
  return (series.parent_path() / fmt::format("{}_{}.{}", series.stem().string(), k, extension)).string();
}

}  // namespace

void write_vtk_series(const fs::path& series, const std::vector<std::int64_t>& frames, const std::string& extension,
                      const ExportFrameWriter& write_frame, const ExportWritten& written) {
  std::vector<std::pair<double, std::string>> collection;
  for (std::int64_t k : frames) {
    const std::string path = frames.size() == 1 ? series.string() : frame_file(series, k, extension);
    collection.emplace_back(write_frame(k, path), fs::path(path).filename().string());
    written(path);
  }
  if (frames.size() > 1) {
    write_pvd(series.string(), collection);
    written(series.string());
  }
}

void export_xyz_frames(const std::string& snapshots, const std::vector<std::int64_t>& frames, const std::string& out) {
  StagedFile file(out);
  for (std::int64_t k : frames) {
    const SnapshotRead s = read_snapshot(snapshots, k);
    const SystemParams& p = s.metadata.system;
    write_xyz_frame(file.stream(), s.frame.particles,
                    {p.diameter, p.length_x, p.length_y, s.frame.clock.time, s.frame.collisions_per_particle,
                     s.metadata.boundary, p.shear_velocity, s.frame.shear_offset, p.length_z});
  }
  file.commit();
}

void export_vtp_frames(const std::string& snapshots, const std::vector<std::int64_t>& frames, const fs::path& out,
                       const ExportWritten& written) {
  write_vtk_series(
      out, frames, "vtp",
      [&](std::int64_t k, const std::string& path) {
        const SnapshotRead s = read_snapshot(snapshots, k);
        write_vtp_particles(path, s.frame.particles, s.metadata.system.diameter, s.frame.clock.time);
        return s.frame.clock.time;
      },
      written);
}

void export_field_file_frames(const std::string& fields, const std::vector<std::int64_t>& frames, const fs::path& out,
                              const ExportWritten& written) {
  write_vtk_series(
      out, frames, "vti",
      [&](std::int64_t k, const std::string& path) {
        const FieldFileFrame f = read_field_file_frame(fields, k);
        write_vti_fields(path, f.grid, f.arrays, f.time);
        return f.time;
      },
      written);
}

}  // namespace granule
