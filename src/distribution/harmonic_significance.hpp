// Which angular harmonics of the velocity distribution the samples resolve.  The thesis chooses the
// number of harmonics of ψ* (5.21) by the quality of the fit (§5.2, after (5.24)); on finite samples
// a harmonic that is only counting noise leaves its (α_p, Q_p) undetermined, so its speed
// dependence Q_p is fitted only when the data show the harmonic.  The test is the score (Rao) test of "the distribution has no harmonic 2p
// at any speed" on the statistics that carry harmonic 2p in the thesis's final form (5.27, 5.29):
// Σ u^i cos 2pθ and Σ u^i sin 2pθ over the samples, i = 0, 1, 2.
#pragma once

#include <vector>

#include "distribution/cumulative_function.hpp"

namespace granule::distribution {

// The score statistic of each harmonic p = 1 … `harmonics` (element p − 1), from the polar counts
// at the bin centres.  Without harmonic 2p the six statistics have mean zero (θ is binned in
// n_θ ≥ 16 equal bins, so for p ≤ 4 only harmonics 2q with q ≥ 5 alias into them) and covariance
// Σ x xᵀ over the samples (x = the six functions); gᵀ V⁻¹ g then follows χ² with 6 degrees of freedom.
std::vector<double> harmonic_chi_square(const CumulativeFunction& c, int harmonics);

// The 99.9% quantile of χ²₆: a harmonic of pure noise is taken as resolved once in a thousand
// windows (its Q_p is then checked by the fit, once_fitted.cpp).
inline constexpr double kResolvedChiSquare = 22.4577;

}  // namespace granule::distribution
