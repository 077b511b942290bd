// What is said about the velocity distribution of a (ρ, T) window (`granule analyze f1` prints
// it): its samples, temperature, b₀ and the traces of the stress from the three estimates, whether
// the fits converged, and its b₀⁽¹⁾ beside Appendix B's in the run's units (docs/f1.md).
#pragma once

#include <string>

#include "distribution/appendix_b_comparison.hpp"
#include "distribution/f1_analysis.hpp"
#include "engine/system_params.hpp"

namespace granule::distribution {

// One line: the window, its samples, T, b₀ = (b₀⁽⁰⁾, b₀⁽¹⁾, b₀⁽²⁾), Tr τ direct/once/twice and the fits.
std::string describe_window(const WindowResult& result);

// Whether the fits of φ*, ψ* and the series converged, and h* is within the thesis's tolerance.
std::string fits_summary(const WindowResult& result);

// One line comparing the window's b₀⁽¹⁾ with Appendix B's in the run's units, with the
// dimensionless √(2T) b₀⁽¹⁾ beside it.
std::string describe_thesis_comparison(const ThesisMatch& match, const WindowResult& window);

// How Appendix B's windows map to the run's units: the length and velocity factors, and the
// boxes in diameters.
std::string describe_thesis_units(const SystemParams& run);

}  // namespace granule::distribution
