// The Fourier transforms of the mass and momentum densities of one configuration, thesis (3.4)–(3.5):
//     ρ̃(k) = (1/2π) Σ_j m_j exp(i k·r_j),   p̃(k) = (1/2π) Σ_j m_j v_j exp(i k·r_j),
// m_j = 1 unless the run is polydisperse, or, with the linear shear profile removed,
// p̃′(k) = (1/2π) Σ_j m_j (v_j − u(y_j) x̂) exp(i k·r_j) (3.17) with u(y) = γ (y − L_y/2) (the thesis writes
// γ y_j with y measured from the centre line; we keep its 1/2π, which (3.17) as printed drops).  The
// wavevectors are those of reciprocal_lattice.hpp, in 2D or 3D (where p̃ gains p̃_z; the same 1/2π is
// kept so that the 2D and 3D numbers read alike).
// For uncorrelated positions ⟨|ρ̃|²⟩ = Σ_j m_j²/4π² and ⟨|p̃|²⟩ = Σ_j m_j² |v_j|²/4π² at every k ≠ 0
// (the ideal-gas level; N/4π² and Σ_j v_j²/4π² for unit masses).
#pragma once

#include <array>

#include "engine/system_params.hpp"
#include "spectra/fast_mode_sums.hpp"
#include "spectra/mode_sums.hpp"
#include "spectra/reciprocal_lattice.hpp"

namespace granule::spectra {

enum class SpectralMethod { fast, exact };

struct TransformOptions {
  int max_mode = 32;                    // M: modes |l|, |m| (, |n|) ≤ M
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
  ModeValues momentum_z = {};    // 3D only
  double ideal_density = 0.0;  // Σ_j m_j²/4π²: ⟨|ρ̃|²⟩ of uncorrelated positions
  // Σ_j m_j² v_{j,a}²/4π² for a = x, y (, z) (v′_x with the profile removed): ⟨|p̃_a|²⟩ likewise
  std::array<double, 3> ideal_momentum_axes = {};
  // The sd of |p̃|² over its mean for uncorrelated positions: the components are complex Gaussians with
  // covariance C_ab = Σ_j m_j² v_{j,a} v_{j,b}/4π², so Var |p̃|² = Σ_ab C_ab² and the ratio is
  // √(Σ_ab C_ab²)/tr C — 1 for a single component, ≈ 1/√d for d equal uncorrelated ones.
  double ideal_momentum_spread = 1.0;
  // The eigenvalues of C over tr C: |p̃|²/tr C of uncorrelated positions is Σ_i λ_i E_i with E_i
  // independent Exp(1) (spectra/mode_significance.hpp); {1, 0, 0} when every velocity is zero.
  std::array<double, 3> ideal_momentum_shares = {1.0, 0.0, 0.0};
};

// `state` holds lab-frame positions inside the box, of the lattice's dimension (std::invalid_argument
// otherwise); `frame` gives the shear profile that `subtract_shear_profile` removes.
DensityMomentumTransforms transform_fields(const ParticleState& state, const ShearFrame& frame,
                                           const ReciprocalLattice& lattice, const TransformOptions& options);

// 2D: the lattice of the frame with Lees–Edwards image offset `shear_offset` (Δ).
DensityMomentumTransforms transform_fields(const ParticleState& state, const ShearFrame& frame, double shear_offset,
                                           const TransformOptions& options);

}  // namespace granule::spectra
