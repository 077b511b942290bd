#include "io/frame_selection.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace granule {

std::int64_t resolve_frame(std::int64_t frame, std::int64_t frames) {
  if (frame < -frames || frame >= frames) {
    throw InputError(fmt::format("--frame {} is out of range: the file has {} frames (allowed {} … {})", frame, frames,
                               -frames, frames - 1));
  }
  return frame < 0 ? frames + frame : frame;
}

std::vector<std::int64_t> chosen_frames(bool every, std::int64_t frame, std::int64_t frames) {
  if (!every) return {resolve_frame(frame, frames)};
  std::vector<std::int64_t> all(static_cast<std::size_t>(frames));
  for (std::int64_t k = 0; k < frames; ++k) all[static_cast<std::size_t>(k)] = k;
  return all;
}

std::optional<FrameRange> resolve_frame_range(std::int64_t first, std::int64_t last, std::int64_t frames) {
  const FrameRange range{first < 0 ? frames + first : first, last < 0 ? frames + last : last};
  if (range.first < 0 || range.last >= frames || range.first > range.last) return std::nullopt;
  return range;
}

std::vector<std::int64_t> parse_frame_selection(const std::string& spec, std::int64_t total) {
  std::vector<std::int64_t> frames;
  const auto resolve = [&](std::int64_t i) { return i < 0 ? total + i : i; };
  std::size_t start = 0;
  while (start <= spec.size()) {
    const std::size_t comma = std::min(spec.find(',', start), spec.size());
    const std::string item = spec.substr(start, comma - start);
    start = comma + 1;
    try {
      if (item == "all") {
        for (std::int64_t i = 0; i < total; ++i) frames.push_back(i);
      } else if (item.find(':') == std::string::npos) {
        std::size_t used = 0;
        const std::int64_t i = resolve(std::stoll(item, &used));
        if (used != item.size() || i < 0 || i >= total) throw std::out_of_range(item);
        frames.push_back(i);
      } else {
        std::vector<std::string> parts;
        for (std::size_t p = 0, colon = 0; colon != std::string::npos; p = colon + 1) {
          colon = item.find(':', p);
          parts.push_back(item.substr(p, colon == std::string::npos ? std::string::npos : colon - p));
        }
        if (parts.size() > 3) throw std::invalid_argument(item);
        const std::int64_t step = parts.size() == 3 && !parts[2].empty() ? std::stoll(parts[2]) : 1;
        if (step <= 0) throw std::invalid_argument(item);
        const std::int64_t first = parts[0].empty() ? 0 : std::clamp<std::int64_t>(resolve(std::stoll(parts[0])), 0, total);
        const std::int64_t last = parts[1].empty() ? total : std::clamp<std::int64_t>(resolve(std::stoll(parts[1])), 0, total);
        for (std::int64_t i = first; i < last; i += step) frames.push_back(i);
      }
    } catch (const std::exception&) {
      throw InputError(fmt::format("--frames: '{}' is not a frame index in [-{}, {}) or a slice start:stop[:step] (step > 0)",
                                 item, total, total));
    }
  }
  if (frames.empty()) throw InputError(fmt::format("--frames '{}' selects no frame (the file has {})", spec, total));
  return frames;
}

}  // namespace granule
