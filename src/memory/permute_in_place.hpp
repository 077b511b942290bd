// Reorder several parallel arrays at once without a second copy of any of them: every engine
// array of 10^8 particles would otherwise need its double at the moment of a renumbering.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>

namespace granule {

// Moves item k of the arrays to position destination[k] (destination is a permutation of
// 0 .. n−1), through swap(a, b), which exchanges items a and b of every array; at most n − 1
// swaps, following the permutation's cycles.  `destination` ends as the identity.
template <typename Swap>
void permute_in_place(std::span<std::int32_t> destination, Swap&& swap) {
  for (std::size_t k = 0; k < destination.size(); ++k) {
    while (static_cast<std::size_t>(destination[k]) != k) {
      const auto place = static_cast<std::size_t>(destination[k]);
      swap(k, place);  // item k reaches its place; the one from there waits at k for its turn
      std::swap(destination[k], destination[place]);
    }
  }
}

}  // namespace granule
