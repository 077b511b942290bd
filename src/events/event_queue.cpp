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
}  // namespace

std::int64_t EventQueue::bucket_of(double time) const {
  const double q = std::floor(time * buckets_per_time_);
  if (!(q < kBucketLimit)) return static_cast<std::int64_t>(kBucketLimit);
  if (!(q > -kBucketLimit)) return -static_cast<std::int64_t>(kBucketLimit);
  return static_cast<std::int64_t>(q);
}

void EventQueue::reset(std::int32_t particles) {
  const auto n = static_cast<std::size_t>(particles);
  slots_.assign(n, EventSlot{});
  heads_.assign(std::bit_ceil(std::max<std::size_t>(16, n / 2)), kEnd);
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
  } else {
    link(particle, list_of(bucket));
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
  } else {
    unlink(particle, list_of(bucket));
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
  if (!current_.empty() || listed_ == 0) return;
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
  for (std::size_t i = 0; i < slots_.size(); ++i) insert(static_cast<std::int32_t>(i));
  crowded_ = std::max(kMinimumCrowd, 2 * current_.size());
  ahead_bucket_ = kNoBucket;  // the lists are new: the walk starts again at a head
}

bool EventQueue::is_consistent() const {
  // Each particle with a finite time is met once, in its bucket's list or in the heap; no other is.
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
      if (list_of(bucket) != list || !(bucket > bucket_)) return false;
    }
  }
  if (listed != listed_) return false;
  for (std::size_t k = 0; k < current_.size(); ++k) {
    const std::int32_t p = current_[k];
    if (!meet(p) || slot(p).link_ != static_cast<std::int32_t>(k) || bucket_of(slot(p).time_) != bucket_) return false;
    if (k > 0 && earlier(p, current_[(k - 1) / 2])) return false;
  }
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
