// Haff's law for the homogeneous cooling of a free granular gas (thesis §2.4.2, (2.9)–(2.15)).
// Conventions: unit-mass particles; T = ½⟨(v − V)²⟩ [length²/time²] (thesis (1.3)); t [time];
// c = accumulated collisions per particle = total collisions / N (N/4 collisions make c = 0.25,
// each collision involving two particles).
#pragma once

namespace granule::theory {

// T(t) = T(0)/(1 + t/t0)², thesis (2.10), the solution of (3/2)ρ Ṫ = −(dρs/σ) T^{3/2} (2.9).
double haff_temperature(double t, double T0, double t0);

// T(c) = T(0) exp(−(1 − ẽ²) c). A collision of two Maxwellian disks dissipates on average
// (1 − ẽ²)/4 ⟨(g·k)²⟩ = (1 − ẽ²) T (the flux-weighted normal relative speed has ⟨(g·k)²⟩ = 4T)
// while the gas holds N T, so dT/dc = −(1 − ẽ²) T whatever the density and time scale. The
// thesis's T(s) = T(0) exp(−2εs) (after (2.35)) is the same exponential decay in c (§2.1).
double haff_temperature_after_collisions(double c, double T0, double restitution);

// c(t) = (2/ε) ln(1 + t/t0): collisions per particle accumulated by a Haff-cooling disk gas, from
// dc/dt = ω/2 with ω ∝ √T(t) (kinetic_scales.hpp). The thesis's ċ ∝ 1/t (§2.1, Fig. 2.5(A)).
double haff_collisions_per_particle(double t, double t0, double restitution);

// Haff time t0 of dilute inelastic disks from Boltzmann kinetic theory: dT/dt = −(ε ω/2) T gives
// t0 = 4/(ε ω(T0)) = √π σ/(2 χ ν ε √T0) [time]. Use this to compare with a disk simulation;
// contact_value χ = 1 is the dilute limit (see henderson_contact_value for an Enskog estimate).
double haff_time_disks(double T0, double restitution, double diameter, double area_fraction,
                       double contact_value = 1.0);

// --- the thesis's three-dimensional Jenkins–Richman version (§2.4.2) ------------------------
// Dissipation coefficient d = (24/√π) ε ν² (2.7), with ε = 1 − ẽ² and ν the volume fraction.
double jenkins_richman_dissipation_coefficient(double restitution, double volume_fraction);

// t0 = 3ρ0σ/(d ρs √T0) = (√π/8)(σ/ν)/(ε√T0), thesis (2.11)–(2.12) [time]. Note: Jenkins and
// Richman's d is written with 1 − ẽ; with ε = 1 − ẽ² it dissipates about twice the Boltzmann
// rate of spheres, so this t0 is about half the kinetic-theory value (docs/theory.md).
double jenkins_richman_haff_time(double T0, double restitution, double diameter,
                                 double volume_fraction);

// Effective mean free path l0 = (√π/8) σ/ν, thesis (2.13) [length]; t0 = l0/(ε√T0) (2.14).
double effective_mean_free_path(double diameter, double volume_fraction);

// Mean free path of spheres l = 1/(πσ² n) = σ/(6ν) as the thesis defines it before (2.15)
// [length]; l0 = (3/4)√π l (2.15).
double sphere_mean_free_path(double diameter, double volume_fraction);

// The thesis's stretched time s = (1/ε) ln(1 + t/t0), (2.19) [dimensionless]: the linearised
// Jenkins–Richman equations have constant coefficients in s, and T0(s) = T0(0) exp(−2εs).
double haff_stretched_time(double t, double t0, double eps);

}  // namespace granule::theory
