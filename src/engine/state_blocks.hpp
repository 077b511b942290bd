// A configuration handed over in blocks of consecutive particles, so that what is computed from
// the whole state of 10^8 disks (time-series samples, fields, snapshots) needs no copy of it.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <utility>

#include "engine/system_params.hpp"

namespace granule {

class StateBlocks {
 public:
  // 2^16 particles: 2 MiB of a block of spheres, small beside any state worth streaming.
  static constexpr std::size_t kBlock = std::size_t{1} << 16;
  // `block(first, count)` gives particles first .. first + count - 1 (each call computes them
  // afresh, e.g. from the engine, which must not move on while the blocks are read).
  using Source = std::function<ParticleState(std::size_t first, std::size_t count)>;

  StateBlocks(std::size_t particles, Source block, std::size_t block_size = kBlock)
      : particles_(particles), block_size_(std::max<std::size_t>(block_size, 1)), block_(std::move(block)) {}
  // A configuration already in memory is one block, not copied (implicit: every analysis of a
  // state also takes its blocks).  `state` must outlive this object.
  StateBlocks(const ParticleState& state) : particles_(state.size()), whole_(&state) {}  // NOLINT

  std::size_t size() const { return particles_; }
  // f(block, first) for consecutive blocks, in particle order: sums carried from one block to the
  // next run in the same order as over the whole state, so results are the same to the bit.
  template <typename F>
  void for_each(F&& f) const {
    if (whole_ != nullptr) {
      f(*whole_, std::size_t{0});
      return;
    }
    for (std::size_t first = 0; first < particles_; first += block_size_) {
      const std::size_t count = std::min(block_size_, particles_ - first);
      const ParticleState block = block_(first, count);
      f(block, first);
    }
  }

 private:
  std::size_t particles_ = 0;
  std::size_t block_size_ = kBlock;
  const ParticleState* whole_ = nullptr;
  Source block_;
};

}  // namespace granule
