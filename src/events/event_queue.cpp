#include "events/event_queue.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>

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
  nodes_.assign(n, Node{kInf, kFirst, kUnscheduled});
  heads_.assign(std::bit_ceil(std::max<std::size_t>(16, n / 2)), kFirst);
  current_.clear();
  current_.reserve(4 * kMinimumCrowd);
  bucket_ = 0;
  buckets_per_time_ = 1.0;
  listed_ = 0;
  crowded_ = kMinimumCrowd;
}

void EventQueue::update(std::int32_t particle, double time) {
  remove(particle);
  nodes_[static_cast<std::size_t>(particle)].time = time;
  insert(particle);
  // A width too large for the present event rate (the first one is a guess): fit it again, unless
  // the bucket is full of one time, which no width can split (then not before it doubles).
  if (current_.size() > crowded_) rebuild();
}

void EventQueue::insert(std::int32_t particle) const {
  const double time = nodes_[static_cast<std::size_t>(particle)].time;
  if (time == kInf) {
    nodes_[static_cast<std::size_t>(particle)].previous = kUnscheduled;
    return;
  }
  const std::int64_t bucket = bucket_of(time);
  if (bucket < bucket_) {
    // Earlier than the current bucket (the clock stopped before the top, and events were
    // predicted afresh): the current bucket goes back to its list and this one becomes current.
    for (const std::int32_t other : current_) link(other, slot_of(bucket_));
    current_.clear();
    bucket_ = bucket;
  }
  if (bucket == bucket_) {
    push_current(particle);
  } else {
    link(particle, slot_of(bucket));
  }
}

void EventQueue::remove(std::int32_t particle) const {
  const auto i = static_cast<std::size_t>(particle);
  if (nodes_[i].previous == kUnscheduled) return;
  if (nodes_[i].previous == kCurrent) {
    erase_current(static_cast<std::size_t>(nodes_[i].next));
  } else {
    unlink(particle, slot_of(bucket_of(nodes_[i].time)));
  }
  nodes_[i].previous = kUnscheduled;
}

void EventQueue::link(std::int32_t particle, std::size_t slot) const {
  const auto i = static_cast<std::size_t>(particle);
  const std::int32_t head = heads_[slot];
  nodes_[i].next = head;
  nodes_[i].previous = kFirst;
  if (head != kFirst) nodes_[static_cast<std::size_t>(head)].previous = particle;
  heads_[slot] = particle;
  ++listed_;
}

void EventQueue::unlink(std::int32_t particle, std::size_t slot) const {
  const auto i = static_cast<std::size_t>(particle);
  const std::int32_t before = nodes_[i].previous;
  const std::int32_t after = nodes_[i].next;
  if (before == kFirst) {
    heads_[slot] = after;
  } else {
    nodes_[static_cast<std::size_t>(before)].next = after;
  }
  if (after != kFirst) nodes_[static_cast<std::size_t>(after)].previous = before;
  --listed_;
}

void EventQueue::push_current(std::int32_t particle) const {
  nodes_[static_cast<std::size_t>(particle)].previous = kCurrent;
  current_.push_back(particle);
  nodes_[static_cast<std::size_t>(particle)].next = static_cast<std::int32_t>(current_.size() - 1);
  sift_up(current_.size() - 1);
}

void EventQueue::erase_current(std::size_t position) const {
  const std::int32_t last = current_.back();
  current_.pop_back();
  if (position == current_.size()) return;
  place(position, last);
  sift_up(position);
  sift_down(static_cast<std::size_t>(nodes_[static_cast<std::size_t>(last)].next));
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
  const std::int64_t slots = static_cast<std::int64_t>(heads_.size());
  for (std::int64_t step = 0; current_.empty(); ++step) {
    if (step == slots) {
      // A whole turn of the calendar without an event: jump to the earliest bucket there is.
      std::int64_t earliest = std::numeric_limits<std::int64_t>::max();
      for (const std::int32_t head : heads_) {
        for (std::int32_t p = head; p != kFirst; p = nodes_[static_cast<std::size_t>(p)].next) {
          earliest = std::min(earliest, bucket_of(nodes_[static_cast<std::size_t>(p)].time));
        }
      }
      bucket_ = earliest - 1;
    }
    ++bucket_;
    const std::size_t slot = slot_of(bucket_);
    for (std::int32_t p = heads_[slot]; p != kFirst;) {
      const std::int32_t after = nodes_[static_cast<std::size_t>(p)].next;
      if (bucket_of(nodes_[static_cast<std::size_t>(p)].time) == bucket_) {
        unlink(p, slot);
        push_current(p);
      }
      p = after;
    }
  }
}

void EventQueue::rebuild() const {
  // The width: kEventsPerBucket events per bucket at the present density of times ahead, the
  // number of finite events over their mean distance from the earliest.
  double earliest = kInf;
  for (const Node& node : nodes_) earliest = std::min(earliest, node.time);
  double spread = 0.0;
  std::size_t finite = 0;
  for (const Node& node : nodes_) {
    if (node.time == kInf) continue;
    spread += node.time - earliest;
    ++finite;
  }
  const double mean = finite > 0 ? spread / static_cast<double>(finite) : 0.0;
  const double width = kEventsPerBucket * mean / static_cast<double>(std::max<std::size_t>(1, finite));
  if (std::isfinite(width) && width > 0.0 && std::isfinite(1.0 / width)) buckets_per_time_ = 1.0 / width;
  std::fill(heads_.begin(), heads_.end(), kFirst);
  current_.clear();
  listed_ = 0;
  bucket_ = std::isfinite(earliest) ? bucket_of(earliest) : 0;
  for (std::size_t i = 0; i < nodes_.size(); ++i) insert(static_cast<std::int32_t>(i));
  crowded_ = std::max(kMinimumCrowd, 2 * current_.size());
}

bool EventQueue::is_consistent() const {
  std::int64_t listed = 0;
  for (std::size_t slot = 0; slot < heads_.size(); ++slot) {
    std::int32_t before = kFirst;
    for (std::int32_t p = heads_[slot]; p != kFirst; p = nodes_[static_cast<std::size_t>(p)].next) {
      const auto i = static_cast<std::size_t>(p);
      if (i >= nodes_.size() || nodes_[i].previous != before || slot_of(bucket_of(nodes_[i].time)) != slot || !(bucket_of(nodes_[i].time) > bucket_)) return false;
      if (++listed > static_cast<std::int64_t>(nodes_.size())) return false;
      before = p;
    }
  }
  if (listed != listed_) return false;
  for (std::size_t k = 0; k < current_.size(); ++k) {
    const auto i = static_cast<std::size_t>(current_[k]);
    if (i >= nodes_.size() || nodes_[i].previous != kCurrent || nodes_[i].next != static_cast<std::int32_t>(k) || bucket_of(nodes_[i].time) != bucket_) return false;
    if (k > 0 && earlier(current_[k], current_[(k - 1) / 2])) return false;
  }
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if ((nodes_[i].time == kInf) != (nodes_[i].previous == kUnscheduled)) return false;
  }
  return true;
}

void EventQueue::shift_times(double delta) {
  for (Node& node : nodes_) node.time -= delta;
  rebuild();
}

void EventQueue::save(StateArchive& archive, const std::string& prefix) const {
  archive.put_generated<double>(prefix + "time", nodes_.size(), [this](std::size_t first, std::span<double> out) {
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = nodes_[first + k].time;
  });
}

void EventQueue::restore(const StateArchive& archive, const std::string& prefix, std::int32_t particles) {
  const auto& times = archive.get<double>(prefix + "time");
  if (times.size() != static_cast<std::size_t>(particles)) throw std::runtime_error("checkpoint event queue has the wrong size");
  if (std::any_of(times.begin(), times.end(), [](double t) { return std::isnan(t); })) {
    throw std::runtime_error("checkpoint event queue has a time that is not a number");
  }
  reset(particles);
  for (std::size_t i = 0; i < times.size(); ++i) nodes_[i].time = times[i];
  rebuild();
}

}  // namespace granule
