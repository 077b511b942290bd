// The dominant wavevector of a power map and the cluster length scale it is compared with:
// L0 = l/√(1 − ẽ²) (eq 1.1, 3.18) with the mean free path l = L_x L_y/(2Nσ) of §3.1.2.
#pragma once

#include <vector>

#include "engine/system_params.hpp"
#include "spectra/power_spectra.hpp"

namespace granule::spectra {

struct DominantMode {
  int l = 0, m = 0;         // lattice indices, chosen with angle in [0°, 180°)
  double kx = 0.0, ky = 0.0;
  double k = 0.0;           // |k|
  double angle_deg = 0.0;   // of k from the +k_x axis, in [0°, 180°): 135° ⇔ structures along 45°
  double length = 0.0;      // 2π/|k|: the dominant length scale
  double power = 0.0;
};

// The mode of largest power among all computed modes except k = 0 and excluded (NaN) ones.  Power is
// even in k, so of the pair ±k the one with angle in [0°, 180°) is returned.
DominantMode dominant_mode(const PowerMaps& maps, const std::vector<double>& power);

double mean_free_path(const SystemParams& system);   // l = L_x L_y / (2Nσ)  (§3.1.2)
double cluster_length(const SystemParams& system);   // L0 = l/√(1 − ẽ²) (1.1); +∞ when ẽ = 1

}  // namespace granule::spectra
