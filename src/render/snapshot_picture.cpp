#include "render/snapshot_picture.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "io/frame_selection.hpp"
#include "render/config3d_picture.hpp"

namespace granule::render {

RasterImage render_snapshot_picture(const SnapshotRead& snapshot, const PictureOptions& options) {
  const SystemParams& s = snapshot.metadata.system;
  const ShearFrame box{s.length_x, s.length_y, snapshot.metadata.boundary == "lees-edwards" ? s.shear_velocity : 0.0};
  std::array<double, 4> shift{};
  for (std::size_t face = 0; face < shift.size(); ++face) {
    const WallMotion& motion = s.wall[face].motion;
    if (motion.moves()) shift[face] = motion.velocity().integral(0.0, snapshot.frame.clock.time);
  }
  return render_configuration(
      {snapshot.frame.particles, s.diameter, box, snapshot.frame.shear_offset, {s.walls[0], s.walls[1]}, shift, s.obstacles}, options);
}

void choose_spin_coloring(PictureOptions& options, bool coloring_chosen, const SnapshotMetadata& metadata) {
  if (!coloring_chosen && metadata.system.roughness.rough) options.coloring = DiskColoring::kSpin;
  if (options.coloring == DiskColoring::kSpin && !metadata.system.roughness.rough) {
    throw InputError("--color spin needs a run of rough grains (its snapshots have no spins)");
  }
}

std::int64_t write_snapshot_picture(const std::string& snapshots, std::int64_t frame, PictureOptions options,
                                    bool coloring_chosen, const std::string& out) {
  const SnapshotRead first = read_snapshot(snapshots, 0);
  choose_spin_coloring(options, coloring_chosen, first.metadata);
  const std::int64_t index = resolve_frame(frame, first.frames);
  write_png(render_snapshot_picture(read_snapshot(snapshots, index), options), out);
  return index;
}

std::string render_run_picture(const std::string& out_dir) {
  const std::string path = out_dir + "/configuration.png";
  const SnapshotRead last = read_snapshot(out_dir + "/snapshots.h5", -1);
  if (last.frame.particles.dimension == 3) {
    Config3dRequest request;
    request.snapshots = out_dir + "/snapshots.h5";
    request.out = path;
    const int status = draw_config_3d(request);
    if (status != 0) throw std::runtime_error(fmt::format("the 3D picture script ended with exit code {}", status));
    return path;
  }
  PictureOptions options;
  // In a sheared box the mean flow dominates the lab velocities: the structure is in the rest.
  options.subtract_shear_profile = last.metadata.boundary == "lees-edwards";
  if (last.frame.particles.rough()) options.coloring = DiskColoring::kSpin;  // thesis Fig C.4
  write_png(render_snapshot_picture(last, options), path);
  return path;
}

}  // namespace granule::render
