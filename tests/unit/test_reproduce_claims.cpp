// The verdicts of `granule reproduce` follow from the numbers alone (src/reproduce/claim.hpp):
// a mean inside the tolerance band agrees unless 2σ alone is wider than the band; a mean outside
// disagrees when ±2σ misses the band and needs more statistics when ±2σ reaches it; a sign claim
// agrees or disagrees only when ±2σ excludes zero.  The cases are the ones the report met at small
// scale, the band's edges and claims without an error.  Also the statistics the claims use (mean
// over seeds, straight-line fit) against exact cases, and the base64 of the inline pictures against
// RFC 4648's test vectors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "reproduce/claim.hpp"
#include "reproduce/report.hpp"
#include "reproduce/run_outputs.hpp"

namespace granule::reproduce {
namespace {

Claim band_claim(double expected, double tolerance, ToleranceKind kind, double measured, double error) {
  Claim c;
  c.expected = expected;
  c.tolerance = tolerance;
  c.tolerance_kind = kind;
  c.measured = measured;
  c.error = error;
  return c;
}

Claim relative_claim(double measured, double error) { return band_claim(1.0, 0.05, ToleranceKind::relative, measured, error); }

TEST(ReproduceVerdict, InsideTheBandAgreesOutsideDisagrees) {
  EXPECT_EQ(judge(relative_claim(1.03, 0.005)), Verdict::agrees);
  EXPECT_EQ(judge(relative_claim(0.96, 0.005)), Verdict::agrees);
  EXPECT_EQ(judge(relative_claim(1.20, 0.005)), Verdict::disagrees);
  EXPECT_EQ(judge(relative_claim(0.80, 0.005)), Verdict::disagrees);
}

TEST(ReproduceVerdict, AMeanOutsideTheBandButWithinTwoSigmaNeedsMoreStatistics) {
  // 1.07 is 0.02 beyond the band [0.95, 1.05]; 2σ = 0.03 reaches the band, 2σ = 0.01 does not.
  const Judgement near = judgement(relative_claim(1.07, 0.015));
  EXPECT_EQ(near.verdict, Verdict::not_resolvable);
  EXPECT_NE(near.reason.find("more statistics"), std::string::npos) << near.reason;
  EXPECT_EQ(judge(relative_claim(1.07, 0.005)), Verdict::disagrees);
  EXPECT_EQ(judge(relative_claim(0.93, 0.015)), Verdict::not_resolvable);  // the same below the band
}

TEST(ReproduceVerdict, TheCasesOfTheSmallScaleReport) {
  // chapter2.system_II.late_power_law: −1.61 ± 0.12 against −2 ± 0.2, 0.19 from the band, 2σ = 0.24.
  Claim late = band_claim(-2.0, 0.2, ToleranceKind::absolute, -1.61, 0.12);
  EXPECT_EQ(judge(late), Verdict::not_resolvable);
  EXPECT_NE(judgement(late).reason.find("more statistics"), std::string::npos);
  late.error = 0.09;  // 2σ = 0.18 < 0.19: the whole interval misses the band
  EXPECT_EQ(judge(late), Verdict::disagrees);
  // appendix_c.fig_c2.clusters_in_flow_plane: 0.567 ± 0.265 against 0 ± 0.5.
  const Claim clusters = band_claim(0.0, 0.5, ToleranceKind::absolute, 0.567, 0.265);
  EXPECT_EQ(judge(clusters), Verdict::not_resolvable);
  EXPECT_NE(judgement(clusters).reason.find("more statistics"), std::string::npos);
}

Claim sign_claim(double expected, double measured, double error) {
  return band_claim(expected, 0.0, ToleranceKind::sign, measured, error);
}

TEST(ReproduceVerdict, ASignClaimNeedsTheSignResolvedAtTwoSigma) {
  // Appendix B's ρ trend of b₀⁽¹⁾ at ẽ = 0.7 and 0.8: means of the other sign, within 2σ of zero.
  for (const Claim& c : {sign_claim(0.074, -0.011, 0.043), sign_claim(-0.147, 0.053, 0.069)}) {
    const Judgement j = judgement(c);
    EXPECT_EQ(j.verdict, Verdict::not_resolvable) << c.measured;
    EXPECT_NE(j.reason.find("sign is not resolved"), std::string::npos) << j.reason;
  }
  // The claimed sign within 2σ of zero does not agree either.
  EXPECT_EQ(judge(sign_claim(0.074, 0.05, 0.043)), Verdict::not_resolvable);
  // Resolved: the claimed sign agrees however steep (no band beyond zero), the other sign disagrees.
  EXPECT_EQ(judge(sign_claim(0.074, 0.117, 0.043 / 2)), Verdict::agrees);
  EXPECT_EQ(judge(sign_claim(0.074, 10.0, 1.0)), Verdict::agrees);
  EXPECT_EQ(judge(sign_claim(-0.108, 0.047, 0.014)), Verdict::disagrees);  // ẽ = 0.9
  EXPECT_EQ(judge(sign_claim(-0.043, 0.20, 0.08)), Verdict::disagrees);    // ẽ = 0.6
  EXPECT_EQ(judge(sign_claim(-0.5, -0.047, 0.010)), Verdict::agrees);      // Fig C.4's C_contact
  EXPECT_EQ(judge(sign_claim(-0.5, 0.047, 0.010)), Verdict::disagrees);
  EXPECT_EQ(judgement(sign_claim(-0.5, 0.047, 0.010)).reason, "");
  EXPECT_EQ(tolerance_text(sign_claim(-0.5, 0.0, 0.0)), "its sign (< 0)");
  EXPECT_EQ(tolerance_text(sign_claim(0.1, 0.0, 0.0)), "its sign (> 0)");
}

TEST(ReproduceVerdict, TheEdgesOfTheBandAndOfTwoSigma) {
  // Exact binary numbers: the band [0.75, 1.25] and the comparisons below are exact.
  Claim c = band_claim(1.0, 0.25, ToleranceKind::absolute, NAN, 0.0);
  for (double edge : {0.75, 1.25}) {
    c.measured = edge;  // the band is closed
    EXPECT_EQ(judge(c), Verdict::agrees) << edge;
  }
  c.measured = std::nextafter(1.25, 2.0);  // no error: just outside disagrees
  EXPECT_EQ(judge(c), Verdict::disagrees);
  c.measured = 1.5;
  c.error = 0.125;  // mean − 2σ lands exactly on the edge: ±2σ reaches the band, not resolvable
  EXPECT_EQ(judge(c), Verdict::not_resolvable);
  c.error = std::nextafter(0.125, 0.0);
  EXPECT_EQ(judge(c), Verdict::disagrees);
  c.measured = 1.25;
  c.error = 0.25;  // on the edge with 2σ exactly the band's width: still an agreement
  EXPECT_EQ(judge(c), Verdict::agrees);
  c.error = std::nextafter(0.25, 1.0);
  EXPECT_EQ(judge(c), Verdict::not_resolvable);
  EXPECT_NE(judgement(c).reason.find("wider than the band"), std::string::npos);
}

TEST(ReproduceVerdict, TheEdgesOfASignClaim) {
  EXPECT_EQ(judge(sign_claim(1.0, 0.5, 0.25)), Verdict::not_resolvable);   // mean − 2σ exactly 0
  EXPECT_EQ(judge(sign_claim(1.0, -0.5, 0.25)), Verdict::not_resolvable);  // mean + 2σ exactly 0
  EXPECT_EQ(judge(sign_claim(1.0, 0.5, std::nextafter(0.25, 0.0))), Verdict::agrees);
  EXPECT_EQ(judge(sign_claim(1.0, -0.5, std::nextafter(0.25, 0.0))), Verdict::disagrees);
  // Without an error (σ = 0 or none) the mean's sign decides; a mean of exactly 0 has none.
  for (double none : {0.0, std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_EQ(judge(sign_claim(-1.0, -1e-9, none)), Verdict::agrees);
    EXPECT_EQ(judge(sign_claim(-1.0, 1e-9, none)), Verdict::disagrees);
    EXPECT_EQ(judge(sign_claim(-1.0, 0.0, none)), Verdict::not_resolvable);
  }
  EXPECT_EQ(judge(sign_claim(0.0, 1.0, 0.1)), Verdict::not_resolvable);  // a claimed number without a sign
}

TEST(ReproduceVerdict, WithoutAnErrorTheBandAloneDecides) {
  for (double none : {0.0, std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_EQ(judge(relative_claim(1.04, none)), Verdict::agrees);
    EXPECT_EQ(judge(relative_claim(1.06, none)), Verdict::disagrees);
    EXPECT_EQ(judgement(relative_claim(1.06, none)).reason, "");
  }
}

TEST(ReproduceVerdict, TooNoisyOrMissingIsNotResolvable) {
  EXPECT_EQ(judge(relative_claim(1.0, 0.06)), Verdict::not_resolvable);  // 2σ = 0.12 > band width 0.10
  // ... yet a number whose whole ±2σ misses the band disagrees however noisy it is.
  EXPECT_EQ(judge(relative_claim(10.0, 0.5)), Verdict::disagrees);
  EXPECT_EQ(judge(relative_claim(std::numeric_limits<double>::quiet_NaN(), 0.0)), Verdict::not_resolvable);
  Claim said = relative_claim(1.0, 0.001);
  said.unresolvable = "no significance available";
  EXPECT_EQ(judge(said), Verdict::not_resolvable);
  EXPECT_EQ(judgement(said).reason, "no significance available");  // the study's reason is the report's
}

TEST(ReproduceVerdict, FactorAndAbsoluteTolerances) {
  Claim c = band_claim(10.0, 2.0, ToleranceKind::factor, NAN, 0.1);
  for (double m : {5.5, 19.0}) {
    c.measured = m;
    EXPECT_EQ(judge(c), Verdict::agrees) << m;
  }
  c.measured = 4.9;  // 0.1 below the band [5, 20]: 2σ = 0.2 reaches it
  EXPECT_EQ(judge(c), Verdict::not_resolvable);
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
  // Two seeds give a mean but no error (one degree of freedom: two nearly equal values would quote a
  // spuriously tiny one).
  const Estimate two = mean_over({0.86827, 0.86834});
  EXPECT_EQ(two.count, 2);
  EXPECT_DOUBLE_EQ(two.mean, 0.5 * (0.86827 + 0.86834));
  EXPECT_TRUE(std::isnan(two.error));
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
