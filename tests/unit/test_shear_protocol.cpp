// The shear protocols of thesis §4.3 (boundary/shear_protocol.hpp): the closed-form ∫U dt against
// an independent quadrature, and the segments the engine follows against their promises — the
// mean of U over each segment, |U − Ū| within the tolerance, no segment across a break.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "boundary/shear_protocol.hpp"

namespace granule {
namespace {

// Composite Simpson on n panels: independent of the closed forms, exact to ~h⁴ on smooth pieces.
// The ends are taken just inside [a, b], so that a step at b counts with its value before it.
double simpson(const ShearProtocol& p, double a, double b, int n = 20000) {
  const double h = (b - a) / n;
  double sum = p.velocity(a) + p.velocity(b - 1e-12 * (b - a));
  for (int k = 1; k < n; ++k) sum += (k % 2 ? 4.0 : 2.0) * p.velocity(a + k * h);
  return sum * h / 3.0;
}

struct Named {
  const char* name;
  double steady;
  ShearHistory history;
  std::vector<double> breaks;  // where U or U' jumps: quadrature splits there
};

std::vector<Named> protocols() {
  ShearHistory ramp;
  ramp.ramp_time = 0.7;
  ShearHistory schedule;
  schedule.schedule = {{0.5, 0.0}, {1.0, 3.0}, {1.0, -2.0}, {2.5, 4.0}};  // a ramp, a step, a ramp
  ShearHistory kick;
  kick.oscillation = ShearOscillation{1.5, 0.4, 0.3, 2.5};
  ShearHistory ramp_and_kick = ramp;
  ramp_and_kick.oscillation = ShearOscillation{-0.8, 0.25, 1.0, 3.0};
  // The same kicks as a square wave (a jump every half period) and a triangle wave (a turn a quarter
  // period in, then every half period).
  ShearHistory square_kick = kick;
  square_kick.oscillation->waveform = Waveform::kSquare;
  ShearHistory ramp_and_triangle = ramp_and_kick;
  ramp_and_triangle.oscillation->waveform = Waveform::kTriangle;
  std::vector<double> jumps, turns;
  for (int k = 0; k <= 5; ++k) jumps.push_back(0.3 + 0.2 * k);
  turns.push_back(1.0);
  for (int k = 0; k < 6; ++k) turns.push_back(1.0 + 0.0625 + 0.125 * k);
  turns.push_back(1.75);
  return {{"ramp", 5.0, ramp, {}},
          {"schedule", 0.0, schedule, {0.5, 1.0, 2.5}},
          {"kick", 2.0, kick, {0.3, 1.3}},
          {"ramp_and_kick", 5.0, ramp_and_kick, {1.0, 1.75}},
          {"square_kick", 2.0, square_kick, jumps},
          {"ramp_and_triangle", 5.0, ramp_and_triangle, turns}};
}

// The square and triangle waves at their defining phases, written out here: U₀ + A w(x).
TEST(ShearProtocol, SquareAndTriangleWavesAtTheirDefiningPhases) {
  const std::vector<Named> all = protocols();
  const ShearProtocol square(all[4].steady, all[4].history);  // A = 1.5, P = 0.4 from 0.3
  EXPECT_EQ(square.velocity(0.35), 2.0 + 1.5);
  EXPECT_EQ(square.velocity(0.55), 2.0 - 1.5);
  EXPECT_EQ(square.velocity(1.31), 2.0);  // after its 2.5 cycles
  EXPECT_EQ(square.slope_bound(0.35), 0.0) << "flat between jumps";
  EXPECT_NEAR(square.next_break(0.35), 0.5, 1e-15);
  EXPECT_NEAR(square.integral(0.3, 0.5), 1.5 * 0.2 + 2.0 * 0.2, 1e-15);
  const ShearProtocol triangle(all[5].steady, all[5].history);  // A = −0.8, P = 0.25 from 1.0, after a ramp
  const double base = 5.0 * (1.0 - std::exp(-1.03125 / 0.7));
  EXPECT_NEAR(triangle.velocity(1.03125), base - 0.8 * 0.5, 1e-14) << "an eighth of a period: half way up";
  EXPECT_NEAR(triangle.next_break(1.03125), 1.0625, 1e-15);
  EXPECT_NEAR(triangle.next_break(1.0625), 1.1875, 1e-15);
  // The triangle's slope 4A/P is the bound, with the ramp's own.
  EXPECT_NEAR(triangle.slope_bound(1.1), 4.0 * 0.8 / 0.25 + 5.0 / 0.7 * std::exp(-1.1 / 0.7), 1e-12);
  // Many cycles on, whole cycles add nothing: ∫ over 7 periods of the wave alone is 0.
  ShearHistory wave_alone;
  wave_alone.oscillation = ShearOscillation{1.0, 0.25, 0.0, 1000.0, Waveform::kTriangle};
  const ShearProtocol alone(0.0, wave_alone);
  EXPECT_NEAR(alone.integral(3.0, 3.0 + 7 * 0.25), 0.0, 1e-14);
  EXPECT_NEAR(alone.integral(100.0, 100.0625), 0.25 * 2.0 * 0.25 * 0.25, 1e-13) << "a quarter cycle: ∫ 4x dx to ¼";
}

TEST(ShearProtocol, ClosedFormIntegralMatchesQuadrature) {
  for (const Named& k : protocols()) {
    const ShearProtocol p(k.steady, k.history);
    std::vector<double> points = {0.0};
    for (double b : k.breaks) points.push_back(b);
    points.push_back(3.5);
    double quadrature = 0.0;
    for (std::size_t i = 0; i + 1 < points.size(); ++i) quadrature += simpson(p, points[i], points[i + 1]);
    const double closed = p.integral(0.0, 3.5);
    std::printf("%s: ∫0^3.5 U = %.15g (closed form), %.15g (Simpson)\n", k.name, closed, quadrature);
    EXPECT_NEAR(closed, quadrature, 1e-11 * (std::abs(quadrature) + p.velocity_scale())) << k.name;
    // Additive over any split point.
    EXPECT_NEAR(p.integral(0.0, 1.234) + p.integral(1.234, 3.5), closed, 1e-13 * p.velocity_scale()) << k.name;
  }
}

TEST(ShearProtocol, ValuesAtTheDefiningPoints) {
  const std::vector<Named> all = protocols();
  const ShearProtocol ramp(all[0].steady, all[0].history);
  EXPECT_EQ(ramp.velocity(0.0), 0.0);
  EXPECT_NEAR(ramp.velocity(0.7), 5.0 * (1.0 - std::exp(-1.0)), 1e-15);
  const ShearProtocol schedule(all[1].steady, all[1].history);
  EXPECT_EQ(schedule.velocity(0.2), 0.0);       // held at the first value before it
  EXPECT_EQ(schedule.velocity(0.75), 1.5);      // halfway up the first ramp
  EXPECT_EQ(schedule.velocity(1.0), -2.0);      // a step takes its later value
  EXPECT_EQ(schedule.velocity(9.0), 4.0);       // held at the last value after it
  const ShearProtocol kick(all[2].steady, all[2].history);
  EXPECT_NEAR(kick.velocity(0.4), 2.0 + 1.5, 1e-14);  // a quarter period after the start
  EXPECT_EQ(kick.velocity(1.31), 2.0);                // after 2.5 cycles
  EXPECT_TRUE(ShearProtocol(3.0, {}).constant());
  EXPECT_FALSE(ramp.constant());
}

TEST(ShearProtocol, SegmentsKeepTheirPromises) {
  for (const Named& k : protocols()) {
    const ShearProtocol p(k.steady, k.history);
    const double bound = k.history.tolerance * p.velocity_scale();
    double worst = 0.0, offset_error = 0.0, offset = 0.0;
    int segments = 0;
    ShearSegment s = p.segment_from(0.0);
    while (s.start < 3.5) {
      ++segments;
      ASSERT_GT(s.end, s.start) << k.name;
      for (double b : k.breaks) EXPECT_FALSE(s.start < b && b < s.end) << k.name << ": a segment straddles " << b;
      const double end = std::min(s.end, 3.5);
      for (int j = 0; j < 64; ++j) worst = std::max(worst, std::abs(p.velocity(s.start + (end - s.start) * j / 64.0) - s.velocity));
      worst = std::max(worst, std::abs(p.velocity(std::nextafter(end, s.start)) - s.velocity));  // before a step at the end
      if (s.end <= 3.5) {  // Δ is exact at whole segments' ends
        offset += s.velocity * (s.end - s.start);
        offset_error = std::max(offset_error, std::abs(offset - p.integral(0.0, s.end)));
      }
      if (s.end == std::numeric_limits<double>::infinity()) break;
      s = p.segment_from(s.end);
    }
    std::printf("%s: %d segments to t = 3.5, max |U − Ū| = %.3g (bound %.3g), Δ drift at segment ends %.2e\n", k.name,
                segments, worst, bound, offset_error);
    EXPECT_LE(worst, bound * (1.0 + 1e-9)) << k.name;
    EXPECT_LT(offset_error, 1e-12 * p.velocity_scale()) << k.name;
    EXPECT_LT(segments, 40000) << k.name;
    // A run restarted at any time finds the segment it was in.
    const ShearSegment found = p.segment_containing(1.2345);
    EXPECT_LE(found.start, 1.2345);
    EXPECT_GT(found.end, 1.2345);
  }
}

// The cost a run is warned of: an exponential ramp needs dn = dt / (tolerance τ e^{t/τ}) segments,
// (1 − tolerance)/tolerance until U is within the tolerance of U₀ (in the continuum limit: the
// engine's steps take the slope at their start, a few per cent more); a linear schedule piece of
// slope s over a span T needs ⌈s T/(tolerance · U_max)⌉.
TEST(ShearProtocol, SegmentsWhileChangingAsTheSlopeDemands) {
  for (const double tolerance : {1e-2, 1e-3, 1e-4}) {
    ShearHistory ramp;
    ramp.ramp_time = 0.7;
    ramp.tolerance = tolerance;
    const double expected = (1.0 - tolerance) / tolerance;
    EXPECT_NEAR(static_cast<double>(ShearProtocol(5.0, ramp).segments_while_changing(1 << 30)), expected, 0.05 * expected + 2.0)
        << "tolerance " << tolerance;
  }
  ShearHistory linear;
  linear.schedule = {{0.0, 0.0}, {2.0, 4.0}};
  linear.tolerance = 1e-3;
  // |U − Ū| ≤ slope · Δt / 2 would allow twice as long; the engine's bound is slope · Δt.
  EXPECT_EQ(ShearProtocol(0.0, linear).segments_while_changing(1 << 30), 1000);
  ShearHistory fine = linear;
  fine.tolerance = 1e-9;
  EXPECT_EQ(ShearProtocol(0.0, fine).segments_while_changing(1000000), 1000000) << "the count stops at the cap";
  EXPECT_EQ(ShearProtocol(3.0, ShearHistory{}).segments_while_changing(1000000), 1) << "a steady U is one segment";
}

}  // namespace
}  // namespace granule
