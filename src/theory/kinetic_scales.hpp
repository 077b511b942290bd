// Kinetic scales of a dilute gas of inelastic hard disks: inelasticity, mean free path, collision
// frequency and the intercluster distance L0. Units: lengths in the box's length unit, speeds in
// length/time, the granular temperature T = ½⟨(v − V)²⟩ of unit-mass disks in length²/time².
#pragma once

namespace granule::theory {

// ε ≡ 1 − ẽ², the thesis's inelasticity (§2.4.2, after (2.7)). Jenkins and Richman use 1 − ẽ.
double inelasticity(double restitution);

// The thesis's mean free path of a disk gas, l ≡ πσ/8ν (definition after (4.5)) [length].
// It omits the √2 of the Boltzmann free path, see boltzmann_mean_free_path.
double mean_free_path(double diameter, double area_fraction);

// Boltzmann mean free path of dilute disks, ⟨|v|⟩/ω = 1/(2√2 nσ) = l/√2 [length].
double boltzmann_mean_free_path(double diameter, double area_fraction);

// Collision frequency of one disk in a Maxwellian gas, ω = 2nσ χ √(πT) = 8νχ√T/(√π σ)
// [1/time]; χ is the pair correlation at contact (1 in the dilute limit the thesis uses).
// Each collision involves two disks, so the collisions counted per disk of the gas, c = total
// collisions / N, grow at ω/2.
double disk_collision_frequency(double temperature, double diameter, double area_fraction,
                                double contact_value = 1.0);

// Henderson's contact value χ(ν) = (1 − 7ν/16)/(1 − ν)² for hard disks (an Enskog correction
// outside the thesis, offered to compare dense runs; 1.085 at ν = 0.05).
double henderson_contact_value(double area_fraction);

// Intercluster distance L0 ≈ l/√(1 − ẽ²), thesis (1.1) and (3.18) [length]: clusters form on the
// scale kl ~ √ε set by the nonlinear analysis (§2.4.3, after (2.52); (4.37)).
double cluster_separation(double restitution, double diameter, double area_fraction);

}  // namespace granule::theory
