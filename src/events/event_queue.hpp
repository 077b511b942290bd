// The pending event of every particle, ordered by (time, particle id): a calendar of time
// buckets (Brown 1988; Smallenburg, Eur. Phys. J. E 45, 22 (2022), keeps his events so), with the
// events of the current bucket in a small binary heap.  Re-scheduling a particle is O(1) expected,
// where a binary heap of every particle costs O(log N) cache misses (a quarter of the run time at
// N = 10⁵: docs/performance.md).
//
// The calendar's lists cover one year ahead of the current bucket, and there are at most
// kMostLists of them, so that their heads stay in the cache; events beyond the year wait unsorted
// in FarChunks (Paul's overflow, J. Comput. Phys. 221, 615 (2007)), filed by chunks of an eighth
// of a year, and are linked into the lists a chunk at a time, seven chunks before the current
// bucket reaches them.
//
// The queue holds each particle's EventSlot: its time and link are the queue's, the rest is the
// engine's, so that an event touches one slot.  Bucket lists are singly linked: a list holds about
// two events, and the walk to a particle's predecessor costs about what a back link's update does
// (measured again at 10⁶ disks: level at ν = 0.5, slower at ν = 0.05; docs/performance.md), without
// its 4 bytes.  Where a particle is (no event, the current bucket, a bucket list) follows
// from its time, the current bucket and the first far chunk; a far event's link is its entry there.
//
// Ties are broken by the particle's user id (set_tie_order: the engine renumbers its particles
// along the cells, and the order of pops must not follow), so the order of pops is a function of
// the times and those ids alone: not of the bucket width, of the calendar's layout, of the order
// of the updates or of the engine's numbering.  The width is
// therefore re-tuned freely (at every re-base, and when the current bucket grows too full), and a
// checkpoint holds only the times.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "archive/state_archive.hpp"
#include "events/event_slot.hpp"
#include "events/far_chunks.hpp"
#include "memory/huge_page_allocator.hpp"

namespace granule {

class EventQueue {
 public:
  // At most this many calendar lists by default: 256 KiB of heads, which stay cached, where a head
  // per two particles was 33.5 MB at 10⁷ and a cache miss at every re-scheduling (2¹⁶ ran 1.05×
  // and 1.07× as fast as 2¹⁸ at 10⁷ and 10⁶: docs/performance.md).
  static constexpr std::size_t kMostLists = std::size_t{1} << 16;

  // All particles present, at time +inf, with default slots; a list per two particles, at least
  // 16 and at most `most_lists` (a power of two).
  void reset(std::int32_t particles, std::size_t most_lists = kMostLists);
  // A particle's slot: the engine's fields are free to change; the time changes through update().
  EventSlot& slot(std::int32_t particle) { return slots_[static_cast<std::size_t>(particle)]; }
  const EventSlot& slot(std::int32_t particle) const { return slots_[static_cast<std::size_t>(particle)]; }
  std::span<EventSlot> slots() { return slots_; }
  std::span<const EventSlot> slots() const { return slots_; }
  // Set a particle's event time (any non-NaN double; +inf: nothing pending).
  void update(std::int32_t particle, double time);
  // The ids that order equal times, one per particle, owned by the caller and kept alive and in
  // place while the queue is used (empty: the particle's own number).
  void set_tie_order(std::span<const std::int32_t> ids) { tie_order_ = ids; }
  // After the caller moved whole slots between particles (EventQueue::slots()), with their times:
  // the calendar is laid out afresh from the times.
  void relink() { rebuild(); }
  // The particle whose event comes first (the one with the lowest tie id of a tie; particle 0
  // when every time is +inf), and its time.
  std::int32_t top() const {
    settle();
    return current_.empty() ? 0 : current_.front();
  }
  double top_time() const { return slot(top()).time_; }
  double time_of(std::int32_t particle) const { return slot(particle).time_; }
  // A hint, no change of state: start fetching the slot `depth` steps down the list that
  // re-scheduling `particle` will walk (the partner of a collision leaves its list while the
  // other's prediction runs; the walk is a chain of cache misses otherwise).  The steps before it
  // are read: call with depth 1, then 2 once that slot has had time to arrive.
  void prefetch_removal(std::int32_t particle, int depth = 1) const {
    const double time = slot(particle).time_;
    if (time == std::numeric_limits<double>::infinity()) return;
    const std::int64_t bucket = bucket_of(time);
    if (bucket == bucket_ || chunk_of(bucket) >= far_from_) return;
    std::int32_t p = heads_[list_of(bucket)];
    for (int step = 1; step < depth && p != kEnd && p != particle; ++step) p = slot(p).link_;
    if (p != kEnd && p != particle) __builtin_prefetch(slots_.data() + p);
  }
  // A hint for the caller's prefetches: the particle whose event likely comes after the top's
  // (the earlier child of the current bucket's root; -1 when the current bucket holds only the
  // top, whose successor is then in a list not yet read: see earliest_walked()).
  std::int32_t runner_up() const {
    if (current_.size() < 2) return -1;
    if (current_.size() == 2 || earlier(current_[1], current_[2])) return current_[1];
    return current_[2];
  }
  // The hint when runner_up() has none (a quarter of the events of a dilute gas): the earliest
  // event of the next bucket among the slots of its list that prefetch_ahead() has fetched, so
  // that this look-up reads cached slots only (-1: none yet).  A list changed since the walk may
  // not lead to ahead_ any more, hence a few steps at most.
  std::int32_t earliest_walked() const {
    if (ahead_bucket_ != bucket_ + 1) return -1;
    constexpr int kMostSteps = 8;
    std::int32_t best = -1;
    std::int32_t p = heads_[list_of(ahead_bucket_)];
    for (int step = 0; step < kMostSteps && p != ahead_ && p != kEnd; ++step, p = slot(p).link_) {
      if (bucket_of(slot(p).time_) == ahead_bucket_ && (best < 0 || earlier(p, best))) best = p;
    }
    return best;
  }
  // Whether a particle's event lies in the bucket after the current one (prefetch_ahead's reads).
  bool in_next_bucket(std::int32_t particle) const { return bucket_of(slot(particle).time_) == bucket_ + 1; }
  // A hint, no change of the order: walk the list of the bucket after the current one a step
  // further and prefetch the slot reached, so that settle() finds the list in cache.  Its walk is a
  // chain of cache misses (a fifth of the run time at N = 10⁶ was settle's); called once per
  // event, the chain is followed while the current bucket's events run.  A list that changed under
  // the walk only makes the hint a poor one: any link is a particle id or a heap position.
  // Returns the particle whose slot the step read (fetched at the last call; -1: none): if its
  // event is still in the next bucket (in_next_bucket), the caller may start fetching what that
  // event will read.
  std::int32_t prefetch_ahead() const {
    const std::int64_t next = bucket_ + 1;
    std::int32_t p = kEnd;
    std::int32_t read = -1;
    if (ahead_bucket_ != next) {
      ahead_bucket_ = next;
      p = heads_[list_of(next)];
    } else if (ahead_ != kEnd) {
      read = ahead_;
      p = slot(ahead_).link_;
    }
    if (static_cast<std::uint32_t>(p) >= slots_.size()) p = kEnd;
    ahead_ = p;
    if (p != kEnd) __builtin_prefetch(slots_.data() + p);
    return read;
  }
  // Every particle is where its time says and the current bucket is in heap order (the
  // GRANULE_PARANOID build checks it at every re-base).
  bool is_consistent() const;
  // Subtract the same amount from every event time (clock re-basing); order is preserved.
  void shift_times(double delta);
  void save(StateArchive& archive, const std::string& prefix) const;
  // The times saved by save(), into the slots of a queue reset() to the same number of particles
  // (whose other fields the engine restores).
  void restore(const StateArchive& archive, const std::string& prefix);
  std::size_t bytes() const {
    return slots_.capacity() * sizeof(EventSlot) +
           (heads_.capacity() + current_.capacity()) * sizeof(std::int32_t) + far_.bytes();
  }

 private:
  static constexpr std::int32_t kEnd = -1;  // the end of a bucket list
  static constexpr std::int64_t kNoBucket = std::numeric_limits<std::int64_t>::min();
  static constexpr std::int64_t kNever = std::numeric_limits<std::int64_t>::max();  // no chunk is far

  std::int64_t bucket_of(double time) const;
  std::size_t list_of(std::int64_t bucket) const { return static_cast<std::size_t>(bucket) & (heads_.size() - 1); }
  std::int64_t chunk_of(std::int64_t bucket) const { return bucket >> chunk_shift_; }
  bool earlier(std::int32_t a, std::int32_t b) const {
    const double ta = slot(a).time_;
    const double tb = slot(b).time_;
    return ta < tb || (ta == tb && tie_id(a) < tie_id(b));
  }
  std::int32_t tie_id(std::int32_t particle) const {
    return tie_order_.empty() ? particle : tie_order_[static_cast<std::size_t>(particle)];
  }
  void insert(std::int32_t particle) const;
  void remove(std::int32_t particle) const;
  void link(std::int32_t particle, std::size_t list) const;
  void unlink(std::int32_t particle, std::size_t list) const;
  EventSlot& mutable_slot(std::int32_t particle) const { return slots_[static_cast<std::size_t>(particle)]; }
  void push_current(std::int32_t particle) const;
  void erase_current(std::size_t position) const;
  void sift_up(std::size_t position) const;
  void sift_down(std::size_t position) const;
  void place(std::size_t position, std::int32_t particle) const {
    current_[position] = particle;
    mutable_slot(particle).link_ = static_cast<std::int32_t>(position);
  }
  // Make the current bucket the earliest non-empty one (the calendar moves lazily, when the top
  // is asked for, so that updates at times before a jump never meet a calendar ahead of them).
  void settle() const;
  // Make every chunk before `target` near (far_from_ = target), taking each one's far events into
  // the lists; chunks with nothing in them are skipped at once.
  void bring_near(std::int64_t target) const;
  // The chunk far_from_: its events into the lists (or the current bucket).
  void take_chunk() const;
  // The overflow's events filed again, into the ring where it now reaches them.
  void refile_overflow() const;
  void file_far(std::int32_t particle, std::int64_t chunk) const {
    mutable_slot(particle).link_ = far_.file(chunk, particle, far_from_);
  }
  // Re-distribute every event with a bucket width fitted to the present spread of times.
  void rebuild() const;

  // The calendar's state changes when the top is looked up (settle), which the engine does in its
  // const queries: it is mutable, the order it gives is not (only the links change there).
  mutable HugePageVector<EventSlot> slots_;
  mutable HugePageVector<std::int32_t> heads_;     // bucket lists, 2^k of them; bucket b in list b mod 2^k
  mutable std::vector<std::int32_t> current_;   // the current bucket: a binary heap by (time, id)
  mutable std::int64_t bucket_ = 0;             // the current bucket
  // The inverse of a bucket's width in time: a product where a quotient took ~14 cycles of latency
  // per event.  Any monotonic map of times to buckets gives the same order of pops.
  mutable double buckets_per_time_ = 1.0;
  mutable std::int64_t listed_ = 0;             // events in bucket lists
  mutable FarChunks far_;                       // the events of chunks from far_from_ on
  bool keeps_far_ = false;                      // whether the lists are capped and far_ used
  mutable std::int64_t far_from_ = kNever;      // the first chunk not in the lists
  mutable std::int64_t far_events_ = 0;         // events in far_
  int chunk_shift_ = 1;                         // a chunk is 2^chunk_shift_ buckets
  mutable std::size_t crowded_ = 0;             // current_'s size that asks for a new width
  mutable std::int64_t ahead_bucket_ = kNoBucket;  // the bucket whose list prefetch_ahead() walks
  mutable std::int32_t ahead_ = kEnd;           // and the last slot it prefetched there
  std::span<const std::int32_t> tie_order_;
};

}  // namespace granule
