// Time scales of clustering in a sheared disk gas and the wavenumber windows where clustering
// can happen (thesis §4.1–4.2, (4.6), (4.12), (4.25)–(4.41)). Units: shear rate γ and shear
// fluctuation rate h = ∂δv2/∂x in 1/time, wavenumber k in 1/length, mean free path
// l = πσ/8ν [length] (kinetic_scales.hpp), times in time units.
#pragma once

namespace granule::theory {

// δ* = l/(L√ε), (4.12): the intercluster distance over the box size L.
double shear_delta_star(double mean_free_path, double box_length, double eps);

// δ̄ = δ*k̃ for the n-th Fourier mode k̃ = 2πn of a box of size L: 2πn l/(L√ε) (after (4.19)).
double shear_delta_bar_of_mode(int n, double mean_free_path, double box_length, double eps);

// Convective time τc ~ 1/γ, (4.6).
double convective_time(double shear_rate);

// Linear growth time 1/s3 ≈ √ε/(kl γ) of the transient mode (4.23) in dimensional units; the
// thesis's (4.38) prints √(ε/klγ), which contradicts its own conclusion that 1/s3 < 1/γ
// requires kl > √ε.
double linear_growth_time(double k, double mean_free_path, double eps, double shear_rate);

// Typical rate h ~ k√(T_i/N) of a thermal shear fluctuation (0, v0 sin kx) in a gas of N disks at
// the initial temperature T_i (§4.2 around (4.25)).
double shear_fluctuation_rate(double k, double initial_temperature, int particle_count);

// Mass-motion time τm ~ √ε/(k l h) when h ≫ γ (T_i ≫ T0), (4.36).
double mass_motion_time_hot(double k, double mean_free_path, double eps, double h);

// Mass-motion time τ′m ~ √(γ/h) √ε/(k l γ) when h ≪ γ (T_i < T0), (4.41).
double mass_motion_time_cold(double k, double mean_free_path, double eps, double h,
                             double shear_rate);

// An open interval lower < kl < upper of dimensionless wavenumbers kl.
struct KlWindow {
  double lower;
  double upper;
  bool open() const { return lower < upper; }
  bool contains(double kl) const { return lower < kl && kl < upper; }
};

// Clustering window for h ≫ γ, (4.37): √ε γ/h < kl < √ε (τm < τc and diffusion negligible,
// (4.31)).
KlWindow clustering_window_hot(double eps, double shear_rate, double h);

// Clustering window for h ≪ γ, (4.39)–(4.40): √(γ/h)√ε < kl < √ε; empty whenever γ > h.
KlWindow clustering_window_cold(double eps, double shear_rate, double h);

// The clustering picture of §4.2 at one wavenumber k, in the regime γ/h selects: the hot start
// (h > γ) has τm (4.36) and the window (4.37); the cold start (h ≤ γ) has τ′m (4.41) and
// (4.39)–(4.40).
struct ClusteringScales {
  bool hot;                   // h > γ
  double convective_time;     // τc (4.6)
  double mass_motion_time;    // τm or τ′m
  double linear_growth_time;  // 1/s3 (4.38, corrected)
  KlWindow window;
};

ClusteringScales clustering_scales(double k, double mean_free_path, double eps, double shear_rate,
                                   double h);

}  // namespace granule::theory
