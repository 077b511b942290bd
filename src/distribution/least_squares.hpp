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

// Minimise ‖r(p)‖² starting from `parameters` (updated in place).
FitReport levenberg_marquardt(const ResidualFunction& residual, Eigen::Index residual_count,
                              Eigen::VectorXd& parameters, int max_evaluations = 20000);

}  // namespace granule::distribution
