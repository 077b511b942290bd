// The shell (3D) or annulus (2D) average of the power relative to the ideal-gas level: for the mass
// S(k) = ⟨R⟩_shell / (Σ_j m_j²/4π²), the static structure factor per particle (|Σ_j e^{ik·r_j}|²/N
// averaged over the modes with |k| in the shell, for unit masses), and likewise for the momentum,
// ⟨P⟩_shell / (Σ_j m_j² |v_j|²/4π²).  For uncorrelated positions the mass power of each mode, over its
// mean, is exponentially distributed with mean 1 and sd 1, and S(−k) = S(k)*: the average over the c
// modes of a shell has mean 1 and standard deviation √(2/c) — the statistical band reported beside S.
// The momentum power sums d components, whose relative sd is PowerMaps::ideal_momentum_spread (≈ 1/√d):
// its band is √(2/c) times that.
#pragma once

#include <vector>

#include "spectra/power_spectra.hpp"

namespace granule::spectra {

struct ShellStructureFactor {
  std::vector<double> density, momentum;        // S_R(k), S_P(k): 1 for uncorrelated positions
  std::vector<double> density_sd, momentum_sd;  // one sd of an uncorrelated gas's shell average
};

// From the shell sums of `maps`; a shell without modes gets NaN.
ShellStructureFactor shell_structure_factor(const AnnulusSpectrum& shells, const PowerMaps& maps);

}  // namespace granule::spectra
