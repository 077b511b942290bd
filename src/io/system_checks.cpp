#include "io/system_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "io/input_ranges.hpp"
#include "io/io_error.hpp"

namespace granule {

namespace {

constexpr const char* kAxes[3] = {"x", "y", "z"};

void require(std::vector<std::string>& problems, const std::string& name, double value, const NumberRange& range) {
  if (!range.contains(value)) problems.push_back(fmt::format("{} is {}; expected {}", name, value, range.text()));
}

// A wall's motion as the configuration allows it (io/config_wall_motion.cpp): A in [0, L], f > 0
// with A > 0, schedule times increasing from t ≥ 0, h in [0, L] from h = 0, and a largest
// displacement that leaves a grain room.
void wall_motion_problems(std::vector<std::string>& problems, const std::string& wall, const WallMotion& m, double length,
                          double diameter) {
  const NumberRange displacements{0.0, length};
  require(problems, "vibration amplitude of " + wall, m.amplitude, displacements);
  if (m.amplitude > 0.0 && !(m.frequency > 0.0 && std::isfinite(m.frequency))) {
    problems.push_back(fmt::format("vibration frequency of {} is {}; allowed: a finite f > 0", wall, m.frequency));
  }
  for (std::size_t k = 0; k < m.schedule.size(); ++k) {
    const WallPositionPoint& p = m.schedule[k];
    const bool ordered = k == 0 ? p.time >= 0.0 && p.displacement == 0.0 : p.time > m.schedule[k - 1].time;
    if (!ordered || !std::isfinite(p.time) || !displacements.contains(p.displacement)) {
      problems.push_back(fmt::format("schedule point {} of {} is ({}, {}); allowed: times t ≥ 0 increasing, h in {} from h = 0",
                                     k, wall, p.time, p.displacement, displacements.text()));
    }
  }
  if (m.moves() && !(m.reach() < length - diameter)) {
    problems.push_back(fmt::format("{} moves {} into the box; allowed: less than L − σ = {}", wall, m.reach(), length - diameter));
  }
}

void require_finite(std::vector<std::string>& problems, const std::string& name, double value) {
  if (!std::isfinite(value)) problems.push_back(fmt::format("{} is {}; expected a finite number", name, value));
}

// The first particle of `values` outside `range` (a problem, not one per particle).
void require_each(std::vector<std::string>& problems, const std::string& name, const std::vector<double>& values,
                  const NumberRange& range) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!range.contains(values[i])) {
      problems.push_back(fmt::format("{} of particle {} is {}; expected {}", name, i, values[i], range.text()));
      return;
    }
  }
}

// The first grain whose centre is closer to an obstacle (or a periodic image of one) than contact,
// less 10⁻⁹ of it: grains sorted by x, each obstacle tested against those within its reach in x.
void grain_in_obstacle(std::vector<std::string>& problems, const ParticleState& p, const SystemParams& s) {
  std::vector<std::size_t> by_x(p.size());
  for (std::size_t i = 0; i < by_x.size(); ++i) by_x[i] = i;
  std::sort(by_x.begin(), by_x.end(), [&](std::size_t a, std::size_t b) { return p.x[a] < p.x[b]; });
  const std::array<bool, 3> images{!s.walls[0], !s.walls[1], !s.walls[2]};
  const std::array<double, 3> lengths{s.length_x, s.length_y, s.length_z};
  for (std::size_t k = 0; k < s.obstacles.size(); ++k) {
    const Obstacle& o = s.obstacles[k];
    const double reach = 0.5 * (o.diameter + s.diameter);
    for (const double shift : images[0] ? std::vector<double>{-s.length_x, 0.0, s.length_x} : std::vector<double>{0.0}) {
      const auto first = std::lower_bound(by_x.begin(), by_x.end(), o.centre[0] + shift - reach,
                                          [&](std::size_t i, double x) { return p.x[i] < x; });
      for (auto it = first; it != by_x.end() && p.x[*it] <= o.centre[0] + shift + reach; ++it) {
        const std::size_t i = *it;
        std::array<double, 3> r{p.x[i], p.y[i], p.dimension == 3 ? p.z[i] : 0.0};
        const double contact = 0.5 * (o.diameter + p.diameter_of(i, s.diameter));
        if (distance_squared_to(o, r, p.dimension, images, lengths) < contact * contact * (1.0 - 2e-9)) {
          problems.push_back(fmt::format("particle {} is inside obstacle {} (distance {} of contact)", i, k,
                                         std::sqrt(distance_squared_to(o, r, p.dimension, images, lengths)) / contact));
          return;
        }
      }
    }
  }
}

}  // namespace

std::vector<std::string> obstacle_problems(const Obstacle& o, const SystemParams& s, const std::string& name) {
  std::vector<std::string> problems;
  require(problems, "diameter of " + name, o.diameter, kLengthRange);
  require(problems, "restitution of " + name, o.restitution, kRestitutions);
  require(problems, "tangential restitution of " + name, o.tangential_restitution, kTangentialRestitutions);
  const double lengths[3] = {s.length_x, s.length_y, s.length_z};
  for (std::size_t a = 0; a < static_cast<std::size_t>(s.dimension == 3 ? 3 : 2); ++a) {
    const bool periodic = !s.walls[a];
    if (!(o.centre[a] >= 0.0 && (periodic ? o.centre[a] < lengths[a] : o.centre[a] <= lengths[a]))) {
      problems.push_back(fmt::format("{} has its centre at {} = {}, outside the box: allowed [0, {}{}", name, kAxes[a], o.centre[a],
                                     lengths[a], periodic ? ") (periodic)" : "]"));
    }
    if (periodic && !(o.diameter + s.diameter < lengths[a])) {
      problems.push_back(fmt::format("{} has diameter {}: along the periodic axis {} it must be below L_{} − σ = {}, so that a "
                                     "grain passes between the obstacle and its image", name, o.diameter, kAxes[a], kAxes[a],
                                     lengths[a] - s.diameter));
    }
  }
  return problems;
}

std::vector<std::string> system_problems(const SystemParams& s) {
  std::vector<std::string> problems;
  if (s.dimension != 2 && s.dimension != 3) problems.push_back(fmt::format("dimension is {}; expected 2 or 3", s.dimension));
  if (s.particles < 2 || s.particles > INT32_MAX) {
    problems.push_back(fmt::format("particles is {}; expected [2, {}]", s.particles, INT32_MAX));
  }
  require(problems, "diameter", s.diameter, kLengthRange);
  const double lengths[3] = {s.length_x, s.length_y, s.length_z};
  for (int a = 0; a < (s.dimension == 3 ? 3 : 2); ++a) {
    const std::string name = fmt::format("box length along {}", kAxes[a]);
    require(problems, name, lengths[a], kLengthRange);
    if (kLengthRange.contains(s.diameter) && lengths[a] / s.diameter > kMaxBoxOverDiameter) {
      problems.push_back(fmt::format("{} is {} diameters; at most {:g} are resolved", name, lengths[a] / s.diameter,
                                     kMaxBoxOverDiameter));
    }
  }
  require(problems, "restitution", s.restitution, kRestitutions);
  require(problems, "tc_duration", s.tc_duration, kContactDurations);
  if (s.restitution_law.kind == RestitutionKind::kThreshold) {
    require(problems, "elastic_below", s.restitution_law.elastic_below, kThresholdSpeeds);
  }
  if (s.restitution_law.kind == RestitutionKind::kViscoelastic) {
    require(problems, "viscoelastic_constant", s.restitution_law.viscoelastic_constant, kViscoelasticConstants);
  }
  require_finite(problems, "shear_velocity", s.shear_velocity);
  for (int a = 0; a < 3; ++a) require_finite(problems, fmt::format("gravity along {}", kAxes[a]), s.gravity[static_cast<std::size_t>(a)]);
  if (s.roughness.rough) {
    require(problems, "tangential_restitution", s.roughness.tangential_restitution, kTangentialRestitutions);
    require(problems, "inertia_factor", s.roughness.inertia_factor, kInertiaFactors);
    if (!std::isinf(s.roughness.friction)) require(problems, "friction", s.roughness.friction, kFrictions);
  }
  for (std::size_t face = 0; face < 6; ++face) {
    if (!s.walls[face / 2]) continue;
    const std::string wall = fmt::format("the wall at {} of {}", face % 2 == 0 ? "0" : "L", kAxes[face / 2]);
    require(problems, "restitution of " + wall, s.wall[face].restitution, kRestitutions);
    require(problems, "tangential restitution of " + wall, s.wall[face].tangential_restitution, kTangentialRestitutions);
    for (std::size_t a = 0; a < 3; ++a) require_finite(problems, fmt::format("velocity of {} along {}", wall, kAxes[a]), s.wall[face].velocity[a]);
    wall_motion_problems(problems, wall, s.wall[face].motion, face / 2 == 0 ? s.length_x : face / 2 == 1 ? s.length_y : s.length_z,
                         s.diameter);
  }
  for (std::size_t k = 0; k < s.obstacles.size(); ++k) {
    for (std::string& problem : obstacle_problems(s.obstacles[k], s, fmt::format("obstacle {}", k))) problems.push_back(std::move(problem));
  }
  return problems;
}

std::vector<std::string> particle_problems(const ParticleState& p, const SystemParams& s) {
  std::vector<std::string> problems;
  const NumberRange any{-kUnbounded, kUnbounded, true, true};
  if (p.polydisperse()) {
    require_each(problems, "diameter", p.diameter, NumberRange{kLengthRange.low, s.diameter});
    require_each(problems, "mass", p.mass, kMassRange);
  }
  const double lengths[3] = {s.length_x, s.length_y, s.length_z};
  for (int a = 0; a < p.dimension; ++a) {
    // Positions lie in [0, L] up to the round-off of wrapping into the box.
    const double length = lengths[a];
    const double slack = 1e-9 * length;
    require_each(problems, fmt::format("position along {}", kAxes[a]), p.position(a), NumberRange{-slack, length + slack});
    require_each(problems, fmt::format("velocity along {}", kAxes[a]), p.velocity(a), any);
  }
  if (p.rough()) {
    for (int k = 0; k < p.spin_components(); ++k) require_each(problems, "angular velocity", p.spin(k), any);
  }
  if (!s.obstacles.empty() && problems.empty()) grain_in_obstacle(problems, p, s);
  return problems;
}

void refuse_problems(const std::string& file, const std::vector<std::string>& problems) {
  if (problems.empty()) return;
  std::string text = file + ":";
  for (std::size_t k = 0; k < problems.size(); ++k) text += (k ? "; " : " ") + problems[k];
  throw InputError(text);
}

}  // namespace granule
