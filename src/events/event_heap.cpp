#include "events/event_heap.hpp"

#include <limits>

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

void EventHeap::shift_times(double delta) {
  for (auto& entry : heap_) entry.time -= delta;
}

}  // namespace granule
