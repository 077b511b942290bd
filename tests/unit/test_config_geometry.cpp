// The geometry keys of 3D and polydisperse runs: system.dimension, a box of d sides,
// system.packing_fraction (the area fraction's 2D name stays), system.diameters and system.masses.
// Every refusal names the key, the value and what is allowed; to_toml() repeats the run.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/config.hpp"

namespace granule {
namespace {

ConfigResult parse(const std::vector<std::string>& overrides) { return parse_config("", overrides); }

void expect_refused(const std::vector<std::string>& overrides, const std::vector<std::string>& fragments) {
  const ConfigResult result = parse(overrides);
  ASSERT_FALSE(result.config.has_value()) << "accepted: " << overrides.back();
  for (const auto& fragment : fragments) {
    EXPECT_NE(result.error.find(fragment), std::string::npos) << "'" << fragment << "' missing from: " << result.error;
  }
}

const std::string kCube = "system.box=[1.0, 1.0, 1.0]";

TEST(ConfigGeometry, DimensionAndBox) {
  expect_refused({"system.dimension=4"}, {"system.dimension = 4", "[2, 3]"});
  expect_refused({"system.dimension=2.0"}, {"system.dimension = 2 is not allowed", "integer"});
  expect_refused({"system.dimension=3", "system.box=[1.0, 1.0]"},
                 {"system.box = [1, 1]", "[Lx, Ly, Lz]", "three numbers", "system.dimension = 3"});
  expect_refused({"system.box=[1.0, 1.0, 1.0]"}, {"system.box = [1, 1, 1]", "[Lx, Ly]", "system.dimension = 2"});
  expect_refused({"system.dimension=3", "system.box=[1.0, 1.0, 1e31]"}, {"system.box", "[1e-30, 1e+30]"});
  const ConfigResult ok = parse({"system.dimension=3", "system.box=[1.0, 2.0, 3.0]", "system.packing_fraction=0.1"});
  ASSERT_TRUE(ok.config) << ok.error;
  EXPECT_EQ(ok.config->system.dimension, 3);
  EXPECT_EQ(ok.config->system.length_z, 3.0);
  // φ = π N σ³ / (6 V) with N = 4000, V = 6.
  const double sigma = ok.config->system.diameter;
  EXPECT_NEAR(M_PI * 4000 * sigma * sigma * sigma / 36.0, 0.1, 1e-15);
}

TEST(ConfigGeometry, PackingFractionNames) {
  // Both in one file (a --set of one replaces the other, below).
  const ConfigResult both = parse_config("[system]\narea_fraction = 0.1\npacking_fraction = 0.1\n", {});
  ASSERT_FALSE(both.config);
  EXPECT_NE(both.error.find("system.area_fraction and system.packing_fraction are both set"), std::string::npos) << both.error;
  const ConfigResult with_diameter = parse_config("[system]\npacking_fraction = 0.1\ndiameter = 0.001\n", {});
  ASSERT_FALSE(with_diameter.config);
  EXPECT_NE(with_diameter.error.find("system.packing_fraction and system.diameter are both set"), std::string::npos)
      << with_diameter.error;
  expect_refused({"system.dimension=3", kCube, "system.area_fraction=0.1"},
                 {"system.area_fraction", "system.packing_fraction", "volume fraction"});
  // In 2D the two names are one: the same σ.
  const ConfigResult a = parse({"system.area_fraction=0.3"}), b = parse({"system.packing_fraction=0.3"});
  ASSERT_TRUE(a.config && b.config);
  EXPECT_EQ(a.config->system.diameter, b.config->system.diameter);
  // A --set replaces the other names from the file.
  const ConfigResult replaced = parse_config("[system]\narea_fraction = 0.2\n", {"system.packing_fraction=0.3"});
  ASSERT_TRUE(replaced.config) << replaced.error;
  EXPECT_EQ(replaced.config->packing_fraction, b.config->packing_fraction);
}

// FCC close packing π/(3√2) = 0.7404804896930609 bounds monodisperse spheres; a polydisperse run
// is bounded by what its placement reaches.
TEST(ConfigGeometry, PackingLimits) {
  EXPECT_TRUE(parse({"system.dimension=3", kCube, "system.packing_fraction=0.74"}).config);
  expect_refused({"system.dimension=3", kCube, "system.packing_fraction=0.741"},
                 {"system.packing_fraction = 0.741", "0.7404804896930609)", "FCC close packing"});
  expect_refused({"system.packing_fraction=0.907"}, {"system.packing_fraction = 0.907", "0.9068996821171089)"});
  // Bidisperse σ_B = 2 σ_A, x_B = 0.3 in 3D: ⟨σ³⟩/σ_B³ = (0.7 + 0.3 · 8)/8 = 0.3875 of the FCC
  // lattice's reach (8 × 8 × 8 cells for N = 2000: 0.7233), i.e. 0.28; random addition 0.30.
  const std::vector<std::string> bidisperse = {"system.dimension=3", kCube, "system.particles=2000",
                                               "system.diameters={distribution=\"bidisperse\", ratio=2.0, fraction=0.3}"};
  auto with = [&](std::vector<std::string> keys, const std::string& more) {
    keys.push_back(more);
    return keys;
  };
  EXPECT_TRUE(parse(with(bidisperse, "system.packing_fraction=0.3")).config);
  expect_refused(with(bidisperse, "system.packing_fraction=0.31"),
                 {"system.packing_fraction = 0.31", "random addition up to 0.3", "FCC lattice of 2000 sites", "0.28"});
  auto lattice = with(bidisperse, "initial.placement=\"lattice\"");
  expect_refused(with(lattice, "system.packing_fraction=0.29"), {"system.packing_fraction = 0.29", "placement \"lattice\""});
  EXPECT_TRUE(parse(with(lattice, "system.packing_fraction=0.28")).config);
  expect_refused(with(bidisperse, "system.diameter=0.1"), {"system.diameter = 0.1", "allowed ["});
}

TEST(ConfigGeometry, DistributionsAndMasses) {
  expect_refused({"system.diameters={distribution=\"gamma\"}"},
                 {"system.diameters.distribution = \"gamma\"", "bidisperse", "lognormal", "monodisperse", "uniform"});
  expect_refused({"system.diameters={width=0.1}"}, {"system.diameters needs a distribution"});
  expect_refused({"system.diameters=\"uniform\""}, {"system.diameters = \"uniform\"", "table"});
  expect_refused({"system.diameters={distribution=\"uniform\", width=-0.1}"}, {"system.diameters.width = -0.1", "(0, 1)"});
  expect_refused({"system.diameters={distribution=\"uniform\", width=1.0}"}, {"system.diameters.width = 1", "(0, 1)"});
  expect_refused({"system.diameters={distribution=\"lognormal\", width=0}"}, {"system.diameters.width = 0", "(0, 1]"});
  expect_refused({"system.diameters={distribution=\"uniform\"}"}, {"system.diameters.width is missing"});
  expect_refused({"system.diameters={distribution=\"bidisperse\", ratio=2.0}"}, {"system.diameters.fraction is missing"});
  expect_refused({"system.diameters={distribution=\"bidisperse\", ratio=2.0, fraction=0.5, width=0.1}"},
                 {"system.diameters.width is not a parameter of the bidisperse distribution"});
  expect_refused({"system.diameters={distribution=\"bidisperse\", ratio=1000.0, fraction=0.5}"},
                 {"system.diameters.ratio = 1000", "[0.01, 100]"});
  expect_refused({"system.diameters={distribution=\"bidisperse\", ratio=2.0, fraction=1.5}"},
                 {"system.diameters.fraction = 1.5", "(0, 1)"});
  expect_refused({"system.diameters={distribution=\"uniform\", width=0.1, sigma=2}"}, {"unknown key system.diameters.sigma"});
  expect_refused({"system.masses=[1.0, 2.0]"}, {"system.masses", "bidisperse", "\"volume\""});
  expect_refused({"system.masses=[1.0, 2.0]", "system.diameters={distribution=\"uniform\", width=0.1}"},
                 {"system.masses", "bidisperse"});
  expect_refused({"system.masses=\"heavy\""}, {"system.masses = \"heavy\"", "volume"});
  const std::string bidisperse = "system.diameters={distribution=\"bidisperse\", ratio=2.0, fraction=0.5}";
  expect_refused({bidisperse, "system.masses=[1.0]"}, {"system.masses = [1]", "[m_A, m_B]", "two numbers"});
  expect_refused({bidisperse, "system.masses=[1.0, 0.0]"}, {"system.masses = [1, 0]", "[1e-12, 1000000000000]"});
  EXPECT_TRUE(parse({bidisperse, "system.masses=[1.0, 3.0]"}).config);
  EXPECT_TRUE(parse({"system.masses=\"volume\""}).config);
  expect_refused({"system.dimension=3", kCube, "boundary.kind=\"lees-edwards\"", "boundary.shear_velocity=10",
                  "initial.temperature_over_steady=2"},
                 {"initial.temperature_over_steady = 2", "equal disks"});
}

// config.toml repeats the run: re-reading to_toml() gives the same TOML, the same resolved
// diameters (largest and reference) and packing fraction, and the same per-particle sizes.
TEST(ConfigGeometry, ToTomlRoundTrips) {
  const std::vector<std::vector<std::string>> cases = {
      {},
      {"system.dimension=3", "system.box=[1.0, 2.0, 0.5]", "system.packing_fraction=0.37"},
      {"system.dimension=3", kCube, "system.diameters={distribution=\"bidisperse\", ratio=0.7, fraction=0.35}",
       "system.masses=[1.5, 0.25]", "system.packing_fraction=0.2", "seed=12"},
      {"system.diameters={distribution=\"lognormal\", width=0.3}", "system.packing_fraction=0.123456789"},
      {"system.dimension=3", kCube, "system.diameters={distribution=\"uniform\", width=0.25}", "system.diameter=0.01",
       "initial.placement=\"lattice\""},
  };
  for (const auto& keys : cases) {
    const ConfigResult first = parse(keys);
    ASSERT_TRUE(first.config) << first.error;
    const std::string text = to_toml(*first.config);
    const ConfigResult again = parse_config(text, {});
    ASSERT_TRUE(again.config) << again.error << "\n" << text;
    EXPECT_EQ(to_toml(*again.config), text);
    EXPECT_EQ(again.config->system.diameter, first.config->system.diameter);
    EXPECT_EQ(again.config->reference_diameter, first.config->reference_diameter);
    EXPECT_EQ(again.config->packing_fraction, first.config->packing_fraction);
    EXPECT_EQ(again.config->system.dimension, first.config->system.dimension);
    EXPECT_EQ(again.config->system.length_z, first.config->system.length_z);
    const ParticleSizes a = particle_sizes(*first.config), b = particle_sizes(*again.config);
    EXPECT_EQ(a.diameter, b.diameter);
    EXPECT_EQ(a.mass, b.mass);
  }
}

// A ν at the limit of its range is allowed, and the round trip ν → σ̄ → ν must not push it an ulp
// beyond: mixtures whose lattice reaches less than random addition have the random-addition
// limit itself as their (inclusive) bound.
TEST(ConfigGeometry, PackingFractionAtItsLimitIsNotRefusedForRoundOff) {
  int parsed = 0;
  for (int n = 300; n <= 700; ++n) {
    for (const char* mixture : {"ratio=3, fraction=0.05", "ratio=5, fraction=0.05", "ratio=8, fraction=0.5", "ratio=5, fraction=0.95"}) {
      const std::string sizes = std::string("system.diameters={distribution=\"bidisperse\", ") + mixture + "}";
      for (const auto& keys : {std::vector<std::string>{"system.dimension=3", kCube, "system.packing_fraction=0.3"},
                               std::vector<std::string>{"system.area_fraction=0.45"}}) {
        std::vector<std::string> all = keys;
        all.push_back("system.particles=" + std::to_string(n));
        all.push_back(sizes);
        const ConfigResult result = parse(all);
        ASSERT_TRUE(result.config) << "N = " << n << ", " << mixture << ": " << result.error;
        ++parsed;
      }
    }
  }
  EXPECT_EQ(parsed, 401 * 8);
}

}  // namespace
}  // namespace granule
