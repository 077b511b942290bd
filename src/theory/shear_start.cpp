#include "theory/shear_start.hpp"

#include <cmath>

#include "theory/steady_shear.hpp"

namespace granule::theory {

double shear_heating_function(double shear_rate, double h) {
  const double total = shear_rate + h;
  return 2.0 * total * total;
}

double hot_start_heating_function(double shear_rate, double h) {
  return 2.0 * h * h * (1.0 + 2.0 * shear_rate / h);
}

double EarlyShearTemperature::alpha() const { return (1.0 - root_ratio) / (1.0 + root_ratio); }

double EarlyShearTemperature::relaxation(double t) const {
  // √A = (1 − αE)/(1 + αE) with E = e^{−rt}, multiplied through by 1 + √(T_i/T_sat): every term
  // is then non-negative, so a start far from T_sat (α → ±1) loses no digits to cancellation.
  const double decay = std::exp(-rate * t);
  const double gone = -std::expm1(-rate * t);  // 1 − E, exact at small rt
  const double root =
      (gone + root_ratio * (1.0 + decay)) / ((1.0 + decay) + root_ratio * gone);
  return root * root;
}

double EarlyShearTemperature::temperature(double t) const { return saturation * relaxation(t); }

EarlyShearTemperature early_shear_temperature(double initial_temperature, double heating_function,
                                              double mean_free_path, double eps) {
  const double saturation = heated_steady_temperature(heating_function, mean_free_path, eps);
  // Q = √T obeys Q̇ = (r/2)(T_sat − Q²)/√T_sat with r = 2√(ab) = √(εD/2), where
  // a = (√π/32)(σ/ν)D and b = (4/√π)(ν/σ)ε are (4.26)'s coefficients divided by 2ν.
  return {saturation, std::sqrt(0.5 * eps * heating_function),
          std::sqrt(initial_temperature / saturation)};
}

}  // namespace granule::theory
