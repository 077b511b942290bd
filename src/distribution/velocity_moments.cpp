#include "distribution/velocity_moments.hpp"

#include <cmath>

namespace granule::distribution {

PlaneIntegrals plane_integrals(const std::function<double(double, double)>& density, double speed_max) {
  constexpr int kAngles = 128;  // exact for trigonometric polynomials of degree < 128
  constexpr int kSpeedIntervals = 600;  // even, for Simpson
  const double du = speed_max / kSpeedIntervals;
  PlaneIntegrals out;
  for (int l = 0; l < kAngles; ++l) {
    const double angle = 2.0 * M_PI * l / kAngles;
    const double c = std::cos(angle), s = std::sin(angle);
    double zeroth = 0.0, second = 0.0;
    for (int k = 0; k <= kSpeedIntervals; ++k) {
      const double u = k * du;
      const double weight = (k == 0 || k == kSpeedIntervals) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
      const double f = density(u, angle) * u;  // polar area element u du dθ
      zeroth += weight * f;
      second += weight * f * u * u;
    }
    const double w = du / 3.0 * 2.0 * M_PI / kAngles;
    out.normalisation += w * zeroth;
    out.moment.xx += w * second * c * c;
    out.moment.xy += w * second * c * s;
    out.moment.yy += w * second * s * s;
  }
  return out;
}

double JenkinsRichman::density(double speed, double angle) const {
  const double vx = speed * std::cos(angle), vy = speed * std::sin(angle);
  const double det = k.xx * k.yy - k.xy * k.xy;
  const double quadratic = (k.yy * vx * vx - 2.0 * k.xy * vx * vy + k.xx * vy * vy) / det;
  return std::exp(-0.5 * quadratic) / (2.0 * M_PI * std::sqrt(det));
}

JenkinsRichman jenkins_richman(const SecondMoment& k) {
  JenkinsRichman jr;
  jr.k = k;
  const double det = k.xx * k.yy - k.xy * k.xy;
  jr.b0 = std::log(2.0 * M_PI * std::sqrt(det));
  // ½ ê·K⁻¹·ê with K⁻¹ = [[yy, −xy], [−xy, xx]]/det:
  //   = [(xx + yy) + (yy − xx) cos 2θ − 2 xy sin 2θ] / (4 det) = mean + A sin(2θ + 2ε).
  jr.b2_mean = (k.xx + k.yy) / (4.0 * det);
  const double sine = -2.0 * k.xy / (4.0 * det), cosine = (k.yy - k.xx) / (4.0 * det);
  jr.b2_amplitude = std::hypot(sine, cosine);
  double phase = 0.5 * std::atan2(cosine, sine);
  jr.phase = phase - M_PI * std::floor(phase / M_PI);
  return jr;
}

}  // namespace granule::distribution
