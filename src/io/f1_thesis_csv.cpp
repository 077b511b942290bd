#include "io/f1_thesis_csv.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "distribution/appendix_b_comparison.hpp"

namespace granule {

using namespace granule::distribution;

namespace {

std::string table_number(double value) { return std::isnan(value) ? std::string() : fmt::format("{:.6g}", value); }

}  // namespace

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

}  // namespace granule
