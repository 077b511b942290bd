// Rough inelastic hard disks (d = 2) and spheres (d = 3): the energy a collision dissipates and
// the homogeneous cooling of the translational and rotational temperatures in the Maxwellian
// (molecular-chaos) approximation (Huthmann and Zippelius, PRE 56, R6275 (1997); Luding,
// Huthmann, McNamara and Zippelius, PRE 58, 3416 (1998)). Derivations in docs/theory.md.
// Units: k_B = 1; T_tr = m⟨|v − V|²⟩/d and T_rot = I⟨|ω|²⟩/d_rot per degree of freedom
// (d_rot = 1 for disks, 3 for spheres) [mass·length²/time²]; rates [1/time]; c = collisions per
// particle = total collisions / N. d must be 2 or 3: anything else throws std::invalid_argument.
#pragma once

namespace granule::theory {

// The collision law of rough grains: the normal relative velocity of the contact points becomes
// g_n' = −e g_n, the tangential one g_t' = −β g_t; moment of inertia I = q m σ²/4.
struct RoughGrains {
  double normal_restitution;      // e ∈ [0, 1]
  double tangential_restitution;  // β ∈ [−1, 1]: −1 smooth, +1 perfectly rough
  double inertia_factor;          // q > 0: ½ uniform disk, 2/5 uniform sphere
};

// Throws std::invalid_argument unless e ∈ [0, 1], β ∈ [−1, 1] and q > 0.
void require_valid_rough_grains(const RoughGrains& grains);

// Rotational degrees of freedom d_rot: 1 for a disk (spin about the normal to its plane), 3 for
// a sphere.
int rotational_degrees_of_freedom(int dimension);

// Effective mass of the tangential motion of the contact points,
// 1/μ_t = 1/m1 + 1/m2 + 1/(q1 m1) + 1/(q2 m2) (each (σ_i/2)²/I_i = 1/(q_i m_i)) [mass]: a
// tangential impulse J_t changes g_t by J_t/μ_t. Equal grains: μ_t = (m/2) q/(1 + q).
double tangential_effective_mass(double mass_1, double inertia_factor_1, double mass_2,
                                 double inertia_factor_2);

// Kinetic energy (translational + rotational) a collision changes, ≤ 0 [energy]:
// ΔE = −(μ/2)(1 − e²) g_n² − (μ_t/2)(1 − β²) |g_t|², μ = m1 m2/(m1 + m2), for the normal and
// tangential relative velocities of the contact points before the collision, g_n and |g_t|.
// Equal grains: −(m/4)[(1 − e²) g_n² + q/(1 + q) (1 − β²) |g_t|²].
double rough_collision_energy_change(const RoughGrains& grains, double mass_1, double mass_2,
                                     double normal_velocity, double tangential_speed);

// η = q(1 + β)/(2(1 + q)): the tangential impulse of equal grains is −2η μ g_t.
double tangential_coupling(const RoughGrains& grains);

// Mean change of the translational and of the rotational kinetic energy of the two grains per
// collision, averaged over collisions in a Maxwellian state of temperatures T_tr, T_rot
// (equal grains of mass m, any m) [energy]:
//   ΔE_tr = −(1 − e²) T_tr − 2(d − 1) η(1 − η) T_tr + 2(d − 1) (η²/q) T_rot,
//   ΔE_rot = 2(d − 1) (η/q) [η T_tr − (1 − η/q) T_rot].
struct RoughEnergyChange {
  double translational;
  double rotational;
};
struct RoughTemperatures {
  double translational;  // T_tr
  double rotational;     // T_rot
};
RoughEnergyChange mean_energy_change_per_collision(int dimension, const RoughGrains& grains,
                                                   RoughTemperatures temperatures);

// The cooling equations in the form of Huthmann–Zippelius and Luding et al.,
//   dT_tr/dt  = G √T_tr [−A T_tr + B T_rot],
//   dT_rot/dt = (d/d_rot) G √T_tr [B T_tr − C T_rot],
// with A = (1 − e²)/(2(d − 1)) + η(1 − η), B = η²/q, C = (η/q)(1 − η/q), and
// G √T_tr = 2(d − 1) ω(T_tr)/d, ω the collision frequency of one grain
// (hard_sphere_collision_frequency; ∝ √T_tr). In 3D A = (1 − e²)/4 + η(1 − η), G√T = 4ω/3 and
// the factor d/d_rot is 1; in 2D A = (1 − e²)/2 + η(1 − η), G√T = ω and the factor is 2.
struct RoughCoolingCoefficients {
  double translational_loss;            // A
  double exchange;                      // B
  double rotational_loss;               // C
  double rotational_factor;             // d/d_rot
  double rate_per_collision_frequency;  // G √T_tr / ω = 2(d − 1)/d
};
RoughCoolingCoefficients rough_cooling_coefficients(int dimension, const RoughGrains& grains);

// dT_tr/dt and dT_rot/dt [temperature/time] at the given temperatures; ω is the collision
// frequency of one grain at T_tr [1/time].
RoughTemperatures rough_cooling_rates(int dimension, const RoughGrains& grains,
                                      RoughTemperatures temperatures, double collision_frequency);

// R = T_rot/T_tr of the homogeneous cooling state, the positive root of
// B R² + (κC − A) R − κB = 0 (κ = d/d_rot): R = h + √(h² + κ), h = (A − κC)/(2B). 1 at
// e = β = 1 (equipartition). Smooth grains (β = −1, B = 0): +∞ when e < 1 (the translation cools
// away from a spin it cannot touch), NaN when e = 1 (nothing changes: R keeps its initial value).
double rough_temperature_ratio(int dimension, const RoughGrains& grains);

// T_tr and T_rot after c collisions per particle, the exact solution of the linear equations
// dT/dc = (2/ω) dT/dt (c grows at ω/2; ω ∝ √T_tr cancels) from T(0).
RoughTemperatures rough_temperatures_after_collisions(int dimension, const RoughGrains& grains,
                                                      RoughTemperatures initial,
                                                      double collisions_per_particle);

// T_tr(t), T_rot(t) from T(0) (Runge–Kutta 4 with steps of 1 % of the current collision time,
// relative error below 10⁻⁹); ω0 is the collision frequency of one grain at T_tr(0) [1/time].
RoughTemperatures rough_temperatures_at_time(int dimension, const RoughGrains& grains,
                                             RoughTemperatures initial,
                                             double collision_frequency_at_start, double t);

// Haff time t0 of the homogeneous cooling state, T_tr(t) = T_tr(0)/(1 + t/t0)² with T_rot = R T_tr
// throughout: t0 = 2/(G √T_tr(0) (A − B R)) [time]; ω0 at T_tr(0). Reduces to
// homogeneous_cooling_time for β = −1.
double rough_homogeneous_cooling_time(int dimension, const RoughGrains& grains,
                                      double collision_frequency_at_start);

}  // namespace granule::theory
