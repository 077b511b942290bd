// The fast method for the sums of mode_sums.hpp (a type-1 non-uniform FFT): deposit every particle
// on an n × n grid with a known window (gridding_kernel.hpp), FFT the grid, keep the modes
// |l|, |m| ≤ M and divide by the window's Fourier transform.  Cost O(N w² + n² log n) instead of
// O(N M²); n ≈ upsampling · (2M + 1).
//
// Lees–Edwards boxes: in the sheared coordinate ξ = x − [γt] y the lattice of (3.10)–(3.12) is
// rectangular (k·r = 2πl ξ/L_x + 2πm y/L_y) and every field of the box is periodic in (ξ mod L_x, y),
// so the same grid and FFT serve: particles are deposited at (ξ mod L_x, y).
//
// 3D: the same on an n³ grid (deposited straight into it with periodic wrapping: a padded grid would
// cost ((n + 2w)/n)³ more), at (ξ mod L_x, y, z mod L_z), z plainly periodic.  Cost O(N w³ + n³ log n),
// memory one complex n³ grid, 16 n³ bytes, at a time: the pairs of fields are gridded one after the
// other (M = 32: n = 135, 39 MB; M = 64: n = 270, 315 MB).
//
// Accuracy (tested against exact_mode_sums): the error of a mode is a small fraction of the window's
// aliasing, ~10^−(w−1), times a sum over particles — it scales like √(Σ w_j²) for scattered
// particles and like |S(k)| for a coherent mode.  See docs/spectra.md for the metric.
#pragma once

#include "spectra/mode_sums.hpp"
#include "spectra/reciprocal_lattice.hpp"

namespace granule::spectra {

struct GriddingOptions {
  int kernel_width = 8;     // w grid points per direction; error ~10^−(w−1)
  double upsampling = 2.0;  // grid size over the number of modes per direction, 2M + 1
};

// The FFT grid size: the smallest 2^a 3^b 5^c ≥ upsampling·(2M+1) (and ≥ 2w).
int fft_grid_size(int max_mode, const GriddingOptions& options);

std::vector<ModeValues> fast_mode_sums(const WeightedPoints& points, const ReciprocalLattice& lattice, int max_mode,
                                       const GriddingOptions& options = {});

}  // namespace granule::spectra
