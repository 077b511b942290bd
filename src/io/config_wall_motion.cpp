#include "io/config_wall_motion.hpp"

#include <fmt/format.h>

#include <cmath>
#include <set>

#include "io/input_ranges.hpp"

namespace granule {

namespace {

constexpr const char* kKey = "boundary.wall_motion";
constexpr NumberRange kTimes{0.0, kUnbounded};
constexpr NumberRange kFrequencies{0.0, kUnbounded, true, true};

}  // namespace

std::string wall_face_name(int face) { return fmt::format("{}{}", "xyz"[face / 2], face % 2); }

void resolve_wall_motion(const ConfigReader& in, bool walls, RunConfig& c) {
  if (!in.has(kKey)) return;
  if (!walls) throw ConfigError{fmt::format("{} requires boundary.kind = \"walls\" (only a wall moves)", kKey)};
  in.table_with_keys(kKey, {"wall", "amplitude", "frequency", "shape", "schedule"});
  SystemParams& s = c.system;
  std::set<std::string> faces;
  for (int face = 0; face < 2 * s.dimension; ++face) {
    if (s.walls[static_cast<std::size_t>(face / 2)]) faces.insert(wall_face_name(face));
  }
  const auto name = in.text(std::string(kKey) + ".wall", faces);
  if (!name) throw ConfigError{fmt::format("{} needs wall = the face that moves, one of the walls of boundary.wall_axes "
                                           "(\"y0\": the wall at y = 0, \"y1\": at y = L_y)", kKey)};
  const int face = 2 * ((*name)[0] - 'x') + ((*name)[1] - '0');
  const auto axis = static_cast<std::size_t>(face / 2);
  const double length = axis == 0 ? s.length_x : axis == 1 ? s.length_y : s.length_z;
  WallMotion& motion = s.wall[static_cast<std::size_t>(face)].motion;
  const NumberRange displacements{0.0, length};
  const std::string amplitude_key = std::string(kKey) + ".amplitude";
  motion.amplitude = in.number(amplitude_key, displacements, " (the wall moves to h = A (1 − cos 2πft))").value_or(0.0);
  const auto frequency = in.number(std::string(kKey) + ".frequency", kFrequencies);
  if (motion.amplitude > 0.0 && !frequency) throw ConfigError{fmt::format("{} > 0 needs {}.frequency = f > 0", amplitude_key, kKey)};
  if (frequency && motion.amplitude == 0.0) {
    throw ConfigError{fmt::format("{}.frequency = {} needs {} = A > 0", kKey, *frequency, amplitude_key)};
  }
  motion.frequency = frequency.value_or(0.0);
  const std::string shape_key = std::string(kKey) + ".shape";
  if (const auto shape = in.text(shape_key, {"sine", "triangle", "biparabolic"})) {
    if (motion.amplitude == 0.0) throw ConfigError{fmt::format("{} = \"{}\" needs {} = A > 0", shape_key, *shape, amplitude_key)};
    motion.shape = *shape == "triangle" ? VibrationShape::kTriangle : *shape == "biparabolic" ? VibrationShape::kBiparabolic : VibrationShape::kSine;
  }
  for (const auto& [t, h] : in.number_pairs(std::string(kKey) + ".schedule", "[t, h]")) {
    const bool first = motion.schedule.empty();
    if (!kTimes.contains(t) || !displacements.contains(h) || (first && h != 0.0) ||
        (!first && !(t > motion.schedule.back().time))) {
      throw ConfigError{fmt::format("{}.schedule point [{}, {}] is not allowed: times t ≥ 0 in increasing order, "
                                    "displacements into the box h in {} starting from h = 0 (the wall rests at its "
                                    "face until the first point)", kKey, t, h, displacements.text())};
    }
    motion.schedule.push_back({t, h});
  }
  if (!motion.moves()) throw ConfigError{fmt::format("{} needs amplitude and frequency, or a schedule", kKey)};
  // The wall never comes closer to the opposite face than the largest grain.
  if (!(motion.reach() < length - s.diameter)) {
    throw ConfigError{fmt::format("{} moves the wall {} into the box (its largest h): it must stay below L_{} − σ = {}, "
                                  "so that a grain fits between it and the opposite wall", kKey, motion.reach(),
                                  "xyz"[axis], length - s.diameter)};
  }
}

std::string wall_motion_to_toml(const RunConfig& c) {
  for (int face = 0; face < 6; ++face) {
    const WallMotion& m = c.system.wall[static_cast<std::size_t>(face)].motion;
    if (!m.moves()) continue;
    std::string out = fmt::format("wall_motion = {{ wall = \"{}\"", wall_face_name(face));
    if (m.amplitude > 0.0) out += fmt::format(", amplitude = {:.17g}, frequency = {:.17g}", m.amplitude, m.frequency);
    if (m.amplitude > 0.0 && m.shape != VibrationShape::kSine) {
      out += fmt::format(", shape = \"{}\"", m.shape == VibrationShape::kTriangle ? "triangle" : "biparabolic");
    }
    if (!m.schedule.empty()) {
      std::string points;
      for (const WallPositionPoint& p : m.schedule) {
        points += fmt::format("{}[{:.17g}, {:.17g}]", points.empty() ? "" : ", ", p.time, p.displacement);
      }
      out += ", schedule = [" + points + "]";
    }
    return out + " }\n";
  }
  return {};
}

}  // namespace granule
