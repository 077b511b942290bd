// The peak memory [bytes] the spectra of one configuration allocate (transform_fields, power_maps,
// annulus_sums), so that a caller can refuse an analysis the machine cannot hold before any of it
// is allocated.  Counted from what the code allocates, phase by phase; the caller adds its own
// copy of the configuration and what it makes of the results.
#pragma once

#include <cstddef>

#include "spectra/spectral_transforms.hpp"

namespace granule::spectra {

// N particles in `dimension` (2 or 3) up to the modes and with the method of `options`, summed
// into `annuli` rings (annulus_count).
double spectra_bytes(std::size_t particles, int dimension, const TransformOptions& options, double annuli);

}  // namespace granule::spectra
