#include "render/snapshot_movie.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/hdf5_util.hpp"
#include "io/io_error.hpp"
#include "render/plot_scripts.hpp"
#include "render/snapshot_picture.hpp"

namespace granule::render {

namespace {

// "t = …   c = …" of a frame, and the image velocity U when the snapshot file stores it per frame.
std::string frame_caption(const SnapshotFrame& frame, const std::vector<double>& shear_velocity, std::size_t k) {
  std::string caption = fmt::format("t = {:.4g}   c = {:.4g}", frame.clock.time, frame.collisions_per_particle);
  if (k < shear_velocity.size()) caption += fmt::format("   U = {:.4g}", shear_velocity[k]);
  return caption;
}

}  // namespace

MovieWritten write_snapshot_movie(const std::string& snapshots, PictureOptions options, bool coloring_chosen,
                                  const MovieSettings& settings, const std::string& out) {
  const SnapshotRead first = read_snapshot(snapshots, 0);
  choose_spin_coloring(options, coloring_chosen, first.metadata);
  const std::int64_t frames = first.frames;
  // Without the encoder the movie cannot be written: say so before drawing anything.
  if (!program_in_path("ffmpeg")) {
    throw IoError(fmt::format("cannot write {}: ffmpeg is not in PATH (install Debian's ffmpeg)", out));
  }
  const std::filesystem::path scratch = out + ".frames";
  const std::string partial = out + ".partial";
  const RemovedAtExit remove_scratch{scratch}, remove_partial{partial};
  std::error_code error;
  std::filesystem::remove_all(scratch, error);
  if (error || !std::filesystem::create_directories(scratch, error)) {
    throw io_error(fmt::format("cannot create {}", scratch.string()), error.value());
  }
  const std::vector<double> shear_velocity = h5::read_frame_series(snapshots, "shear_velocity");
  std::int64_t drawn = 0;
  for (std::int64_t k = 0; k < frames; k += settings.stride, ++drawn) {
    const SnapshotRead snapshot = read_snapshot(snapshots, k);
    if (settings.caption) options.caption = frame_caption(snapshot.frame, shear_velocity, static_cast<std::size_t>(k));
    write_png(render_snapshot_picture(snapshot, options), (scratch / fmt::format("frame_{:06d}.png", drawn)).string());
  }
  // H.264 needs even dimensions: pad by one white pixel where needed.
  const int status = run_program({"ffmpeg", "-loglevel", "error", "-y", "-framerate", fmt::format("{}", settings.fps), "-i",
                                  (scratch / "frame_%06d.png").string(), "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2:color=white",
                                  "-c:v", "libx264", "-pix_fmt", "yuv420p", "-f", "mp4", partial});
  if (status != 0) {
    throw IoError(status == 127 ? fmt::format("cannot write {}: ffmpeg could not be started", out)
                                : fmt::format("cannot write {}: ffmpeg failed with exit code {}", out, status));
  }
  publish_file(partial, out);
  return {drawn, frames};
}

}  // namespace granule::render
