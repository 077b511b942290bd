// The verdicts of `granule reproduce` follow from the numbers alone (src/reproduce/claim.hpp):
// a measurement inside the tolerance band (widened by 2σ) agrees, one outside disagrees, and one
// whose statistical error alone spans the band, or that is missing, cannot be judged.  Also the
// statistics the claims use (mean over seeds, straight-line fit) against exact cases, and the
// base64 of the inline pictures against RFC 4648's test vectors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "reproduce/claim.hpp"
#include "reproduce/report.hpp"
#include "reproduce/run_outputs.hpp"

namespace granule::reproduce {
namespace {

Claim relative_claim(double measured, double error) {
  Claim c;
  c.expected = 1.0;
  c.tolerance = 0.05;
  c.measured = measured;
  c.error = error;
  return c;
}

TEST(ReproduceVerdict, InsideTheBandAgreesOutsideDisagrees) {
  EXPECT_EQ(judge(relative_claim(1.03, 0.005)), Verdict::agrees);
  EXPECT_EQ(judge(relative_claim(0.96, 0.005)), Verdict::agrees);
  EXPECT_EQ(judge(relative_claim(1.20, 0.005)), Verdict::disagrees);
  EXPECT_EQ(judge(relative_claim(0.80, 0.005)), Verdict::disagrees);
}

TEST(ReproduceVerdict, TheStatisticalErrorWidensTheBand) {
  // 1.07 is 0.02 beyond the band; 2σ = 0.03 covers it, 2σ = 0.01 does not.
  EXPECT_EQ(judge(relative_claim(1.07, 0.015)), Verdict::agrees);
  EXPECT_EQ(judge(relative_claim(1.07, 0.005)), Verdict::disagrees);
}

TEST(ReproduceVerdict, TooNoisyOrMissingIsNotResolvable) {
  EXPECT_EQ(judge(relative_claim(1.0, 0.06)), Verdict::not_resolvable);  // 2σ = 0.12 > band width 0.10
  // ... yet a number whose whole ±2σ misses the band disagrees however noisy it is.
  EXPECT_EQ(judge(relative_claim(10.0, 0.5)), Verdict::disagrees);
  EXPECT_EQ(judge(relative_claim(std::numeric_limits<double>::quiet_NaN(), 0.0)), Verdict::not_resolvable);
  Claim said = relative_claim(1.0, 0.001);
  said.unresolvable = "no significance available";
  EXPECT_EQ(judge(said), Verdict::not_resolvable);
  // A single seed has no error estimate: judged on the tolerance alone.
  EXPECT_EQ(judge(relative_claim(1.04, std::numeric_limits<double>::quiet_NaN())), Verdict::agrees);
}

TEST(ReproduceVerdict, FactorAndAbsoluteTolerances) {
  Claim c;
  c.expected = 10.0;
  c.tolerance = 2.0;
  c.tolerance_kind = ToleranceKind::factor;
  c.error = 0.1;
  for (double m : {5.5, 19.0}) {
    c.measured = m;
    EXPECT_EQ(judge(c), Verdict::agrees) << m;
  }
  for (double m : {4.0, 25.0}) {
    c.measured = m;
    EXPECT_EQ(judge(c), Verdict::disagrees) << m;
  }
  c.expected = -2.0;
  c.tolerance = 0.2;
  c.tolerance_kind = ToleranceKind::absolute;
  c.error = 0.02;
  c.measured = -1.3;  // the post-clustering exponent Granule finds against the thesis's t⁻²
  EXPECT_EQ(judge(c), Verdict::disagrees);
  c.measured = -1.85;
  EXPECT_EQ(judge(c), Verdict::agrees);
}

TEST(ReproduceStatistics, MeanOverSeedsAndItsStandardError) {
  const Estimate e = mean_over({1.0, 2.0, 3.0, std::numeric_limits<double>::quiet_NaN()});
  EXPECT_EQ(e.count, 3);
  EXPECT_DOUBLE_EQ(e.mean, 2.0);
  EXPECT_NEAR(e.error, 1.0 / std::sqrt(3.0), 1e-15);  // sample standard deviation 1, over √3
  EXPECT_TRUE(std::isnan(mean_over({4.0}).error));
}

TEST(ReproduceStatistics, StraightLineFitOfAnExactLine) {
  const LineFit fit = fit_line({0.0, 1.0, 2.0, 3.0}, {2.0, 5.0, 8.0, 11.0});
  EXPECT_NEAR(fit.slope, 3.0, 1e-14);
  EXPECT_NEAR(fit.intercept, 2.0, 1e-14);
  EXPECT_NEAR(fit.slope_error, 0.0, 1e-14);
  EXPECT_TRUE(std::isnan(fit_line({0.0, 1.0}, {0.0, 1.0}).slope));
}

TEST(ReproduceReport, Base64OfTheRfc4648Vectors) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foob"), "Zm9vYg==");
  EXPECT_EQ(base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64(std::string("\xff\x00\x10", 3)), "/wAQ");
}

}  // namespace
}  // namespace granule::reproduce
