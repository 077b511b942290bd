// A checkpoint records the surfaces, the collision law's spin and the motion's gravity it was written
// with (boundary/surface_identity.hpp, engine/simulation_checkpoint.cpp): resuming it under a
// configuration that lacks one of them, has one more, or sets one otherwise is refused, naming the
// entry; the same configuration resumes.
#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>

#include "boundary/surface_identity.hpp"
#include "validation/surfaces_setup.hpp"

namespace granule {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Rough grains under gravity between y walls, the floor vibrating in a triangle wave, around an obstacle.
SystemParams every_surface() {
  SystemParams p = surfaces_system<2>({16, 12}, {1.0, 2.0}, 0.03, 0.9);
  add_walls(p, 1, 0.9, 0.3);
  make_rough(p, 0.2, 0.5);
  p.gravity[1] = -1.0;
  p.wall[2].motion = {0.02, 3.0, {}, VibrationShape::kTriangle};
  p.wall[3].motion = {0.0, 0.0, {{0.0, 0.0}, {1.0, 0.01}, {2.0, 0.0}}};
  p.obstacles.push_back({{0.0625, 1.0 / 6.0, 0.0}, 0.02, 0.8, 0.1});
  return p;
}

// The message of the refusal of `saved` under `other`, or "" if it is taken.
std::string refusal(const SystemParams& other, const CellGrid& grid, const StateArchive& saved) {
  try {
    Simulation<2> resumed(other, grid, saved, "");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(SurfaceCheckpoints, AConfigurationWithOtherSurfacesIsRefusedByName) {
  const SystemParams p = every_surface();
  const CellGrid grid = surfaces_grid<2>(p);
  Simulation<2> sim(p, grid, lattice_gas<2>(p, {16, 12}, 0.2, 5));
  sim.start_production(p);
  sim.run(kInf, 2 * p.particles);
  StateArchive saved;
  sim.save(saved, "");
  EXPECT_EQ(refusal(p, grid, saved), "");

  const std::vector<std::pair<std::string, std::function<void(SystemParams&)>>> changes{
      {"walls_y", [](SystemParams& q) { q.walls[1] = false; }},
      {"walls_x", [](SystemParams& q) { q.walls[0] = true; }},
      {"wall_3_tangential_restitution", [](SystemParams& q) { q.wall[3].tangential_restitution = 0.4; }},
      {"wall_2_vibration_", [](SystemParams& q) { q.wall[2].motion = {}; }},
      {"wall_2_vibration_shape", [](SystemParams& q) { q.wall[2].motion.shape = VibrationShape::kSine; }},
      {"wall_3_vibration_amplitude", [](SystemParams& q) { q.wall[3].motion.amplitude = 0.01; }},
      {"wall_3_schedule_time_2", [](SystemParams& q) { q.wall[3].motion.schedule.pop_back(); }},
      {"wall_3_schedule_", [](SystemParams& q) { q.wall[3].motion.schedule.push_back({3.0, 0.01}); }},
      {"wall_2_schedule_", [](SystemParams& q) { q.wall[2].motion.schedule = {{0.0, 0.0}, {1.0, 0.01}}; }},
      {"obstacles", [](SystemParams& q) { q.obstacles.clear(); }},
      {"obstacles", [](SystemParams& q) { q.obstacles[0].restitution = 0.7; }},
      {"obstacles", [](SystemParams& q) { q.obstacles.push_back({{0.5, 1.0, 0.0}, 0.02, 1.0, -1.0}); }},
      {"gravity_", [](SystemParams& q) { q.gravity[1] = 0.0; }},
      {"gravity_x", [](SystemParams& q) { q.gravity[0] = 0.1; }},
      {"friction", [](SystemParams& q) { q.roughness.friction = 0.5; }},
  };
  for (const auto& [entry, change] : changes) {
    SystemParams other = p;
    change(other);
    const std::string message = refusal(other, grid, saved);
    EXPECT_NE(message.find(entry), std::string::npos) << "changing " << entry << " gave: '" << message << "'";
  }
}

// The names a checkpoint may hold for surfaces are those some configuration gives: every one the
// refusal looks for is written by a box with walls, vibrations and an obstacle, in both dimensions.
TEST(SurfaceCheckpoints, EveryRecordedSurfaceNameIsOneSomeConfigurationWrites) {
  for (int d : {2, 3}) {
    const std::array<bool, 3> walls{};
    const std::array<WallParams, 6> wall{};
    const std::vector<Obstacle> obstacles;
    const std::set<std::string> names = surface_identity_names({walls, wall, obstacles}, d);
    EXPECT_TRUE(names.count("obstacles"));
    EXPECT_EQ(names.count("walls_z"), d == 3 ? 1u : 0u);
    for (int face = 0; face < 2 * d; ++face) {
      const std::string face_name = "wall_" + std::to_string(face);
      for (const char* part : {"_restitution", "_tangential_restitution", "_vibration_amplitude", "_vibration_frequency",
                               "_vibration_shape", "_velocity_x", "_velocity_y"}) {
        EXPECT_TRUE(names.count(face_name + part)) << face_name + part;
      }
    }
    EXPECT_FALSE(names.count("wall_" + std::to_string(2 * d) + "_restitution"));
    EXPECT_TRUE(names.count("wall_0_schedule_time_0"));  // a schedule the configuration does not have
  }
}

}  // namespace
}  // namespace granule
