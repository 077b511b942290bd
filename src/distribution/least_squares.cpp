#include "distribution/least_squares.hpp"

#include <cmath>
#include <limits>
// The newer LevenbergMarquardt module only: it clashes with NonLinearOptimization in one file.
#include <unsupported/Eigen/LevenbergMarquardt>

namespace granule::distribution {

namespace {

struct ResidualFunctor : Eigen::DenseFunctor<double> {
  const ResidualFunction* residual;
  ResidualFunctor(const ResidualFunction& f, Eigen::Index parameters, Eigen::Index values)
      : Eigen::DenseFunctor<double>(static_cast<int>(parameters), static_cast<int>(values)), residual(&f) {}
  int operator()(const InputType& p, ValueType& r) const {
    (*residual)(p, r);
    return 0;
  }
};

// Whether r is finite at p and on the central-difference stencil around it (NumericalDiff's steps).
// A NaN in the Jacobian makes MINPACK's gradient test compare NaN and stop, reporting the start
// as a minimum ("residual orthogonal to the Jacobian"): such a point is the edge of the model's
// finite range, not a fit.
bool finite_around(const ResidualFunction& residual, const Eigen::VectorXd& p, Eigen::VectorXd& r) {
  residual(p, r);
  if (!p.allFinite() || !r.allFinite()) return false;
  const double epsilon = std::sqrt(std::numeric_limits<double>::epsilon());
  for (Eigen::Index j = 0; j < p.size(); ++j) {
    const double h = p[j] == 0.0 ? epsilon : epsilon * std::abs(p[j]);
    for (const double step : {-h, h}) {
      Eigen::VectorXd shifted = p;
      shifted[j] += step;
      Eigen::VectorXd around(r.size());
      residual(shifted, around);
      if (!around.allFinite()) return false;
    }
  }
  return true;
}

std::string describe(Eigen::LevenbergMarquardtSpace::Status status) {
  using namespace Eigen::LevenbergMarquardtSpace;
  switch (status) {
    case RelativeReductionTooSmall: return "relative reduction of the residual below ftol";
    case RelativeErrorTooSmall: return "relative change of the parameters below xtol";
    case RelativeErrorAndReductionTooSmall: return "residual and parameters converged";
    case CosinusTooSmall: return "residual orthogonal to the Jacobian";
    case TooManyFunctionEvaluation: return "too many evaluations";
    case FtolTooSmall: return "at machine precision (ftol)";
    case XtolTooSmall: return "at machine precision (xtol)";
    case GtolTooSmall: return "at machine precision (gtol)";
    case ImproperInputParameters: return "improper input";
    default: return "not finished";
  }
}

}  // namespace

FitReport levenberg_marquardt(const ResidualFunction& residual, Eigen::Index residual_count,
                              Eigen::VectorXd& parameters, int max_evaluations, double relative_reduction) {
  FitReport report;
  Eigen::VectorXd r(residual_count);
  if (!finite_around(residual, parameters, r)) {  // nothing to start from: a failed fit, not a result
    report.status = "residual not finite at or next to the starting point";
    report.evaluations = 1 + 2 * static_cast<int>(parameters.size());
    report.residual_norm = report.residual_rms = std::numeric_limits<double>::quiet_NaN();
    return report;
  }
  ResidualFunctor functor(residual, parameters.size(), residual_count);
  Eigen::NumericalDiff<ResidualFunctor, Eigen::Central> differentiated(functor);
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<ResidualFunctor, Eigen::Central>> lm(differentiated);
  lm.setMaxfev(max_evaluations);
  lm.setFtol(relative_reduction);
  const auto status = lm.minimize(parameters);
  const bool finite = finite_around(residual, parameters, r);
  using namespace Eigen::LevenbergMarquardtSpace;
  // Statuses 1–4 are MINPACK's convergence tests; 6–8 mean no further reduction is possible in
  // double precision, i.e. the minimum has been reached as closely as it can be.
  report.converged = finite && (status == RelativeReductionTooSmall || status == RelativeErrorTooSmall ||
                                status == RelativeErrorAndReductionTooSmall || status == CosinusTooSmall ||
                                status == FtolTooSmall || status == XtolTooSmall || status == GtolTooSmall);
  report.status = finite ? describe(status) : "stopped at the edge of the model's finite range";
  report.evaluations = static_cast<int>(lm.nfev()) + 2 * (1 + 2 * static_cast<int>(parameters.size()));  // with both checks
  report.residual_norm = r.norm();
  report.residual_rms = r.norm() / std::sqrt(static_cast<double>(residual_count));
  return report;
}

}  // namespace granule::distribution
