// Steps (1)–(3) of the cumulative sampling algorithm (thesis §5.2): divide each configuration
// into the cells of §1.4.3, select the cells whose density ρ (particles per unit area) and
// temperature T (1.3) lie in given windows, and collect the fluctuating velocities
// v' = v − V(cell) of their particles, snapshot by snapshot (the ensemble of (5.7) is the set
// of snapshots, which the bootstrap resamples).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "analysis/field_grid.hpp"
#include "boundary/shear_frame.hpp"
#include "engine/system_params.hpp"

namespace granule::distribution {

// A closed interval centre ± half_width.
struct ValueWindow {
  double center = 0.0;
  double half_width = 0.0;
  bool contains(double value) const { return value >= center - half_width && value <= center + half_width; }
};

// A window written "C±W", "C+-W" or "C+/-W" with W > 0 (docs/f1.md); none when the text is not one.
std::optional<ValueWindow> parse_value_window(const std::string& text);

struct WindowSamples {
  ValueWindow density;      // particles per unit area
  ValueWindow temperature;  // T = ½⟨v'²⟩
  std::vector<double> vx, vy;               // v' of the selected particles, all snapshots
  std::vector<std::size_t> snapshot_end;    // samples of snapshot k are [end[k−1], end[k])
  std::vector<double> selected_area;        // Ω_{ρ,T} of each snapshot (area of the selected cells)
  std::vector<double> temperature_weighted; // Σ over selected cells of count × T(cell), per snapshot

  std::size_t snapshots() const { return snapshot_end.size(); }
  std::size_t samples() const { return vx.size(); }
};

struct SamplingOptions {
  FieldGrid grid;
  // Lees–Edwards: take velocities relative to the imposed profile u(y) before the cell average,
  // so that v' = v − u(y) − ⟨v − u⟩_cell.  This removes the spread γ·Δy of the mean flow across a
  // cell, which the plain cell average (the thesis's literal definition) leaves in v'_x.
  bool subtract_shear_profile = false;
};

// Adds one configuration to every window (each window gets one more snapshot, possibly empty).
void sample_configuration(const ParticleState& state, const ShearFrame& frame, const SamplingOptions& options,
                          std::vector<WindowSamples>& windows);

}  // namespace granule::distribution
