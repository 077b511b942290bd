#include "app/plot/plot_run_picture.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "app/plot/plot_config3d.hpp"

namespace granule::app {

render::RasterImage render_snapshot_picture(const SnapshotRead& snapshot, const render::PictureOptions& options) {
  const SystemParams& s = snapshot.metadata.system;
  const ShearFrame box{s.length_x, s.length_y, snapshot.metadata.boundary == "lees-edwards" ? s.shear_velocity : 0.0};
  return render::render_configuration({snapshot.frame.particles, s.diameter, box, snapshot.frame.shear_offset, {s.walls[0], s.walls[1]}},
                                      options);
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
  render::PictureOptions options;
  // In a sheared box the mean flow dominates the lab velocities: the structure is in the rest.
  options.subtract_shear_profile = last.metadata.boundary == "lees-edwards";
  if (last.frame.particles.rough()) options.coloring = render::DiskColoring::kSpin;  // thesis Fig C.4
  render::write_png(render_snapshot_picture(last, options), path);
  return path;
}

}  // namespace granule::app
