// The dominant wavevector of a power map, how far it stands above the noise of uncorrelated positions,
// and the cluster length scale it is compared with: L0 = l/√(1 − ẽ²) (eq 1.1, 3.18) with the mean free
// path l = L_x L_y/(2Nσ) of §3.1.2 for disks; for spheres the same formula with the Boltzmann mean free
// path of theory/hard_spheres.hpp, l = 1/(√2 π n σ²), n = N/(L_x L_y L_z) (the thesis gives no 3D l).
#pragma once

#include <vector>

#include "engine/system_params.hpp"
#include "spectra/mode_significance.hpp"
#include "spectra/power_spectra.hpp"

namespace granule::spectra {

struct DominantMode {
  int l = 0, m = 0, n = 0;  // lattice indices (n = 0 in 2D), chosen with angle in [0°, 180°)
  double kx = 0.0, ky = 0.0, kz = 0.0;
  double k = 0.0;           // |k|
  double angle_deg = 0.0;   // of (k_x, k_y) from the +k_x axis, in [0°, 180°): 135° ⇔ structures along 45°
  double length = 0.0;      // 2π/|k|: the dominant length scale
  double power = 0.0;
  // Its significance against uncorrelated positions (spectra/mode_significance.hpp): s = power / ⟨power⟩
  // of such a gas (the noise level), the K independent modes (pairs ±k) compared, the false-alarm
  // probability p = 1 − (1 − Q(s))^K that noise puts at least s into one of them, the s at which p
  // equals the chosen false-alarm level, and whether this mode lies above it (p < level).
  double power_over_ideal_gas = 0.0;
  double independent_modes = 0.0;
  double noise_p_value = 1.0;
  double noise_threshold = 0.0;
  bool significant = false;
};

// The mode of largest power among all computed modes except k = 0 and excluded (NaN) ones; `noise` is
// the field's power for uncorrelated positions (no significance when its level is 0), `false_alarm`
// the level in (0, 1) below which p makes the mode significant.  Power is even in k, so of the pair ±k
// the one with k_y > 0 (or k_y = 0 and k_x > 0, or k ∥ +ẑ) is returned.
DominantMode dominant_mode(const PowerMaps& maps, const std::vector<double>& power, const ModeNoise& noise = {},
                           double false_alarm = kDefaultFalseAlarm);

double mean_free_path(const SystemParams& system);   // l: 2D (§3.1.2) or 3D (Boltzmann), above
double cluster_length(const SystemParams& system);   // L0 = l/√(1 − ẽ²) (1.1); +∞ when ẽ = 1

}  // namespace granule::spectra
