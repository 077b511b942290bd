// The numerical bounds of the run configuration (README "Ranges the engine can run"): each
// refusal names the key, the value and the allowed range, and values just inside each bound are
// accepted.  The bounds are written out here as literals, independently of io/input_ranges.hpp.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/config.hpp"

namespace granule {
namespace {

ConfigResult parse(const std::vector<std::string>& overrides) { return parse_config("", overrides); }

void expect_accepted(const std::vector<std::string>& overrides) {
  const ConfigResult result = parse(overrides);
  EXPECT_TRUE(result.config.has_value()) << "refused: " << result.error;
}

// Refused, and the message contains every fragment (the key, the value, the range).
void expect_refused(const std::vector<std::string>& overrides, const std::vector<std::string>& fragments) {
  const ConfigResult result = parse(overrides);
  ASSERT_FALSE(result.config.has_value()) << "accepted: " << overrides.back();
  for (const auto& fragment : fragments) {
    EXPECT_NE(result.error.find(fragment), std::string::npos) << "'" << fragment << "' missing from: " << result.error;
  }
}

// Every numeric key, with the other keys it needs to be read at all.
const std::vector<std::vector<std::string>> kNumericKeys = {
    {"system.area_fraction"},
    {"system.diameter"},
    {"system.restitution"},
    {"system.tc_duration"},
    {"system.elastic_below", "system.restitution_law=\"threshold\""},
    {"system.viscoelastic_constant", "system.restitution_law=\"viscoelastic\""},
    {"boundary.shear_velocity", "boundary.kind=\"lees-edwards\""},
    {"initial.temperature"},
    {"initial.equilibrate"},
    {"run.until_collisions_per_particle"},
    {"run.until_time"},
    {"output.every_collisions_per_particle"},
    {"output.every_time"},
    {"output.snapshot_every_collisions_per_particle"},
    {"output.snapshot_every_time"},
    {"engine.particles_per_cell"},
    {"engine.renumber_every"},
    {"fields.every_collisions_per_particle"},
    {"fields.every_time"},
    {"collisions.window_collisions_per_particle"},
    {"collisions.from_collisions_per_particle"},
    {"collisions.max_length"},
};

TEST(ConfigValidation, NonFiniteNumbersAreRefusedByName) {
  for (const auto& key : kNumericKeys) {
    for (const std::string value : {"nan", "inf", "-inf"}) {
      std::vector<std::string> overrides(key.begin() + 1, key.end());
      overrides.push_back(key[0] + "=" + value);
      expect_refused(overrides, {key[0] + " = " + value, "allowed"});
    }
  }
  for (const std::string value : {"[nan, 1.0]", "[1.0, inf]"}) {
    expect_refused({"system.box=" + value}, {"system.box", "[1e-30, 1e+30]"});
  }
  expect_refused({"collisions.density_windows=[[nan, 2.0]]"}, {"collisions.density_windows", "both finite"});
  expect_refused({"collisions.density_windows=[[0.0, inf]]"}, {"collisions.density_windows"});
  expect_refused({"collisions.speed_windows=[[1.0, nan]]"}, {"collisions.speed_windows"});
  expect_accepted({"collisions.density_windows=[[0.0, 1e300]]"});
}

TEST(ConfigValidation, BoxSidesBetween1em30And1e30) {
  expect_accepted({"system.box=[1e-30, 1e-30]"});
  expect_accepted({"system.box=[1e30, 1e30]"});
  expect_refused({"system.box=[1e31, 1e30]"}, {"system.box = [1e+31, 1e+30]", "[1e-30, 1e+30]"});
  expect_refused({"system.box=[1e-31, 1.0]"}, {"system.box", "[1e-30, 1e+30]"});
  // The review's case: a finite diameter and box whose area fraction was inf/inf = NaN.
  expect_refused({"system.box=[1e300, 1e300]", "system.diameter=1e200"}, {"system.box", "[1e-30, 1e+30]"});
}

TEST(ConfigValidation, AtMostABillionDiametersAcrossTheBox) {
  // N = 2 in a unit box: σ ≥ 1e-9; ν ≥ π·2·1e-18/4 = 1.5707963267948966e-18.
  expect_accepted({"system.particles=2", "system.diameter=1e-9"});
  expect_refused({"system.particles=2", "system.diameter=0.99e-9"},
                 {"system.diameter = 9.9e-10", "[1e-09, ", "diameters across the box"});
  expect_accepted({"system.particles=2", "system.area_fraction=1.5708e-18"});
  expect_refused({"system.particles=2", "system.area_fraction=1.5e-18"},
                 {"system.area_fraction = 1.5e-18", "[1.570796326794", ", 0.9068996821171089)"});
  // In a 4 × 1e9 box a disk of σ = 1 is a billionth of the long side.
  expect_accepted({"system.particles=2", "system.box=[4.0, 1e9]", "system.diameter=1.0"});
  expect_refused({"system.particles=2", "system.box=[4.0, 1e9]", "system.diameter=0.99"}, {"system.diameter"});
}

TEST(ConfigValidation, AreaFractionBelowClosePacking) {
  expect_accepted({"system.area_fraction=0.9"});
  expect_refused({"system.area_fraction=0.907"}, {"system.area_fraction = 0.907", "0.9068996821171089)"});
  // σ from ν = 0.9 of N = 4000 in a unit box is 0.016925; close packing is reached at 0.016992.
  expect_accepted({"system.diameter=0.0169"});
  expect_refused({"system.diameter=0.017"}, {"system.diameter = 0.017", "allowed ["});
}

TEST(ConfigValidation, ABoxTooElongatedForAnyDiameterNamesTheBox) {
  // N = 2^31 − 1: aspect ratio at most 4·0.9069·1e18/(πN) = 5.38e8.
  expect_refused({"system.particles=2147483647", "system.box=[1e9, 1.0]"}, {"system.box", "too elongated", "5.3"});
  // At aspect 1e8 the default ν = 0.05 would put 1.7e9 diameters along the box; 0.5 does not.
  expect_refused({"system.particles=2147483647", "system.box=[1e8, 1.0]"}, {"system.area_fraction = 0.05 (the default)"});
  expect_accepted({"system.particles=2147483647", "system.box=[1e8, 1.0]", "system.area_fraction=0.5"});
}

TEST(ConfigValidation, RenumberingCadenceIsNonNegative) {
  expect_accepted({"engine.renumber_every=0"});
  expect_accepted({"engine.renumber_every=2.5"});
  expect_refused({"engine.renumber_every=-1"}, {"engine.renumber_every = -1", "[0, 1000000]", "events per particle"});
  expect_refused({"engine.renumber_every=2e6"}, {"engine.renumber_every", "[0, 1000000]"});
}

// Unset, the cadence follows the size of the particle records (48 bytes a disk, 64 a sphere):
// renumbering from 2 MiB of them on (README, engine.renumber_every).
TEST(ConfigValidation, RenumberingByDefaultOnlyBeyondTwoMebibytesOfRecords) {
  const auto cadence = [](const std::vector<std::string>& overrides) {
    const ConfigResult result = parse(overrides);
    EXPECT_TRUE(result.config.has_value()) << result.error;
    return result.config ? result.config->system.renumber_every : -1.0;
  };
  EXPECT_EQ(cadence({"system.particles=43690"}), 0.0);
  EXPECT_EQ(cadence({"system.particles=43691"}), 4.0);
  EXPECT_EQ(cadence({"system.dimension=3", "system.particles=32768"}), 0.0);
  EXPECT_EQ(cadence({"system.dimension=3", "system.particles=32769"}), 4.0);
  EXPECT_EQ(cadence({"system.particles=4000", "engine.renumber_every=2"}), 2.0);
}

TEST(ConfigValidation, EngineCellIdsFitIn28Bits) {
  // N = 2^29 at two particles per cell needs 2^28 cells; at 1.5 per cell more than that.
  expect_accepted({"system.particles=536870912", "engine.particles_per_cell=2.0"});
  expect_refused({"system.particles=536870912", "engine.particles_per_cell=1.5"},
                 {"engine.particles_per_cell = 1.5", "[2, 20]", "2^28 engine cells"});
  expect_refused({"engine.particles_per_cell=0.09"}, {"engine.particles_per_cell", "[0.1, 20]"});
  // A box 2.9 cells wide gets 3 columns (the minimum): its automatic grid has taller rows to stay
  // within 2^28 cells, where a grid given by hand is refused.
  expect_accepted({"system.particles=2147483647", "system.box=[2.9, 740511257.6]", "system.area_fraction=0.5"});
  expect_refused({"system.particles=2147483647", "engine.cells=[32768, 32768]"},
                 {"engine.cells gives an engine grid of 32768 × 32768", "2^28", "choose fewer"});
}

TEST(ConfigValidation, RestitutionInZeroOne) {
  expect_accepted({"system.restitution=1.0"});
  expect_accepted({"system.restitution=1e-300"});
  expect_refused({"system.restitution=0.0"}, {"system.restitution = 0 ", "(0, 1]"});
  expect_refused({"system.restitution=2"}, {"system.restitution = 2", "(0, 1]"});
}

TEST(ConfigValidation, RestitutionLawsTakeTheirOwnKeysOnly) {
  expect_accepted({"system.restitution_law=\"threshold\"", "system.elastic_below=0.1"});
  expect_accepted({"system.restitution_law=\"viscoelastic\"", "system.viscoelastic_constant=0.05"});
  expect_refused({"system.restitution_law=\"linear\""}, {"system.restitution_law", "constant", "threshold", "viscoelastic"});
  expect_refused({"system.restitution_law=\"threshold\""}, {"needs system.elastic_below"});
  expect_refused({"system.restitution_law=\"viscoelastic\""}, {"needs system.viscoelastic_constant"});
  expect_refused({"system.elastic_below=0.1"}, {"system.elastic_below is for system.restitution_law = \"threshold\""});
  expect_refused({"system.restitution_law=\"threshold\"", "system.elastic_below=0.1", "system.viscoelastic_constant=0.05"},
                 {"system.viscoelastic_constant is for system.restitution_law = \"viscoelastic\""});
  expect_refused({"system.restitution_law=\"viscoelastic\"", "system.viscoelastic_constant=0.05", "system.restitution=0.8"},
                 {"system.restitution cannot be combined"});
  expect_refused({"system.restitution_law=\"threshold\"", "system.elastic_below=0"}, {"system.elastic_below = 0", "(0, "});
}

TEST(ConfigValidation, TemperatureBetween1em60And1e60) {
  expect_accepted({"initial.temperature=1e-60"});
  expect_accepted({"initial.temperature=1e60"});
  expect_refused({"initial.temperature=1e308"}, {"initial.temperature = 1e+308", "[1e-60, 1e+60]"});
  expect_refused({"initial.temperature=0.99e-60"}, {"initial.temperature", "[1e-60, 1e+60]"});
  expect_refused({"initial.temperature=0"}, {"initial.temperature = 0", "[1e-60, 1e+60]"});
}

TEST(ConfigValidation, ShearSpeedBoundedAbsolutelyAndByTheThermalSpeed) {
  const std::string le = "boundary.kind=\"lees-edwards\"";
  expect_refused({le, "boundary.shear_velocity=1e300"}, {"boundary.shear_velocity = 1e+300", "[1e-30, 10000000000]"});
  expect_accepted({le, "boundary.shear_velocity=1e10"});
  expect_accepted({le, "boundary.shear_velocity=-1e10"});
  expect_refused({le, "boundary.shear_velocity=1.1e10"}, {"boundary.shear_velocity", "initial.temperature = 1"});
  expect_accepted({le, "boundary.shear_velocity=1e-30"});
  expect_refused({le, "boundary.shear_velocity=-1e-31"}, {"boundary.shear_velocity", "0 or |U| in [1e-30, "});
  expect_accepted({le, "initial.temperature=1e60", "boundary.shear_velocity=1e30"});
  expect_refused({le, "initial.temperature=1e60", "boundary.shear_velocity=1.01e30"}, {"[1e-30, 1e+30]"});
  expect_accepted({le, "initial.temperature=1e-60", "boundary.shear_velocity=1e-20"});
  expect_refused({le, "initial.temperature=1e-60", "boundary.shear_velocity=1.01e-20"}, {"[1e-30, 1e-20]"});
  expect_refused({"boundary.shear_velocity=1.0"}, {"boundary.shear_velocity = 1", "lees-edwards"});
}

// Settings in collisions per particle, N = 4000: from 1/N = 0.00025 to 2^62/N = 1152921504606846.9.
struct CountSetting {
  std::string key;
  bool zero_allowed;
};

TEST(ConfigValidation, CollisionCountsFromOneCollisionTo2Pow62) {
  const std::vector<CountSetting> settings = {
      {"run.until_collisions_per_particle", false},     {"output.every_collisions_per_particle", false},
      {"fields.every_collisions_per_particle", false},  {"collisions.window_collisions_per_particle", false},
      {"output.snapshot_every_collisions_per_particle", true}, {"initial.equilibrate", true},
  };
  for (const auto& [key, zero_allowed] : settings) {
    expect_accepted({key + "=0.00025"});
    expect_refused({key + "=0.0002"}, {key + " = 0.0002", "[0.00025, 11529215046068", "for N = 4000"});
    expect_accepted({key + "=1152921504606846.0"});
    expect_refused({key + "=1152921504606848.0"}, {key, "2^62"});
    expect_refused({key + "=1e300"}, {key + " = 1e+300", "[0.00025, "});
    if (zero_allowed) {
      expect_accepted({key + "=0"});
    } else {
      expect_refused({key + "=0"}, {key + " = 0", "[0.00025, "});
    }
    expect_refused({key + "=-1"}, {key + " = -1"});
  }
  // The minimum follows N: one collision among 3 disks is c = 1/3.
  expect_accepted({"system.particles=3", "output.every_collisions_per_particle=0.3333333333333333"});
  expect_refused({"system.particles=3", "output.every_collisions_per_particle=0.33"}, {"[0.3333333333333333, "});
  expect_accepted({"collisions.from_collisions_per_particle=0"});
  expect_accepted({"collisions.from_collisions_per_particle=1152921504606846.0"});
  expect_refused({"collisions.from_collisions_per_particle=1152921504606848.0"},
                 {"collisions.from_collisions_per_particle", "2^62"});
}

TEST(ConfigValidation, TimesFinitePositive) {
  for (const std::string key : {"run.until_time", "output.every_time", "output.snapshot_every_time", "fields.every_time"}) {
    expect_accepted({key + "=1e-300"});
    expect_accepted({key + "=1e300"});
    expect_refused({key + "=0"}, {key + " = 0", "(0, ∞)"});
    expect_refused({key + "=-1e-300"}, {key});
  }
  expect_accepted({"system.tc_duration=0"});
  expect_accepted({"system.tc_duration=1e300"});
  expect_refused({"system.tc_duration=-1e-300"}, {"system.tc_duration", "[0, ∞)"});
}

TEST(ConfigValidation, FreePathRangeFromANanoDiameterTo1e12Boxes) {
  // Default system: σ = √(4·0.05/(4000π)) = 0.0039894228.
  expect_accepted({"collisions.max_length=4e-12"});
  expect_refused({"collisions.max_length=3.9e-12"}, {"collisions.max_length = 3.9e-12", "σ to"});
  expect_accepted({"collisions.max_length=1e12"});
  expect_refused({"collisions.max_length=1.01e12"}, {"collisions.max_length", ", 1000000000000]"});
}

TEST(ConfigValidation, MalformedStructureNamesTheKey) {
  expect_refused({"system=3"}, {"system = 3", "section"});
  expect_refused({"seed.x=1"}, {"unknown section [seed]"});
  expect_refused({"seed=1", "seed.x=1"}, {"--set seed.x=1", "not a section"});
  expect_refused({"system.restitution=0.5\nseed = 3"}, {"--set", "single TOML value"});
  expect_refused({"=1"}, {"--set =1", "section.key=value"});
  const ConfigResult duplicate = parse_config("[system]\nparticles = 10\nparticles = 20\n", {});
  ASSERT_FALSE(duplicate.config);
  EXPECT_NE(duplicate.error.find("malformed TOML at line 3"), std::string::npos) << duplicate.error;
}

// A configuration at the edges of every range is written by to_toml and read back identically:
// a resumed run reads its own config.toml.
TEST(ConfigValidation, ExtremeValidConfigurationsRoundTrip) {
  const std::vector<std::vector<std::string>> cases = {
      {"system.box=[1e-30, 1e-30]", "initial.temperature=1e-60", "boundary.kind=\"lees-edwards\"",
       "boundary.shear_velocity=1e-20", "run.until_collisions_per_particle=0.00025"},
      {"system.box=[1e30, 1e30]", "initial.temperature=1e60", "system.particles=2", "system.area_fraction=1e-17",
       "output.snapshot_every_collisions_per_particle=0.5", "collisions.max_length=1e42"},
      {"system.particles=2147483647", "engine.particles_per_cell=8", "run.until_time=1e-300",
       "initial.equilibrate=2147483647e-9", "collisions.density_windows=[[0, 1e300]]"},
      {"initial.from=\"runs/a\"", "initial.frame=3", "boundary.kind=\"lees-edwards\"", "boundary.shear_velocity=2"},
      {"system.restitution_law=\"threshold\"", "system.elastic_below=1e-300"},
      {"system.restitution_law=\"viscoelastic\"", "system.viscoelastic_constant=1e300"},
  };
  for (const auto& overrides : cases) {
    const ConfigResult first = parse(overrides);
    ASSERT_TRUE(first.config) << first.error;
    const std::string text = to_toml(*first.config);
    const ConfigResult second = parse_config(text, {});
    ASSERT_TRUE(second.config) << second.error << "\n" << text;
    EXPECT_EQ(to_toml(*second.config), text);
  }
}

}  // namespace
}  // namespace granule
