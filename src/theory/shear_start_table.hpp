// The early-time temperature of a sheared gas after a hot or a cold start, (4.26)–(4.30), and the
// clustering scales of that start, (4.25), (4.36)–(4.41) (thesis §4.2), as the table of
// `granule theory shear-start`.  Inputs are assumed inside the ranges the command checks.
#pragma once

#include "theory/prediction_table.hpp"

namespace granule::theory {

struct ShearStartInputs {
  double restitution = 0.6, area_fraction = 0.05;
  double diameter = 0.0;                 // σ; 0: from N, L_x, L_y and ν
  double shear_rate = 100.0;             // γ = U/L_y [1/time]
  double box_x = 1.0, box_y = 1.0;
  double initial_temperature = 0.0;      // T_i = ⟨v′²⟩/2, unless temperature_over_steady > 0
  double temperature_over_steady = 0.0;  // T_i/T0 (4.5) when positive
  double kl = 0.0;                       // k l of the fluctuation; 0: mode, or √ε
  double time_max = 0.0;                 // last row's t; 0: kSaturationTimes/rate of (4.26)
  int particles = 20000;
  int mode = 0;                          // box mode n, k = 2πn/L_x, when kl is 0
  int points = 21;                       // rows, evenly spaced in t
};

// The curve ends after this many saturation times 1/r of (4.26) unless time_max says otherwise:
// A(t) is then within 3e-2 of 1 for any start (|α| < 1, so |A − 1| ≤ 4e^{−rt}/(1 − e^{−rt})²).
inline constexpr double kSaturationTimes = 5.0;

struct ShearStartPrediction {
  double initial_temperature = 0.0;  // T_i, from the inputs or as a multiple of T0
  PredictionTable table;             // columns t, strain, A_4.29, T_4.28, T_4.26
};

ShearStartPrediction shear_start_table(const ShearStartInputs& in);

}  // namespace granule::theory
