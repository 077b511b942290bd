// Power spectra of the transformed fields: the maps R(k) = |ρ̃|² (3.13), P_x = |p̃_x|² (3.14),
// P_y = |p̃_y|² (3.15) (and P_z = |p̃_z|² in 3D) and P = |p̃|² = P_x + P_y (+ P_z) (Figs 3.21–3.27), and
// their annulus integrals R(k), P(k) against |k| (Figs 2.8–2.10) — in 3D shell integrals: the sum over
// the allowed modes with |k| in a ring (shell) of width Δk.  Under equipartition every mode carries the
// same power, so annulus sums grow linearly in k, shell sums quadratically.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "spectra/mode_significance.hpp"
#include "spectra/spectral_transforms.hpp"

namespace granule::spectra {

struct PowerMaps {
  ReciprocalLattice lattice;
  ModeGrid modes;
  std::vector<double> kx, ky;      // the wavevector of each mode
  std::vector<double> density;     // R (3.13)
  std::vector<double> momentum_x;  // P_x (3.14); NaN on the k_y axis when it is left out
  std::vector<double> momentum_y;  // P_y (3.15)
  std::vector<double> momentum;    // P = P_x + P_y (+ P_z) (NaN where P_x is)
  std::vector<double> kz = {}, momentum_z = {};  // 3D only
  double ideal_density = 0.0;                        // ⟨R⟩ of uncorrelated positions
  std::array<double, 3> ideal_momentum_axes = {};     // ⟨P_x⟩, ⟨P_y⟩, ⟨P_z⟩ likewise
  double ideal_momentum_spread = 1.0;                 // sd of P over its mean, likewise
  std::array<double, 3> ideal_momentum_shares = {1.0, 0.0, 0.0};  // P's components' shares, likewise

  double ideal_momentum() const { return ideal_momentum_axes[0] + ideal_momentum_axes[1] + ideal_momentum_axes[2]; }
  // The power of one mode of uncorrelated positions (mode_significance.hpp): R, one component a of p̃, P.
  ModeNoise density_noise() const { return ModeNoise(ideal_density); }
  ModeNoise momentum_component_noise(int axis) const { return ModeNoise(ideal_momentum_axes[static_cast<std::size_t>(axis)]); }
  ModeNoise momentum_noise() const {
    return {ideal_momentum(), {ideal_momentum_shares.begin(), ideal_momentum_shares.end()}};
  }
  double k(std::size_t i) const;  // |k| of mode i
};

// `exclude_ky_axis_from_px`: leave out the modes on the k_y axis (l = 0, and n = 0 in 3D) of P_x,
// which carry the linear shear profile and the global trend of p′_x (thesis §3.2.1, after
// (3.16)–(3.17)); the profile depends on y alone, so in 3D only k ∥ ŷ carries it.
PowerMaps power_maps(const DensityMomentumTransforms& transforms, bool exclude_ky_axis_from_px);

// Annulus (shell) integrals: bin b collects the modes with (b − ½)Δk ≤ |k| < (b + ½)Δk, i.e. the thesis's
// ring "from k to k + Δk" centred on k = bΔk, so that the shortest lattice modes (|k| = 2π/L for
// Δk = 2π/L) sit mid-bin instead of on an edge.  Only rings that lie wholly inside `max_radius` are
// reported (b ≥ 1, (b + ½)Δk ≤ max_radius), which must not exceed the radius where all lattice modes
// were computed (ReciprocalLattice::complete_radius); excluded (NaN) modes are left out of the sums
// (and of `momentum_modes`).
struct AnnulusSpectrum {
  double dk = 0.0;
  std::vector<double> k;                // ring centres bΔk
  std::vector<std::int64_t> modes;      // lattice modes in each ring
  std::vector<double> density, momentum_x, momentum_y, momentum;
  std::vector<double> momentum_z = {};            // 3D only
  std::vector<std::int64_t> momentum_modes = {};  // modes in each ring that P includes
};

AnnulusSpectrum annulus_sums(const PowerMaps& maps, double dk, double max_radius);

// How many rings of width `dk` lie wholly inside `max_radius` (b = 1 … floor(max_radius/dk − ½)):
// those annulus_sums reports, counted before anything is allocated for them.
double annulus_count(double dk, double max_radius);
// The most rings annulus_sums makes (their count is a size_t): a narrower dk throws
// std::length_error before anything is allocated for them.
inline constexpr double kMaxAnnuli = 4294967296.0;  // 2^32

// Default Δk: the spacing 2π/max(L_x, L_y (, L_z)) of the lattice along its longest side.
double default_annulus_width(const ReciprocalLattice& lattice);

}  // namespace granule::spectra
