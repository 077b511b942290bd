#include "distribution/least_squares.hpp"

#include <cmath>
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
                              Eigen::VectorXd& parameters, int max_evaluations) {
  ResidualFunctor functor(residual, parameters.size(), residual_count);
  Eigen::NumericalDiff<ResidualFunctor, Eigen::Central> differentiated(functor);
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<ResidualFunctor, Eigen::Central>> lm(differentiated);
  lm.setMaxfev(max_evaluations);
  const auto status = lm.minimize(parameters);
  Eigen::VectorXd r(residual_count);
  residual(parameters, r);
  using namespace Eigen::LevenbergMarquardtSpace;
  FitReport report;
  // Statuses 1–4 are MINPACK's convergence tests; 6–8 mean no further reduction is possible in
  // double precision, i.e. the minimum has been reached as closely as it can be.
  report.converged = r.allFinite() && (status == RelativeReductionTooSmall || status == RelativeErrorTooSmall ||
                                       status == RelativeErrorAndReductionTooSmall || status == CosinusTooSmall ||
                                       status == FtolTooSmall || status == XtolTooSmall || status == GtolTooSmall);
  report.status = describe(status);
  report.evaluations = static_cast<int>(lm.nfev());
  report.residual_norm = r.norm();
  report.residual_rms = r.norm() / std::sqrt(static_cast<double>(residual_count));
  return report;
}

}  // namespace granule::distribution
