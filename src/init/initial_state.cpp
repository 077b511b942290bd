#include "init/initial_state.hpp"

#include <cmath>

#include "boundary/shear_frame.hpp"
#include "init/placement.hpp"
#include "init/random.hpp"

namespace granule {

namespace {

double area_fraction(const SystemParams& p) {
  return M_PI * static_cast<double>(p.particles) * p.diameter * p.diameter / (4.0 * p.length_x * p.length_y);
}

}  // namespace

InitialStateResult make_initial_state(const SystemParams& params, double temperature,
                                      std::uint64_t seed, Placement placement,
                                      std::optional<double> profile_velocity) {
  InitialStateResult result;
  ParticleState& s = result.state;
  const auto n = static_cast<std::size_t>(params.particles);
  s.resize(n);
  Random rng(seed);
  const double nu = area_fraction(params);
  if (placement == Placement::kAuto) {
    placement = nu <= kRandomPlacementLimit ? Placement::kRandom : Placement::kLattice;
  }
  const bool placed = placement == Placement::kRandom ? place_randomly(params, rng, s)
                                                       : place_on_lattice(params, rng, s);
  if (!placed) {
    result.error = placement == Placement::kRandom
                       ? "random placement jammed at area fraction " + std::to_string(nu) +
                             "; use initial.placement = \"lattice\" for dense systems"
                       : "no triangular lattice of " + std::to_string(params.particles) +
                             " sites fits disks of this diameter in this box";
    return result;
  }

  // Gaussian peculiar velocities, rescaled to exactly T_i = ½⟨v'²⟩ after removing their mean.
  double mean_x = 0.0, mean_y = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    s.vx[i] = rng.normal();
    s.vy[i] = rng.normal();
    mean_x += s.vx[i];
    mean_y += s.vy[i];
  }
  mean_x /= static_cast<double>(n);
  mean_y /= static_cast<double>(n);
  double sum_sq = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    s.vx[i] -= mean_x;
    s.vy[i] -= mean_y;
    sum_sq += s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i];
  }
  const double scale = sum_sq > 0.0 ? std::sqrt(2.0 * temperature * static_cast<double>(n) / sum_sq) : 0.0;
  const ShearFrame frame{params.length_x, params.length_y, profile_velocity.value_or(params.shear_velocity)};
  double total_x = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    s.vx[i] = scale * s.vx[i] + frame.mean_flow(s.y[i]);  // linear shear profile (§1.4.2)
    s.vy[i] *= scale;
    total_x += s.vx[i];
  }
  // The profile's sample mean is not exactly zero: remove the total momentum P/N per disk.
  for (std::size_t i = 0; i < n; ++i) s.vx[i] -= total_x / static_cast<double>(n);
  return result;
}

}  // namespace granule
