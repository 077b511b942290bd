// What a run of free cooling shows (thesis Chapter 2): the early exponential decay of T̄, the onset
// of clustering against the linear-stability estimate, and the late power law of T̄ and of E.
#pragma once

#include <cmath>

#include "reproduce/run_outputs.hpp"

namespace granule::reproduce {

// The thesis's Systems I and II are at ν = 0.05 (§2.1).
inline constexpr double kFreeCoolingAreaFraction = 0.05;

// E exceeding the extrapolation of its early exponential decay by this factor marks the onset:
// the thesis reads the transition off the change of decay rate of E (Fig 2.5).
inline constexpr double kOnsetExcess = 1.2;

// The linear-stability onset: the shear mode of the box's longest wave grows against the thermal
// speed as exp((ε − 5K²/12) s) ((2.35) with T ∝ e^{−2εs}), from the noise level 1/√N of one
// mode to order one, so s* = ln √N/(ε − 5K²/12) and c* = 2s* = ln N/(ε − 5K²/12), K = 2π l0/L
// with l0 of (2.13), at ν = 0.05.  NaN when the box is too small for any growing shear mode.
double linear_stability_onset_c(double restitution, int particles, double diameter, double box);

struct CoolingMeasures {
  double early_slope = NAN;           // d ln T̄/dc before clustering
  double onset_c = NAN;               // first c where E exceeds the early exponential by kOnsetExcess
  double late_exponent = NAN;         // d ln T̄/d ln t over c ∈ [2 onset, end]
  double late_energy_exponent = NAN;  // d ln E/d ln t over the same c, E the lab kinetic energy (mean flows included)
};

// The measures of run `p`, its early decay fitted over c ∈ [1, early_to_c].
CoolingMeasures measure_cooling(const PointOutputs& p, double early_to_c);

}  // namespace granule::reproduce
