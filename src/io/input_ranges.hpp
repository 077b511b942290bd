// The ranges of numeric inputs that the double-precision engine runs correctly, shared by the run
// configuration and `granule theory`.  Hard disks have no intrinsic length, speed or time scale
// (U and √T only set the time unit), so these bounds are numerical, not physical: they keep
// squares, fourth powers and sums over N ≤ 2³¹ disks far from overflow and underflow, and keep
// positions resolved on the scale of a diameter.  README.md "Ranges the engine can run" gives
// each bound and why.
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <string>

namespace granule {

// An interval of allowed values.  NaN and ±∞ are never inside, whatever the ends.
struct NumberRange {
  double low = 0.0;
  double high = 0.0;
  bool low_open = false;
  bool high_open = false;

  bool contains(double value) const {
    return std::isfinite(value) && (low_open ? value > low : value >= low) &&
           (high_open ? value < high : value <= high);
  }
  // "(0, 1]", "[1e-30, 1e+30]", "[0, ∞)"; the ends in their shortest exact form.
  std::string text() const {
    const auto end = [](double v) { return std::isinf(v) ? std::string(v > 0 ? "∞" : "-∞") : fmt::format("{}", v); };
    return fmt::format("{}{}, {}{}", low_open ? '(' : '[', end(low), end(high), high_open ? ')' : ']');
  }
};

inline constexpr double kUnbounded = INFINITY;

// Lengths (box sides, and in `granule theory` diameters): with speeds in [1e-30, 1e30] every
// product the engine forms (r·v, r²v², their sums over 2³¹ disks) stays within 1e±130 of 1.
inline constexpr NumberRange kLengthRange{1e-30, 1e30};
// Speeds: |U| when shearing, and √T_i.  Fourth powers summed over 2³¹ disks (the flatness κ)
// stay below 1e130 (T may still grow 1e80-fold under shear heating); the smallest product, σ²v²
// in the collision-time discriminant, starts above 1e-140, so a gas may cool 1e150-fold
// (ln T falling by 345, (1 − ẽ²)c = 345 in homogeneous cooling) before it underflows.
inline constexpr NumberRange kSpeedRange{1e-30, 1e30};
inline constexpr NumberRange kTemperatureRange{1e-60, 1e60};
// Rates (a shear rate γ = U/L in `granule theory`): T0 ∝ (lγ)²/ε stays finite.
inline constexpr NumberRange kRateRange{1e-30, 1e30};

// Masses of the species of a mixture and of each particle (the unit is the mass of the reference
// grain; volume-scaled masses of size ratios within 10^±2 stay inside): T/m and m v² stay within
// the speed and temperature ranges.
inline constexpr NumberRange kMassRange{1e-12, 1e12};

// The ranges of the collision law's parameters, for the configuration and for every file that
// records them: ẽ and the walls' e_w in (0, 1]; β and β_w in [−1, 1] (−1 smooth, +1 perfectly
// rough); q = 4I/(mσ²) in (0, 1] (1 puts all the mass on the rim); Coulomb μ ≥ 0; t_c ≥ 0.
inline constexpr NumberRange kRestitutions{0.0, 1.0, true, false};
inline constexpr NumberRange kTangentialRestitutions{-1.0, 1.0};
inline constexpr NumberRange kInertiaFactors{0.0, 1.0, true, false};
inline constexpr NumberRange kFrictions{0.0, kUnbounded, false, true};
inline constexpr NumberRange kContactDurations{0.0, kUnbounded, false, true};
// The speed laws of ẽ (physics/restitution_law.hpp): the threshold speed v_c > 0 and the
// viscoelastic constant δ > 0, both finite.
inline constexpr NumberRange kThresholdSpeeds{0.0, kUnbounded, true, true};
inline constexpr NumberRange kViscoelasticConstants{0.0, kUnbounded, true, true};

// Largest box side over the diameter: a position x ≤ L is stored to L·2⁻⁵³, so at L/σ = 1e9
// contacts are still resolved to 1e-7 σ; it also keeps every cell count of the engine's grid
// (≤ L/σ per direction) inside an int.
inline constexpr double kMaxBoxOverDiameter = 1e9;
// Largest |U|/√T_i: the thermal part of v = u(y) + v′ is stored to |U|·2⁻⁵³, so at 1e10 the
// initial peculiar velocities keep ~6 significant digits beside the shear profile.
inline constexpr double kMaxShearOverThermalSpeed = 1e10;
// Largest number of collisions any count setting may name: 2⁶², so that a count plus an interval
// (each ≤ 2⁶²) still fits in an int64.
inline constexpr double kMaxCollisions = 4611686018427387904.0;
// Largest number of engine cells: cell ids have 28 bits (the event slot keeps the event kind in
// the other 4 of their word, events/event_slot.hpp).  At the default occupancy that is 1.6·10⁸
// particles; larger runs get fuller cells (engine.particles_per_cell).
inline constexpr std::int64_t kMaxEngineCells = std::int64_t{1} << 28;
// Range of the free-path histogram (collisions.max_length): at least 1e-9 σ, so that its bins
// (max_length/length_bins) are normal non-zero numbers, at most 1e12 box lengths, so that it is
// finite and holds the default 10 l (≤ 2.5e9 box lengths at the extreme N = 2, L/σ = 1e9).
inline constexpr double kMinMaxLengthOverDiameter = 1e-9;
inline constexpr double kMaxMaxLengthOverBox = 1e12;

}  // namespace granule
