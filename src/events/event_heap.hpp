// Indexed binary min-heap of one event time per particle: O(log N) update of any particle's
// time, O(1) access to the earliest.  Times are relative to the engine's clock base.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "engine/state_archive.hpp"

namespace granule {

class EventHeap {
 public:
  // All particles present, at time +inf.
  void reset(std::int32_t particles);
  // Set a particle's event time, restoring heap order.
  void update(std::int32_t particle, double time);
  std::int32_t top() const { return heap_[0].particle; }
  double top_time() const { return heap_[0].time; }
  double time_of(std::int32_t particle) const { return heap_[slot_[static_cast<std::size_t>(particle)]].time; }
  // Heap order holds and every particle's slot points at its entry (GRANULE_PARANOID checks).
  bool is_consistent() const;
  // Subtract the same amount from every time (clock re-basing); order is preserved.
  void shift_times(double delta);
  // The heap's layout decides which of two equal times pops first: a checkpoint keeps it exactly.
  void save(StateArchive& archive, const std::string& prefix) const;
  void restore(const StateArchive& archive, const std::string& prefix, std::int32_t particles);
  std::size_t bytes() const {
    return heap_.capacity() * sizeof(Entry) + slot_.capacity() * sizeof(std::uint32_t);
  }

 private:
  struct Entry {
    double time;
    std::int32_t particle;
  };
  void sift_up(std::uint32_t slot);
  void sift_down(std::uint32_t slot);
  void place(std::uint32_t slot, Entry entry) {
    heap_[slot] = entry;
    slot_[static_cast<std::size_t>(entry.particle)] = slot;
  }

  std::vector<Entry> heap_;
  std::vector<std::uint32_t> slot_;
};

}  // namespace granule
