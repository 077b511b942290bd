// Unit tier: the inelastic-collapse detector (src/engine/collapse_detector.hpp) on synthetic
// sequences of collision times, fed exactly as the engine feeds it (the clock advanced by
// t_now = t_now + delay in double precision, re-based every 16 N events by shift_times).
//
// What must hold: a steady rate never triggers; neither does a cooling gas, whose rate falls as
// Haff's law 1/(1 + t/t₀) (thesis §2.1) over any number of decades; a geometric pile-up of
// collisions (intervals shrinking by a factor r per collision, the signature of McNamara & Young's
// inelastic collapse) triggers within a number of windows that follows from r, the window and the
// double-precision clock; a frozen clock triggers at the end of its first window; the first window
// after a reset has nothing to compare with, so it cannot trigger by the ratio.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "engine/collapse_detector.hpp"
#include "init/random.hpp"

namespace granule {
namespace {

// The engine's clock: times relative to a base, re-based every `rebase_every` collisions.
class Clock {
 public:
  Clock(CollapseDetector& detector, std::int64_t rebase_every) : detector_(detector), rebase_every_(rebase_every) {}
  // One collision `delay` after the previous one; true when the detector reports collapse.
  bool collide_after(double delay) {
    now_ += delay;
    const bool collapsed = detector_.on_collision(now_);
    if (++since_rebase_ >= rebase_every_) {
      detector_.shift_times(now_);
      base_ += now_;
      now_ = 0.0;
      since_rebase_ = 0;
    }
    return collapsed;
  }
  double absolute() const { return base_ + now_; }

 private:
  CollapseDetector& detector_;
  std::int64_t rebase_every_;
  double now_ = 0.0, base_ = 0.0;
  std::int64_t since_rebase_ = 0;
};

constexpr std::int64_t kWindow = 1000;  // the engine's max(1000, N) for N ≤ 1000

// Exponential waiting time of a Poisson process of unit rate.
double exponential(Random& random) { return -std::log(1.0 - random.uniform()); }

TEST(CollapseDetector, SteadyRateNeverTriggers) {
  for (const double rate : {1e-6, 1.0, 1e9}) {
    CollapseDetector detector;
    detector.reset(kWindow, 0.0);
    Clock clock(detector, 16 * kWindow);
    Random random(3);
    std::int64_t triggered = 0;
    for (std::int64_t k = 0; k < 2'000'000; ++k) triggered += clock.collide_after(exponential(random) / rate);
    std::printf("steady Poisson rate %g: %lld triggers in 2e6 collisions (2000 windows)\n", rate, static_cast<long long>(triggered));
    EXPECT_EQ(triggered, 0);
  }
}

// Haff cooling: the collision rate falls as R₀/(1 + t/t₀), so the k-th collision comes when the
// integrated rate R₀t₀ log(1 + t/t₀) reaches the k-th arrival of a unit Poisson process.  Twelve
// decades of t/t₀ (the temperature falls by 10²⁴) with N = 10⁴ disks, window N.
TEST(CollapseDetector, CoolingGasNeverTriggersOverTwelveDecades) {
  constexpr std::int64_t kParticles = 10000;
  const double t0 = 0.37, rate0 = 2.0 * kParticles / t0;  // two collisions per particle per t₀ at first
  CollapseDetector detector;
  detector.reset(kParticles, 0.0);
  Clock clock(detector, 16 * kParticles);
  Random random(5);
  double integrated = 0.0, previous = 0.0;
  std::int64_t collisions = 0, triggered = 0;
  while (previous < 1e12 * t0) {
    integrated += exponential(random);
    const double t = t0 * std::expm1(integrated / (rate0 * t0));
    triggered += clock.collide_after(t - previous);
    previous = t;
    ++collisions;
  }
  std::printf("Haff cooling to t/t0 = %.3g: %lld collisions, %lld windows, %lld triggers; clock %.6g vs exact %.6g\n",
              previous / t0, static_cast<long long>(collisions), static_cast<long long>(collisions / kParticles),
              static_cast<long long>(triggered), clock.absolute(), previous);
  EXPECT_EQ(triggered, 0);
  EXPECT_GT(collisions, 25 * kParticles);  // really many windows: R₀t₀ ln(10¹²) ≈ 27.6 N
}

// The first window after a reset has no predecessor: however short, it cannot trigger by the ratio
// (a frozen clock, span 0, is still caught).
TEST(CollapseDetector, FirstWindowCannotTriggerByTheRatio) {
  CollapseDetector detector;
  detector.reset(kWindow, 0.0);
  double now = 0.0;
  const auto window_triggers = [&](double delay) {
    bool triggered = false;
    for (std::int64_t k = 0; k < kWindow; ++k) triggered |= detector.on_collision(now += delay);
    return triggered;
  };
  EXPECT_FALSE(window_triggers(1e-300)) << "first window, span 1e-297";
  EXPECT_FALSE(window_triggers(1e-300)) << "second window, as long as the first";
  EXPECT_TRUE(window_triggers(1e-309)) << "third window, 1e-9 of the second";

  // After a reset mid-run the same holds: windows 10⁹ times shorter than the one before the
  // reset are not compared with it, and then only with each other.
  detector.reset(kWindow, 0.0);
  now = 0.0;
  EXPECT_FALSE(window_triggers(1.0));
  detector.reset(kWindow, now);
  EXPECT_FALSE(window_triggers(1e-9));
  EXPECT_FALSE(window_triggers(1e-9));
}

// The threshold itself: a window kRatio times the previous one (or longer) passes, a shorter one
// triggers.  Spans are powers of two apart so that the clock arithmetic is exact.
TEST(CollapseDetector, RatioThresholdIsOneInTenMillion) {
  const auto drop_triggers = [](double factor) {
    CollapseDetector detector;
    detector.reset(kWindow, 0.0);
    double now = 0.0;
    for (std::int64_t k = 0; k < kWindow; ++k) detector.on_collision(now += 1.0);  // span 1000
    bool triggered = false;
    const double delay = factor;  // the second window spans 1000 · factor
    for (std::int64_t k = 0; k < kWindow; ++k) triggered |= detector.on_collision(now += delay);
    return triggered;
  };
  EXPECT_FALSE(drop_triggers(0x1p-23));  // 1.19e-7 ≥ kRatio
  EXPECT_TRUE(drop_triggers(0x1p-24));   // 5.96e-8 < kRatio
  EXPECT_FALSE(drop_triggers(1e-6));     // a speed-up by 10⁶ is physics, not collapse
  EXPECT_TRUE(drop_triggers(1e-9));
}

TEST(CollapseDetector, FrozenClockTriggersAtTheEndOfItsWindow) {
  // From the start: the very first window spans no time.
  {
    CollapseDetector detector;
    detector.reset(kWindow, 2.5);
    std::int64_t at = -1;
    for (std::int64_t k = 1; k <= 3 * kWindow && at < 0; ++k)
      if (detector.on_collision(2.5)) at = k;
    EXPECT_EQ(at, kWindow);
  }
  // After 10 ordinary windows the clock stops mid-window: the next full window triggers.
  {
    CollapseDetector detector;
    detector.reset(kWindow, 0.0);
    Clock clock(detector, 16 * kWindow);
    Random random(8);
    bool early = false;
    for (std::int64_t k = 0; k < 10 * kWindow + kWindow / 2; ++k) early |= clock.collide_after(exponential(random));
    EXPECT_FALSE(early);
    std::int64_t at = -1;
    for (std::int64_t k = 1; k <= 5 * kWindow && at < 0; ++k)
      if (clock.collide_after(0.0)) at = k;
    std::printf("clock frozen half-way through window 11: collapse reported after %lld frozen collisions\n",
                static_cast<long long>(at));
    EXPECT_EQ(at, kWindow / 2 + kWindow);  // the rest of window 11 (compared with window 10: not short), then window 12
  }
}

// Collisions k = 0, 1, … at intervals τ rᵏ: they accumulate at t* = t_start + τ/(1 − r), which
// is reached in finite time after infinitely many collisions (inelastic collapse).  Consecutive
// windows of w collisions span times in the ratio r^w, so the ratio test triggers on the second
// window if r^w < kRatio.  Otherwise the spans shrink until the delays fall below half an ulp of
// the clock (≥ t*·2⁻⁵⁵) and the clock freezes, after k_f ≈ log(ulp(t*)/2τ)/log r collisions;
// the frozen window then triggers.  Bound: ⌈k_f/w⌉ + 2 windows — provided the clock is not
// re-based before k_f (see the disabled test below).
struct PileUp {
  double r;
  double tau;
};

constexpr double kPileUpStart = 3.0;

double pile_up_bound_windows(const PileUp& pile) {
  const double t_star = kPileUpStart + pile.tau / (1.0 - pile.r);
  // Half an ulp in the binade below t*: the clock's rounded sum can stop just short of a power of two.
  const double half_ulp = std::ldexp(1.0, std::ilogb(t_star) - 54);
  const double by_ratio = std::pow(pile.r, kWindow) < CollapseDetector::kRatio ? 2.0 : std::numeric_limits<double>::infinity();
  const double frozen_after = std::log(half_ulp / pile.tau) / std::log(pile.r);
  return std::min(by_ratio, std::ceil(frozen_after / kWindow) + 2.0);
}

std::int64_t collisions_until_collapse(const PileUp& pile, std::int64_t rebase_every, std::int64_t limit) {
  CollapseDetector detector;
  detector.reset(kWindow, 0.0);
  Clock clock(detector, rebase_every);
  clock.collide_after(kPileUpStart);
  double delay = pile.tau;
  for (std::int64_t k = 1; k <= limit; ++k) {
    if (clock.collide_after(delay)) return k;
    delay *= pile.r;
  }
  return -1;
}

void expect_pile_up_found(const PileUp& pile, std::int64_t rebase_every) {
  const double bound = pile_up_bound_windows(pile);
  const std::int64_t limit = static_cast<std::int64_t>(bound * kWindow) + 1;
  const std::int64_t at = collisions_until_collapse(pile, rebase_every, 20 * limit);
  const std::string rebase = rebase_every < (std::int64_t{1} << 40) ? "every " + std::to_string(rebase_every) : "never";
  std::printf("pile-up r = %g (r^w = %.3g), clock re-based %s: collapse after %lld collisions = %.2f windows (bound %.0f)\n",
              pile.r, std::pow(pile.r, kWindow), rebase.c_str(), static_cast<long long>(at), static_cast<double>(at) / kWindow,
              bound);
  EXPECT_GT(at, 0) << "no collapse reported for r = " << pile.r;
  EXPECT_LE(at, limit) << "r = " << pile.r;
}

constexpr std::int64_t kEngineRebase = 16 * kWindow;  // the engine re-bases every 16 N events
constexpr std::int64_t kNever = std::int64_t{1} << 60;

TEST(CollapseDetector, GeometricPileUpTriggersWithinTheBound) {
  // Caught by the ratio, or by the frozen clock before the engine's first re-base.
  for (const PileUp pile : {PileUp{0.5, 1e-2}, PileUp{0.9, 1e-2}, PileUp{0.98, 1e-2}, PileUp{0.99, 1e-2}})
    expect_pile_up_found(pile, kEngineRebase);
  // Slower pile-ups freeze the clock only after many windows; without re-basing they are caught.
  for (const PileUp pile : {PileUp{0.999, 1e-3}, PileUp{0.9999, 1e-4}}) expect_pile_up_found(pile, kNever);
}

// Re-basing every 16 N events restores the clock's precision (after a re-base t_now = Σ of the
// later delays, and delay/t_now ≈ (1 − r) r^j stays far above 2⁻⁵³ for r = 0.999 over 16 N
// collisions), so the clock never freezes, while consecutive windows shrink only by r^w = 0.37 >
// kRatio: the detector must compare with a longer history than the previous window.
TEST(CollapseDetector, SlowPileUpIsFoundDespiteClockReBasing) {
  expect_pile_up_found(PileUp{0.999, 1e-3}, kEngineRebase);
}

// The same pile-up inside a gas of 10⁴ disks colliding at a steady rate: the background's
// collisions stop at t* (none of them is ever reached), after which only the pile-up remains.
TEST(CollapseDetector, PileUpAmongSteadyCollisionsIsFound) {
  constexpr double kRate = 2e4;  // background collisions per unit time
  const PileUp pile{0.99, 2e-3};
  const double t_start = 1.0, t_star = t_start + pile.tau / (1.0 - pile.r);
  CollapseDetector detector;
  detector.reset(kWindow, 0.0);
  Clock clock(detector, 16 * kWindow);
  Random random(12);
  double now = 0.0, background = exponential(random) / kRate, cluster = t_start, delay = pile.tau;
  std::int64_t collisions = 0, cluster_collisions = 0, background_collisions = 0;
  bool triggered = false;
  while (!triggered && collisions < 10'000'000) {
    double next = 0.0;
    if (background < cluster) {
      next = background;
      background += exponential(random) / kRate;
      ++background_collisions;
    } else {
      next = cluster;
      cluster += delay;
      delay *= pile.r;
      ++cluster_collisions;
    }
    triggered = clock.collide_after(next - now);
    now = next;
    ++collisions;
  }
  std::printf("pile-up (r = %g) among %g background collisions per unit time: collapse at t = %.12g (t* = %.12g) after "
              "%lld collisions (%lld of the pile-up, %lld background)\n",
              pile.r, kRate, clock.absolute(), t_star, static_cast<long long>(collisions),
              static_cast<long long>(cluster_collisions), static_cast<long long>(background_collisions));
  ASSERT_TRUE(triggered);
  EXPECT_LT(t_star - clock.absolute(), 1e-9);
  // Background collisions up to t* (≈ kRate t*), then the pile-up's own bound as above.
  EXPECT_LT(static_cast<double>(collisions), kRate * t_star + 10.0 * std::sqrt(kRate * t_star) + 20.0 * kWindow);
}

// Re-basing the clock must not change any decision: with times exactly representable before and
// after the shift, the collapse is reported at the same collision whatever the re-base interval.
TEST(CollapseDetector, ReBasingDoesNotChangeTheDecision) {
  std::int64_t reference = -1;
  for (const std::int64_t rebase_every : {std::int64_t{1} << 40, std::int64_t{16000}, std::int64_t{777}, std::int64_t{1}}) {
    CollapseDetector detector;
    detector.reset(kWindow, 0.0);
    Clock clock(detector, rebase_every);
    Random random(21);
    std::int64_t at = -1;
    for (std::int64_t k = 1; k <= 200 * kWindow && at < 0; ++k) {
      // Delays on a dyadic grid (exact sums below 2¹⁵); from collision 50000 on, 2⁻³⁰ instead of ~½:
      // a drop by 2·10⁻⁹.
      const double delay = k < 50 * kWindow ? static_cast<double>(1 + random.below(1024)) * 0x1p-10 : 0x1p-30;
      if (clock.collide_after(delay)) at = k;
    }
    if (reference < 0) reference = at;
    EXPECT_EQ(at, reference) << "re-base every " << rebase_every;
  }
  EXPECT_EQ(reference, 51 * kWindow);
}

}  // namespace
}  // namespace granule
