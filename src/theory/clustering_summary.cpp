#include "theory/clustering_summary.hpp"

#include <fmt/format.h>

#include <numbers>

namespace granule::theory {

std::vector<std::string> clustering_lines(const ClusteringScales& scales, double k,
                                          double mean_free_path, double diameter,
                                          double box_length) {
  const double kl = k * mean_free_path;
  const auto& w = scales.window;
  // kl = x is the wavelength 2π/k = 2πl/x: the window's lower edge is its longest wavelength.
  const double longest = 2.0 * std::numbers::pi * mean_free_path / w.lower;
  const double shortest = 2.0 * std::numbers::pi * mean_free_path / w.upper;
  // The default k of shear-start sits on the upper edge kl = √ε: the fastest clustering scale
  // the window allows (after (4.38)).
  const char* where = w.contains(kl)                 ? "inside: clusters"
                      : w.open() && kl == w.upper ? "at the upper edge: the fastest clustering scale"
                                                  : "outside: does not cluster";
  return {
      fmt::format("tau_c = 1/gamma (4.6) {:.6g}   {} {:.6g}   1/s3 ~ sqrt(eps)/(kl gamma) (4.38) "
                  "{:.6g}",
                  scales.convective_time, scales.hot ? "tau_m (4.36)" : "tau'_m (4.41)",
                  scales.mass_motion_time, scales.linear_growth_time),
      fmt::format("clustering window {}: {:.6g} < kl < {:.6g}: {}; kl = {:.6g} {}",
                  scales.hot ? "(4.37)" : "(4.39)-(4.40)", w.lower, w.upper,
                  w.open() ? "open" : "empty (no clustering at early times)", kl, where),
      fmt::format("window as wavelengths 2 pi/k: {:.6g} to {:.6g} sigma = {:.6g} to {:.6g} L_x{}",
                  shortest / diameter, longest / diameter, shortest / box_length,
                  longest / box_length, w.open() ? "" : " (bounds crossed)")};
}

}  // namespace granule::theory
