// A recurring output trigger of the run loop, every `every_c` collisions per particle or every
// `every_t` of time, counted from an origin.  Advancing jumps straight to the first trigger after
// the present (O(1), however far the clock moved), and always lies strictly ahead, so no schedule
// can stall the loop.  A time schedule fires at most once between two events: triggers before the
// next event would repeat the same configuration, merely streamed (a cooling gas whose mean free
// time outgrows the interval would otherwise write without end); they are skipped and counted in
// `skipped`, and an interval below one ulp of the clock is rounded up (`rounded_up`).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "engine/simulation.hpp"
#include "archive/state_archive.hpp"

namespace granule::driver {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr std::int64_t kNoLimit = std::numeric_limits<std::int64_t>::max();

struct Schedule {
  std::optional<double> every_c;  // 0 or absent: never by collisions
  std::optional<double> every_t;
  std::int64_t particles = 1;
  std::int64_t origin_collisions = 0;
  double origin_time = 0.0;
  std::int64_t next_collisions = kNoLimit;
  double next_time = kInf;
  bool rounded_up = false;
  std::int64_t skipped = 0;

  // First trigger one interval after the origin.
  void start(std::int64_t n, std::int64_t from_collisions = 0, double from_time = 0.0) {
    particles = n;
    origin_collisions = from_collisions;
    origin_time = from_time;
    next_collisions = by_collisions() ? from_collisions + interval_collisions(1.0) : kNoLimit;
    next_time = every_t ? from_time + *every_t : kInf;
  }
  template <typename Engine>
  bool due(const Engine& sim) const { return sim.collisions() >= next_collisions || sim.time() >= next_time; }
  // Move to the first trigger after the present.
  template <typename Engine>
  void advance(const Engine& sim) {
    if (by_collisions() && sim.collisions() >= next_collisions) {
      next_collisions = collision_trigger_after(sim.collisions());
    }
    if (every_t && sim.time() >= next_time) {
      next_time = trigger_after(sim.time());
      if (const double next_event = sim.next_event_time(); next_event > next_time) {
        const double first_after_event = trigger_after(next_event);
        skipped += std::llround((first_after_event - next_time) / *every_t);
        next_time = first_after_event;
      }
    }
  }

  void save(StateArchive& archive, const std::string& prefix) const {
    archive.put_integer(prefix + "origin_collisions", origin_collisions);
    archive.put_scalar(prefix + "origin_time", origin_time);
    archive.put_integer(prefix + "next_collisions", next_collisions);
    archive.put_scalar(prefix + "next_time", next_time);
    archive.put_integer(prefix + "skipped", skipped);
    archive.put_integer(prefix + "rounded_up", rounded_up ? 1 : 0);
    archive.put_scalar(prefix + "every_collisions_per_particle", every_c.value_or(0.0));
    archive.put_scalar(prefix + "every_time", every_t.value_or(0.0));
  }
  // The saved triggers belong to the saved intervals.  A run resumed with other intervals (`--set`
  // on `--resume`) keeps the origin and fires next at the first trigger of the new intervals after
  // the present: taking the old triggers over wrote nothing when the old schedule was off.
  // (Checkpoints from before the intervals were saved keep their triggers.)
  template <typename Engine>
  void restore(const StateArchive& archive, const std::string& prefix, const Engine& sim) {
    origin_collisions = archive.integer(prefix + "origin_collisions");
    origin_time = archive.scalar(prefix + "origin_time");
    next_collisions = archive.integer(prefix + "next_collisions");
    next_time = archive.scalar(prefix + "next_time");
    skipped = archive.integer(prefix + "skipped");
    rounded_up = archive.integer(prefix + "rounded_up") != 0;
    // Triggers from an origin in the run's past, lying ahead of it: a damaged schedule (NaN, or a
    // trigger behind its origin) would fire at every stop or never.
    if (origin_collisions < 0 || origin_collisions > sim.collisions() || !std::isfinite(origin_time) || origin_time < 0.0 ||
        origin_time > sim.time() || next_collisions < origin_collisions || std::isnan(next_time) || next_time < origin_time ||
        skipped < 0) {
      throw std::runtime_error("checkpoint entries " + prefix + "*: the schedule's origin or next trigger is not of this run");
    }
    const std::string saved_c = prefix + "every_collisions_per_particle", saved_t = prefix + "every_time";
    if (!archive.contains(saved_c)) return;
    if (archive.scalar(saved_c) != every_c.value_or(0.0)) {
      next_collisions = by_collisions() ? collision_trigger_after(sim.collisions()) : kNoLimit;
    }
    if (archive.scalar(saved_t) != every_t.value_or(0.0)) next_time = every_t ? trigger_after(sim.time()) : kInf;
  }

 private:
  bool by_collisions() const { return every_c && *every_c > 0.0; }
  // The first trigger by collisions strictly after `collisions`.
  std::int64_t collision_trigger_after(std::int64_t collisions) const {
    const double periods =
        std::floor(static_cast<double>(collisions - origin_collisions) / (*every_c * static_cast<double>(particles)));
    return std::max(collisions + 1, origin_collisions + interval_collisions(periods + 1.0));
  }
  // The first trigger strictly after t.
  double trigger_after(double t) {
    const double next = origin_time + (std::floor((t - origin_time) / *every_t) + 1.0) * *every_t;
    if (next > t) return next;
    rounded_up = true;
    return std::nextafter(t, kInf);
  }
  std::int64_t interval_collisions(double periods) const {
    return std::llround(periods * *every_c * static_cast<double>(particles));
  }
};

}  // namespace granule::driver
