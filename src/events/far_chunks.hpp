// The events beyond the calendar's year: Paul's unsorted overflow (G. Paul, J. Comput. Phys. 221,
// 615 (2007)), here filed by chunk of buckets.  A chunk is a bag of particle ids in no order:
// filing is an append to the open block of one of thousands of bags, where linking the
// event into its calendar list was a cache miss on that list's head once the heads outgrew the
// cache (33.5 MB of them at 10⁷ disks: docs/performance.md).
//
// The chunks from `first` (the first not yet near) on have a bag each in a ring; later ones share
// an overflow bag, filed again when the ring reaches them.  Bags are chains of 64-entry blocks from
// one pool sized at reset for every particle at once, so that the memory is the same whatever
// happened before (a resumed run reports what the run it continues did).  An entry is removed by
// moving its bag's last entry into its place: the caller keeps each particle's entry in its slot.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "memory/huge_page_allocator.hpp"

namespace granule {

class FarChunks {
 public:
  static constexpr std::int64_t kNone = std::numeric_limits<std::int64_t>::max();
  static constexpr std::int32_t kBlock = 64;  // entries per block: 256 bytes

  // Empty, with room for `particles` entries in a ring of `ring_chunks` bags (a power of two).
  void reset(std::size_t particles, std::size_t ring_chunks) {
    ring_.assign(ring_chunks, Bag{});
    // Each bag has at most one block not full (the one it fills), the entry being filed again
    // in drain() one more.
    const std::size_t blocks = (particles + kBlock - 1) / kBlock + ring_chunks + 2;
    entries_.assign(blocks * kBlock, 0);
    next_.assign(blocks, kNoBlock);
    clear();
  }
  // Empty: every block free, in order.
  void clear() {
    std::fill(ring_.begin(), ring_.end(), Bag{});
    overflow_ = Bag{};
    overflow_first_ = kNone;
    ring_entries_ = 0;
    free_ = kNoBlock;
    for (auto b = static_cast<std::int32_t>(next_.size()); b-- > 0;) release(b);
  }
  // Whether `chunk` (≥ first) has its bag in the ring.
  bool in_ring(std::int64_t chunk, std::int64_t first) const { return chunk - first < static_cast<std::int64_t>(ring_.size()); }
  // File `particle` under `chunk` (≥ first); returns its entry.
  std::int32_t file(std::int64_t chunk, std::int32_t particle, std::int64_t first) {
    if (in_ring(chunk, first)) {
      ++ring_entries_;
      return append(ring_bag(chunk), particle);
    }
    overflow_first_ = std::min(overflow_first_, chunk);
    return append(overflow_, particle);
  }
  // Remove `entry` of `chunk` (≥ first); returns the particle moved into its place (-1: none),
  // whose entry is now `entry`.
  std::int32_t remove(std::int64_t chunk, std::int32_t entry, std::int64_t first) {
    if (in_ring(chunk, first)) {
      --ring_entries_;
      return take_out(ring_bag(chunk), entry);
    }
    return take_out(overflow_, entry);
  }
  std::int32_t particle_at(std::int32_t entry) const { return entries_[static_cast<std::size_t>(entry)]; }
  // Every entry of `chunk`'s bag (in the ring), a block at a time, to `use(span)`; the bag is left
  // empty, and its blocks free before `use` sees them, so that `use` may file.
  template <typename Use>
  void drain(std::int64_t chunk, Use&& use) {
    Bag& bag = ring_bag(chunk);
    ring_entries_ -= bag.entries;
    drain_bag(bag, use);
  }
  // The overflow's entries alike; a chunk no later than the earliest of them (kNone: empty).
  template <typename Use>
  void drain_overflow(Use&& use) {
    overflow_first_ = kNone;
    drain_bag(overflow_, use);
  }
  std::int64_t overflow_first() const { return overflow_first_; }
  std::int64_t ring_entries() const { return ring_entries_; }
  std::size_t ring_chunks() const { return ring_.size(); }
  // The entries of a bag, for consistency checks (`chunk` in the ring; kNone: the overflow).
  template <typename See>
  void for_each(std::int64_t chunk, See&& see) const {
    const Bag& bag = chunk == kNone ? overflow_ : ring_[static_cast<std::size_t>(chunk) & (ring_.size() - 1)];
    std::int32_t count = bag.filled;
    for (std::int32_t b = bag.block; b != kNoBlock; b = next_[static_cast<std::size_t>(b)], count = kBlock) {
      for (std::int32_t k = 0; k < count; ++k) see(b * kBlock + k);
    }
  }
  std::size_t bytes() const {
    return entries_.capacity() * sizeof(std::int32_t) + next_.capacity() * sizeof(std::int32_t) + ring_.capacity() * sizeof(Bag);
  }

 private:
  static constexpr std::int32_t kNoBlock = -1;
  // A chain of blocks: the first, being filled, has `filled` entries; the rest are full.
  struct Bag {
    std::int32_t block = kNoBlock;
    std::int32_t filled = 0;
    std::int64_t entries = 0;
  };

  Bag& ring_bag(std::int64_t chunk) { return ring_[static_cast<std::size_t>(chunk) & (ring_.size() - 1)]; }
  void release(std::int32_t block) {
    next_[static_cast<std::size_t>(block)] = free_;
    free_ = block;
  }
  std::int32_t append(Bag& bag, std::int32_t particle) {
    if (bag.block == kNoBlock || bag.filled == kBlock) {
      const std::int32_t block = free_;  // the pool holds every particle's entry: never none
      free_ = next_[static_cast<std::size_t>(block)];
      next_[static_cast<std::size_t>(block)] = bag.block;
      bag.block = block;
      bag.filled = 0;
    }
    const std::int32_t entry = bag.block * kBlock + bag.filled++;
    entries_[static_cast<std::size_t>(entry)] = particle;
    ++bag.entries;
    return entry;
  }
  std::int32_t take_out(Bag& bag, std::int32_t entry) {
    const std::int32_t last = bag.block * kBlock + --bag.filled;
    const std::int32_t moved = last == entry ? -1 : entries_[static_cast<std::size_t>(last)];
    if (moved >= 0) entries_[static_cast<std::size_t>(entry)] = moved;
    --bag.entries;
    if (bag.filled == 0) {
      const std::int32_t emptied = bag.block;
      bag.block = next_[static_cast<std::size_t>(emptied)];
      bag.filled = bag.block == kNoBlock ? 0 : kBlock;
      release(emptied);
    }
    return moved;
  }
  template <typename Use>
  void drain_bag(Bag& bag, Use& use) {
    std::int32_t block = bag.block;
    std::int32_t count = bag.filled;
    bag = Bag{};
    std::array<std::int32_t, kBlock> copy{};
    while (block != kNoBlock) {
      const std::int32_t next = next_[static_cast<std::size_t>(block)];
      const auto* first = entries_.data() + static_cast<std::size_t>(block) * kBlock;
      std::copy(first, first + count, copy.begin());
      release(block);
      use(std::span<const std::int32_t>(copy.data(), static_cast<std::size_t>(count)));
      block = next;
      count = kBlock;
    }
  }

  std::vector<Bag> ring_;
  Bag overflow_;
  std::int64_t overflow_first_ = kNone;
  std::int64_t ring_entries_ = 0;
  HugePageVector<std::int32_t> entries_;  // the blocks, one after another
  std::vector<std::int32_t> next_;       // each block's next in its bag's chain, or in the free list
  std::int32_t free_ = kNoBlock;
};

}  // namespace granule
