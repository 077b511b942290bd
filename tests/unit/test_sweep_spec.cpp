// The expansion of a sweep spec into points (src/sweep/sweep_spec.hpp): the order of the product,
// zipped keys, seeds from the base seed, point names, and the exact --set text of each value.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/config.hpp"
#include "sweep/sweep_spec.hpp"

namespace granule::sweep {
namespace {

const std::string kBase = "seed = 5\n[system]\nparticles = 300\n[boundary]\nkind = \"lees-edwards\"\n";

std::vector<std::string> names(const std::string& sweep) {
  const SweepSpecResult parsed = parse_sweep_spec(kBase + "[sweep]\n" + sweep);
  EXPECT_TRUE(parsed.spec) << parsed.error;
  std::vector<std::string> out;
  if (parsed.spec) {
    for (const SweepPoint& p : parsed.spec->points) out.push_back(p.name);
  }
  return out;
}

TEST(SweepSpec, ProductVariesTheFirstKeySlowestAndTheSeedsLast) {
  EXPECT_EQ(names("system.restitution = [0.6, 0.8]\n\"boundary.shear_velocity\" = [1, 2.5]\nseeds = 2\n"),
            (std::vector<std::string>{
                "shear_velocity=1__restitution=0.6__seed=5", "shear_velocity=1__restitution=0.6__seed=6",
                "shear_velocity=1__restitution=0.8__seed=5", "shear_velocity=1__restitution=0.8__seed=6",
                "shear_velocity=2.5__restitution=0.6__seed=5", "shear_velocity=2.5__restitution=0.6__seed=6",
                "shear_velocity=2.5__restitution=0.8__seed=5", "shear_velocity=2.5__restitution=0.8__seed=6"}));
}

TEST(SweepSpec, ZippedKeysStepTogetherAndTheOthersMultiply) {
  EXPECT_EQ(names("system.restitution = [0.6, 0.8]\nboundary.shear_velocity = [1, 2]\nzip = true\n"),
            (std::vector<std::string>{"shear_velocity=1__restitution=0.6", "shear_velocity=2__restitution=0.8"}));
  EXPECT_EQ(
      names("system.restitution = [0.6, 0.8]\nboundary.shear_velocity = [1, 2]\nsystem.particles = [200, 400]\n"
            "zip = [\"system.restitution\", \"boundary.shear_velocity\"]\n"),
      (std::vector<std::string>{
          "shear_velocity=1__particles=200__restitution=0.6", "shear_velocity=1__particles=400__restitution=0.6",
          "shear_velocity=2__particles=200__restitution=0.8", "shear_velocity=2__particles=400__restitution=0.8"}));
}

TEST(SweepSpec, KeysEndingAlikeAreNamedInFullAndStringsAreMadeSafe) {
  EXPECT_EQ(names("fields.cells = [[10, 10]]\ndiagnostics.cells = [[8, 8]]\n"),
            (std::vector<std::string>{"diagnostics-cells=8,8__fields-cells=10,10"}));
  EXPECT_EQ(names("initial.placement = [\"random\", \"lattice\"]\nseeds = [3]\n"),
            (std::vector<std::string>{"placement=random__seed=3", "placement=lattice__seed=3"}));
}

TEST(SweepSpec, ValuesReachTheRunExactly) {
  const SweepSpecResult parsed = parse_sweep_spec(kBase + "[sweep]\nsystem.restitution = [0.1, 0.30000000000000004]\n");
  ASSERT_TRUE(parsed.spec) << parsed.error;
  for (std::size_t k = 0; k < 2; ++k) {
    const ConfigResult config = parse_config(parsed.spec->base_toml, parsed.spec->points[k].overrides());
    ASSERT_TRUE(config.config) << config.error;
    EXPECT_EQ(config.config->system.restitution, k == 0 ? 0.1 : 0.30000000000000004);
  }
  EXPECT_EQ(parsed.spec->points[1].name, "restitution=0.30000000000000004");
}

TEST(SweepSpec, RefusalsNameTheKey) {
  const std::pair<std::string, std::string> cases[] = {
      {"system.restitution = []\n", "system.restitution"},
      {"system.restitution = [0.6, 1.5]\n", "system.restitution = 1.5"},
      {"system.restitution = [0.6]\nzip = [\"seed\"]\n", "seed"},
      {"seeds = [1, 1]\n", "seeds"},
      {"seeds = -2\n", "seeds"},
      {"zip = 3\n", "zip"},
      {"initial.placement = [\"a/b\", \"a_b\"]\n", "directory name"},
  };
  for (const auto& [sweep, key] : cases) {
    const SweepSpecResult parsed = parse_sweep_spec(kBase + "[sweep]\n" + sweep);
    EXPECT_FALSE(parsed.spec) << sweep;
    EXPECT_NE(parsed.error.find(key), std::string::npos) << sweep << " → " << parsed.error;
  }
  EXPECT_FALSE(parse_sweep_spec(kBase).spec) << "no [sweep] table";
}

}  // namespace
}  // namespace granule::sweep
