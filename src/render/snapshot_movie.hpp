// A movie of a 2D run: one configuration picture per snapshot (every S-th), each with its t and c
// (and the image velocity U when the file stores it) in the corner, encoded as H.264 mp4 by ffmpeg.
#pragma once

#include <cstdint>
#include <string>

#include "render/configuration_picture.hpp"

namespace granule::render {

struct MovieSettings {
  double fps = 10.0;         // frames per second
  std::int64_t stride = 1;   // every stride-th snapshot: 0, S, 2S, …
  bool caption = true;       // t, c (and U) in the top-left corner of each frame
};

struct MovieWritten {
  std::int64_t drawn = 0;   // the movie's frames
  std::int64_t frames = 0;  // the snapshot file's
};

// Draws the snapshots of `snapshots` (rough grains by choose_spin_coloring) and encodes them to
// `out`.  The frames go to a scratch folder beside `out` and the movie to `<out>.partial`, both
// removed whatever happens; only a complete movie is renamed to `out`.  Without ffmpeg in PATH, or
// when it fails, throws IoError and writes nothing.
MovieWritten write_snapshot_movie(const std::string& snapshots, PictureOptions options, bool coloring_chosen,
                                  const MovieSettings& settings, const std::string& out);

}  // namespace granule::render
