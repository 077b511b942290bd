#include "events/event_heap.hpp"

#include <limits>
#include <stdexcept>

namespace granule {

void EventHeap::reset(std::int32_t particles) {
  const auto n = static_cast<std::size_t>(particles);
  time_.resize(n);
  particle_.resize(n);
  slot_.resize(n);
  for (std::int32_t i = 0; i < particles; ++i) place(static_cast<std::uint32_t>(i), std::numeric_limits<double>::infinity(), i);
}

void EventHeap::update(std::int32_t particle, double time) {
  const std::uint32_t slot = slot_[static_cast<std::size_t>(particle)];
  const double old = time_[slot];
  time_[slot] = time;
  if (time < old) {
    sift_up(slot);
  } else {
    sift_down(slot);
  }
}

void EventHeap::sift_up(std::uint32_t slot) {
  const double time = time_[slot];
  const std::int32_t particle = particle_[slot];
  while (slot > 0) {
    const std::uint32_t parent = (slot - 1) / 2;
    if (!(time < time_[parent])) break;
    place(slot, time_[parent], particle_[parent]);
    slot = parent;
  }
  place(slot, time, particle);
}

void EventHeap::sift_down(std::uint32_t slot) {
  const double time = time_[slot];
  const std::int32_t particle = particle_[slot];
  const auto size = static_cast<std::uint32_t>(time_.size());
  while (true) {
    std::uint32_t child = 2 * slot + 1;
    if (child >= size) break;
    if (child + 1 < size && time_[child + 1] < time_[child]) ++child;
    if (!(time_[child] < time)) break;
    place(slot, time_[child], particle_[child]);
    slot = child;
  }
  place(slot, time, particle);
}

bool EventHeap::is_consistent() const {
  if (slot_.size() != time_.size() || particle_.size() != time_.size()) return false;
  for (std::size_t k = 0; k < time_.size(); ++k) {
    const auto particle = static_cast<std::size_t>(particle_[k]);
    if (particle >= slot_.size() || slot_[particle] != k) return false;
    if (k > 0 && time_[k] < time_[(k - 1) / 2]) return false;
  }
  return true;
}

void EventHeap::shift_times(double delta) {
  for (double& time : time_) time -= delta;
}

void EventHeap::save(StateArchive& archive, const std::string& prefix) const {
  archive.put(prefix + "time", time_);
  archive.put(prefix + "particle", particle_);
}

void EventHeap::restore(const StateArchive& archive, const std::string& prefix, std::int32_t particles) {
  const auto& times = archive.get<double>(prefix + "time");
  const auto& ids = archive.get<std::int32_t>(prefix + "particle");
  const auto n = static_cast<std::size_t>(particles);
  if (times.size() != n || ids.size() != n) throw std::runtime_error("checkpoint event heap has the wrong size");
  time_.resize(n);
  particle_.resize(n);
  slot_.assign(n, static_cast<std::uint32_t>(n));
  for (std::size_t k = 0; k < n; ++k) {
    const std::int32_t id = ids[k];
    if (id < 0 || id >= particles || slot_[static_cast<std::size_t>(id)] != n) {
      throw std::runtime_error("checkpoint event heap is not a permutation of the particles");
    }
    place(static_cast<std::uint32_t>(k), times[k], id);
  }
  for (std::size_t k = 1; k < n; ++k) {
    if (time_[k] < time_[(k - 1) / 2]) throw std::runtime_error("checkpoint event heap is out of order");
  }
}

}  // namespace granule
