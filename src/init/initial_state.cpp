#include "init/initial_state.hpp"

#include <cmath>

#include "boundary/shear_frame.hpp"
#include "init/placement.hpp"
#include "init/random.hpp"

namespace granule {

namespace {

std::string placement_error(const SystemParams& p, Placement placement, double nu) {
  const char* fraction = p.dimension == 3 ? "volume fraction" : "area fraction";
  if (placement == Placement::kRandom) {
    return "random placement jammed at " + std::string(fraction) + " " + std::to_string(nu) +
           "; use initial.placement = \"lattice\" for dense systems";
  }
  const bool spheres = p.dimension == 3;
  return std::string("no ") + (spheres ? "FCC" : "triangular") + " lattice of " + std::to_string(p.particles) +
         " sites fits " + (spheres ? "spheres" : "disks") + " of this (largest) diameter in this box";
}

// Gaussian peculiar velocities of variance T/m_i per component, rescaled to exactly T_i =
// Σ m_i |v_i − V|² / (d N) after removing the mass-weighted mean V; then the shear profile along
// x, and the total momentum it leaves (its sample mean is not exactly zero) removed.  For unit
// masses every operation is the one of the 2D code before polydispersity (same bits).
void draw_velocities(const SystemParams& params, double temperature, double profile_velocity, Random& rng,
                     ParticleState& s) {
  const int d = params.dimension;
  const std::size_t n = s.size();
  double total_mass = 0.0;
  double momentum[3] = {0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < n; ++i) {
    const double m = s.mass_of(i);
    const double spread = s.mass.empty() ? 1.0 : 1.0 / std::sqrt(m);
    for (int a = 0; a < d; ++a) {
      s.velocity(a)[i] = spread * rng.normal();
      momentum[a] += m * s.velocity(a)[i];
    }
    total_mass += m;
  }
  double twice_kinetic = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    double speed_sq = 0.0;
    for (int a = 0; a < d; ++a) {
      s.velocity(a)[i] -= momentum[a] / total_mass;
      speed_sq += s.velocity(a)[i] * s.velocity(a)[i];
    }
    twice_kinetic += s.mass_of(i) * speed_sq;
  }
  const double scale =
      twice_kinetic > 0.0 ? std::sqrt(static_cast<double>(d) * temperature * static_cast<double>(n) / twice_kinetic) : 0.0;
  const ShearFrame frame{params.length_x, params.length_y, profile_velocity};
  double momentum_x = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    s.vx[i] = scale * s.vx[i] + frame.mean_flow(s.y[i]);  // linear shear profile (§1.4.2)
    for (int a = 1; a < d; ++a) s.velocity(a)[i] *= scale;
    momentum_x += s.mass_of(i) * s.vx[i];
  }
  for (std::size_t i = 0; i < n; ++i) s.vx[i] -= momentum_x / total_mass;
}

}  // namespace

InitialStateResult make_initial_state(const SystemParams& params, double temperature, std::uint64_t seed,
                                      Placement placement, std::optional<double> profile_velocity,
                                      const ParticleSizes& sizes) {
  InitialStateResult result;
  ParticleState& s = result.state;
  const auto n = static_cast<std::size_t>(params.particles);
  if (!sizes.monodisperse() && (sizes.diameter.size() != n || sizes.mass.size() != n)) {
    result.error = "internal error: per-particle diameters and masses do not match N";
    return result;
  }
  s.dimension = params.dimension;
  s.diameter = sizes.diameter;
  s.mass = sizes.mass;
  s.resize(n);
  Random rng(seed);
  const double nu = packing_fraction(params, sizes);
  if (placement == Placement::kAuto) {
    placement = nu <= random_placement_limit(params.dimension) ? Placement::kRandom : Placement::kLattice;
  }
  const bool placed = placement == Placement::kRandom ? place_randomly(params, rng, s) : place_on_lattice(params, rng, s);
  if (!placed) {
    result.error = placement_error(params, placement, nu);
    return result;
  }
  draw_velocities(params, temperature, profile_velocity.value_or(params.shear_velocity), rng, s);
  return result;
}

}  // namespace granule
