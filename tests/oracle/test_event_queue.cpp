// Oracle tier: the event queue (src/events/event_queue.hpp, a calendar of buckets) against a sorted
// reference.
//
// The queue holds one time per particle and never removes anyone: the engine "pops" by reading the
// top and re-scheduling that particle.  The reference is an ordered multiset of (time, particle)
// pairs beside a plain array of each particle's time.  After every operation the queue's top must
// be the reference's first pair, the lowest id of a tie (the queue's order is a function of the
// times alone); at intervals every particle's time_of() is compared.  The engine only stores
// times ≥ now or +inf, but the class promises order for any non-NaN double, so the random times
// include −inf, ±0, denormals, exact ties from a small pool, huge values and repeated moves of one
// particle up and down; shift_times() is applied with the same subtraction in the reference (IEEE
// subtraction is monotone, so a ≤ b still gives a − d ≤ b − d and order must survive).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <set>
#include <utility>
#include <vector>

#include "events/event_queue.hpp"
#include "init/random.hpp"

namespace granule {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDenormal = std::numeric_limits<double>::denorm_min();

class ReferenceQueue {
 public:
  void reset(std::int32_t particles) {
    times_.assign(static_cast<std::size_t>(particles), kInf);
    ordered_.clear();
    for (std::int32_t i = 0; i < particles; ++i) ordered_.insert({kInf, i});
  }
  void update(std::int32_t particle, double time) {
    double& slot = times_[static_cast<std::size_t>(particle)];
    ordered_.erase(ordered_.find({slot, particle}));
    slot = time;
    ordered_.insert({time, particle});
  }
  void shift_times(double delta) {
    ordered_.clear();
    for (std::size_t i = 0; i < times_.size(); ++i) {
      times_[i] -= delta;
      ordered_.insert({times_[i], static_cast<std::int32_t>(i)});
    }
  }
  double smallest() const { return ordered_.begin()->first; }
  std::int32_t first_particle() const { return ordered_.begin()->second; }
  bool smallest_is_tied() const { return size() > 1 && std::next(ordered_.begin())->first == smallest(); }
  double time_of(std::int32_t particle) const { return times_[static_cast<std::size_t>(particle)]; }
  std::int32_t size() const { return static_cast<std::int32_t>(times_.size()); }

 private:
  std::vector<double> times_;
  std::multiset<std::pair<double, std::int32_t>> ordered_;
};

// Random event times of every kind the class must order.
class TimeSource {
 public:
  explicit TimeSource(std::uint64_t seed) : random_(seed) {
    // A small pool of values drawn again and again: exact ties between many particles.
    for (double& t : pool_) t = static_cast<double>(random_.below(1000)) * 0.125;
  }
  double any() {
    switch (random_.below(10)) {
      case 0: return kInf;
      case 1: return pool_[random_.below(pool_.size())];
      case 2: return static_cast<double>(random_.below(4)) * kDenormal;  // 0, and the three smallest denormals
      case 3: return -static_cast<double>(random_.below(3)) * kDenormal;  // −0 and negative denormals
      case 4: return random_.below(50) == 0 ? -kInf : -1e3 * random_.uniform();
      case 5: return 1e300 * random_.uniform();
      default: return 1e3 * random_.uniform();
    }
  }
  // The engine's case: now + a delay, or +inf when nothing lies ahead.
  double after(double now) { return random_.below(20) == 0 ? kInf : now + 10.0 * random_.uniform(); }
  Random& random() { return random_; }

 private:
  Random random_;
  std::array<double, 8> pool_{};
};

struct RunFigures {
  std::int64_t operations = 0, pops = 0, ties_at_top = 0, shifts = 0;
  std::vector<std::int32_t> tops;  // the queue's top after every operation (for determinism)
};

// Applies `operations` random operations to a queue of `particles` (with at most `most_lists`
// calendar lists), checking it against the reference after each; records the sequence of tops.
RunFigures exercise(std::int32_t particles, std::uint64_t seed, std::int64_t operations,
                    std::size_t most_lists = EventQueue::kMostLists) {
  EventQueue queue;
  ReferenceQueue reference;
  TimeSource times(seed);
  Random& random = times.random();
  queue.reset(particles, most_lists);
  reference.reset(particles);
  RunFigures figures;
  for (std::int64_t op = 0; op < operations; ++op) {
    const std::uint64_t choice = random.below(1000);
    if (choice < 400) {  // pop: the engine re-schedules the top particle at or after the top time
      const std::int32_t p = queue.top();
      const double now = queue.top_time();
      const double t = std::isfinite(now) ? times.after(now) : times.any();
      queue.update(p, t);
      reference.update(p, t);
      ++figures.pops;
    } else if (choice < 800) {  // any particle to any time
      const auto p = static_cast<std::int32_t>(random.below(static_cast<std::uint64_t>(particles)));
      const double t = times.any();
      queue.update(p, t);
      reference.update(p, t);
    } else if (choice < 990) {  // one particle moved up and down repeatedly
      const auto p = static_cast<std::int32_t>(random.below(static_cast<std::uint64_t>(particles)));
      for (int k = 0; k < 6; ++k) {
        const double t = k % 2 == 0 ? times.any() : reference.time_of(p) - 1.0;
        queue.update(p, t);
        reference.update(p, t);
      }
    } else if (choice < 999) {  // clock re-base: by the top time when finite (as the engine), else at random
      const double top = queue.top_time();
      const double delta = std::isfinite(top) ? top : 1e3 * random.uniform();
      queue.shift_times(delta);
      reference.shift_times(delta);
      ++figures.shifts;
    } else {
      queue.reset(particles, most_lists);
      reference.reset(particles);
    }
    ++figures.operations;
    const std::int32_t top = queue.top();
    figures.tops.push_back(top);
    const double smallest = reference.smallest();
    // Compare by value: −0 and +0 are the same time, and a tie may put either particle on top.
    EXPECT_EQ(queue.top_time(), smallest) << "operation " << op;
    EXPECT_EQ(top, reference.first_particle()) << "operation " << op << ": top " << top;
    if (reference.smallest_is_tied()) ++figures.ties_at_top;
    if (op % 997 == 0 || op + 1 == operations) {
      for (std::int32_t i = 0; i < particles; ++i) EXPECT_EQ(queue.time_of(i), reference.time_of(i)) << "particle " << i << " op " << op;
      EXPECT_TRUE(queue.is_consistent()) << "op " << op;
    }
    if (::testing::Test::HasFailure()) break;  // one failure explains itself; do not flood the log
  }
  return figures;
}

TEST(EventQueueOracle, EveryTopMatchesTheSortedReference) {
  struct Case {
    std::int32_t particles;
    std::uint64_t seed;
  };
  for (const Case c : {Case{1, 1}, Case{2, 2}, Case{7, 3}, Case{64, 4}, Case{1000, 5}, Case{4096, 6}}) {
    const RunFigures f = exercise(c.particles, c.seed, 120000);
    std::printf("N = %4d seed %llu: %lld operations (%lld pops, %lld shifts), %lld tops tied with another particle\n",
                c.particles, static_cast<unsigned long long>(c.seed), static_cast<long long>(f.operations),
                static_cast<long long>(f.pops), static_cast<long long>(f.shifts), static_cast<long long>(f.ties_at_top));
    ASSERT_FALSE(HasFailure()) << "N = " << c.particles << " seed " << c.seed;
    if (c.particles > 2) {
      EXPECT_GT(f.ties_at_top, 100) << "the ties were not exercised";
    }
  }
}

// With the calendar's lists capped far below one per two particles (as at 10⁷ particles, where
// they are capped at EventQueue::kMostLists), most events wait in the far chunks, and the order
// must not change.
TEST(EventQueueOracle, EveryTopMatchesTheReferenceWithFewLists) {
  for (const std::int32_t particles : {100, 1000, 4096}) {
    const RunFigures f = exercise(particles, 20 + static_cast<std::uint64_t>(particles), 120000, 16);
    ASSERT_FALSE(HasFailure()) << "N = " << particles;
    EXPECT_GT(f.ties_at_top, 100) << "the ties were not exercised";
  }
}

// The engine's regime with capped lists: pops re-scheduled an exponential delay ahead, partners
// re-scheduled at random, a few events a hundred mean delays ahead (beyond the ring of far
// chunks, in the overflow) while the ring stays busy, and re-bases; the top is checked after every
// operation.
TEST(EventQueueOracle, EngineRegimeWithFewLists) {
  constexpr std::int32_t kParticles = 4000;
  constexpr std::int64_t kOperations = 300000;
  Random random(31);
  EventQueue queue;
  ReferenceQueue reference;
  queue.reset(kParticles, 64);
  reference.reset(kParticles);
  const auto delay = [&] { return -std::log(1.0 - random.uniform()) * (random.below(100) == 0 ? 100.0 : 1.0); };
  for (std::int32_t i = 0; i < kParticles; ++i) {
    const double t = delay();
    queue.update(i, t);
    reference.update(i, t);
  }
  for (std::int64_t op = 0; op < kOperations; ++op) {
    const double now = queue.top_time();
    const std::int32_t p = random.below(10) < 7 ? queue.top() : static_cast<std::int32_t>(random.below(kParticles));
    const double t = now + delay();
    queue.update(p, t);
    reference.update(p, t);
    if (op % 50000 == 49999) {
      queue.shift_times(queue.top_time());
      reference.shift_times(reference.smallest());
    }
    ASSERT_EQ(queue.top_time(), reference.smallest()) << "operation " << op;
    ASSERT_EQ(queue.top(), reference.first_particle()) << "operation " << op;
    if (op % 5000 == 0) {
      ASSERT_TRUE(queue.is_consistent()) << "operation " << op;
    }
  }
}

// The same sequence of operations gives the same pops (a trajectory depends on which of two
// simultaneous events runs first).
TEST(EventQueueOracle, SameOperationsGiveTheSamePops) {
  const RunFigures a = exercise(500, 77, 100000);
  const RunFigures b = exercise(500, 77, 100000);
  ASSERT_EQ(a.tops.size(), b.tops.size());
  EXPECT_TRUE(a.tops == b.tops);
}

// Sorting: draining the queue (top, then re-schedule at +inf) gives the (time, id) pairs in order,
// whatever order the times came in.
TEST(EventQueueOracle, DrainingGivesTheSortedTimes) {
  Random random(9);
  constexpr std::int32_t kParticles = 20000;
  EventQueue queue;
  queue.reset(kParticles);
  std::vector<std::pair<double, std::int32_t>> sorted;
  for (std::int32_t i = 0; i < kParticles; ++i) {
    const double t = random.below(3) == 0 ? static_cast<double>(random.below(50)) : random.uniform();  // many ties
    queue.update(i, t);
    sorted.push_back({t, i});
  }
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::pair<double, std::int32_t>> drained;
  for (std::int32_t k = 0; k < kParticles; ++k) {
    drained.push_back({queue.top_time(), queue.top()});
    queue.update(queue.top(), kInf);
  }
  EXPECT_EQ(queue.top_time(), kInf);
  EXPECT_TRUE(drained == sorted);
}

// The prefetch hints (runner_up, then earliest_walked after prefetch_ahead's walk, once per event
// as the engine calls them) against the reference's second event: they must name a valid particle
// or none, and, in the engine's regime of pops re-scheduled a little ahead, name the next top far
// more often than the runner-up alone, which has none when the top is alone in its bucket.
TEST(EventQueueOracle, HintsNameTheNextEvent) {
  constexpr std::int32_t kParticles = 20000;
  constexpr std::int64_t kPops = 400000;
  Random random(11);
  EventQueue queue;
  queue.reset(kParticles);
  for (std::int32_t i = 0; i < kParticles; ++i) queue.update(i, random.uniform());
  std::int64_t runner_up_right = 0, hint_right = 0;
  for (std::int64_t pop = 0; pop < kPops; ++pop) {
    const std::int32_t walked = queue.prefetch_ahead();
    ASSERT_GE(walked, -1);
    ASSERT_LT(walked, kParticles);
    const std::int32_t runner_up = queue.runner_up();
    std::int32_t hint = runner_up;
    if (hint < 0) {
      hint = queue.earliest_walked();
      if (hint >= 0) {
        ASSERT_LT(hint, kParticles);
        EXPECT_TRUE(queue.in_next_bucket(hint)) << "pop " << pop;
      }
    }
    const std::int32_t top = queue.top();
    const double now = queue.top_time();
    queue.update(top, now + 1e-3 * kParticles * random.uniform() / 2.0);  // a mean delay of N/2000
    const std::int32_t next = queue.top();
    runner_up_right += runner_up == next;
    hint_right += hint == next;
  }
  const double runner_up_rate = static_cast<double>(runner_up_right) / kPops;
  const double hint_rate = static_cast<double>(hint_right) / kPops;
  std::printf("next event named: runner-up alone %.3f, with the walked slots %.3f\n", runner_up_rate, hint_rate);
  EXPECT_TRUE(queue.is_consistent());
  EXPECT_GT(hint_rate, runner_up_rate + 0.05);
  EXPECT_GT(hint_rate, 0.85);
}

}  // namespace
}  // namespace granule
