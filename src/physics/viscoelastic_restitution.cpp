#include "physics/viscoelastic_restitution.hpp"

#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <cstddef>
#include <vector>

namespace granule {

namespace {

using State = std::array<double, 2>;  // u, u'

// The table: ẽ at y = (k h)², k = 0 … kPoints − 1.  Uniform in √y because ẽ is a power series in
// √y (Schwager & Pöschel 2008), smooth there, so four-point interpolation reaches ~1e-9.
constexpr std::size_t kPoints = 1025;
constexpr double kRootStep = 5.0 / (kPoints - 1);  // up to y = 25

// The collision's force in scaled units, u^{3/2} + y u^{1/2} u' (up to the factor u^{1/2}): the
// contact ends where u + y u' turns negative.
double pushes(const State& s, double y) { return s[0] + y * s[1]; }

}  // namespace

double integrate_viscoelastic_restitution(double y) {
  if (!(y > 0.0)) return 1.0;
  namespace odeint = boost::numeric::odeint;
  const auto motion = [y](const State& s, State& rate, double) {
    const double root = std::sqrt(std::max(s[0], 0.0));
    rate[0] = s[1];
    rate[1] = -root * pushes(s, y);
  };
  // Dormand–Prince with dense output: its error control shrinks the steps where u^{1/2} varies
  // fastest (the first instants), and the end of the contact is found between two steps on the
  // interpolant, by bisection.
  auto stepper = odeint::make_dense_output(1e-13, 1e-13, odeint::runge_kutta_dopri5<State>());
  stepper.initialize(State{0.0, 1.0}, 0.0, 1e-6);
  // A contact lasts ~3.2 scaled time units when elastic, less when damped: the bound only stops a
  // loop that could not otherwise end.
  while (stepper.current_time() < 1000.0) {
    const auto [from, to] = stepper.do_step(motion);
    if (pushes(stepper.current_state(), y) >= 0.0 || stepper.current_state()[1] > 0.0) continue;
    double low = from, high = to;  // pushes ≥ 0 at low (still in contact), < 0 at high
    State s{};
    for (int k = 0; k < 200 && high - low > 1e-15 * high; ++k) {
      const double middle = 0.5 * (low + high);
      stepper.calc_state(middle, s);
      (pushes(s, y) >= 0.0 ? low : high) = middle;
    }
    stepper.calc_state(high, s);
    return -s[1];
  }
  return -stepper.current_state()[1];
}

double viscoelastic_restitution(double y) {
  static const std::vector<double> table = [] {
    std::vector<double> values(kPoints);
    for (std::size_t k = 0; k < kPoints; ++k) {
      const double root = static_cast<double>(k) * kRootStep;
      values[k] = integrate_viscoelastic_restitution(root * root);
    }
    return values;
  }();
  if (!(y > 0.0)) return 1.0;
  const double position = std::sqrt(y) / kRootStep;
  if (position >= static_cast<double>(kPoints - 2)) return integrate_viscoelastic_restitution(y);
  // Lagrange through the four points around `position` (the first interval uses 0 … 3).
  const std::size_t first = position < 1.0 ? 0 : static_cast<std::size_t>(position) - 1;
  const double t = position - static_cast<double>(first);
  const double* e = table.data() + first;
  return -e[0] * (t - 1.0) * (t - 2.0) * (t - 3.0) / 6.0 + e[1] * t * (t - 2.0) * (t - 3.0) / 2.0 -
         e[2] * t * (t - 1.0) * (t - 3.0) / 2.0 + e[3] * t * (t - 1.0) * (t - 2.0) / 6.0;
}

}  // namespace granule
