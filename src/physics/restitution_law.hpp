// How the normal restitution ẽ of a contact depends on its normal impact speed g = (v₁ − v₂)·k̂.
// The thesis's grains have one ẽ (eq 1.2); real grains are nearly elastic when they touch slowly,
// and a gas of them cools as t^{−5/3} rather than Haff's t^{−2} (Brilliantov & Pöschel, Kinetic
// Theory of Granular Gases, 2004).  Three laws:
//  - constant: ẽ at every speed (the thesis);
//  - threshold: ẽ = 1 below the speed v_c, the constant ẽ above it (the simplest cure for
//    inelastic collapse: slow contacts, those of a collapsing cluster, dissipate nothing);
//  - viscoelastic: ẽ(y) of physics/viscoelastic_restitution.hpp with y = δ_ij g^{1/5}.  δ, the
//    material constant (3/2) A ρ^{2/5}, is given for two reference grains (diameter σ, unit mass); a
//    contact of radii and masses with another effective radius R_eff = a₁a₂/(a₁ + a₂) and mass
//    m_eff = m₁m₂/(m₁ + m₂) has ρ ∝ √R_eff / m_eff, so δ_ij = δ (ρ_ij / ρ_ref)^{2/5}.  A wall is a
//    half-space of the grains' material (R_eff = a, m_eff = m).  In 2D the grains are spheres
//    confined to a plane (a monolayer), as viscoelastic disks are usually modelled.
#pragma once

#include <cmath>

#include "physics/viscoelastic_restitution.hpp"

namespace granule {

enum class RestitutionKind { kConstant, kThreshold, kViscoelastic };

struct RestitutionLaw {
  RestitutionKind kind = RestitutionKind::kConstant;
  double elastic_below = 0.0;          // v_c of the threshold law
  double viscoelastic_constant = 0.0;  // δ = (3/2) A ρ^{2/5} of the viscoelastic law, in (time/length)^{1/5}
  double reference_radius = 0.5;       // σ/2 of the reference grains of δ

  bool constant() const { return kind == RestitutionKind::kConstant; }

  // ẽ of a contact at normal impact speed `speed` between sides of radii a₁, a₂ and masses m₁, m₂
  // (a wall: m₂ = ∞, a₂ ignored), `restitution` being the constant ẽ of the constant and threshold
  // laws.
  double at(double restitution, double speed, double a1, double m1, double a2, double m2) const {
    switch (kind) {
      case RestitutionKind::kConstant:
        return restitution;
      case RestitutionKind::kThreshold:
        return speed < elastic_below ? 1.0 : restitution;
      case RestitutionKind::kViscoelastic: {
        const bool wall = std::isinf(m2);
        const double radius = wall ? a1 : a1 * a2 / (a1 + a2);
        const double mass = wall ? m1 : m1 * m2 / (m1 + m2);
        // ρ_ij / ρ_ref with R_ref = σ/4 and m_ref = 1/2 (two reference grains).
        const double rho_ratio = std::sqrt(radius / (0.5 * reference_radius)) * (0.5 / mass);
        return viscoelastic_restitution(viscoelastic_constant * std::pow(rho_ratio, 0.4) * std::pow(speed, 0.2));
      }
    }
    return restitution;
  }
};

}  // namespace granule
