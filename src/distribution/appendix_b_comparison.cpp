#include "distribution/appendix_b_comparison.hpp"

#include <cmath>

namespace granule::distribution {

namespace {

constexpr double kSameRelative = 1e-6;

bool same_restitution(double a, double b) { return std::abs(a - b) < 1e-9; }

}  // namespace

std::vector<AppendixBEntry> thesis_windows_in_run_units(const SystemParams& run) {
  std::vector<AppendixBEntry> mapped;
  if (run.shear_velocity == 0.0) return mapped;
  const ThesisUnitMap map = appendix_b_unit_map(run);
  for (const AppendixBEntry& entry : appendix_b_means()) {
    if (same_restitution(entry.restitution, run.restitution)) mapped.push_back(map.to_run_units(entry));
  }
  return mapped;
}

bool add_thesis_windows(const SystemParams& run, std::vector<ValueWindow>& densities, std::vector<ValueWindow>& temperatures) {
  const std::vector<AppendixBEntry> mapped = thesis_windows_in_run_units(run);
  const auto add_unique = [](std::vector<ValueWindow>& list, ValueWindow w) {
    for (const ValueWindow& known : list) {
      if (known.center == w.center) return;
    }
    list.push_back(w);
  };
  for (const AppendixBEntry& e : mapped) {
    add_unique(densities, {e.density, e.density_half_width});
    add_unique(temperatures, {e.temperature, e.temperature_half_width});
  }
  return !mapped.empty();
}

std::optional<ThesisMatch> nearest_thesis_window(const SystemParams& run, const WindowResult& window) {
  std::optional<ThesisMatch> best;
  double best_distance = 0.0;
  const ValueWindow &rho = window.density_window, &t = window.temperature_window;
  for (const AppendixBEntry& entry : thesis_windows_in_run_units(run)) {
    const double distance = std::hypot((rho.center - entry.density) / entry.density_half_width,
                                       (t.center - entry.temperature) / entry.temperature_half_width);
    if (best && distance >= best_distance) continue;
    best_distance = distance;
    const bool same = std::abs(rho.center - entry.density) <= kSameRelative * entry.density &&
                      std::abs(t.center - entry.temperature) <= kSameRelative * entry.temperature;
    best = ThesisMatch{entry, same};
  }
  return best;
}

}  // namespace granule::distribution
