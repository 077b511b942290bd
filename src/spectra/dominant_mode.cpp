#include "spectra/dominant_mode.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "theory/hard_spheres.hpp"

namespace granule::spectra {

DominantMode dominant_mode(const PowerMaps& maps, const std::vector<double>& power, const ModeNoise& noise,
                           double false_alarm) {
  const std::size_t origin = maps.modes.index(0, 0);
  std::size_t best = origin, included = 0;
  for (std::size_t i = 0; i < power.size(); ++i) {
    if (i == origin || std::isnan(power[i])) continue;
    ++included;
    if (best == origin || power[i] > power[best]) best = i;
  }
  DominantMode mode;
  if (best == origin) return mode;
  const auto side = static_cast<std::size_t>(maps.modes.side());
  mode.l = static_cast<int>(best % side) - maps.modes.max_mode;
  mode.m = static_cast<int>(best / side % side) - maps.modes.max_mode;
  mode.n = static_cast<int>(best / maps.modes.plane_count()) - maps.modes.max_mode_z();
  mode.kx = maps.kx[best];
  mode.ky = maps.ky[best];
  if (!maps.kz.empty()) mode.kz = maps.kz[best];
  if (mode.ky < 0.0 || (mode.ky == 0.0 && (mode.kx < 0.0 || (mode.kx == 0.0 && mode.kz < 0.0)))) {
    mode.l = -mode.l;
    mode.m = -mode.m;
    mode.n = -mode.n;
    mode.kx = -mode.kx;
    mode.ky = -mode.ky;
    mode.kz = -mode.kz + 0.0;
  }
  mode.k = maps.kz.empty() ? std::hypot(mode.kx, mode.ky) : std::hypot(mode.kx, mode.ky, mode.kz);
  mode.angle_deg = std::atan2(mode.ky, mode.kx) * 180.0 / std::numbers::pi + 0.0;  // + 0.0 turns −0° into 0°
  mode.length = 2.0 * std::numbers::pi / mode.k;
  mode.power = power[best];
  if (noise.level > 0.0) {
    mode.power_over_ideal_gas = mode.power / noise.level;
    mode.independent_modes = 0.5 * static_cast<double>(included);  // S(−k) = S(k)*: pairs
    mode.noise_p_value = false_alarm_probability(single_mode_survival(mode.power_over_ideal_gas, noise.shares),
                                                 mode.independent_modes);
    mode.noise_threshold = noise_threshold(false_alarm, mode.independent_modes, noise.shares);
    mode.significant = mode.noise_p_value < false_alarm;
  }
  return mode;
}

double mean_free_path(const SystemParams& system) {
  if (system.dimension == 3) {
    const double density = static_cast<double>(system.particles) / (system.length_x * system.length_y * system.length_z);
    return theory::hard_sphere_mean_free_path(3, density, system.diameter, 1.0);
  }
  return system.length_x * system.length_y / (2.0 * static_cast<double>(system.particles) * system.diameter);
}

double cluster_length(const SystemParams& system) {
  const double dissipation = 1.0 - system.restitution * system.restitution;
  return dissipation > 0.0 ? mean_free_path(system) / std::sqrt(dissipation) : std::numeric_limits<double>::infinity();
}

}  // namespace granule::spectra
