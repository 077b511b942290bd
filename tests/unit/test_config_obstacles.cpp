// [[obstacles]] (README "Configuration reference"): each entry a fixed disk or sphere (centre,
// diameter) or a CSV file of them, with its restitutions.  Good values reach SystemParams as
// documented and come back through to_toml(); each bad one is refused naming the entry, the key and
// what is allowed (written out here as literals); Lees–Edwards images are refused, naming why.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "io/config.hpp"

namespace granule {
namespace {

// A 2D system of 200 disks of σ = 0.02 in a unit box (the default's N is too large for a small box).
const std::string kSmall = "[system]\nparticles = 200\ndiameter = 0.02\nbox = [1.0, 1.0]\n";

ConfigResult parsed(const std::string& text) { return parse_config(kSmall + text, {}); }

void expect_refused(const std::string& text, const std::vector<std::string>& fragments) {
  const ConfigResult result = parse_config(kSmall + text, {});
  ASSERT_FALSE(result.config.has_value()) << "accepted: " << text;
  for (const auto& fragment : fragments) {
    EXPECT_NE(result.error.find(fragment), std::string::npos) << "'" << fragment << "' missing from: " << result.error;
  }
}

TEST(ConfigObstacles, EachEntryIsAnObstacleWithItsRestitutions) {
  const ConfigResult result = parsed(
      "[[obstacles]]\ncentre = [0.5, 0.25]\ndiameter = 0.1\n\n"
      "[[obstacles]]\ncentre = [0.0, 0.9]\ndiameter = 0.2\nrestitution = 0.8\ntangential_restitution = 0.3\n");
  ASSERT_TRUE(result.config) << result.error;
  const auto& obstacles = result.config->system.obstacles;
  ASSERT_EQ(obstacles.size(), 2u);
  EXPECT_EQ(obstacles[0].centre[0], 0.5);
  EXPECT_EQ(obstacles[0].centre[1], 0.25);
  EXPECT_EQ(obstacles[0].diameter, 0.1);
  EXPECT_EQ(obstacles[0].restitution, 1.0);  // elastic and smooth unless given
  EXPECT_EQ(obstacles[0].tangential_restitution, -1.0);
  EXPECT_EQ(obstacles[1].restitution, 0.8);
  EXPECT_EQ(obstacles[1].tangential_restitution, 0.3);
  const ConfigResult again = parse_config(to_toml(*result.config), {});
  ASSERT_TRUE(again.config) << again.error;
  ASSERT_EQ(again.config->system.obstacles.size(), 2u);
  EXPECT_EQ(again.config->system.obstacles[1].centre[1], 0.9);
  EXPECT_EQ(again.config->system.obstacles[1].tangential_restitution, 0.3);
}

TEST(ConfigObstacles, AFileGivesManyObstaclesSharingTheirRestitutions) {
  const std::string path = testing::TempDir() + "pegs.csv";
  {
    std::ofstream file(path);
    file << "diameter, x, y\n0.1, 0.2, 0.3\n0.05, 0.7, 0.7\n\n";
  }
  const ConfigResult result = parsed("[[obstacles]]\nfile = \"" + path + "\"\nrestitution = 0.9\n");
  ASSERT_TRUE(result.config) << result.error;
  const auto& obstacles = result.config->system.obstacles;
  ASSERT_EQ(obstacles.size(), 2u);
  EXPECT_EQ(obstacles[1].centre[0], 0.7);
  EXPECT_EQ(obstacles[1].diameter, 0.05);
  EXPECT_EQ(obstacles[0].restitution, 0.9);
  {
    std::ofstream file(path);
    file << "x,y,diameter\n0.2,0.3,0.1\n0.7,oops,0.1\n";
  }
  expect_refused("[[obstacles]]\nfile = \"" + path + "\"\n", {path, "line 3", "column 2", "\"y\"", "not a finite number"});
  {
    std::ofstream file(path);
    file << "x,diameter\n0.2,0.1\n";
  }
  expect_refused("[[obstacles]]\nfile = \"" + path + "\"\n", {path, "no column \"y\""});
  std::remove(path.c_str());
  expect_refused("[[obstacles]]\nfile = \"" + path + "\"\n", {"cannot read the obstacle file", path});
}

TEST(ConfigObstacles, BadEntriesAreRefusedByNameAndRange) {
  expect_refused("[[obstacles]]\ncentre = [0.5, 0.5]\n", {"obstacles[0] needs diameter = D in [1e-30, 1e+30]"});
  expect_refused("[[obstacles]]\ndiameter = 0.1\n", {"obstacles[0] needs centre = [x, y]", "2 numbers"});
  expect_refused("[[obstacles]]\ncentre = [0.5, 0.5, 0.5]\ndiameter = 0.1\n", {"obstacles[0]", "centre = [x, y]", "[0.5, 0.5, 0.5]"});
  expect_refused("[[obstacles]]\ncentre = [0.5, 0.5]\ndiameter = -1\n", {"obstacles[0].diameter = -1", "[1e-30, 1e+30]"});
  expect_refused("[[obstacles]]\ncentre = [0.5, 0.5]\ndiameter = 0.1\nrestitution = 1.5\n", {"obstacles[0].restitution = 1.5", "(0, 1]"});
  expect_refused("[[obstacles]]\ncentre = [0.5, 0.5]\ndiameter = 0.1\ntangential_restitution = 2\n",
                 {"obstacles[0].tangential_restitution = 2", "[-1, 1]"});
  expect_refused("[[obstacles]]\ncentre = [0.5, 0.5]\ndiameter = 0.1\nspeed = 2\n", {"unknown key obstacles[0].speed", "allowed: centre"});
  expect_refused("[[obstacles]]\ncentre = [0.5, 0.5]\ndiameter = 0.1\n[[obstacles]]\ncentre = [1.5, 0.5]\ndiameter = 0.1\n",
                 {"obstacles[1] has its centre at x = 1.5, outside the box: allowed [0, 1) (periodic)"});
  expect_refused("[[obstacles]]\ncentre = [0.5, 0.5]\ndiameter = 0.99\n", {"obstacles[0] has diameter 0.99", "below L_x − σ = 0.98"});
  const ConfigResult scalar = parse_config("obstacles = 3\n" + kSmall, {});
  ASSERT_FALSE(scalar.config);
  EXPECT_NE(scalar.error.find("obstacles must be an array of tables"), std::string::npos) << scalar.error;
  expect_refused("[[obstacles]]\ncentre = [0.5, 0.5]\ndiameter = 0.1\nfile = \"a.csv\"\n", {"obstacles[0] has a file and a centre"});
}

TEST(ConfigObstacles, LeesEdwardsImagesAreRefusedNamingWhyAndWallsAccepted) {
  expect_refused("[boundary]\nkind = \"lees-edwards\"\nshear_velocity = 1\n[[obstacles]]\ncentre = [0.5, 0.5]\ndiameter = 0.1\n",
                 {"[[obstacles]] cannot be combined with boundary.kind = \"lees-edwards\"", "slide at ±U", "wall-driven"});
  const ConfigResult walled = parsed(
      "[boundary]\nkind = \"walls\"\nwall_axes = [\"y\"]\nshear_velocity = 1\n[[obstacles]]\ncentre = [0.5, 1.0]\ndiameter = 0.3\n");
  ASSERT_TRUE(walled.config) << walled.error;  // on a wall: a bump of the wall, allowed
  EXPECT_EQ(walled.config->system.obstacles.size(), 1u);
}

}  // namespace
}  // namespace granule
