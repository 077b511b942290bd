// The freely cooling gas of thesis chapter 2 as tables (`granule theory haff` and
// `free-stability`): Haff's law (2.10) and the eigenvalues of the linearised Jenkins–Richman
// equations (2.28), (2.35).  Inputs are assumed inside the ranges the command checks.
#pragma once

#include "theory/prediction_table.hpp"

namespace granule::theory {

struct HaffInputs {
  double restitution = 0.9, area_fraction = 0.05;
  double diameter = 1.26e-3;         // σ [length]
  double temperature = 1.0;          // T0 = ⟨v′²⟩/2
  double contact_value = 1.0;        // χ, unless `enskog` (Henderson's χ(ν))
  bool enskog = false;
  double collisions = 0.0;           // last row's collisions per particle c; 0: 3/ε
  int points = 11;                   // rows, evenly spaced in c
};

// Columns c, t, T, collision_rate.
PredictionTable haff_table(const HaffInputs& in);

struct FreeStabilityInputs {
  double eps = 0.19;                 // ε = 1 − e²
  double k_min = 1e-3, k_max = 1.0;  // K = k l0
  int points = 13;                   // rows, log-spaced in K
  bool asymptotic = false;           // add the forms (2.30)–(2.32) and (2.33)–(2.34)
};

// Columns K, the three eigenvalues of (2.28), the shear eigenvalue (2.35) and the growth
// exponent of the density (2.36).
PredictionTable free_stability_table(const FreeStabilityInputs& in);

}  // namespace granule::theory
