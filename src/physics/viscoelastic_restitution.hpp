// The coefficient of normal restitution of viscoelastic spheres (Brilliantov, Spahn, Hertzsch &
// Pöschel, Phys Rev E 53, 5382 (1996)): two spheres pressed together by ξ feel the Hertz force and
// its viscous part,
//     ξ'' = −ρ (ξ^{3/2} + (3/2) A ξ^{1/2} ξ'),   ρ = 2Y √R_eff / (3 m_eff (1 − ν²)),
// with ξ(0) = 0, ξ'(0) = g, the normal impact speed.  Scaling ξ by g^{4/5} ρ^{−2/5} and time by
// g^{−1/5} ρ^{−2/5} leaves one parameter, y = (3/2) A ρ^{2/5} g^{1/5}:
//     u'' = −u^{3/2} − y u^{1/2} u',   u(0) = 0, u'(0) = 1,
// and ẽ = −u' when the collision ends.  It ends when the force vanishes (u + y u' = 0), not when u
// returns to 0: a viscoelastic contact cannot pull, and the surfaces part before they have
// recovered (Schwager & Pöschel, Phys Rev E 78, 051304 (2008)).  For small y,
// ẽ = 1 − C₁ y + C₂ y² + O(y^{5/2}), C₁ = Γ(3/5)√π / (2^{1/5} 5^{2/5} Γ(21/10)) ≈ 1.15344 (the
// viscous work over the elastic collision, Schwager & Pöschel, Phys Rev E 57, 650 (1998)) and
// C₂ ≈ 0.798544 (Ramírez, Pöschel, Brilliantov & Schwager, Phys Rev E 60, 4465 (1999)).
#pragma once

namespace granule {

// ẽ(y) from a table of the exact solution (computed once, on first use, by integrating the scaled
// equation above), accurate to ~1e-9; beyond the table, the equation is integrated for y itself.
double viscoelastic_restitution(double y);

// ẽ(y) by integrating the scaled equation for this y (what the table holds).
double integrate_viscoelastic_restitution(double y);

}  // namespace granule
