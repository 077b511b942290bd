// Steady granular temperature of a simply sheared (Lees–Edwards) dilute disk gas (thesis §3.1.1
// and §4.1). Inputs: restitution ẽ, shear rate γ = U/Ly [1/time], disk diameter σ [length],
// area fraction ν̄ = πNσ²/(4 Lx Ly). Output: T̄ = ½⟨(v − V)²⟩ averaged over cells, unit-mass disks
// [length²/time²].
#pragma once

namespace granule::theory {

// Constants of the thesis's empirical fit (3.1).
inline constexpr double tan_fit_A = 0.080;
inline constexpr double tan_fit_B = -0.54;

// T̄ = A (γσ/ν̄)² (1/(1 − ẽ²) + B), A ≈ 0.080, B ≈ −0.54: the thesis's fit to its simulations,
// (3.1).
double steady_shear_temperature_tan_fit(double restitution, double shear_rate, double diameter,
                                        double area_fraction);

// T̄ = π/((1 + ẽ)²(7 − 3ẽ)²) (γσ/ν̄)² (1/(1 − ẽ) − 7/16): the dilute limit of Jenkins and
// Richman's theory of plane shear of disks, (3.2). As ẽ → 1 it tends to π(γσ/ν̄)²/(32ε), the
// Boltzmann balance of viscous heating and collisional cooling.
double steady_shear_temperature_jenkins_richman(double restitution, double shear_rate,
                                                double diameter, double area_fraction);

// The steady temperature of (4.1) under a uniform viscous heating function Tr D̂² [1/time²]:
// the balance of its heating and dissipation terms, (√π/16)σ√T Tr D̂² = (8/√π)(ν²/σ)εT^{3/2},
// gives T = l² Tr D̂²/(2πε) with l = πσ/8ν. (4.5) is the case Tr D̂² = 2γ², and (4.28)'s
// saturation value the case of (4.27).
double heated_steady_temperature(double heating_function, double mean_free_path, double eps);

// T0 = l²γ²/(πε) with l = πσ/8ν, (4.5): the homogeneous steady state of the thesis's equations
// (4.1)–(4.3). Their dissipation term carries 8/√π with ε = 1 − ẽ², twice the Boltzmann rate,
// so T0 is half the ẽ → 1 limit of (3.2) (docs/theory.md).
double steady_shear_temperature_kinetic(double restitution, double shear_rate, double diameter,
                                        double area_fraction);

// The disk diameter that gives N disks the area fraction ν̄ in an Lx × Ly box:
// σ = √(4ν̄ Lx Ly/(πN)) (definition of ν̄ after (3.2)).
double diameter_for_area_fraction(double area_fraction, int particle_count, double box_x,
                                  double box_y);

}  // namespace granule::theory
