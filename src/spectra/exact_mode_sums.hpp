// The reference method: the sums of mode_sums.hpp evaluated term by term, cos and sin of k·r_j in
// the lab frame for every particle and mode (cost N × (2M+1)^d: in 3D N = 10⁴, M = 16 is ~4 · 10⁸ cos/sin
// pairs, a few seconds).  The fast method is tested against it.
#pragma once

#include "spectra/mode_sums.hpp"
#include "spectra/reciprocal_lattice.hpp"

namespace granule::spectra {

std::vector<ModeValues> exact_mode_sums(const WeightedPoints& points, const ReciprocalLattice& lattice, int max_mode);

}  // namespace granule::spectra
