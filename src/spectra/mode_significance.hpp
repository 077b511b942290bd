// The null hypothesis of every spectral claim: uncorrelated positions (an ideal gas).  For N such
// positions each Fourier sum at an allowed k ≠ 0 is, by the central limit theorem, a complex Gaussian
// of mean 0, and distinct allowed wavevectors are uncorrelated (E ρ̃(k) ρ̃(k′)* = 0 for k′ ≠ ±k).  The
// power of one mode over its mean (the ideal-gas level) is therefore exponential with mean 1 for the
// mass R and for one momentum component; for P = |p̃|² it is Σ_i λ_i E_i, E_i independent Exp(1), where
// λ_i are the eigenvalues of the components' covariance C_ab = Σ_j m_j² v_{j,a} v_{j,b}/4π² over tr C
// (a hypoexponential law).  As S(−k) = S(k)*, the modes ±k count once: K independent modes among the
// 2K + 1 of a lattice window.  The dominant mode is the largest of K such powers, so its false-alarm
// probability is p = 1 − (1 − Q(s))^K, Q the survival function of one mode at s = power/level.
#pragma once

#include <span>
#include <vector>

namespace granule::spectra {

// The default false-alarm probability at which a dominant mode is called significant.
inline constexpr double kDefaultFalseAlarm = 0.05;

// What the power of one mode of one field is for uncorrelated positions: its mean `level`, and the
// shares λ_i (summing to 1) of its independent exponential components ({1} for R and P_x, P_y, P_z).
struct ModeNoise {
  double level = 0.0;
  std::vector<double> shares = {1.0};
  ModeNoise() = default;
  ModeNoise(double mean_level) : level(mean_level) {}  // one component: implicit on purpose
  ModeNoise(double mean_level, std::vector<double> component_shares)
      : level(mean_level), shares(std::move(component_shares)) {}
};

// Q(s) = P(Σ_i λ_i E_i > s) for one mode; zero shares are ignored, near-equal ones are handled.
double single_mode_survival(double power_over_level, std::span<const double> shares);

// p = 1 − (1 − q)^K: the chance that at least one of K independent modes exceeds a level that one
// mode exceeds with probability q.
double false_alarm_probability(double single_mode_survival, double independent_modes);

// The power over the level that the largest of K modes of uncorrelated positions exceeds with
// probability `false_alarm`: the smallest significant dominant mode.
double noise_threshold(double false_alarm, double independent_modes, std::span<const double> shares);

}  // namespace granule::spectra
