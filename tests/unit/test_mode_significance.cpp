// The null law of one mode's power (spectra/mode_significance.hpp) against closed forms: Exp(1) for a
// single component, the Gamma(2, ½) survival (1 + 2s) e^{−2s} for two equal shares, the two-rate
// hypoexponential (λ₁ e^{−s/λ₁} − λ₂ e^{−s/λ₂})/(λ₁ − λ₂), Gamma(3, ⅓) for three equal ones; the
// maximum of K modes; and the threshold as the inverse of the false-alarm probability.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "spectra/mode_significance.hpp"

namespace granule::spectra {
namespace {

TEST(ModeSignificance, SingleModeSurvivalMatchesClosedForms) {
  for (const double s : {0.1, 1.0, 5.0, 12.0}) {
    const std::vector<double> one = {1.0}, two = {0.5, 0.5}, unequal = {0.7, 0.3}, three = {1.0 / 3, 1.0 / 3, 1.0 / 3};
    EXPECT_NEAR(single_mode_survival(s, one) / std::exp(-s), 1.0, 1e-12) << s;
    // Equal shares are spread by 1e-5 of themselves: a relative error of about s · 1e-5.
    EXPECT_NEAR(single_mode_survival(s, two) / ((1.0 + 2.0 * s) * std::exp(-2.0 * s)), 1.0, 3e-5 * (1.0 + s)) << s;
    const double hypo = (0.7 * std::exp(-s / 0.7) - 0.3 * std::exp(-s / 0.3)) / 0.4;
    EXPECT_NEAR(single_mode_survival(s, unequal) / hypo, 1.0, 1e-12) << s;
    const double gamma3 = (1.0 + 3.0 * s + 4.5 * s * s) * std::exp(-3.0 * s);
    EXPECT_NEAR(single_mode_survival(s, three) / gamma3, 1.0, 3e-5 * (1.0 + s)) << s;
    // A zero share (v_z = 0, say) is no component at all.
    const std::vector<double> with_zero = {1.0, 0.0};
    EXPECT_NEAR(single_mode_survival(s, with_zero) / std::exp(-s), 1.0, 1e-12) << s;
  }
}

TEST(ModeSignificance, FalseAlarmIsTheMaximumOfIndependentModes) {
  const double q = 1e-3, modes = 300.0;
  EXPECT_NEAR(false_alarm_probability(q, modes), 1.0 - std::pow(1.0 - q, modes), 1e-14);
  EXPECT_NEAR(false_alarm_probability(1e-12, 10.0), 1e-11, 1e-20);  // no cancellation for tiny p
}

TEST(ModeSignificance, ThresholdInvertsTheFalseAlarmProbability) {
  const std::vector<double> shares = {0.6, 0.4};
  for (const double alpha : {0.01, 0.05, 0.5}) {
    const double s = noise_threshold(alpha, 312.0, shares);
    EXPECT_NEAR(false_alarm_probability(single_mode_survival(s, shares), 312.0), alpha, 1e-9 * alpha) << alpha;
  }
  // One component: s* = −ln(1 − (1 − α)^{1/K}) ≈ ln(K/α).
  const std::vector<double> one = {1.0};
  EXPECT_NEAR(noise_threshold(0.05, 312.0, one), -std::log(-std::expm1(std::log1p(-0.05) / 312.0)), 1e-9);
}

}  // namespace
}  // namespace granule::spectra
