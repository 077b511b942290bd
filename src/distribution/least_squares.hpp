// Nonlinear least squares for the fits of thesis §5.2, delegated to Eigen's (MINPACK-derived)
// Levenberg–Marquardt with a central-difference Jacobian.  Every fit reports its residual and
// whether the minimiser converged, so that no fitted number is reported without its quality.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>

namespace granule::distribution {

struct FitReport {
  bool converged = false;
  std::string status;          // Eigen's termination reason, in words
  int evaluations = 0;         // residual evaluations used
  double residual_norm = 0.0;  // ‖r‖ at the solution (r as returned by the residual function)
  double residual_rms = 0.0;   // ‖r‖ / √(number of residuals)
};

// r(p): the vector of (weighted) residuals for parameters p; must fill all `residual_count` entries.
using ResidualFunction = std::function<void(const Eigen::VectorXd& parameters, Eigen::VectorXd& residuals)>;

// The fit stops when a step reduces ‖r‖² by less than this fraction.  The weighted fits of §5.2
// have ‖r‖² ≈ number of residuals (10²–10⁴ terms of order one), so 10⁻⁶ of it is below 10⁻², while
// moving a parameter by one standard deviation changes ‖r‖² by 1.  (MINPACK's default, 1.5·10⁻⁸,
// let the ψ fit crawl along its shallow valleys to the evaluation limit.)
inline constexpr double kRelativeReduction = 1e-6;

// Minimise ‖r(p)‖² starting from `parameters` (updated in place).  The fit has failed (not
// converged) when r is not finite at the start or at the result or on the central-difference
// stencil around them: the minimiser cannot see past such a point.
FitReport levenberg_marquardt(const ResidualFunction& residual, Eigen::Index residual_count,
                              Eigen::VectorXd& parameters, int max_evaluations = 20000,
                              double relative_reduction = kRelativeReduction);

}  // namespace granule::distribution
