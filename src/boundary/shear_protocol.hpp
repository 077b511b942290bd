// The Lees–Edwards drive of thesis Chapter 4: the velocity U(t) of the images above the box as a
// function of the production time t (§4.3: ramps, instantaneous or incremental changes, a
// transient sinusoidal kick).  The image offset is Δ(t) = ∫ U dt (mod L_x).
//
// The engine follows U(t) as a sequence of segments of constant velocity (ARCHITECTURE.md,
// "Shear protocols"): on each segment [a, b] it uses the mean Ū = ∫_a^b U dt / (b − a), so that
// Δ is exact at every segment end, and the segments are short enough that |U(t) − Ū| ≤
// tolerance · velocity_scale() on each.  Segments never straddle a break of the protocol (a
// schedule point, the start or end of the oscillation).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace granule {

// The shape w(x) of an oscillation over one cycle x ∈ [0, 1), each starting at 0 and rising, with
// peak 1 and mean 0: sin 2πx; a square wave, +1 on the first half and −1 on the second; a triangle
// wave, 4x up to ¼, 2 − 4x up to ¾, 4x − 4 after.
enum class Waveform { kSine, kSquare, kTriangle };

// U += A w((t − start)/P) for start ≤ t ≤ start + cycles·P.
struct ShearOscillation {
  double amplitude = 0.0;  // A
  double period = 1.0;     // P
  double start = 0.0;      // t_s
  double cycles = 1.0;     // n (may be fractional)
  Waveform waveform = Waveform::kSine;
  double end() const { return start + cycles * period; }
};

struct ShearSchedulePoint {
  double time = 0.0;
  double velocity = 0.0;
};

struct ShearHistory {
  // τ > 0: U(t) = U₀ (1 − e^{−t/τ}) (Fig 4.7, Fig C.3).  0: no ramp.
  double ramp_time = 0.0;
  // Non-empty: U(t) piecewise linear through the points (times non-decreasing; two points at one
  // time make a step), held at the first value before and at the last value after.  Replaces U₀.
  std::vector<ShearSchedulePoint> schedule;
  std::optional<ShearOscillation> oscillation;
  // Largest |U(t) − Ū| on a segment, relative to velocity_scale().
  double tolerance = 1e-3;
};

// The same history with every velocity times `factor` (a wall driven at a share of U(t)).
ShearHistory scaled(const ShearHistory& history, double factor);

struct ShearSegment {
  double start = 0.0;
  double end = 0.0;       // +inf when U stays constant from `start` on
  double velocity = 0.0;  // Ū over [start, end] (U(start) when the segment is endless)
};

class ShearProtocol {
 public:
  ShearProtocol() = default;
  ShearProtocol(double steady_velocity, const ShearHistory& history);

  double velocity(double t) const;
  // ∫_a^b U dt, in closed form.
  double integral(double a, double b) const;
  // The largest |U| the protocol can reach (the scale of its tolerance).
  double velocity_scale() const;
  // True when U(t) never changes.
  bool constant() const;
  // The segment that starts at t (t ≥ 0).
  ShearSegment segment_from(double t) const;
  // The segments a run takes while U(t) changes (up to its last break, or until a ramp is within
  // the tolerance of U₀), counted up to `cap`: each segment end costs the engine an action.
  std::int64_t segments_while_changing(std::int64_t cap) const;
  // The segment that contains t, found by chaining segments from 0 exactly as a run does.
  ShearSegment segment_containing(double t) const;
  // The next time after t at which U or its derivative jumps (+inf if none).
  double next_break(double t) const;
  // An upper bound of |dU/dt| over [t, next_break(t)).
  double slope_bound(double t) const;

 private:
  double base_velocity(double t) const;
  double base_integral(double a, double b) const;

  double steady_ = 0.0;  // U₀
  ShearHistory history_;
};

}  // namespace granule
