#include "reproduce/free_cooling.hpp"

#include <numbers>
#include <vector>

#include "theory/free_gas_stability.hpp"
#include "theory/haff.hpp"
#include "theory/kinetic_scales.hpp"

namespace granule::reproduce {

double linear_stability_onset_c(double restitution, int particles, double diameter, double box) {
  const double eps = theory::inelasticity(restitution);
  const double K = 2.0 * std::numbers::pi * theory::effective_mean_free_path(diameter, kFreeCoolingAreaFraction) / box;
  const double growth = theory::free_gas_shear_eigenvalue(K, eps) + 2.0 * eps;
  return growth > 0.0 ? std::log(static_cast<double>(particles)) / growth : NAN;
}

CoolingMeasures measure_cooling(const PointOutputs& p, double early_to_c) {
  CoolingMeasures m;
  const EarlyDecay decay = early_decay(p.samples, early_to_c, kOnsetExcess);
  m.early_slope = decay.temperature_slope;
  m.onset_c = decay.onset_c;
  std::vector<double> log_t, log_late, log_energy;
  for (const DiagnosticsSample& s : p.samples) {
    if (std::isfinite(m.onset_c) && s.c >= 2.0 * m.onset_c && s.t > 0.0) {
      log_t.push_back(std::log(s.t));
      log_late.push_back(std::log(s.temperature));
      log_energy.push_back(std::log(s.kinetic_energy));
    }
  }
  m.late_exponent = fit_line(log_t, log_late).slope;
  m.late_energy_exponent = fit_line(log_t, log_energy).slope;
  return m;
}

}  // namespace granule::reproduce
