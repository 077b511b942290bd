// The frames of a run's file that an analysis, an export or a picture uses, chosen by index
// (negative indices count from the end), by a range, by a list of indices and slices, or all of
// them.  Every index returned is a frame of the file, ≥ 0.  A choice that names no frame of the
// file throws InputError, whose message names the option it came from.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "io/io_error.hpp"

namespace granule {

// Frame `frame` of a file of `frames` frames (--frame).
std::int64_t resolve_frame(std::int64_t frame, std::int64_t frames);

// Every frame when `every`, else the one frame `frame` (resolve_frame).
std::vector<std::int64_t> chosen_frames(bool every, std::int64_t frame, std::int64_t frames);

// Frames first..last, both included; none when that range holds no frame of the file.
struct FrameRange {
  std::int64_t first = 0, last = 0;
};
std::optional<FrameRange> resolve_frame_range(std::int64_t first, std::int64_t last, std::int64_t frames);

// "all", or comma-separated items: an index or a Python-style slice start:stop[:step] with
// optional parts (--frames).  The indices in the order given.
std::vector<std::int64_t> parse_frame_selection(const std::string& spec, std::int64_t total);

}  // namespace granule
