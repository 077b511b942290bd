// Homogeneous cooling of a dilute gas of smooth inelastic hard disks (d = 2) or spheres (d = 3),
// with the first Sonine correction to the Maxwellian (van Noije and Ernst, Granular Matter 1, 57
// (1998)). Units: T per degree of freedom (hard_spheres.hpp); c = collisions per particle =
// total collisions / N, as in haff.hpp; rates [1/time]. Derivations in docs/theory.md. d must be
// 2 or 3: anything else throws std::invalid_argument.
#pragma once

namespace granule::theory {

// Second Sonine coefficient of the homogeneous cooling state,
// a2 = 16(1 − e)(1 − 2e²)/(9 + 24d − e(41 − 8d) + 30(1 − e)e²) (van Noije and Ernst (1998)):
// zero at e = 1 and e = 1/√2, −(1 − e)/(2(d − 1)) to first order in 1 − e.
double sonine_a2(double restitution, int dimension);

// ⟨|g|^p⟩ over two particles of f_M(1 + a2 S2) is (1 + a2 p(p − 2)/16) times its Maxwellian value
// at first order in a2, in any dimension: the collision frequency (p = 1) carries 1 − a2/16 ...
double sonine_collision_frequency_factor(double a2);

// ... and the dissipation (p = 3) 1 + 3a2/16.
double sonine_cooling_rate_factor(double a2);

// Cooling rate ζ in dT/dt = −ζT: ζ = (1 − e²)/d · ω_M · (1 + 3a2/16) [1/time], with ω_M the
// collision frequency of one particle in a Maxwellian gas (hard_sphere_collision_frequency).
double homogeneous_cooling_rate(int dimension, double restitution,
                                double maxwellian_collision_frequency, double a2);

// Fraction of the mean kinetic energy d·T of the two colliding particles dissipated per collision:
// (1 − e²)/d · (1 + 3a2/16)/(1 − a2/16). (Per Maxwellian collision time, the rate ζ above carries
// (1 + 3a2/16) alone; per actual collision the Sonine correction to the frequency divides it.)
double energy_loss_per_collision(int dimension, double restitution, double a2);

// Haff time t0 = 2/ζ(T0) of T(t) = T0/(1 + t/t0)² (use haff_temperature) [time]; for d = 2,
// a2 = 0 it is haff_time_disks's 4/((1 − e²) ω0).
double homogeneous_cooling_time(int dimension, double restitution,
                                double maxwellian_collision_frequency_at_T0, double a2);

// T(c) = T0 exp(−2 f c) with f = energy_loss_per_collision: each collision removes f·dT of the
// gas's N·dT/2.
double temperature_after_collisions(int dimension, double collisions_per_particle, double T0,
                                    double restitution, double a2);

// c(t) = ln(1 + t/t0)/f: T(c) = T0 exp(−2fc) along T(t) = T0/(1 + t/t0)²; for d = 2, a2 = 0 it is
// haff_collisions_per_particle's (2/(1 − e²)) ln(1 + t/t0).
double collisions_per_particle(int dimension, double t, double t0, double restitution, double a2);

}  // namespace granule::theory
