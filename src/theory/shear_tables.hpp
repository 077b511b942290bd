// The sheared gas of thesis chapters 3 and 4 as tables (`granule theory shear-stability`,
// `shear-scales` and `steady-shear`): the growth rates of the 4×4 system (4.19), the clustering
// time scales (4.36)–(4.41) and the steady temperature (3.1), (3.2), (4.5).  Inputs are assumed
// inside the ranges the command checks.
#pragma once

#include <string>

#include "theory/prediction_table.hpp"
#include "theory/shear_stability.hpp"

namespace granule::theory {

struct ShearStabilityInputs {
  double sqrt_eps = 0.8;                            // √(1 − e²)
  double theta_deg = 135.0;                         // wavevector angle from the flow [degrees]
  double delta_min = 0.0, delta_max = 1.0;          // δ̄
  int points = 21;                                  // points per axis
  std::string figure;                               // "4.1" … "4.4": that figure's data; empty: one θ
  ShearPressureScaling scaling = ShearPressureScaling::thesis;
};

// Re s_m over δ̄ at one θ (with the small-δ̄ roots and the most unstable direction), or the data
// of one of Figs 4.1–4.4.
PredictionTable shear_stability_table(const ShearStabilityInputs& in);

struct ShearScalesInputs {
  double restitution = 0.6, area_fraction = 0.05;
  double diameter = 0.0;               // σ; 0: from N, L and ν
  double shear_rate = 100.0;           // γ = U/L [1/time]
  double box = 1.0;                    // side L of the square box
  double initial_temperature = -1.0;   // T_i; not positive: T0, a start near the steady state
  int particles = 20000, mode = 1;     // N; the Fourier mode n, k = 2πn/L
};

// Summary lines only (no columns); `derived` holds σ, l, T0, h, τm and 1/s3.
PredictionTable shear_scales_table(const ShearScalesInputs& in);

struct SteadyShearInputs {
  double restitution = -1.0;           // one restitution; negative: the sweep e_min … e_max
  double e_min = 0.5, e_max = 0.99;
  int points = 11;
  double shear_rate = 100.0;           // γ = U/L_y [1/time]
  double diameter = 0.0;               // σ; 0: from N, L_x, L_y and ν
  double area_fraction = 0.05, box_x = 1.0, box_y = 1.0;
  int particles = 200000;
};

// Columns restitution, eps and the steady temperatures of (3.1), (3.2) and (4.5).
PredictionTable steady_shear_table(const SteadyShearInputs& in);

}  // namespace granule::theory
