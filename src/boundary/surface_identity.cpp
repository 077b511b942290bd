#include "boundary/surface_identity.hpp"

namespace granule {

namespace {

std::string schedule_time_name(int face, std::size_t point) {
  return "wall_" + std::to_string(face) + "_schedule_time_" + std::to_string(point);
}

}  // namespace

std::map<std::string, std::vector<double>> surface_identity(const SurfaceSet& surfaces, int dimension) {
  std::map<std::string, std::vector<double>> out;
  for (int axis = 0; axis < dimension; ++axis) {
    if (!surfaces.walls[static_cast<std::size_t>(axis)]) continue;
    out[std::string("walls_") + "xyz"[axis]] = {1.0};
    for (int face = 2 * axis; face <= 2 * axis + 1; ++face) {
      const WallParams& wall = surfaces.wall[static_cast<std::size_t>(face)];
      const std::string name = "wall_" + std::to_string(face);
      out[name + "_restitution"] = {wall.restitution};
      out[name + "_tangential_restitution"] = {wall.tangential_restitution};
      for (int a = 0; a < dimension; ++a) out[name + "_velocity_" + "xyz"[a]] = {wall.velocity[static_cast<std::size_t>(a)]};
      // Where a moving wall is follows from its drive and the clock: a resumed run must have the same.
      if (!wall.motion.moves()) continue;
      out[name + "_vibration_amplitude"] = {wall.motion.amplitude};
      out[name + "_vibration_frequency"] = {wall.motion.frequency};
      if (wall.motion.shape != VibrationShape::kSine) out[name + "_vibration_shape"] = {static_cast<double>(wall.motion.shape)};
      for (std::size_t k = 0; k < wall.motion.schedule.size(); ++k) {
        out[schedule_time_name(face, k)] = {wall.motion.schedule[k].time};
        out[name + "_schedule_displacement_" + std::to_string(k)] = {wall.motion.schedule[k].displacement};
      }
    }
  }
  // Six values per obstacle: centre x, y, z, diameter and the restitutions.
  if (!surfaces.obstacles.empty()) {
    std::vector<double>& table = out["obstacles"];
    for (const Obstacle& o : surfaces.obstacles) {
      table.insert(table.end(), {o.centre[0], o.centre[1], o.centre[2], o.diameter, o.restitution, o.tangential_restitution});
    }
  }
  return out;
}

std::set<std::string> surface_identity_names(const SurfaceSet& configured, int dimension) {
  // Every surface there is: walls on every axis, each vibrating in a shape other than the default
  // (whose entry is written only then), and an obstacle.
  const std::array<bool, 3> walls{true, true, true};
  std::array<WallParams, 6> wall{};
  for (WallParams& w : wall) w.motion = {1.0, 1.0, {}, VibrationShape::kTriangle};
  const std::vector<Obstacle> obstacles(1);
  std::set<std::string> names;
  for (const auto& entry : surface_identity({walls, wall, obstacles}, dimension)) names.insert(entry.first);
  for (int face = 0; face < 2 * dimension; ++face) {
    names.insert(schedule_time_name(face, configured.wall[static_cast<std::size_t>(face)].motion.schedule.size()));
  }
  return names;
}

}  // namespace granule
