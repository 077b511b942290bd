// The space–time picture of a run's streamwise profiles ρ(y, t), V_x(y, t), T(y, t), time across and
// y up, with U(t) above when the profiles have it (thesis Figs 4.7–4.8), drawn by
// python/granule_plots/spacetime.py from the HDF5 file of the arrays (io/spacetime_file.hpp).
#pragma once

#include <string>

#include "analysis/spacetime_profiles.hpp"

namespace granule::render {

// Writes the arrays to `<data>.partial`, draws the PNG `out` from them at `dpi`, and only then gives
// the arrays their name `data`, so that the two are published together (the partial file is
// removed whatever happens).  Returns the script's exit code: 0 when both were written.
int draw_spacetime(const SpacetimeProfiles& profiles, const std::string& out, const std::string& data, int dpi);

}  // namespace granule::render
