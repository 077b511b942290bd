// What only a particle's own events read and write, in one 16-byte slot (four per cache line): the
// time of its pending event and its link in the calendar queue (the queue's part, private to it),
// the event's kind and the particle's cell.  An event reads, and a prediction writes, one line,
// where a separate engine slot and queue node would cost two lines and 40 bytes
// (docs/performance.md).  The collision candidate lives in the particle's record
// (engine/particle_record.hpp).
#pragma once

#include <cstdint>
#include <limits>

#include "events/event.hpp"

namespace granule {

class EventQueue;

class alignas(16) EventSlot {
 public:
  // Cell ids have 28 bits: the other 4 of the word hold the event kind.  The configuration refuses
  // grids of more cells (io/input_ranges.hpp, kMaxEngineCells).
  static constexpr int kKindBits = 4;
  static constexpr std::int64_t kCellLimit = std::int64_t{1} << (32 - kKindBits);

  // The pending event's time (the queue's key; +inf: none).  EventQueue::update sets it.
  double time() const { return time_; }
  std::int32_t cell() const { return static_cast<std::int32_t>(cell_and_kind_ >> kKindBits); }
  EventKind kind() const { return static_cast<EventKind>(cell_and_kind_ & kKindMask); }
  void set_cell(std::int32_t cell) {
    cell_and_kind_ = (static_cast<std::uint32_t>(cell) << kKindBits) | (cell_and_kind_ & kKindMask);
  }
  void set_kind(EventKind kind) { cell_and_kind_ = (cell_and_kind_ & ~kKindMask) | static_cast<std::uint32_t>(kind); }

 private:
  friend class EventQueue;
  static constexpr std::uint32_t kKindMask = (1u << kKindBits) - 1;
  static_assert(kLastEventKind < (1 << kKindBits), "every event kind fits beside the cell id");

  double time_ = std::numeric_limits<double>::infinity();
  std::uint32_t cell_and_kind_ = 0;  // cell id << 4 | kind
  // Next in its bucket's list of the calendar, or its position in the current bucket's heap.
  std::int32_t link_ = -1;
};

static_assert(sizeof(EventSlot) == 16);

}  // namespace granule
