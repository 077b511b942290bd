// The configuration keys of walls, gravity and rough grains (README "Configuration reference"): walls (boundary.kind =
// "walls", wall_axes, wall_restitution, wall_tangential_restitution, a wall-driven shear), gravity
// and rough grains (tangential_restitution, inertia_factor, friction, initial.rotational_temperature).
// Good values reach SystemParams as documented; each bad one is refused with a message naming the
// key and the allowed range (written out here as literals); to_toml() repeats every new key.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/config.hpp"

namespace granule {
namespace {

RunConfig accepted(const std::vector<std::string>& overrides) {
  const ConfigResult result = parse_config("", overrides);
  EXPECT_TRUE(result.config.has_value()) << "refused: " << result.error;
  return result.config.value_or(RunConfig{});
}

// Refused, and the message contains every fragment (the key, the value, the range).
void expect_refused(const std::vector<std::string>& overrides, const std::vector<std::string>& fragments) {
  const ConfigResult result = parse_config("", overrides);
  ASSERT_FALSE(result.config.has_value()) << "accepted: " << overrides.back();
  for (const auto& fragment : fragments) {
    EXPECT_NE(result.error.find(fragment), std::string::npos) << "'" << fragment << "' missing from: " << result.error;
  }
}

const std::string kWalls = "boundary.kind=\"walls\"";
const std::string k3d = "system.dimension=3";

TEST(ConfigWalls, DefaultWallsAreElasticSmoothAndAtRestOnY) {
  const RunConfig c = accepted({kWalls});
  const SystemParams& s = c.system;
  EXPECT_FALSE(c.lees_edwards);
  EXPECT_FALSE(s.walls[0]);
  EXPECT_TRUE(s.walls[1]);
  EXPECT_FALSE(s.walls[2]);
  for (const int face : {2, 3}) {
    EXPECT_EQ(s.wall[face].restitution, 1.0);
    EXPECT_EQ(s.wall[face].tangential_restitution, -1.0);
    EXPECT_EQ(s.wall[face].velocity[0], 0.0);
  }
  EXPECT_EQ(boundary_kind_name(c), "walls");
  EXPECT_EQ(wall_shear_velocity(s), 0.0);
}

TEST(ConfigWalls, RestitutionsPerWallOrPerSideOfEveryWallAxis) {
  const RunConfig c = accepted({k3d, kWalls, "boundary.wall_axes=[\"z\", \"x\"]", "boundary.wall_restitution=[0.8, 0.9]",
                                "boundary.wall_tangential_restitution=0.5"});
  const SystemParams& s = c.system;
  EXPECT_TRUE(s.walls[0]);
  EXPECT_FALSE(s.walls[1]);
  EXPECT_TRUE(s.walls[2]);
  for (const int axis : {0, 2}) {
    EXPECT_EQ(s.wall[2 * axis].restitution, 0.8) << axis;
    EXPECT_EQ(s.wall[2 * axis + 1].restitution, 0.9) << axis;
    EXPECT_EQ(s.wall[2 * axis].tangential_restitution, 0.5) << axis;
    EXPECT_EQ(s.wall[2 * axis + 1].tangential_restitution, 0.5) << axis;
  }
  // The faces of the periodic y axis keep the defaults.
  EXPECT_EQ(s.wall[2].restitution, 1.0);
  EXPECT_EQ(s.wall[3].tangential_restitution, -1.0);
}

TEST(ConfigWalls, ShearVelocityMovesTheYWallsAtPlusMinusHalfUAndTheImagesStayAtRest) {
  const RunConfig c = accepted({kWalls, "boundary.shear_velocity=3"});
  const SystemParams& s = c.system;
  EXPECT_EQ(s.shear_velocity, 0.0);  // no Lees–Edwards image velocity
  EXPECT_TRUE(s.shear_history.schedule.empty());
  EXPECT_EQ(s.shear_history.ramp_time, 0.0);
  EXPECT_FALSE(s.shear_history.oscillation);
  EXPECT_EQ(s.wall[2].velocity[0], -1.5);  // lower wall, y = 0
  EXPECT_EQ(s.wall[3].velocity[0], 1.5);   // upper wall, y = L_y
  EXPECT_EQ(s.wall[2].velocity[1], 0.0);
  EXPECT_EQ(s.wall[3].velocity[2], 0.0);
  EXPECT_EQ(wall_shear_velocity(s), 3.0);
  // The same range as a Lees–Edwards U: at most 10¹⁰ √T_i.
  expect_refused({kWalls, "boundary.shear_velocity=2e10"}, {"boundary.shear_velocity = 20000000000", "1e+10 √T_i"});
}

TEST(ConfigWalls, BadWallKeysAreRefusedByNameAndRange) {
  expect_refused({kWalls, "boundary.wall_axes=[\"z\"]"},
                 {"boundary.wall_axes = [\"z\"]", "x, y", "z walls need system.dimension = 3"});
  expect_refused({kWalls, "boundary.wall_axes=[]"}, {"boundary.wall_axes = []", "non-empty list"});
  expect_refused({kWalls, "boundary.wall_axes=[\"y\", \"y\"]"}, {"boundary.wall_axes", "distinct"});
  expect_refused({kWalls, "boundary.wall_axes=\"y\""}, {"boundary.wall_axes = \"y\"", "list"});
  expect_refused({k3d, kWalls, "boundary.wall_axes=[\"w\"]"}, {"boundary.wall_axes = [\"w\"]", "x, y, z"});
  expect_refused({kWalls, "boundary.wall_restitution=0"}, {"boundary.wall_restitution = 0", "(0, 1]"});
  expect_refused({kWalls, "boundary.wall_restitution=1.01"}, {"boundary.wall_restitution = 1.01", "(0, 1]"});
  expect_refused({kWalls, "boundary.wall_restitution=[0.5]"}, {"boundary.wall_restitution = [0.5]", "[lower, upper]", "(0, 1]"});
  expect_refused({kWalls, "boundary.wall_restitution=[0.5, nan]"}, {"boundary.wall_restitution", "[lower, upper]"});
  expect_refused({kWalls, "boundary.wall_tangential_restitution=-1.5"},
                 {"boundary.wall_tangential_restitution = -1.5", "[-1, 1]"});
  expect_refused({kWalls, "boundary.wall_tangential_restitution=[0, 2]"},
                 {"boundary.wall_tangential_restitution = [0, 2]", "[-1, 1]"});
  for (const std::string key : {"wall_axes=[\"y\"]", "wall_restitution=0.5", "wall_tangential_restitution=0"}) {
    expect_refused({"boundary.kind=\"lees-edwards\"", "boundary." + key}, {"boundary." + key.substr(0, key.find('=')),
                                                                           "requires boundary.kind = \"walls\""});
  }
  // A side along a wall axis must hold a diameter: centres stay a radius from each wall.
  expect_refused({kWalls, "system.particles=10", "system.diameter=0.01", "system.box=[100.0, 0.005]"},
                 {"boundary.wall_axes", "L_y = 0.005", "σ = 0.01"});
}

TEST(ConfigWalls, OnlyYWallsShear) {
  expect_refused({kWalls, "boundary.wall_axes=[\"x\"]", "boundary.shear_velocity=1"},
                 {"boundary.shear_velocity = 1", "\"y\" in boundary.wall_axes"});
  expect_refused({"boundary.shear_velocity=1"}, {"boundary.shear_velocity = 1", "lees-edwards", "allowed: 0"});
  expect_refused({kWalls, "boundary.wall_axes=[\"x\"]", "boundary.shear_ramp_time=1"},
                 {"boundary.shear_ramp_time", "\"y\" in boundary.wall_axes"});
  // Walls follow U(t) exactly, not in segments: no tolerance to set.
  expect_refused({kWalls, "boundary.shear_velocity=1", "boundary.shear_tolerance=0.01"},
                 {"boundary.shear_tolerance", "exactly ±U(t)/2"});
}

// The y walls follow the Lees–Edwards drives of Chapter 4 at ∓½ U(t), the images rest.
TEST(ConfigWalls, WallDrivesTakeTheShearProtocolsAtHalfTheirVelocity) {
  const RunConfig ramp = accepted({kWalls, "boundary.shear_velocity=2", "boundary.shear_ramp_time=0.5"});
  EXPECT_EQ(ramp.system.shear_velocity, 0.0);
  for (const int face : {2, 3}) {
    const WallParams& w = ramp.system.wall[face];
    const ShearProtocol drive(w.velocity[0], w.along);
    const double half = face == 2 ? -1.0 : 1.0;
    EXPECT_EQ(drive.velocity(0.0), 0.0);
    EXPECT_NEAR(drive.velocity(0.5), half * (1.0 - std::exp(-1.0)), 1e-15);
  }
  const RunConfig schedule = accepted({kWalls, "boundary.shear_schedule=[[0, 1], [1, 3]]"});
  EXPECT_EQ(wall_shear_velocity(schedule.system), 3.0);
  EXPECT_DOUBLE_EQ(ShearProtocol(schedule.system.wall[3].velocity[0], schedule.system.wall[3].along).velocity(0.5), 1.0);
  EXPECT_DOUBLE_EQ(ShearProtocol(schedule.system.wall[2].velocity[0], schedule.system.wall[2].along).velocity(0.5), -1.0);
  const RunConfig kick = accepted({kWalls, "boundary.shear_velocity=1", "boundary.shear_oscillation={ amplitude = 0.4, period = 2 }"});
  EXPECT_DOUBLE_EQ(ShearProtocol(kick.system.wall[3].velocity[0], kick.system.wall[3].along).velocity(0.5), 0.5 + 0.2);
  // The echo reads back to the same walls.
  const ConfigResult again = parse_config(to_toml(kick), {});
  ASSERT_TRUE(again.config) << again.error;
  EXPECT_EQ(again.config->system.wall[2].along.oscillation->amplitude, -0.2);
  // A square kick: +A for the first half period, −A for the second, read back from the echo.
  const RunConfig square = accepted({kWalls, "boundary.shear_velocity=1",
                                     "boundary.shear_oscillation={ amplitude = 0.4, period = 2, waveform = \"square\" }"});
  const ShearProtocol upper(square.system.wall[3].velocity[0], square.system.wall[3].along);
  EXPECT_DOUBLE_EQ(upper.velocity(0.5), 0.5 + 0.2);
  EXPECT_DOUBLE_EQ(upper.velocity(1.5), 0.5 - 0.2);
  const ConfigResult square_again = parse_config(to_toml(square), {});
  ASSERT_TRUE(square_again.config) << square_again.error;
  EXPECT_EQ(square_again.config->system.wall[3].along.oscillation->waveform, Waveform::kSquare);
  expect_refused({kWalls, "boundary.shear_oscillation={ amplitude = 0.4, period = 2, waveform = \"saw\" }"},
                 {"boundary.shear_oscillation.waveform", "sine", "square", "triangle"});
}

TEST(ConfigWalls, AWallMovesNormalToItselfByAVibrationOrASchedule) {
  const RunConfig c = accepted({kWalls, "system.gravity=[0, -1]", "system.box=[8.0, 8.0]",
                                "boundary.wall_motion={ wall = \"y0\", amplitude = 0.5, frequency = 2, schedule = [[0, 0], [1, 3]] }"});
  const WallMotion& m = c.system.wall[2].motion;
  EXPECT_EQ(m.amplitude, 0.5);
  EXPECT_EQ(m.frequency, 2.0);
  ASSERT_EQ(m.schedule.size(), 2u);
  EXPECT_EQ(m.reach(), 4.0);
  EXPECT_FALSE(c.system.wall[3].motion.moves());
  const ConfigResult again = parse_config(to_toml(c), {});
  ASSERT_TRUE(again.config) << again.error;
  EXPECT_EQ(again.config->system.wall[2].motion.schedule.back().displacement, 3.0);
  const std::string key = "boundary.wall_motion";
  expect_refused({key + "={ wall = \"y0\", amplitude = 1, frequency = 1 }"}, {key, "requires boundary.kind = \"walls\""});
  expect_refused({kWalls, key + "={ wall = \"x0\", amplitude = 1, frequency = 1 }"}, {key + ".wall", "y0", "y1"});
  expect_refused({kWalls, key + "={ wall = \"y0\", amplitude = 1 }"}, {key + ".amplitude", "frequency"});
  expect_refused({kWalls, key + "={ wall = \"y0\", frequency = 1 }"}, {key + ".frequency", "amplitude"});
  expect_refused({kWalls, key + "={ wall = \"y0\" }"}, {key, "amplitude and frequency, or a schedule"});
  expect_refused({kWalls, key + "={ wall = \"y1\", schedule = [[0, 1]] }"}, {key + ".schedule point [0, 1]", "starting from h = 0"});
  expect_refused({kWalls, key + "={ wall = \"y1\", schedule = [[0, 0], [0, 1]] }"}, {"increasing order"});
  expect_refused({kWalls, key + "={ wall = \"y0\", amplitude = 1, frequency = 1, speed = 2 }"}, {key, "speed"});
  expect_refused({kWalls, key + "={ wall = \"y0\", amplitude = 1, frequency = 1, shape = \"square\" }"},
                 {key + ".shape", "sine", "triangle", "biparabolic"});
  expect_refused({kWalls, key + "={ wall = \"y1\", schedule = [[0, 0], [1, 1]], shape = \"triangle\" }"}, {key + ".shape", "amplitude"});
}

// The shape of the vibration, read back from the echo; the drive's velocity wave gives h between 0
// and 2A: its integral over the first half period.
TEST(ConfigWalls, AVibrationTakesTheShapeOfASineATriangleOrParabolicArcs) {
  for (const auto& [name, shape] : {std::pair{"sine", VibrationShape::kSine}, std::pair{"triangle", VibrationShape::kTriangle},
                                    std::pair{"biparabolic", VibrationShape::kBiparabolic}}) {
    const RunConfig c = accepted({kWalls, "system.gravity=[0, -1]", "system.box=[8.0, 8.0]",
                                  std::string("boundary.wall_motion={ wall = \"y0\", amplitude = 0.5, frequency = 2, shape = \"") + name + "\" }"});
    const WallMotion& m = c.system.wall[2].motion;
    EXPECT_EQ(m.shape, shape) << name;
    EXPECT_NEAR(m.velocity().integral(0.0, 0.25), 1.0, 1e-15) << name << ": h at half a period is 2A";
    EXPECT_NEAR(m.velocity().integral(0.0, 0.5), 0.0, 1e-15) << name << ": back at the face after a period";
    const ConfigResult again = parse_config(to_toml(c), {});
    ASSERT_TRUE(again.config) << again.error;
    EXPECT_EQ(again.config->system.wall[2].motion.shape, shape) << name;
  }
}

TEST(ConfigGravity, FiniteVectorOfTheDimension) {
  EXPECT_EQ(accepted({"system.gravity=[0.5, -2]"}).system.gravity, (std::array<double, 3>{0.5, -2.0, 0.0}));
  EXPECT_EQ(accepted({k3d, "system.gravity=[1, -2, 3]"}).system.gravity, (std::array<double, 3>{1.0, -2.0, 3.0}));
  expect_refused({"system.gravity=[0, -1, 0]"}, {"system.gravity = [0, -1, 0]", "[g_x, g_y]", "(-∞, ∞)", "system.dimension = 2"});
  expect_refused({k3d, "system.gravity=[0, -1]"}, {"system.gravity = [0, -1]", "[g_x, g_y, g_z]"});
  expect_refused({"system.gravity=[0, nan]"}, {"system.gravity = [0, nan]", "(-∞, ∞)"});
  expect_refused({"system.gravity=[inf, 0]"}, {"system.gravity = [inf, 0]", "(-∞, ∞)"});
  expect_refused({"system.gravity=-1"}, {"system.gravity = -1", "[g_x, g_y]"});
}

TEST(ConfigGravity, GravityAlongYIsRefusedWithLeesEdwardsAndAllowedAcrossTheShear) {
  expect_refused({"boundary.kind=\"lees-edwards\"", "boundary.shear_velocity=1", "system.gravity=[0, -1]"},
                 {"system.gravity = [0, -1]", "g_y = -1", "lees-edwards", "cubic in time", "boundary.kind = \"walls\""});
  EXPECT_EQ(accepted({"boundary.kind=\"lees-edwards\"", "system.gravity=[2, 0]"}).system.gravity[0], 2.0);
  EXPECT_EQ(accepted({kWalls, "boundary.shear_velocity=1", "system.gravity=[0, -1]"}).system.gravity[1], -1.0);
}

TEST(ConfigRoughness, TangentialRestitutionMakesGrainsRoughWithUniformInertiaByDefault) {
  const RunConfig smooth = accepted({});
  EXPECT_FALSE(smooth.system.roughness.rough);
  EXPECT_EQ(smooth.initial_rotational_temperature, 0.0);

  const RunConfig disks = accepted({"system.tangential_restitution=-0.8", "initial.temperature=2"});
  const RoughnessParams& r = disks.system.roughness;
  EXPECT_TRUE(r.rough);
  EXPECT_EQ(r.tangential_restitution, -0.8);
  EXPECT_EQ(r.inertia_factor, 0.5);  // uniform disk: I = m σ²/8
  EXPECT_TRUE(std::isinf(r.friction));
  EXPECT_EQ(disks.initial_rotational_temperature, 2.0);  // equipartition

  const RunConfig spheres = accepted({k3d, "system.tangential_restitution=1", "system.inertia_factor=1",
                                      "system.friction=0.3", "initial.rotational_temperature=0"});
  EXPECT_EQ(accepted({k3d, "system.tangential_restitution=0"}).system.roughness.inertia_factor, 0.4);  // m σ²/10
  EXPECT_EQ(spheres.system.roughness.inertia_factor, 1.0);
  EXPECT_EQ(spheres.system.roughness.friction, 0.3);
  EXPECT_EQ(spheres.initial_rotational_temperature, 0.0);
  EXPECT_EQ(accepted({"system.tangential_restitution=-1", "system.friction=0"}).system.roughness.friction, 0.0);
}

TEST(ConfigRoughness, BadValuesAreRefusedByNameAndRange) {
  expect_refused({"system.tangential_restitution=1.5"}, {"system.tangential_restitution = 1.5", "[-1, 1]"});
  expect_refused({"system.tangential_restitution=-1.01"}, {"system.tangential_restitution = -1.01", "[-1, 1]"});
  expect_refused({"system.tangential_restitution=nan"}, {"system.tangential_restitution = nan", "[-1, 1]"});
  const std::string rough = "system.tangential_restitution=0";
  expect_refused({rough, "system.inertia_factor=0"}, {"system.inertia_factor = 0", "(0, 1]"});
  expect_refused({rough, "system.inertia_factor=1.5"}, {"system.inertia_factor = 1.5", "(0, 1]"});
  expect_refused({rough, "system.friction=-0.1"}, {"system.friction = -0.1", "[0, ∞)"});
  expect_refused({rough, "system.friction=inf"}, {"system.friction = inf", "[0, ∞)"});
  expect_refused({rough, "initial.rotational_temperature=-1"}, {"initial.rotational_temperature = -1", "[1e-60, 1e+60]"});
  expect_refused({rough, "initial.rotational_temperature=1e61"}, {"initial.rotational_temperature = 1e+61", "0 (no spin)"});
  for (const std::string key : {"system.inertia_factor=0.5", "system.friction=1", "initial.rotational_temperature=1"}) {
    expect_refused({key}, {key.substr(0, key.find('=')), "system.tangential_restitution"});
  }
  expect_refused({rough, "initial.from=\"elsewhere\"", "initial.rotational_temperature=1"},
                 {"initial.rotational_temperature", "initial.from"});
  expect_refused({rough, "boundary.kind=\"lees-edwards\"", "boundary.shear_velocity=1", "initial.temperature_over_steady=2"},
                 {"initial.temperature_over_steady = 2", "smooth disks"});
}

TEST(ConfigWallsGravityRoughness, ToTomlRepeatsEveryNewKeyExactly) {
  const std::vector<std::vector<std::string>> cases = {
      {kWalls, "boundary.shear_velocity=0.3", "boundary.wall_restitution=[0.8, 0.7]", "boundary.wall_tangential_restitution=-0.8",
       "system.tangential_restitution=-0.8", "system.gravity=[0.1, -1]", "initial.rotational_temperature=0.25"},
      {k3d, kWalls, "boundary.wall_axes=[\"y\", \"z\"]", "boundary.wall_restitution=0.9", "system.tangential_restitution=0.4",
       "system.inertia_factor=0.35", "system.friction=0.5", "system.gravity=[0.5, -1, 0]", "initial.placement=\"lattice\""},
      {"boundary.kind=\"lees-edwards\"", "boundary.shear_velocity=5", "system.tangential_restitution=-0.8",
       "system.gravity=[-3, 0]"},
  };
  for (const auto& overrides : cases) {
    const RunConfig first = accepted(overrides);
    const std::string text = to_toml(first);
    const ConfigResult again = parse_config(text, {});
    ASSERT_TRUE(again.config) << again.error << "\n" << text;
    const RunConfig& second = *again.config;
    EXPECT_EQ(to_toml(second), text);
    const SystemParams& a = first.system;
    const SystemParams& b = second.system;
    EXPECT_EQ(a.walls, b.walls) << text;
    for (std::size_t face = 0; face < 6; ++face) {
      EXPECT_EQ(a.wall[face].restitution, b.wall[face].restitution) << face << "\n" << text;
      EXPECT_EQ(a.wall[face].tangential_restitution, b.wall[face].tangential_restitution) << face << "\n" << text;
      EXPECT_EQ(a.wall[face].velocity, b.wall[face].velocity) << face << "\n" << text;
    }
    EXPECT_EQ(a.gravity, b.gravity) << text;
    EXPECT_EQ(a.shear_velocity, b.shear_velocity) << text;
    EXPECT_EQ(a.roughness.rough, b.roughness.rough) << text;
    EXPECT_EQ(a.roughness.tangential_restitution, b.roughness.tangential_restitution) << text;
    EXPECT_EQ(a.roughness.inertia_factor, b.roughness.inertia_factor) << text;
    EXPECT_EQ(a.roughness.friction, b.roughness.friction) << text;
    EXPECT_EQ(first.initial_rotational_temperature, second.initial_rotational_temperature) << text;
    EXPECT_EQ(first.lees_edwards, second.lees_edwards) << text;
  }
  // The walls of the first case as written, read by eye.
  const std::string walled = to_toml(accepted(cases[0]));
  for (const std::string line : {"kind = \"walls\"\n", "wall_axes = [\"y\"]\n", "wall_restitution = [0.80000000000000004, 0.69999999999999996]\n",
                                 "wall_tangential_restitution = -0.80000000000000004\n", "shear_velocity = 0.29999999999999999\n",
                                 "tangential_restitution = -0.80000000000000004\n", "inertia_factor = 0.5\n",
                                 "gravity = [0.10000000000000001, -1]\n", "rotational_temperature = 0.25\n"}) {
    EXPECT_NE(walled.find(line), std::string::npos) << line << " missing from\n" << walled;
  }
  EXPECT_EQ(walled.find("friction"), std::string::npos) << "no Coulomb limit is written as no key";
}

TEST(ConfigWallsGravityRoughness, SmoothPeriodicRunsWriteNoNewKey) {
  const std::string text = to_toml(accepted({"boundary.kind=\"lees-edwards\"", "boundary.shear_velocity=1"}));
  for (const std::string key : {"wall", "gravity", "tangential_restitution", "inertia_factor", "friction", "rotational"}) {
    EXPECT_EQ(text.find(key), std::string::npos) << key << " in\n" << text;
  }
}

// Grains at rest (physics/rest_rule.hpp): the keys, their default and the combinations refused by name.
TEST(ConfigRest, RestSpeedNeedsGravityAndDisksAndNoLeesEdwardsImagesAndSetsAWakeSpeed) {
  const RunConfig c = accepted({kWalls, "system.gravity=[0, -4]", "system.diameter=0.01", "system.particles=100",
                                "system.box=[1.0, 1.0]", "system.rest_speed=0.002"});
  EXPECT_EQ(c.system.rest.speed, 0.002);
  EXPECT_DOUBLE_EQ(c.system.rest.wake_speed, 0.1 * std::sqrt(4.0 * 0.01));  // lifts a grain by σ/200
  EXPECT_EQ(accepted({kWalls, "system.gravity=[0, -1]", "system.rest_speed=0.01", "system.wake_speed=0.5"}).system.rest.wake_speed, 0.5);
  EXPECT_FALSE(accepted({kWalls, "system.gravity=[0, -1]"}).system.rest.on());
  expect_refused({kWalls, "system.rest_speed=0.01"}, {"system.rest_speed = 0.01", "needs system.gravity"});
  expect_refused({kWalls, "system.gravity=[0, -1]", "system.rest_speed=0"}, {"system.rest_speed = 0", "(0, ∞)"});
  expect_refused({kWalls, "system.gravity=[0, -1]", "system.rest_speed=-1"}, {"system.rest_speed = -1"});
  expect_refused({kWalls, "system.gravity=[0, -1]", "system.wake_speed=0.1"}, {"system.wake_speed needs system.rest_speed"});
  expect_refused({k3d, kWalls, "system.gravity=[0, -1, 0]", "system.rest_speed=0.01"}, {"system.rest_speed = 0.01", "disks"});
  expect_refused({"boundary.kind=\"lees-edwards\"", "system.gravity=[-1, 0]", "system.rest_speed=0.01"},
                 {"system.rest_speed = 0.01", "lees-edwards"});
}

}  // namespace
}  // namespace granule
