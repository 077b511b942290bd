#include "distribution/window_sampling.hpp"

#include <cmath>
#include <stdexcept>

#include "analysis/cell_fields.hpp"

namespace granule::distribution {

std::optional<ValueWindow> parse_value_window(const std::string& text) {
  for (const std::string separator : {"±", "+/-", "+-"}) {
    const std::size_t at = text.find(separator);
    if (at == std::string::npos) continue;
    try {
      std::size_t used_center = 0, used_width = 0;
      const std::string center = text.substr(0, at), width = text.substr(at + separator.size());
      ValueWindow w{std::stod(center, &used_center), std::stod(width, &used_width)};
      if (used_center != center.size() || used_width != width.size() || !std::isfinite(w.center) ||
          !(w.half_width > 0.0) || !std::isfinite(w.half_width))
        return std::nullopt;
      return w;
    } catch (const std::exception&) {
      return std::nullopt;
    }
  }
  return std::nullopt;
}

void sample_configuration(const ParticleState& state, const ShearFrame& frame, const SamplingOptions& options,
                          std::vector<WindowSamples>& windows) {
  CellMoments moments(options.grid);
  moments.add(state, frame, options.subtract_shear_profile);
  // The shear offset only enters the vorticity, which is not used here.
  const CellFields fields = fields_from_moments(moments, frame, 0.0, options.subtract_shear_profile);
  const double cell_area = options.grid.cell_area();
  for (WindowSamples& w : windows) {
    // Step (2): the set S(ρ, T) of cells inside both windows (empty cells have no temperature).
    std::vector<char> selected(fields.count.size(), 0);
    double area = 0.0, temperature_weighted = 0.0;
    for (std::size_t c = 0; c < fields.count.size(); ++c) {
      if (fields.count[c] > 0.0 && w.density.contains(fields.density[c]) && w.temperature.contains(fields.temperature[c])) {
        selected[c] = 1;
        area += cell_area;
        temperature_weighted += fields.count[c] * fields.temperature[c];
      }
    }
    // Step (3): the fluctuating velocities of their particles.
    for (std::size_t i = 0; i < state.size(); ++i) {
      const std::size_t c = options.grid.index(state.x[i], state.y[i]);
      if (!selected[c]) continue;
      const double profile = options.subtract_shear_profile ? frame.mean_flow(state.y[i]) : 0.0;
      w.vx.push_back(state.vx[i] - profile - fields.velocity_x[c]);
      w.vy.push_back(state.vy[i] - fields.velocity_y[c]);
    }
    w.snapshot_end.push_back(w.vx.size());
    w.selected_area.push_back(area);
    w.temperature_weighted.push_back(temperature_weighted);
  }
}

}  // namespace granule::distribution
