#include "distribution/f1_report.hpp"

#include <fmt/format.h>

#include <cmath>

namespace granule::distribution {

std::string describe_window(const WindowResult& r) {
  const SineSeries& b = r.estimate.series;
  return fmt::format("rho {:g}±{:g}, T {:g}±{:g}: {} samples, T = {:.4g}; b0 = ({:.4g}, {:.4g}, {:.4g}); "
                     "Tr tau direct/once/twice = {:.4g}/{:.4g}/{:.4g}; {}",
                     r.density_window.center, r.density_window.half_width, r.temperature_window.center,
                     r.temperature_window.half_width, r.samples, r.temperature, b.mean[0], b.mean[1], b.mean[2],
                     r.estimate.direct.trace(), r.estimate.once_integrals.moment.trace(),
                     r.estimate.twice_integrals.moment.trace(), fits_summary(r));
}

std::string fits_summary(const WindowResult& r) {
  const auto word = [](const FitReport& f) { return f.converged ? "converged" : "NOT converged (" + f.status + ")"; };
  return fmt::format("phi* {}, psi* {}, series {}; h* within thesis tolerance: {}", word(r.estimate.once.speed.report),
                     word(r.estimate.once.angular.report), word(r.estimate.series.report),
                     r.quality.within_tolerance() ? "yes" : "no");
}

std::string describe_thesis_comparison(const ThesisMatch& match, const WindowResult& window) {
  const AppendixBEntry& e = match.entry;
  const double b1 = window.estimate.series.mean[1], error = window.errors.series.mean[1];
  return fmt::format("  Appendix B {}at rho {:.4g}, T {:.4g} (thesis units mapped to this run's): b0^(1) = {:.4g}, "
                     "sqrt(2T) b0^(1) = {:.3g}; here {:.4g} ± {:.2g}, sqrt(2T) b0^(1) = {:.3g} (ratio {:.3g})",
                     match.same_window ? "" : "(nearest window) ", e.density, e.temperature, e.b1,
                     std::sqrt(2.0 * e.temperature) * e.b1, b1, error, window.speed_scale * b1, b1 / e.b1);
}

std::string describe_thesis_units(const SystemParams& run) {
  const ThesisUnitMap map = appendix_b_unit_map(run);
  return fmt::format("Appendix B windows in this run's units: lengths × {:.4g}, velocities × {:.4g} of the thesis's "
                     "(N = 2e5, L = 1, U = 100, sigma = {:.4g}); this box is {:.4g} sigma wide, the thesis's {:.4g}",
                     map.length, map.velocity, AppendixBSystem::diameter(), run.length_x / run.diameter,
                     AppendixBSystem::box / AppendixBSystem::diameter());
}

}  // namespace granule::distribution
