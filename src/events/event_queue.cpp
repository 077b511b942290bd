#include "events/event_queue.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <vector>

namespace granule {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
// Bucket numbers are clamped here, so that any double has one (far times share the extreme
// buckets, where the current bucket's heap still orders them).
constexpr double kBucketLimit = 4.0e18;
// About this many events per bucket near the front (4 ran level with 8 or faster, 2 and 16 took
// more instructions: docs/performance.md); with a slot for every second particle the calendar
// then reaches about two mean delays ahead, and later events wait in their slot for a later turn.
constexpr double kEventsPerBucket = 4.0;
constexpr std::size_t kMinimumCrowd = 64;
// A year of lists is this many chunks (a power of two); the lists hold the chunks from the current
// bucket's on, so that a list holds one bucket's events.
constexpr int kChunksPerYear = 8;
// The ring of far chunks reaches about this many mean delays ahead; the rare events beyond it
// wait in the overflow.
constexpr std::size_t kRingMeanDelays = 32;
// Slots fetched this many entries ahead while a chunk is taken into the lists.
constexpr std::size_t kTakeAhead = 16;
}  // namespace

std::int64_t EventQueue::bucket_of(double time) const {
  const double q = std::floor(time * buckets_per_time_);
  if (!(q < kBucketLimit)) return static_cast<std::int64_t>(kBucketLimit);
  if (!(q > -kBucketLimit)) return -static_cast<std::int64_t>(kBucketLimit);
  return static_cast<std::int64_t>(q);
}

void EventQueue::reset(std::int32_t particles, std::size_t most_lists) {
  const auto n = static_cast<std::size_t>(particles);
  slots_.assign(n, EventSlot{});
  const std::size_t lists = std::bit_ceil(std::max<std::size_t>(16, n / 2));
  heads_.assign(std::min(lists, std::max<std::size_t>(16, std::bit_floor(most_lists))), kEnd);
  chunk_shift_ = std::countr_zero(heads_.size()) - std::countr_zero(static_cast<unsigned>(kChunksPerYear));
  // Uncapped, the lists reach two mean delays ahead or more, and the few later events wait in
  // their list for a later turn (4 bytes per particle less than a pool for every one).  A year
  // spans about 4·lists/N mean delays (kEventsPerBucket events per bucket), a chunk an eighth.
  keeps_far_ = heads_.size() < lists;
  far_.reset(keeps_far_ ? n : 0, keeps_far_ ? std::bit_ceil(std::max<std::size_t>(64, 2 * kRingMeanDelays * n / heads_.size())) : 1);
  far_events_ = 0;
  far_from_ = keeps_far_ ? kChunksPerYear : kNever;
  current_.clear();
  current_.reserve(4 * kMinimumCrowd);
  bucket_ = 0;
  buckets_per_time_ = 1.0;
  listed_ = 0;
  crowded_ = kMinimumCrowd;
  ahead_bucket_ = kNoBucket;
}

void EventQueue::update(std::int32_t particle, double time) {
  remove(particle);
  mutable_slot(particle).time_ = time;
  insert(particle);
  // A width too large for the present event rate (the first one is a guess): fit it again, unless
  // the bucket is full of one time, which no width can split (then not before it doubles).
  if (current_.size() > crowded_) rebuild();
}

void EventQueue::insert(std::int32_t particle) const {
  const double time = slot(particle).time_;
  if (time == kInf) return;
  const std::int64_t bucket = bucket_of(time);
  if (bucket < bucket_) {
    // Earlier than the current bucket (the clock stopped before the top, and events were
    // predicted afresh): the current bucket goes back to its list and this one becomes current.
    for (const std::int32_t other : current_) link(other, list_of(bucket_));
    current_.clear();
    bucket_ = bucket;
  }
  if (bucket == bucket_) {
    push_current(particle);
  } else if (const std::int64_t chunk = chunk_of(bucket); chunk < far_from_) {
    link(particle, list_of(bucket));
  } else {
    file_far(particle, chunk);
    ++far_events_;
  }
}

// A particle is in the current bucket's heap exactly when its time falls in the current bucket,
// and in a bucket list when it falls in a later one (insert and settle keep it so).
void EventQueue::remove(std::int32_t particle) const {
  const double time = slot(particle).time_;
  if (time == kInf) return;
  const std::int64_t bucket = bucket_of(time);
  if (bucket == bucket_) {
    erase_current(static_cast<std::size_t>(slot(particle).link_));
  } else if (const std::int64_t chunk = chunk_of(bucket); chunk < far_from_) {
    unlink(particle, list_of(bucket));
  } else {
    const std::int32_t entry = slot(particle).link_;
    const std::int32_t moved = far_.remove(chunk, entry, far_from_);
    if (moved >= 0) mutable_slot(moved).link_ = entry;
    --far_events_;
  }
}

void EventQueue::link(std::int32_t particle, std::size_t list) const {
  mutable_slot(particle).link_ = heads_[list];
  heads_[list] = particle;
  ++listed_;
}

void EventQueue::unlink(std::int32_t particle, std::size_t list) const {
  std::int32_t* link = &heads_[list];
  while (*link != particle) link = &mutable_slot(*link).link_;
  *link = slot(particle).link_;
  --listed_;
}

void EventQueue::push_current(std::int32_t particle) const {
  current_.push_back(particle);
  mutable_slot(particle).link_ = static_cast<std::int32_t>(current_.size() - 1);
  sift_up(current_.size() - 1);
}

void EventQueue::erase_current(std::size_t position) const {
  const std::int32_t last = current_.back();
  current_.pop_back();
  if (position == current_.size()) return;
  place(position, last);
  sift_up(position);
  sift_down(static_cast<std::size_t>(slot(last).link_));
}

void EventQueue::sift_up(std::size_t position) const {
  const std::int32_t moving = current_[position];
  while (position > 0) {
    const std::size_t parent = (position - 1) / 2;
    if (!earlier(moving, current_[parent])) break;
    place(position, current_[parent]);
    position = parent;
  }
  place(position, moving);
}

void EventQueue::sift_down(std::size_t position) const {
  const std::int32_t moving = current_[position];
  const std::size_t size = current_.size();
  while (true) {
    std::size_t child = 2 * position + 1;
    if (child >= size) break;
    if (child + 1 < size && earlier(current_[child + 1], current_[child])) ++child;
    if (!earlier(current_[child], moving)) break;
    place(position, current_[child]);
    position = child;
  }
  place(position, moving);
}

void EventQueue::settle() const {
  if (!current_.empty()) return;
  if (listed_ == 0) {
    if (far_events_ == 0) return;
    // Nothing in the lists: the chunks up to the next with an event come near, and the calendar
    // moves to the first bucket of the earliest.
    while (listed_ == 0 && current_.empty()) {
      // One chunk more; past the overflow's earliest when the ring is empty.
      const std::int64_t after_overflow = far_.ring_entries() > 0 ? far_from_ : far_.overflow_first();
      bring_near(std::max(far_from_, after_overflow) + 1);
    }
    if (current_.empty()) bucket_ = std::max(bucket_, ((far_from_ - 1) << chunk_shift_) - 1);
  }
  const std::int64_t lists = static_cast<std::int64_t>(heads_.size());
  for (std::int64_t step = 0; current_.empty(); ++step) {
    if (step == lists) {
      // A whole turn of the calendar without an event: jump to the earliest bucket there is.
      std::int64_t earliest = std::numeric_limits<std::int64_t>::max();
      for (const std::int32_t head : heads_) {
        for (std::int32_t p = head; p != kEnd; p = slot(p).link_) earliest = std::min(earliest, bucket_of(slot(p).time_));
      }
      bucket_ = earliest - 1;
    }
    ++bucket_;
    bring_near(chunk_of(bucket_) + kChunksPerYear);
    // Move this bucket's events from its list to the heap, unlinking them on the way.
    std::int32_t* link = &heads_[list_of(bucket_)];
    while (*link != kEnd) {
      const std::int32_t p = *link;
      if (bucket_of(slot(p).time_) == bucket_) {
        *link = slot(p).link_;
        --listed_;
        push_current(p);
      } else {
        link = &mutable_slot(p).link_;
      }
    }
  }
}

void EventQueue::bring_near(std::int64_t target) const {
  while (far_from_ < target) {
    if (far_.ring_entries() == 0) {
      // The ring's chunks are empty: on to the target, or to the earliest chunk of the overflow.
      far_from_ = std::max(far_from_, std::min(target, far_.overflow_first()));
      refile_overflow();
      continue;
    }
    take_chunk();
  }
}

void EventQueue::take_chunk() const {
  const std::int64_t chunk = far_from_++;
  far_.drain(chunk, [this](std::span<const std::int32_t> entries) {
    // The slots are anywhere in memory: fetched many at once, where one at a time would wait.
    for (const std::int32_t p : entries.first(std::min(entries.size(), kTakeAhead))) __builtin_prefetch(slots_.data() + p);
    for (std::size_t k = 0; k < entries.size(); ++k) {
      if (k + kTakeAhead < entries.size()) __builtin_prefetch(slots_.data() + entries[k + kTakeAhead]);
      --far_events_;
      insert(entries[k]);  // the chunk is near now: to the current bucket or to a list
    }
  });
  refile_overflow();
}

void EventQueue::refile_overflow() const {
  if (far_.overflow_first() == FarChunks::kNone || !far_.in_ring(far_.overflow_first(), far_from_)) return;
  far_.drain_overflow([this](std::span<const std::int32_t> entries) {
    for (const std::int32_t p : entries) file_far(p, chunk_of(bucket_of(slot(p).time_)));
  });
}

void EventQueue::rebuild() const {
  // The width: kEventsPerBucket events per bucket at the present density of times ahead, the
  // number of finite events over their mean distance from the earliest.
  double earliest = kInf;
  for (const EventSlot& s : slots_) earliest = std::min(earliest, s.time_);
  double spread = 0.0;
  std::size_t finite = 0;
  for (const EventSlot& s : slots_) {
    if (s.time_ == kInf) continue;
    spread += s.time_ - earliest;
    ++finite;
  }
  const double mean = finite > 0 ? spread / static_cast<double>(finite) : 0.0;
  const double width = kEventsPerBucket * mean / static_cast<double>(std::max<std::size_t>(1, finite));
  if (std::isfinite(width) && width > 0.0 && std::isfinite(1.0 / width)) buckets_per_time_ = 1.0 / width;
  std::fill(heads_.begin(), heads_.end(), kEnd);
  current_.clear();
  listed_ = 0;
  bucket_ = std::isfinite(earliest) ? bucket_of(earliest) : 0;
  far_.clear();
  far_events_ = 0;
  if (keeps_far_) far_from_ = chunk_of(bucket_) + kChunksPerYear;
  for (std::size_t i = 0; i < slots_.size(); ++i) insert(static_cast<std::int32_t>(i));
  crowded_ = std::max(kMinimumCrowd, 2 * current_.size());
  ahead_bucket_ = kNoBucket;  // the lists are new: the walk starts again at a head
}

bool EventQueue::is_consistent() const {
  // Each particle with a finite time is met once: in its bucket's list, in the heap, or far; no
  // other is.
  std::vector<char> met(slots_.size(), 0);
  const auto meet = [&](std::int32_t p) {
    return p >= 0 && static_cast<std::size_t>(p) < slots_.size() && slot(p).time_ != kInf && met[static_cast<std::size_t>(p)]++ == 0;
  };
  std::int64_t listed = 0;
  for (std::size_t list = 0; list < heads_.size(); ++list) {
    for (std::int32_t p = heads_[list]; p != kEnd; p = slot(p).link_) {
      if (!meet(p)) return false;
      ++listed;
      const std::int64_t bucket = bucket_of(slot(p).time_);
      if (list_of(bucket) != list || !(bucket > bucket_) || chunk_of(bucket) >= far_from_) return false;
    }
  }
  if (listed != listed_) return false;
  for (std::size_t k = 0; k < current_.size(); ++k) {
    const std::int32_t p = current_[k];
    if (!meet(p) || slot(p).link_ != static_cast<std::int32_t>(k) || bucket_of(slot(p).time_) != bucket_) return false;
    if (k > 0 && earlier(p, current_[(k - 1) / 2])) return false;
  }
  // A far event is in the ring's bag of its chunk, or in the overflow when the ring does not
  // reach its chunk, at the entry its link names.
  const auto ring = static_cast<std::int64_t>(far_.ring_chunks());
  std::int64_t far = 0;
  bool filed_right = true;
  const auto check_bag = [&](std::int64_t bag) {
    far_.for_each(bag, [&](std::int32_t entry) {
      const std::int32_t p = far_.particle_at(entry);
      ++far;
      if (!meet(p) || slot(p).link_ != entry) {
        filed_right = false;
        return;
      }
      const std::int64_t chunk = chunk_of(bucket_of(slot(p).time_));
      if (bag == FarChunks::kNone ? chunk < far_from_ + ring || chunk < far_.overflow_first() : chunk != bag) filed_right = false;
    });
  };
  if (keeps_far_) {
    for (std::int64_t chunk = far_from_; chunk < far_from_ + ring; ++chunk) check_bag(chunk);
    if (far != far_.ring_entries()) return false;
    check_bag(FarChunks::kNone);
  }
  if (!filed_right || far != far_events_) return false;
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    if ((slots_[i].time_ != kInf) != (met[i] == 1)) return false;
  }
  return true;
}

void EventQueue::shift_times(double delta) {
  for (EventSlot& s : slots_) s.time_ -= delta;
  rebuild();
}

void EventQueue::save(StateArchive& archive, const std::string& prefix) const {
  archive.put_generated<double>(prefix + "time", slots_.size(), [this](std::size_t first, std::span<double> out) {
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = slots_[first + k].time_;
  });
}

void EventQueue::restore(const StateArchive& archive, const std::string& prefix) {
  const auto& times = archive.get<double>(prefix + "time");
  if (times.size() != slots_.size()) throw std::runtime_error("checkpoint event queue has the wrong size");
  if (std::any_of(times.begin(), times.end(), [](double t) { return std::isnan(t); })) {
    throw std::runtime_error("checkpoint event queue has a time that is not a number");
  }
  for (std::size_t i = 0; i < times.size(); ++i) slots_[i].time_ = times[i];
  rebuild();
}

}  // namespace granule
