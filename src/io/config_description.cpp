#include "io/config_description.hpp"

#include <fmt/format.h>

#include <algorithm>

#include <array>
#include <cmath>
#include <numbers>

namespace granule {

std::string describe_system(const RunConfig& config) {
  const SystemParams& s = config.system;
  const char* boundary = config.lees_edwards ? "Lees–Edwards" : s.has_walls() ? "walled" : "periodic";
  const double u = config.lees_edwards ? s.shear_velocity : wall_shear_velocity(s);
  return fmt::format("{}{}, N = {}, ν = {:.4g}, σ = {:.6g}{}, e = {}, {} box {} × {}{}{}", s.roughness.rough ? "rough " : "",
                     s.dimension == 3 ? "spheres" : "disks", s.particles, config.packing_fraction, s.diameter,
                     config.diameters.monodisperse() ? "" : " (largest)", s.restitution, boundary, s.length_x, s.length_y,
                     s.dimension == 3 ? fmt::format(" × {}", s.length_z) : std::string{},
                     config.lees_edwards || s.walls[1] ? fmt::format(", U = {}", u) : std::string{});
}

std::string collision_model_text(const SystemParams& s) {
  const RestitutionLaw& law = s.restitution_law;
  const std::string e = law.kind == RestitutionKind::kThreshold
                            ? fmt::format("e = {} (1 below the normal impact speed {:g})", s.restitution, law.elastic_below)
                        : law.kind == RestitutionKind::kViscoelastic
                            ? fmt::format("viscoelastic e(g) = 1 − 1.15344 δ g^(1/5) + … with δ = {:g}", law.viscoelastic_constant)
                            : fmt::format("e = {}", s.restitution);
  if (s.tc_duration > 0.0) {
    return fmt::format("{} with the TC model (Luding & McNamara 1998): a collision within t_c = {:g} of either "
                       "grain's previous collision is elastic",
                       e, s.tc_duration);
  }
  return fmt::format("{} in every collision (TC model off: an inelastic collapse stops the run with exit 3)", e);
}

std::vector<std::string> describe_surfaces(const RunConfig& config) {
  const SystemParams& s = config.system;
  const RoughnessParams& r = s.roughness;
  std::vector<std::string> lines;
  if (r.rough) {
    lines.push_back(fmt::format("rough grains: β = {}, q = {} (I = q m σ²/4), μ = {}{}", r.tangential_restitution,
                                r.inertia_factor, std::isfinite(r.friction) ? fmt::format("{}", r.friction) : "∞ (no Coulomb limit)",
                                config.initial_from ? std::string{}
                                                    : fmt::format("; initial T_rot = {}", config.initial_rotational_temperature)));
  }
  const auto vector_text = [d = s.dimension](const std::array<double, 3>& v) {
    return d == 3 ? fmt::format("({}, {}, {})", v[0], v[1], v[2]) : fmt::format("({}, {})", v[0], v[1]);
  };
  const std::array<double, 3> lengths{s.length_x, s.length_y, s.length_z};
  for (std::size_t axis = 0; axis < 3; ++axis) {
    if (!s.walls[axis]) continue;
    const WallParams& lower = s.wall[2 * axis];
    const WallParams& upper = s.wall[2 * axis + 1];
    const char name = "xyz"[axis];
    lines.push_back(fmt::format("walls at {} = 0 (e_w = {}, β_w = {}, velocity {}) and {} = {} (e_w = {}, β_w = {}, velocity {})",
                                name, lower.restitution, lower.tangential_restitution, vector_text(lower.velocity), name,
                                lengths[axis], upper.restitution, upper.tangential_restitution, vector_text(upper.velocity)));
  }
  for (int face = 0; face < 2 * s.dimension; ++face) {
    const WallParams& wall = s.wall[static_cast<std::size_t>(face)];
    const std::string name = fmt::format("wall {}{}", "xyz"[face / 2], face % 2);
    if (!ShearProtocol(wall.velocity[static_cast<std::size_t>(wall.along_axis)], wall.along).constant()) {
      lines.push_back(fmt::format("{} slides at {}U(t)/2, U(t) the shear protocol's", name, face % 2 == 0 ? "−" : "+"));
    }
    const WallMotion& m = wall.motion;
    if (m.amplitude > 0.0) {
      const double g = std::abs(s.gravity[static_cast<std::size_t>(face / 2)]);
      const auto gamma = [&](double peak) { return g > 0.0 ? fmt::format(" (Γ = {:.3g} g)", peak / g) : std::string{}; };
      if (m.shape == VibrationShape::kSine) {
        const double peak = std::pow(2.0 * std::numbers::pi * m.frequency, 2) * m.amplitude;
        lines.push_back(fmt::format("{} vibrates into the box: h = A (1 − cos 2πft), A = {}, f = {}: peak speed {:.4g}, peak "
                                    "acceleration {:.4g}{}", name, m.amplitude, m.frequency,
                                    2.0 * std::numbers::pi * m.frequency * m.amplitude, peak, gamma(peak)));
      } else if (m.shape == VibrationShape::kTriangle) {
        lines.push_back(fmt::format("{} vibrates into the box: h a triangle wave from 0 to 2A, A = {}, f = {}: speed ±{:.4g}, "
                                    "turning at once every half period", name, m.amplitude, m.frequency, 4.0 * m.frequency * m.amplitude));
      } else {
        const double peak = 32.0 * m.frequency * m.frequency * m.amplitude;
        lines.push_back(fmt::format("{} vibrates into the box: h bi-parabolic from 0 to 2A, A = {}, f = {}: peak speed {:.4g}, "
                                    "acceleration ±{:.4g}{}", name, m.amplitude, m.frequency, 8.0 * m.frequency * m.amplitude, peak,
                                    gamma(peak)));
      }
    }
    if (!m.schedule.empty()) {
      std::string points;
      for (const WallPositionPoint& p : m.schedule) points += fmt::format("{}({}, {})", points.empty() ? "" : ", ", p.time, p.displacement);
      lines.push_back(fmt::format("{} moves into the box through (t, h) = {}{}", name, points, m.amplitude > 0.0 ? ", plus the vibration" : ""));
    }
  }
  if (s.has_gravity()) lines.push_back(fmt::format("gravity g = {}", vector_text(s.gravity)));
  if (!s.obstacles.empty()) {
    const Obstacle& first = s.obstacles.front();
    const bool alike = std::all_of(s.obstacles.begin(), s.obstacles.end(), [&](const Obstacle& o) {
      return o.diameter == first.diameter && o.restitution == first.restitution && o.tangential_restitution == first.tangential_restitution;
    });
    lines.push_back(s.obstacles.size() == 1 || alike
                        ? fmt::format("{} fixed obstacle{} of diameter {} (e_o = {}, β_o = {}){}", s.obstacles.size(),
                                      s.obstacles.size() == 1 ? "" : "s", first.diameter, first.restitution, first.tangential_restitution,
                                      s.obstacles.size() == 1 ? fmt::format(" at ({}, {}{})", first.centre[0], first.centre[1],
                                                                            s.dimension == 3 ? fmt::format(", {}", first.centre[2]) : "")
                                                              : "")
                        : fmt::format("{} fixed obstacles of diameters, restitutions and roughnesses of their own", s.obstacles.size()));
  }
  return lines;
}

}  // namespace granule
