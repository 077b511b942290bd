#include "spectra/dominant_mode_report.hpp"

#include <fmt/format.h>

#include <cmath>

namespace granule::spectra {

std::string describe_comparison(const SystemParams& system, double cluster_length, double false_alarm) {
  const std::string free_path = system.dimension == 3 ? "l = 1/(√2 π n σ²) (Boltzmann)" : "l = L_x L_y/(2Nσ) (§3.1.2)";
  return fmt::format("dominant lengths 2π/|k| are compared with L0 = l/√(1−ẽ²) (eq 1.1) = {:.4g}, {} = {:.4g}; "
                     "a mode is significant when uncorrelated positions would put as much power into one of the "
                     "modes compared with probability < {:g}",
                     cluster_length, free_path, mean_free_path(system), false_alarm);
}

std::string describe_dominant(const char* name, const DominantMode& mode, double cluster_length,
                              double false_alarm) {
  const std::string where = fmt::format("{}: largest mode 2π/|k| = {:.4g} ({:.3g} L0) at {:.1f}°{}", name, mode.length,
                                        mode.length / cluster_length, mode.angle_deg,
                                        mode.kz != 0.0 ? fmt::format(", k_z = {:.4g}", mode.kz) : std::string());
  const std::string noise = fmt::format("{:.3g} × the noise level, false-alarm p = {:.2g} over {:g} modes", mode.power_over_ideal_gas,
                                        mode.noise_p_value, mode.independent_modes);
  return mode.significant ? fmt::format("{}: {}: significant", where, noise)
                          : fmt::format("{}: {}: no significant mode (needs > {:.3g} × noise at p < {:g})", where, noise,
                                        mode.noise_threshold, false_alarm);
}

void SignificanceTally::add(const DominantMode& mode, double cluster_length) {
  ++frames_;
  if (!mode.significant) return;
  ++significant_;
  sum_length_over_l0_ += mode.length / cluster_length;
}

std::string SignificanceTally::summary(const char* name, double false_alarm) const {
  if (significant_ == 0) {
    return fmt::format("{}: no significant mode in any of {} frames (false-alarm level {:g})", name, frames_, false_alarm);
  }
  return fmt::format("{}: significant dominant mode in {} of {} frames (false-alarm level {:g}); their mean 2π/|k| = {:.3g} L0",
                     name, significant_, frames_, false_alarm, sum_length_over_l0_ / significant_);
}

}  // namespace granule::spectra
