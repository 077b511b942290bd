// The map from Appendix B's units to a run's (distribution/appendix_b_reference.hpp), checked against
// what it must satisfy independently of how it is computed:
// * the thesis's own numbers: Appendix B's system is the N = 2·10⁵ one, whose σ the thesis prints
//   (System IV: 0.000564); its T windows must sit where the thesis's empirical T̄ (3.1) of that system
//   puts them (0.75–1.66 T̄, within a factor 2 for every ẽ; with N = 2·10⁴, System III's, they would be
//   10 × too cold);
// * dimensional analysis: a run that is the thesis's system has the identity map; for N = 2·10⁴ in the
//   same box (σ √10 larger) lengths and velocities scale by √10, T by 10, ρ by 1/10; the dimensionless
//   amplitudes √(2T) b₀⁽¹⁾, 2T b₀⁽²⁾ and b₀⁽⁰⁾ − log T do not change.
#include <gtest/gtest.h>

#include <cmath>

#include "distribution/appendix_b_reference.hpp"
#include "theory/steady_shear.hpp"

namespace granule::distribution {
namespace {

SystemParams sheared(std::int64_t particles) {
  SystemParams s;
  s.particles = particles;
  s.length_x = s.length_y = 1.0;
  s.diameter = theory::diameter_for_area_fraction(0.05, static_cast<int>(particles), 1.0, 1.0);
  s.shear_velocity = 100.0;
  return s;
}

TEST(AppendixBUnits, TheThesisSystemIsTheOneWithTwoHundredThousandDisks) {
  EXPECT_NEAR(AppendixBSystem::diameter(), 0.000564, 0.0000005);  // σ printed for System IV (§3.1)
  for (const AppendixBEntry& e : appendix_b_means()) {
    const double mean = theory::steady_shear_temperature_tan_fit(e.restitution, 100.0, AppendixBSystem::diameter(), 0.05);
    EXPECT_GT(e.temperature / mean, 0.5) << "ẽ " << e.restitution << " T " << e.temperature << " vs (3.1) " << mean;
    EXPECT_LT(e.temperature / mean, 2.0) << "ẽ " << e.restitution << " T " << e.temperature << " vs (3.1) " << mean;
    // The density windows bracket the mean N/L² = 2·10⁵.
    EXPECT_GE(e.density, 0.8 * 2.0e5);
    EXPECT_LE(e.density, 1.4 * 2.0e5);
  }
  EXPECT_EQ(appendix_b_means().size(), 64u);
}

TEST(AppendixBUnits, MapFollowsDimensionalAnalysis) {
  const ThesisUnitMap same = appendix_b_unit_map(sheared(200000));
  EXPECT_NEAR(same.length, 1.0, 1e-12);
  EXPECT_NEAR(same.velocity, 1.0, 1e-12);

  const ThesisUnitMap smaller = appendix_b_unit_map(sheared(20000));
  EXPECT_NEAR(smaller.length, std::sqrt(10.0), 1e-12);
  EXPECT_NEAR(smaller.velocity, std::sqrt(10.0), 1e-12);
  SystemParams slower = sheared(20000);
  slower.shear_velocity = 50.0;  // half the shear rate: half the velocities, the same lengths
  EXPECT_NEAR(appendix_b_unit_map(slower).velocity, 0.5 * std::sqrt(10.0), 1e-12);

  for (const AppendixBEntry& t : appendix_b_means()) {
    const AppendixBEntry r = smaller.to_run_units(t);
    EXPECT_NEAR(r.temperature / t.temperature, 10.0, 1e-12);
    EXPECT_NEAR(r.density / t.density, 0.1, 1e-12);
    EXPECT_NEAR(std::sqrt(2.0 * r.temperature) * r.b1, std::sqrt(2.0 * t.temperature) * t.b1, 1e-12);
    EXPECT_NEAR(2.0 * r.temperature * r.b2, 2.0 * t.temperature * t.b2, 1e-12);
    EXPECT_NEAR(r.b0 - std::log(r.temperature), t.b0 - std::log(t.temperature), 1e-12);
    // (3.1) in the run: the mapped window sits at the same fraction of the run's T̄ as in the thesis.
    const double ratio_thesis = t.temperature / theory::steady_shear_temperature_tan_fit(t.restitution, 100.0,
                                                                                         AppendixBSystem::diameter(), 0.05);
    const double ratio_run = r.temperature / theory::steady_shear_temperature_tan_fit(r.restitution, 100.0,
                                                                                      sheared(20000).diameter, 0.05);
    EXPECT_NEAR(ratio_run, ratio_thesis, 1e-9);
  }
}

}  // namespace
}  // namespace granule::distribution
