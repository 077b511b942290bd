// Indexed binary min-heap of one event time per particle: O(log N) update of any particle's
// time, O(1) access to the earliest.  Times are relative to the engine's clock base.  Times and
// particle ids are two arrays, not one array of {time, id} records: 12 bytes per entry instead of
// 16 (padding), and the times a sift compares sit twice as densely in the cache.
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
  std::int32_t top() const { return particle_[0]; }
  double top_time() const { return time_[0]; }
  double time_of(std::int32_t particle) const { return time_[slot_[static_cast<std::size_t>(particle)]]; }
  // Heap order holds and every particle's slot points at its entry (GRANULE_PARANOID checks).
  bool is_consistent() const;
  // Subtract the same amount from every time (clock re-basing); order is preserved.
  void shift_times(double delta);
  // The heap's layout decides which of two equal times pops first: a checkpoint keeps it exactly.
  void save(StateArchive& archive, const std::string& prefix) const;
  void restore(const StateArchive& archive, const std::string& prefix, std::int32_t particles);
  std::size_t bytes() const {
    return time_.capacity() * sizeof(double) + (particle_.capacity() + slot_.capacity()) * sizeof(std::uint32_t);
  }

 private:
  void sift_up(std::uint32_t slot);
  void sift_down(std::uint32_t slot);
  void place(std::uint32_t slot, double time, std::int32_t particle) {
    time_[slot] = time;
    particle_[slot] = particle;
    slot_[static_cast<std::size_t>(particle)] = slot;
  }

  std::vector<double> time_;           // heap order
  std::vector<std::int32_t> particle_;  // the particle of each heap entry
  std::vector<std::uint32_t> slot_;     // the heap entry of each particle
};

}  // namespace granule
