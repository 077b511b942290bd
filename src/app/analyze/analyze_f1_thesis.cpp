// The comparison of `granule analyze f1` with thesis Appendix B, like with like: the thesis's windows
// and b₀⁽ⁱ⁾ are mapped to the run's units (distribution/appendix_b_reference.hpp) before anything is
// compared, and the dimensionless forms √(2T) b₀⁽¹⁾, 2T b₀⁽²⁾ are written beside them.
#include <fmt/format.h>

#include <cmath>

#include "app/analyze/analyze_f1.hpp"

namespace granule::app {

using namespace granule::distribution;

namespace {

constexpr double kSameRelative = 1e-6;

bool same_restitution(double a, double b) { return std::abs(a - b) < 1e-9; }

std::string table_number(double value) { return std::isnan(value) ? std::string() : fmt::format("{:.6g}", value); }

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

std::string describe_thesis_comparison(const ThesisMatch& match, const WindowResult& window) {
  const AppendixBEntry& e = match.entry;
  const double b1 = window.estimate.series.mean[1], error = window.errors.series.mean[1];
  return fmt::format("  Appendix B {}at rho {:.4g}, T {:.4g} (thesis units mapped to this run's): b0^(1) = {:.4g}, "
                     "sqrt(2T) b0^(1) = {:.3g}; here {:.4g} ± {:.2g}, sqrt(2T) b0^(1) = {:.3g} (ratio {:.3g})",
                     match.same_window ? "" : "(nearest window) ", e.density, e.temperature, e.b1,
                     std::sqrt(2.0 * e.temperature) * e.b1, b1, error, window.speed_scale * b1, b1 / e.b1);
}

std::string thesis_comparison_csv(const SystemParams& run, const std::vector<WindowResult>& windows) {
  std::string csv;
  const ThesisUnitMap map = appendix_b_unit_map(run);
  for (std::size_t w = 0; w < windows.size(); ++w) {
    const std::optional<ThesisMatch> match = nearest_thesis_window(run, windows[w]);
    if (!match) continue;
    const WindowResult& r = windows[w];
    const AppendixBEntry& e = match->entry;
    const SineSeries &b = r.estimate.series, &error = r.errors.series;
    const double s = r.speed_scale, s_thesis = std::sqrt(2.0 * e.temperature);
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", w,
                       table_number(r.density_window.center), table_number(r.temperature_window.center), table_number(e.density), table_number(e.temperature),
                       match->same_window ? 1 : 0, table_number(e.b0), table_number(e.b1), table_number(e.b2), table_number(b.mean[0]), table_number(error.mean[0]),
                       table_number(b.mean[1]), table_number(error.mean[1]), table_number(b.mean[2]), table_number(error.mean[2]), table_number(b.mean[1] / e.b1),
                       table_number((b.mean[1] - e.b1) / error.mean[1]), table_number(s_thesis * e.b1), table_number(s * b.mean[1]),
                       table_number(s_thesis * s_thesis * e.b2), table_number(s * s * b.mean[2]), table_number(map.length), table_number(map.velocity));
  }
  if (csv.empty()) return csv;
  return "window,rho_center,T_center,thesis_rho_center,thesis_T_center,same_window,thesis_b0_0,thesis_b1_0,"
         "thesis_b2_0,b0_0,b0_0_error,b1_0,b1_0_error,b2_0,b2_0_error,b1_ratio,b1_deviation_in_errors,"
         "thesis_sqrt2T_b1_0,sqrt2T_b1_0,thesis_twoT_b2_0,twoT_b2_0,length_per_thesis_length,"
         "velocity_per_thesis_velocity\n" +
         csv;
}

}  // namespace granule::app
