// The window used to deposit particles on the FFT grid: the "exponential of semicircle" kernel
// φ(z) = exp(β(√(1−z²) − 1)) on |z| ≤ 1 (Barnett, Magland & af Klinteberg 2019, the FINUFFT
// kernel), spanning `width` grid points.  With an upsampling factor 2 and β = 2.30·width its
// aliasing error falls roughly as 10^−(width−1).  Its Fourier transform has no closed form and is
// computed by Gauss–Legendre quadrature, which converges fast because φ is smooth inside and
// vanishes to e^−β at the ends.
#pragma once

#include <vector>

namespace granule::spectra {

class GriddingKernel {
 public:
  explicit GriddingKernel(int width);

  int width() const { return width_; }
  double half_width() const { return 0.5 * width_; }
  // φ at z = (grid point − particle) / half_width, |z| ≤ 1.
  double value(double z) const;
  // Φ(ω) = ∫ φ(g / half_width) e^{iωg} dg over grid units g: the factor a depositing with this
  // window multiplies mode ω (radians per grid spacing) by, divided out afterwards.
  double fourier(double omega) const;

 private:
  int width_;
  double beta_;
  std::vector<double> nodes_, weights_;  // Gauss–Legendre on [−1, 1]
};

}  // namespace granule::spectra
