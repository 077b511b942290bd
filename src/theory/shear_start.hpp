// The early-time granular temperature of a sheared dilute disk gas after a hot or a cold start
// (thesis §4.2, (4.25)–(4.30)): the temperature equation (4.1) without diffusion and convection,
// at fixed density, under a constant viscous heating function, (4.26). Units: shear rate γ and
// fluctuation rate h in 1/time, Tr D̂² in 1/time², mean free path l = πσ/8ν in length,
// temperatures T = ½⟨(v − V)²⟩ in length²/time², times in time units.
#pragma once

namespace granule::theory {

// Tr D̂² where a thermal shear fluctuation of rate h = ∂δv2/∂x (4.25) adds to the mean shear γ:
// 2(γ + h)², the first form of (4.27) ((4.4) with ∂v1/∂y = γ, ∂v2/∂x = h).
double shear_heating_function(double shear_rate, double h);

// The hot-start expansion of (4.27): 2h²(1 + 2γ/h), dropping O(γ²/h²) (h ≫ γ). The heating of
// (4.28).
double hot_start_heating_function(double shear_rate, double h);

// The solution of (4.26), ν Ṫ = (√π/16)σ√T·Tr D̂² − (8/√π)(ν²/σ)εT^{3/2}, for constant Tr D̂² = D
// and T(0) = T_i (a Riccati equation in √T, solved as (2.41)–(2.44)):
//   T(t) = T_sat A(t),  A(t) = [(1 − α e^{−rt})/(1 + α e^{−rt})]²,
//   T_sat = l²D/(2πε),  r = √(εD/2),  α = (1 − √(T_i/T_sat))/(1 + √(T_i/T_sat)).
// With D from hot_start_heating_function this is (4.28)–(4.30) in the form consistent with
// (4.26): the thesis prints the rate as √(εh) (not a rate; √ε h to leading order) and
// normalises T_i in α by l²h²/(πε) without the factor 1 + 2γ/h, so that its T(0) is
// T_i(1 + 2γ/h) (docs/theory.md, discrepancy 16).
struct EarlyShearTemperature {
  double saturation;  // T_sat [length²/time²]: (4.28)'s prefactor; (4.5) when D = 2γ²
  double rate;        // r [1/time]
  double root_ratio;  // √(T_i/T_sat)

  double alpha() const;                  // (4.30)
  double relaxation(double t) const;     // A(t), (4.29); A(0) = T_i/T_sat, A(∞) = 1
  double temperature(double t) const;    // T(t), (4.28)
};

EarlyShearTemperature early_shear_temperature(double initial_temperature, double heating_function,
                                              double mean_free_path, double eps);

}  // namespace granule::theory
