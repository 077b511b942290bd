#include "boundary/shear_protocol.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace granule {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// g(x) = x + e^{−x} − 1 without cancellation: the ramp's integral over a short segment.
double ramp_excess(double x) {
  if (x < 1e-2) return x * x * (0.5 - x * (1.0 / 6.0 - x * (1.0 / 24.0 - x / 120.0)));
  return x + std::expm1(-x);
}

// The square and triangle waves of unit amplitude and period 1 at phase x (Waveform).
double piecewise_wave(Waveform shape, double x) {
  const double f = x - std::floor(x);
  if (shape == Waveform::kSquare) return f < 0.5 ? 1.0 : -1.0;
  return f < 0.25 ? 4.0 * f : f < 0.75 ? 2.0 - 4.0 * f : 4.0 * f - 4.0;
}

// Where the square wave jumps (every half cycle) and the triangle wave turns (a quarter cycle on,
// every half cycle), in cycles.
double first_break_phase(Waveform shape) { return shape == Waveform::kSquare ? 0.0 : 0.25; }

// The first break of a piecewise wave strictly after phase x.
double next_break_phase(Waveform shape, double x) {
  const double offset = first_break_phase(shape);
  double next = offset + 0.5 * (std::floor((x - offset) / 0.5) + 1.0);
  while (next <= x) next += 0.5;
  return next;
}

// ∫ w over the phases [x0, x1] of a piecewise wave, piece by piece by the midpoint rule (exact on
// constant and linear pieces; whole cycles add nothing).
double piecewise_wave_integral(Waveform shape, double x0, double x1) {
  const double cycles = std::floor(x1 - x0);
  double x = x0;
  const double end = x1 - cycles;
  double sum = 0.0;
  while (x < end) {
    const double to = std::min(end, next_break_phase(shape, x));
    sum += (to - x) * piecewise_wave(shape, 0.5 * (x + to));
    x = to;
  }
  return sum;
}

}  // namespace

ShearHistory scaled(const ShearHistory& history, double factor) {
  ShearHistory out = history;
  for (ShearSchedulePoint& p : out.schedule) p.velocity *= factor;
  if (out.oscillation) out.oscillation->amplitude *= factor;
  return out;
}

ShearProtocol::ShearProtocol(double steady_velocity, const ShearHistory& history)
    : steady_(steady_velocity), history_(history) {}

double ShearProtocol::base_velocity(double t) const {
  const auto& points = history_.schedule;
  if (!points.empty()) {
    if (t < points.front().time) return points.front().velocity;
    for (std::size_t k = 0; k + 1 < points.size(); ++k) {
      const ShearSchedulePoint& p = points[k];
      const ShearSchedulePoint& q = points[k + 1];
      if (t >= p.time && t < q.time) return p.velocity + (q.velocity - p.velocity) * ((t - p.time) / (q.time - p.time));
    }
    return points.back().velocity;  // at or after the last point (a step takes its later value)
  }
  if (history_.ramp_time > 0.0) return t <= 0.0 ? 0.0 : -steady_ * std::expm1(-t / history_.ramp_time);
  return steady_;
}

double ShearProtocol::base_integral(double a, double b) const {
  const auto& points = history_.schedule;
  if (!points.empty()) {
    // The trapezoid rule is exact on each linear piece; summed over the parts of [a, b] in each
    // piece (never as a difference of antiderivatives, which would cancel on short segments).
    double sum = 0.0;
    const auto add = [&](double from, double to, const ShearSchedulePoint& p, const ShearSchedulePoint& q) {
      const double u = std::max(a, from), w = std::min(b, to);
      if (!(w > u)) return;
      const auto at = [&](double t) {
        return q.time > p.time ? p.velocity + (q.velocity - p.velocity) * ((t - p.time) / (q.time - p.time)) : p.velocity;
      };
      sum += 0.5 * (w - u) * (at(u) + at(w));
    };
    add(-kInf, points.front().time, points.front(), points.front());
    for (std::size_t k = 0; k + 1 < points.size(); ++k) add(points[k].time, points[k + 1].time, points[k], points[k + 1]);
    add(points.back().time, kInf, points.back(), points.back());
    return sum;
  }
  const double tau = history_.ramp_time;
  if (tau > 0.0) {
    // U₀ ∫_a^b (1 − e^{−t/τ}) dt = U₀ [(b − a)(1 − e^{−a/τ}) + τ e^{−a/τ} g((b − a)/τ)].
    const double a0 = std::max(a, 0.0);
    if (b <= a0) return 0.0;
    const double decay = std::exp(-a0 / tau);
    return steady_ * ((b - a0) * -std::expm1(-a0 / tau) + tau * decay * ramp_excess((b - a0) / tau));
  }
  return steady_ * (b - a);
}

double ShearProtocol::velocity(double t) const {
  double u = base_velocity(t);
  // A square or triangle wave stops at its end (where it may jump back to 0), the sine, continuous
  // there, includes it.
  if (const auto& osc = history_.oscillation;
      osc && t >= osc->start && (t < osc->end() || (t == osc->end() && osc->waveform == Waveform::kSine))) {
    if (osc->waveform == Waveform::kSine) {
      u += osc->amplitude * std::sin(2.0 * std::numbers::pi * (t - osc->start) / osc->period);
    } else if (osc->waveform == Waveform::kTriangle) {
      u += osc->amplitude * piecewise_wave(osc->waveform, (t - osc->start) / osc->period);
    } else {
      // The square wave's side of a jump is decided by the jump's time as next_break gives it, not by
      // the rounded phase: from that instant on, the value after it.
      const double x = (t - osc->start) / osc->period;
      const double next = next_break_phase(osc->waveform, x);
      const double previous = next - 0.5;
      const double inside = osc->start + osc->period * next <= t       ? next + 0.25
                            : osc->start + osc->period * previous > t ? previous - 0.25
                                                                      : previous + 0.25;
      u += osc->amplitude * piecewise_wave(osc->waveform, inside);
    }
  }
  return u;
}

double ShearProtocol::integral(double a, double b) const {
  double sum = base_integral(a, b);
  if (const auto& osc = history_.oscillation) {
    const double u = std::max(a, osc->start);
    const double w = std::min(b, osc->end());
    if (w > u && osc->waveform == Waveform::kSine) {
      // A/k (cos φ(u) − cos φ(w)) as a product of sines: no cancellation on short segments.
      const double k = 2.0 * std::numbers::pi / osc->period;
      sum += 2.0 * osc->amplitude / k * std::sin(0.5 * k * (u + w - 2.0 * osc->start)) * std::sin(0.5 * k * (w - u));
    } else if (w > u) {
      sum += osc->amplitude * osc->period *
             piecewise_wave_integral(osc->waveform, (u - osc->start) / osc->period, (w - osc->start) / osc->period);
    }
  }
  return sum;
}

double ShearProtocol::velocity_scale() const {
  double scale = std::abs(steady_);
  if (!history_.schedule.empty()) {
    scale = 0.0;
    for (const ShearSchedulePoint& p : history_.schedule) scale = std::max(scale, std::abs(p.velocity));
  }
  if (history_.oscillation) scale += std::abs(history_.oscillation->amplitude);
  return scale;
}

bool ShearProtocol::constant() const {
  if (history_.oscillation && history_.oscillation->amplitude != 0.0) return false;
  for (const ShearSchedulePoint& p : history_.schedule) {
    if (p.velocity != history_.schedule.front().velocity) return false;
  }
  return history_.schedule.empty() ? history_.ramp_time <= 0.0 || steady_ == 0.0 : true;
}

double ShearProtocol::next_break(double t) const {
  double next = kInf;
  for (const ShearSchedulePoint& p : history_.schedule) {
    if (p.time > t) next = std::min(next, p.time);
  }
  if (const auto& osc = history_.oscillation) {
    if (osc->start > t) next = std::min(next, osc->start);
    if (osc->end() > t) next = std::min(next, osc->end());
    if (osc->waveform != Waveform::kSine && t >= osc->start && osc->end() > t) {
      // A jump or turn of the wave: the next whole-cycle count of its phase, mapped back to time.
      const double phase = next_break_phase(osc->waveform, (t - osc->start) / osc->period);
      double at = osc->start + osc->period * phase;
      if (at <= t) at = osc->start + osc->period * (phase + 0.5);  // t is that break, its phase rounded below it
      while (at <= t) at = std::nextafter(at, kInf);
      next = std::min(next, at);
    }
  }
  return next;
}

double ShearProtocol::slope_bound(double t) const {
  double bound = 0.0;
  const auto& points = history_.schedule;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    if (t >= points[k].time && t < points[k + 1].time) {
      bound = std::abs((points[k + 1].velocity - points[k].velocity) / (points[k + 1].time - points[k].time));
    }
  }
  // |dU/dt| = |U₀|/τ e^{−t/τ} decreases: its value at the segment start bounds the segment.
  if (points.empty() && history_.ramp_time > 0.0) {
    bound = std::abs(steady_) / history_.ramp_time * std::exp(-std::max(t, 0.0) / history_.ramp_time);
  }
  if (const auto& osc = history_.oscillation; osc && t >= osc->start && t < osc->end()) {
    // |dU/dt| ≤ 2π|A|/P for the sine, 4|A|/P for the triangle; the square wave is flat between jumps.
    const double peak_slope = osc->waveform == Waveform::kSine ? 2.0 * std::numbers::pi : osc->waveform == Waveform::kTriangle ? 4.0 : 0.0;
    bound += peak_slope * std::abs(osc->amplitude) / osc->period;
  }
  return bound;
}

ShearSegment ShearProtocol::segment_from(double t) const {
  const double limit = next_break(t);
  const double slope = slope_bound(t);
  double end = limit;
  if (slope > 0.0) {
    // Equal segments up to the next break, none longer than the tolerance allows: no slivers.
    const double longest = history_.tolerance * velocity_scale() / slope;
    end = limit == kInf ? t + longest : t + (limit - t) / std::ceil((limit - t) / longest);
    if (end > limit) end = limit;
  }
  if (end <= t) end = std::min(limit, std::nextafter(t, kInf));  // always move on
  if (end == kInf) return {t, kInf, velocity(t)};
  return {t, end, integral(t, end) / (end - t)};
}

std::int64_t ShearProtocol::segments_while_changing(std::int64_t cap) const {
  if (constant()) return 1;
  // The protocol changes until its last break, and a ramp until U is within the tolerance of U₀
  // (t = τ ln(1/tolerance)); each later segment is longer than any before.
  double last_break = 0.0;
  for (double t = 0.0; (t = next_break(t)) < kInf;) last_break = t;
  const double ramp_end = history_.ramp_time > 0.0 ? history_.ramp_time * std::log(1.0 / history_.tolerance) : 0.0;
  const double until = std::max(last_break, ramp_end);
  std::int64_t count = 1;
  for (ShearSegment segment = segment_from(0.0); segment.end < until && count < cap; segment = segment_from(segment.end)) ++count;
  return count;
}

ShearSegment ShearProtocol::segment_containing(double t) const {
  ShearSegment segment = segment_from(0.0);
  while (segment.end <= t) segment = segment_from(segment.end);
  return segment;
}

}  // namespace granule
