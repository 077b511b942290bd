// The Fourier transforms of the mass and momentum densities of one configuration, thesis (3.4)–(3.5):
//     ρ̃(k) = (1/2π) m Σ_j exp(i k·r_j),   p̃(k) = (1/2π) m Σ_j v_j exp(i k·r_j),   m = 1,
// or, with the linear shear profile removed, p̃′(k) = (1/2π) m Σ_j (v_j − u(y_j) x̂) exp(i k·r_j) (3.17)
// with u(y) = γ (y − L_y/2) (the thesis writes γ y_j with y measured from the centre line; we keep its
// 1/2π, which (3.17) as printed drops).  The wavevectors are those of reciprocal_lattice.hpp.
// For uncorrelated positions ⟨|ρ̃|²⟩ = N/4π² and ⟨|p̃|²⟩ = Σ_j v_j²/4π² (the ideal-gas level).
#pragma once

#include "engine/system_params.hpp"
#include "spectra/fast_mode_sums.hpp"
#include "spectra/mode_sums.hpp"
#include "spectra/reciprocal_lattice.hpp"

namespace granule::spectra {

enum class SpectralMethod { fast, exact };

struct TransformOptions {
  int max_mode = 32;                    // M: modes |l|, |m| ≤ M
  SpectralMethod method = SpectralMethod::fast;
  bool subtract_shear_profile = false;  // p̃′ (3.17) instead of p̃ (3.5)
  GriddingOptions gridding;             // fast method only
};

struct DensityMomentumTransforms {
  ReciprocalLattice lattice;
  ModeGrid modes;
  ModeValues density;     // ρ̃ (3.4)
  ModeValues momentum_x;  // p̃_x (3.5) or p̃′_x (3.17)
  ModeValues momentum_y;
};

// `state` holds lab-frame positions inside the box; `shear_offset` is the Lees–Edwards image offset Δ.
DensityMomentumTransforms transform_fields(const ParticleState& state, const ShearFrame& frame, double shear_offset,
                                           const TransformOptions& options);

}  // namespace granule::spectra
