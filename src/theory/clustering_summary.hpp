// The summary lines of the clustering picture of thesis §4.2 at one wavenumber (time scales
// (4.6), (4.36), (4.38), (4.41) and the window (4.37) or (4.39)–(4.40)), shared by the
// shear-scales and shear-start predictions (shear_tables.hpp, shear_start_table.hpp).
#pragma once

#include <string>
#include <vector>

#include "theory/shear_time_scales.hpp"

namespace granule::theory {

// k [1/length], l = πσ/8ν, σ and the box length L_x along k (the fluctuation is (0, v0 sin kx))
// [length]: the window is also given as wavelengths 2π/k in units of σ and of L_x.
std::vector<std::string> clustering_lines(const ClusteringScales& scales, double k,
                                          double mean_free_path, double diameter,
                                          double box_length);

}  // namespace granule::theory
