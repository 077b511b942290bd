// Checks of thesis §5.2–5.3 on a fitted distribution: the kinetic stress per particle (5.30),
// compared with the direct value (5.31) (Fig 5.7), and the Jenkins–Richman anisotropic
// Maxwellian (5.32)–(5.34) built from the measured second moment K (Figs 5.10, 5.11).
#pragma once

#include <functional>

namespace granule::distribution {

// ⟨v_a v_b⟩ per particle.  With f̃ normalised to 1 (5.12), (5.30) is this moment; the direct
// (5.31) summed over the cells S(ρ, T) and divided by N_{ρ,T} is the same moment of the data.
struct SecondMoment {
  double xx = 0.0, xy = 0.0, yy = 0.0;
  double trace() const { return xx + yy; }
};

struct PlaneIntegrals {
  double normalisation = 0.0;  // ∫ f̃ d²v
  SecondMoment moment;         // ∫ v v f̃ d²v  (5.30)
};

// Quadrature of a density given in polar coordinates (speed, angle) over speeds in
// [0, speed_max]: Simpson in the speed, the periodic trapezoid rule in the angle.
PlaneIntegrals plane_integrals(const std::function<double(double speed, double angle)>& density, double speed_max);

// (5.32)–(5.34): f_JR = exp(−½ v·K⁻¹·v) / (2π √det K); in the form of (5.27),
// −log f_JR = b^(0) + b^(2)(θ) v² with b^(1) = 0 and b^(2)(θ) = ½ ê·K⁻¹·ê
//           = b2_mean + b2_amplitude sin[2(θ + phase)]: a single harmonic.
struct JenkinsRichman {
  SecondMoment k;
  double b0 = 0.0;
  double b2_mean = 0.0;
  double b2_amplitude = 0.0;
  double phase = 0.0;  // in [0, π), amplitude ≥ 0 (the convention of the sine series)

  double density(double speed, double angle) const;
};

JenkinsRichman jenkins_richman(const SecondMoment& k);

}  // namespace granule::distribution
