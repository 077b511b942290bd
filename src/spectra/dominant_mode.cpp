#include "spectra/dominant_mode.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace granule::spectra {

DominantMode dominant_mode(const PowerMaps& maps, const std::vector<double>& power) {
  const std::size_t origin = maps.modes.index(0, 0);
  std::size_t best = origin;
  for (std::size_t i = 0; i < power.size(); ++i) {
    if (i != origin && !std::isnan(power[i]) && (best == origin || power[i] > power[best])) best = i;
  }
  DominantMode mode;
  if (best == origin) return mode;
  const int side = maps.modes.side();
  mode.l = static_cast<int>(best % static_cast<std::size_t>(side)) - maps.modes.max_mode;
  mode.m = static_cast<int>(best / static_cast<std::size_t>(side)) - maps.modes.max_mode;
  mode.kx = maps.kx[best];
  mode.ky = maps.ky[best];
  if (mode.ky < 0.0 || (mode.ky == 0.0 && mode.kx < 0.0)) {
    mode.l = -mode.l;
    mode.m = -mode.m;
    mode.kx = -mode.kx;
    mode.ky = -mode.ky;
  }
  mode.k = std::hypot(mode.kx, mode.ky);
  mode.angle_deg = std::atan2(mode.ky, mode.kx) * 180.0 / std::numbers::pi + 0.0;  // + 0.0 turns −0° into 0°
  mode.length = 2.0 * std::numbers::pi / mode.k;
  mode.power = power[best];
  return mode;
}

double mean_free_path(const SystemParams& system) {
  return system.length_x * system.length_y / (2.0 * static_cast<double>(system.particles) * system.diameter);
}

double cluster_length(const SystemParams& system) {
  const double dissipation = 1.0 - system.restitution * system.restitution;
  return dissipation > 0.0 ? mean_free_path(system) / std::sqrt(dissipation) : std::numeric_limits<double>::infinity();
}

}  // namespace granule::spectra
