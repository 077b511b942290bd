// Pending events are plain data: one per particle, invalidated lazily by collision counters.
#pragma once

#include <cstdint>

namespace granule {

enum class EventKind : std::uint8_t {
  kNone,       // nothing ahead (event time is +inf)
  kCollision,  // with `partner`, valid while the partner's collision counter is unchanged
  kCrossLeft,  // leave the current cell through its left ξ edge
  kCrossRight,
  kCrossDown,  // leave through the lower edge
  kCrossUp,
};

constexpr bool is_crossing(EventKind kind) {
  return kind == EventKind::kCrossLeft || kind == EventKind::kCrossRight ||
         kind == EventKind::kCrossDown || kind == EventKind::kCrossUp;
}

}  // namespace granule
