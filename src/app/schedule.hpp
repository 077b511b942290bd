// A recurring output trigger of the run loop, in collisions per particle or in time.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "engine/simulation.hpp"

namespace granule::app {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr std::int64_t kNoLimit = std::numeric_limits<std::int64_t>::max();

struct Schedule {
  std::optional<double> every_c;
  std::optional<double> every_t;
  std::int64_t next_collisions = kNoLimit;
  double next_time = kInf;
  std::int64_t particles = 1;

  // First trigger one interval after `from_collisions`.
  void start(std::int64_t n, std::int64_t from_collisions = 0) {
    particles = n;
    if (every_c && *every_c > 0.0) next_collisions = from_collisions + collisions_at(*every_c);
    if (every_t) next_time = *every_t;
  }
  std::int64_t collisions_at(double c) const { return std::llround(c * static_cast<double>(particles)); }
  bool due(const Simulation& sim) const { return sim.collisions() >= next_collisions || sim.time() >= next_time; }
  void advance(const Simulation& sim) {
    while (every_c && *every_c > 0.0 && sim.collisions() >= next_collisions) {
      next_collisions = collisions_at(static_cast<double>(next_collisions) / static_cast<double>(particles) + *every_c);
    }
    while (every_t && sim.time() >= next_time) next_time += *every_t;
  }
};

}  // namespace granule::app
