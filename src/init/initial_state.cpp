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

// The mean flow along x added to the initial velocities: u(y) = mean + γ (y − L_y/2), γ = U/L_y.
struct ShearProfile {
  double shear_velocity = 0.0;  // U: u(L_y) − u(0)
  double mean = 0.0;            // u(L_y/2): 0 under Lees–Edwards, the mean wall velocity between walls
};

ShearProfile shear_profile(const SystemParams& params, std::optional<double> profile_velocity, bool wall_profile) {
  if (!params.walls[1]) return {profile_velocity.value_or(params.shear_velocity), 0.0};
  if (!wall_profile) return {};
  // The walls' velocities as production starts (a ramped drive starts from rest).
  const double lower = ShearProtocol(params.wall[2].velocity[0], params.wall[2].along).velocity(0.0);
  const double upper = ShearProtocol(params.wall[3].velocity[0], params.wall[3].along).velocity(0.0);
  return {upper - lower, 0.5 * (lower + upper)};
}

// Gaussian peculiar velocities of variance T/m_i per component, rescaled to exactly T_i =
// Σ m_i |v_i − V|² / (d N) after removing the mass-weighted mean V; then the shear profile along
// x, and the total momentum it leaves (its sample mean is not exactly the profile's) set to the
// profile's mean.  For unit masses every operation is the one of the 2D code before
// polydispersity (same bits; subtracting a mean of 0 changes no bit).
void draw_velocities(const SystemParams& params, double temperature, const ShearProfile& profile, Random& rng,
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
  const ShearFrame frame{params.length_x, params.length_y, profile.shear_velocity};
  double momentum_x = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    s.vx[i] = scale * s.vx[i] + frame.mean_flow(s.y[i]);  // linear shear profile (§1.4.2)
    for (int a = 1; a < d; ++a) s.velocity(a)[i] *= scale;
    momentum_x += s.mass_of(i) * s.vx[i];
  }
  for (std::size_t i = 0; i < n; ++i) s.vx[i] -= momentum_x / total_mass - profile.mean;
}

// Rough grains: Gaussian angular velocities of variance T_rot/I_i per component, I_i =
// q m_i σ_i²/4, rescaled to exactly T_rot = Σ I_i |ω_i|² / (d_rot N).  The mean spin is kept: no
// conservation law fixes it (spin and orbital angular momentum are exchanged, and a periodic box
// has no orbital angular momentum).
void draw_spins(const SystemParams& params, double rotational_temperature, Random& rng, ParticleState& s) {
  s.make_rough();
  if (rotational_temperature == 0.0) return;
  const std::size_t n = s.size();
  const int components = s.spin_components();
  const double q = params.roughness.inertia_factor;
  const auto inertia = [&](std::size_t i) {
    const double sigma = s.diameter_of(i, params.diameter);
    return 0.25 * q * s.mass_of(i) * sigma * sigma;
  };
  double twice_rotational = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double moment = inertia(i);
    for (int k = 0; k < components; ++k) {
      const double w = rng.normal() / std::sqrt(moment);
      s.spin(k)[i] = w;
      twice_rotational += moment * w * w;
    }
  }
  const double scale = twice_rotational > 0.0
                           ? std::sqrt(static_cast<double>(components) * rotational_temperature * static_cast<double>(n) /
                                       twice_rotational)
                           : 0.0;
  for (int k = 0; k < components; ++k) {
    for (double& w : s.spin(k)) w *= scale;
  }
}

}  // namespace

InitialStateResult make_initial_state(const SystemParams& params, double temperature, std::uint64_t seed,
                                      Placement placement, std::optional<double> profile_velocity,
                                      const ParticleSizes& sizes, const WallFlowAndSpins& walls_and_spins) {
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
  draw_velocities(params, temperature, shear_profile(params, profile_velocity, walls_and_spins.wall_profile), rng, s);
  if (params.roughness.rough) draw_spins(params, walls_and_spins.rotational_temperature.value_or(temperature), rng, s);
  return result;
}

}  // namespace granule
