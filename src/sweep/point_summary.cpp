#include "sweep/point_summary.hpp"

#include <fmt/format.h>

namespace granule::sweep {

namespace {

// A run's summary is a few kilobytes, its objects nested four deep at most (a wall's vectors).
constexpr std::size_t kMaxSummaryBytes = 1 << 20;
constexpr int kMaxSummaryDepth = 8;

}  // namespace

std::optional<JsonFile> read_point_summary(const SweepDirectory& dir, const SweepPoint& point) {
  return JsonFile::read(dir.run(point) / "summary.json", kMaxSummaryBytes, kMaxSummaryDepth,
                        fmt::format("delete {} to run the point again", dir.run(point).string()));
}

}  // namespace granule::sweep
