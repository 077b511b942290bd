#include "events/event_heap.hpp"

#include <limits>
#include <stdexcept>

namespace granule {

void EventHeap::reset(std::int32_t particles) {
  heap_.resize(static_cast<std::size_t>(particles));
  slot_.resize(static_cast<std::size_t>(particles));
  for (std::int32_t i = 0; i < particles; ++i) {
    place(static_cast<std::uint32_t>(i), {std::numeric_limits<double>::infinity(), i});
  }
}

void EventHeap::update(std::int32_t particle, double time) {
  const std::uint32_t slot = slot_[static_cast<std::size_t>(particle)];
  const double old = heap_[slot].time;
  heap_[slot].time = time;
  if (time < old) {
    sift_up(slot);
  } else {
    sift_down(slot);
  }
}

void EventHeap::sift_up(std::uint32_t slot) {
  const Entry moving = heap_[slot];
  while (slot > 0) {
    const std::uint32_t parent = (slot - 1) / 2;
    if (!(moving.time < heap_[parent].time)) break;
    place(slot, heap_[parent]);
    slot = parent;
  }
  place(slot, moving);
}

void EventHeap::sift_down(std::uint32_t slot) {
  const Entry moving = heap_[slot];
  const auto size = static_cast<std::uint32_t>(heap_.size());
  while (true) {
    std::uint32_t child = 2 * slot + 1;
    if (child >= size) break;
    if (child + 1 < size && heap_[child + 1].time < heap_[child].time) ++child;
    if (!(heap_[child].time < moving.time)) break;
    place(slot, heap_[child]);
    slot = child;
  }
  place(slot, moving);
}

bool EventHeap::is_consistent() const {
  if (slot_.size() != heap_.size()) return false;
  for (std::size_t k = 0; k < heap_.size(); ++k) {
    const auto particle = static_cast<std::size_t>(heap_[k].particle);
    if (particle >= slot_.size() || slot_[particle] != k) return false;
    if (k > 0 && heap_[k].time < heap_[(k - 1) / 2].time) return false;
  }
  return true;
}

void EventHeap::shift_times(double delta) {
  for (auto& entry : heap_) entry.time -= delta;
}

void EventHeap::save(StateArchive& archive, const std::string& prefix) const {
  std::vector<double> times(heap_.size());
  std::vector<std::int32_t> particles(heap_.size());
  for (std::size_t k = 0; k < heap_.size(); ++k) {
    times[k] = heap_[k].time;
    particles[k] = heap_[k].particle;
  }
  archive.put(prefix + "time", std::move(times));
  archive.put(prefix + "particle", std::move(particles));
}

void EventHeap::restore(const StateArchive& archive, const std::string& prefix, std::int32_t particles) {
  const auto& times = archive.get<double>(prefix + "time");
  const auto& ids = archive.get<std::int32_t>(prefix + "particle");
  const auto n = static_cast<std::size_t>(particles);
  if (times.size() != n || ids.size() != n) throw std::runtime_error("checkpoint event heap has the wrong size");
  heap_.resize(n);
  slot_.assign(n, static_cast<std::uint32_t>(n));
  for (std::size_t k = 0; k < n; ++k) {
    const std::int32_t id = ids[k];
    if (id < 0 || id >= particles || slot_[static_cast<std::size_t>(id)] != n) {
      throw std::runtime_error("checkpoint event heap is not a permutation of the particles");
    }
    place(static_cast<std::uint32_t>(k), {times[k], id});
  }
  for (std::size_t k = 1; k < n; ++k) {
    if (heap_[k].time < heap_[(k - 1) / 2].time) throw std::runtime_error("checkpoint event heap is out of order");
  }
}

}  // namespace granule
