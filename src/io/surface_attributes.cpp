#include "io/surface_attributes.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "io/hdf5_util.hpp"
#include "io/io_error.hpp"

namespace granule {

using namespace h5;

namespace {
// A row of dataset `obstacles`: centre x, y, z (0 in 2D), diameter, restitution, tangential restitution.
constexpr std::size_t kObstacleColumns = 6;
}  // namespace

void write_grains_walls_gravity_attributes(hid_t f, const SystemParams& p) {
  if (p.roughness.rough) {
    write_attribute(f, "tangential_restitution", H5T_NATIVE_DOUBLE, &p.roughness.tangential_restitution);
    write_attribute(f, "inertia_factor", H5T_NATIVE_DOUBLE, &p.roughness.inertia_factor);
    write_attribute(f, "friction", H5T_NATIVE_DOUBLE, &p.roughness.friction);
  }
  if (p.has_walls()) {
    const int walls[3] = {p.walls[0] ? 1 : 0, p.walls[1] ? 1 : 0, p.walls[2] ? 1 : 0};
    write_attribute(f, "walls", H5T_NATIVE_INT, walls, 3);
    double restitution[6], tangential[6], velocity[18];
    for (std::size_t face = 0; face < 6; ++face) {
      restitution[face] = p.wall[face].restitution;
      tangential[face] = p.wall[face].tangential_restitution;
      for (std::size_t a = 0; a < 3; ++a) velocity[3 * face + a] = p.wall[face].velocity[a];
    }
    write_attribute(f, "wall_restitution", H5T_NATIVE_DOUBLE, restitution, 6);
    write_attribute(f, "wall_tangential_restitution", H5T_NATIVE_DOUBLE, tangential, 6);
    write_attribute(f, "wall_velocity", H5T_NATIVE_DOUBLE, velocity, 18);
    double vibration[12];
    std::vector<double> schedule;
    bool moves = false;
    for (std::size_t face = 0; face < 6; ++face) {
      const WallMotion& m = p.wall[face].motion;
      moves = moves || m.moves();
      vibration[2 * face] = m.amplitude;
      vibration[2 * face + 1] = m.frequency;
      for (const WallPositionPoint& point : m.schedule) schedule.insert(schedule.end(), {static_cast<double>(face), point.time, point.displacement});
    }
    if (moves) write_attribute(f, "wall_vibration", H5T_NATIVE_DOUBLE, vibration, 12);
    if (!schedule.empty()) write_dataset(f, "wall_schedule", {schedule.size() / 3, 3}, schedule);
  }
  if (p.has_gravity()) write_attribute(f, "gravity", H5T_NATIVE_DOUBLE, p.gravity.data(), 3);
  if (!p.obstacles.empty()) {
    std::vector<double> rows;
    for (const Obstacle& o : p.obstacles) {
      rows.insert(rows.end(), {o.centre[0], o.centre[1], o.centre[2], o.diameter, o.restitution, o.tangential_restitution});
    }
    write_dataset(f, "obstacles", {p.obstacles.size(), kObstacleColumns}, rows);
  }
  const RestitutionLaw& law = p.restitution_law;
  if (law.kind == RestitutionKind::kThreshold) {
    write_string_attribute(f, "restitution_law", "threshold");
    write_attribute(f, "elastic_below", H5T_NATIVE_DOUBLE, &law.elastic_below);
  } else if (law.kind == RestitutionKind::kViscoelastic) {
    write_string_attribute(f, "restitution_law", "viscoelastic");
    write_attribute(f, "viscoelastic_constant", H5T_NATIVE_DOUBLE, &law.viscoelastic_constant);
  }
}

void read_grains_walls_gravity_attributes(hid_t f, SystemParams& p) {
  p.roughness.rough = has_attribute(f, "inertia_factor");
  if (p.roughness.rough) {
    p.roughness.tangential_restitution = read_attribute<double>(f, "tangential_restitution", H5T_NATIVE_DOUBLE);
    p.roughness.inertia_factor = read_attribute<double>(f, "inertia_factor", H5T_NATIVE_DOUBLE);
    p.roughness.friction = read_attribute<double>(f, "friction", H5T_NATIVE_DOUBLE);
  }
  if (has_attribute(f, "walls")) {
    int walls[3] = {0, 0, 0};
    read_attribute_values(f, "walls", H5T_NATIVE_INT, walls, 3);
    double restitution[6], tangential[6], velocity[18];
    read_attribute_values(f, "wall_restitution", H5T_NATIVE_DOUBLE, restitution, 6);
    read_attribute_values(f, "wall_tangential_restitution", H5T_NATIVE_DOUBLE, tangential, 6);
    read_attribute_values(f, "wall_velocity", H5T_NATIVE_DOUBLE, velocity, 18);
    for (std::size_t a = 0; a < 3; ++a) p.walls[a] = walls[a] != 0;
    for (std::size_t face = 0; face < 6; ++face) {
      p.wall[face].restitution = restitution[face];
      p.wall[face].tangential_restitution = tangential[face];
      for (std::size_t a = 0; a < 3; ++a) p.wall[face].velocity[a] = velocity[3 * face + a];
    }
    if (has_attribute(f, "wall_vibration")) {
      double vibration[12];
      read_attribute_values(f, "wall_vibration", H5T_NATIVE_DOUBLE, vibration, 12);
      for (std::size_t face = 0; face < 6; ++face) {
        p.wall[face].motion.amplitude = vibration[2 * face];
        p.wall[face].motion.frequency = vibration[2 * face + 1];
      }
    }
    if (has_link(f, "wall_schedule")) {
      const std::vector<double> rows = read_values(f, "wall_schedule");
      if (rows.size() % 3 != 0) throw InputError(file_name(f) + ": dataset wall_schedule must have 3 columns (face, t, h)");
      for (std::size_t k = 0; k < rows.size(); k += 3) {
        const double face = rows[k];
        if (!(face >= 0.0 && face <= 5.0 && face == std::floor(face))) {
          throw InputError(file_name(f) + ": dataset wall_schedule names face " + std::to_string(face) + "; expected 0 to 5");
        }
        p.wall[static_cast<std::size_t>(face)].motion.schedule.push_back({rows[k + 1], rows[k + 2]});
      }
    }
  }
  if (has_attribute(f, "gravity")) read_attribute_values(f, "gravity", H5T_NATIVE_DOUBLE, p.gravity.data(), 3);
  if (has_link(f, "obstacles")) {
    const std::vector<double> rows = read_values(f, "obstacles");
    if (rows.empty() || rows.size() % kObstacleColumns != 0) {
      throw InputError(file_name(f) + ": dataset obstacles must have 6 columns (x, y, z, diameter, restitution, "
                       "tangential_restitution) and at least one row");
    }
    for (std::size_t k = 0; k < rows.size(); k += kObstacleColumns) {
      p.obstacles.push_back({{rows[k], rows[k + 1], rows[k + 2]}, rows[k + 3], rows[k + 4], rows[k + 5]});
    }
  }
  if (has_attribute(f, "restitution_law")) {
    const std::string law = read_string_attribute(f, "restitution_law");
    if (law == "threshold") {
      p.restitution_law.kind = RestitutionKind::kThreshold;
      p.restitution_law.elastic_below = read_attribute<double>(f, "elastic_below", H5T_NATIVE_DOUBLE);
    } else if (law == "viscoelastic") {
      p.restitution_law.kind = RestitutionKind::kViscoelastic;
      p.restitution_law.viscoelastic_constant = read_attribute<double>(f, "viscoelastic_constant", H5T_NATIVE_DOUBLE);
    } else {
      throw InputError(file_name(f) + ": attribute restitution_law is \"" + law + "\"; expected threshold or viscoelastic");
    }
    p.restitution_law.reference_radius = 0.5 * p.diameter;
  }
}

}  // namespace granule
