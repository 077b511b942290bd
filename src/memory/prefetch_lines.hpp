// A hint for the cache: start fetching every line an object of at most one line's size spans.
// A 48-byte disk record straddles two 64-byte lines at every second place of its array, so a
// prefetch of its first byte alone left the neighbour scan to miss on the line with its velocity
// and list link (docs/performance.md, "Both lines of a record; the next bucket's events fetched a
// bucket ahead").
#pragma once

#include <cstddef>

namespace granule {

inline constexpr std::size_t kCacheLine = 64;

// Forced inline: GCC drops the call of a function that only prefetches.
// every_line = false: the first line only, for objects that mostly stay in the L2/L3 caches,
// where the second prefetch costs an instruction more than it hides (1–3 % at 2·10⁴ disks).
template <typename T>
[[gnu::always_inline]] inline void prefetch_lines(const T* object, bool every_line = true) {
  static_assert(sizeof(T) <= kCacheLine, "an object of more than one line can span three");
  const char* first = reinterpret_cast<const char*>(object);
  __builtin_prefetch(first);
  if constexpr (alignof(T) % kCacheLine != 0) {
    if (every_line) __builtin_prefetch(first + sizeof(T) - 1);
  }
}

}  // namespace granule
