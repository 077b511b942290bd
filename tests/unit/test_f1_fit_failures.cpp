// Unit tier: a fit of the f1 analysis (src/distribution) that fails is reported as failed, never as
// numbers: the minimiser at the edge of a model's finite range, and a window whose speeds the
// form (5.20, 5.22) cannot represent.
#include <gtest/gtest.h>

#include <cmath>

#include "distribution/f1_analysis.hpp"
#include "distribution/least_squares.hpp"
#include "init/random.hpp"

namespace granule::distribution {
namespace {

// r(p) = √(p − 1) − 2 has its minimum at p = 5, but from p = 1 every central difference reaches
// p < 1, where r is NaN: MINPACK then stops at once and calls the start a minimum.
TEST(F1FitFailures, AFitStuckAtTheEdgeOfTheFiniteRangeHasFailed) {
  Eigen::VectorXd p(1);
  p << 1.0;
  const FitReport report = levenberg_marquardt(
      [](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
        r[0] = std::sqrt(x[0] - 1.0) - 2.0;
        r[1] = 0.0;
      },
      2, p);
  EXPECT_FALSE(report.converged) << report.status;
  EXPECT_NE(report.status.find("not finite"), std::string::npos) << report.status;
}

// r(p) = log p + 20: the first Gauss–Newton step from p = 1 lands at p = −19 (NaN); the fit must
// step back and still reach p = e⁻²⁰.
TEST(F1FitFailures, AStepIntoTheNonFiniteRangeIsRejectedNotAccepted) {
  Eigen::VectorXd p(1);
  p << 1.0;
  const FitReport report = levenberg_marquardt(
      [](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
        r[0] = std::log(x[0]) + 20.0;
        r[1] = 0.0;
      },
      2, p);
  EXPECT_TRUE(report.converged) << report.status;
  EXPECT_NEAR(std::log(p[0]), -20.0, 1e-9);
}

// Every speed equal: φ is a step, which 1 − exp(−J) with a quartic J (5.20, 5.22) can only
// approach by a J that falls again, so φ* is no distribution function.  The window must be
// skipped with a warning that names the failed fit, not reported with its numbers.
TEST(F1FitFailures, AWindowWhoseSpeedsTheFormCannotRepresentIsSkippedWithAWarning) {
  Random random(5);
  WindowSamples w;
  for (int s = 0; s < 10; ++s) {
    for (int i = 0; i < 2000; ++i) {
      const double theta = 2.0 * M_PI * random.uniform();
      w.vx.push_back(std::cos(theta));
      w.vy.push_back(std::sin(theta));
    }
    w.snapshot_end.push_back(w.vx.size());
    w.selected_area.push_back(1.0);
    w.temperature_weighted.push_back(0.0);
  }
  F1Options options;
  options.speed_bins = options.angle_bins = 32;
  options.bootstrap = 4;
  const WindowResult r = analyse_window(w, options);
  EXPECT_FALSE(r.analysed);
  EXPECT_NE(r.warning.find("fits failed"), std::string::npos) << r.warning;
  EXPECT_NE(r.warning.find("phi*"), std::string::npos) << r.warning;
}

}  // namespace
}  // namespace granule::distribution
