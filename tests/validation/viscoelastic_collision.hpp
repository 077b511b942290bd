// The collision of two viscoelastic spheres in its dimensional form (Brilliantov, Spahn, Hertzsch &
// Pöschel 1996: the Hertz force and its viscous part), integrated here by a plain fixed-step
// Runge–Kutta — another integrator, other variables and every physical constant explicit — as the
// reference the engine's ẽ(y) (physics/viscoelastic_restitution.hpp) is tested against.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace granule {

// The grains' material: Young's modulus Y, Poisson ratio ν_P, dissipative constant A.
struct ViscoelasticMaterial {
  double young = 1e7, poisson = 0.3, dissipation = 5e-4;
};

// ρ = 2Y √R_eff / (3 m_eff (1 − ν_P²)) of a contact of radius R_eff and mass m_eff.
inline double hertz_rho(const ViscoelasticMaterial& m, double radius, double mass) {
  return 2.0 * m.young * std::sqrt(radius) / (3.0 * mass * (1.0 - m.poisson * m.poisson));
}

// −ξ'(end)/g of m_eff ξ'' = −ρ m_eff (ξ^{3/2} + (3/2) A ξ^{1/2} ξ'), ξ(0) = 0, ξ'(0) = g, by classical
// RK4 at a fixed step of a 20000th of the elastic contact's duration, the first step from the series
// ξ ≈ g t (where ξ^{1/2} is not smooth); the contact ends where the force vanishes (its zero located
// linearly within its step).  NaN if it has not ended after ten elastic durations.
inline double restitution_by_integration(const ViscoelasticMaterial& m, double radius, double mass, double speed) {
  const double r = hertz_rho(m, radius, mass), a = m.dissipation;
  const double h = 3.22 * std::pow(speed, -0.2) * std::pow(r, -0.4) / 20000.0;
  const auto force = [&](double xi, double v) { return -r * std::sqrt(std::max(xi, 0.0)) * (xi + 1.5 * a * v); };
  double xi = speed * 1e-4 * h, v = speed;
  for (int step = 0; step < 200000; ++step) {
    const double k1x = v, k1v = force(xi, v);
    const double k2x = v + 0.5 * h * k1v, k2v = force(xi + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = force(xi + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = force(xi + h * k3x, v + h * k3v);
    const double xi_next = xi + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
    const double v_next = v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
    if (v_next < 0.0 && xi_next + 1.5 * a * v_next < 0.0) {
      const double before = xi + 1.5 * a * v, after = xi_next + 1.5 * a * v_next;
      return -(v + before / (before - after) * (v_next - v)) / speed;
    }
    xi = xi_next;
    v = v_next;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace granule
