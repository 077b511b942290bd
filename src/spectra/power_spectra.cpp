#include "spectra/power_spectra.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace granule::spectra {

double PowerMaps::k(std::size_t i) const {
  return lattice.dimension == 3 ? std::hypot(kx[i], ky[i], kz[i]) : std::hypot(kx[i], ky[i]);
}

PowerMaps power_maps(const DensityMomentumTransforms& t, bool exclude_ky_axis_from_px) {
  const std::size_t count = t.modes.count();
  const bool depth = t.modes.dimension == 3;
  PowerMaps maps{t.lattice, t.modes, std::vector<double>(count), std::vector<double>(count), std::vector<double>(count),
                 std::vector<double>(count), std::vector<double>(count), std::vector<double>(count)};
  maps.ideal_density = t.ideal_density;
  maps.ideal_momentum_axes = t.ideal_momentum_axes;
  maps.ideal_momentum_spread = t.ideal_momentum_spread;
  maps.ideal_momentum_shares = t.ideal_momentum_shares;
  if (depth) {
    maps.kz.resize(count);
    maps.momentum_z.resize(count);
  }
  const int max_mode = t.modes.max_mode;
  for (int n = -t.modes.max_mode_z(); n <= t.modes.max_mode_z(); ++n) {
    for (int m = -max_mode; m <= max_mode; ++m) {
      for (int l = -max_mode; l <= max_mode; ++l) {
        const std::size_t i = t.modes.index(l, m, n);
        maps.kx[i] = t.lattice.kx(l);
        maps.ky[i] = t.lattice.ky(l, m);
        maps.density[i] = std::norm(t.density[i]);
        maps.momentum_x[i] = exclude_ky_axis_from_px && l == 0 && n == 0 ? std::numeric_limits<double>::quiet_NaN()
                                                                         : std::norm(t.momentum_x[i]);
        maps.momentum_y[i] = std::norm(t.momentum_y[i]);
        maps.momentum[i] = maps.momentum_x[i] + maps.momentum_y[i];
        if (depth) {
          maps.kz[i] = t.lattice.kz(n);
          maps.momentum_z[i] = std::norm(t.momentum_z[i]);
          maps.momentum[i] += maps.momentum_z[i];
        }
      }
    }
  }
  return maps;
}

AnnulusSpectrum annulus_sums(const PowerMaps& maps, double dk, double max_radius) {
  AnnulusSpectrum out;
  out.dk = dk;
  const double radius = std::min(max_radius, maps.lattice.complete_radius(maps.modes.max_mode));
  const double count = annulus_count(dk, radius);
  if (!(count <= kMaxAnnuli)) {  // a width too small for any table (and for the cast below)
    throw std::length_error("an annulus width dk = " + std::to_string(dk) + " makes more than 2^32 annuli up to k = " +
                            std::to_string(radius) + ": choose a wider dk");
  }
  const auto bins = static_cast<std::size_t>(count);
  out.k.resize(bins);
  for (std::size_t b = 0; b < bins; ++b) out.k[b] = static_cast<double>(b + 1) * dk;
  out.modes.assign(bins, 0);
  out.momentum_modes.assign(bins, 0);
  const bool depth = maps.lattice.dimension == 3;
  for (auto* sum : {&out.density, &out.momentum_x, &out.momentum_y, &out.momentum}) sum->assign(bins, 0.0);
  if (depth) out.momentum_z.assign(bins, 0.0);
  const auto add = [](std::vector<double>& sum, std::size_t b, double power) {
    if (!std::isnan(power)) sum[b] += power;
  };
  for (std::size_t i = 0; i < maps.modes.count(); ++i) {
    const double b = std::floor(maps.k(i) / dk + 0.5);
    if (b < 1.0 || b > static_cast<double>(bins)) continue;
    const auto bin = static_cast<std::size_t>(b) - 1;
    ++out.modes[bin];
    if (!std::isnan(maps.momentum[i])) ++out.momentum_modes[bin];
    add(out.density, bin, maps.density[i]);
    add(out.momentum_x, bin, maps.momentum_x[i]);
    add(out.momentum_y, bin, maps.momentum_y[i]);
    add(out.momentum, bin, maps.momentum[i]);
    if (depth) add(out.momentum_z, bin, maps.momentum_z[i]);
  }
  return out;
}

double annulus_count(double dk, double max_radius) { return std::max(0.0, std::floor(max_radius / dk - 0.5)); }

double default_annulus_width(const ReciprocalLattice& lattice) {
  const double longest = std::max(lattice.length_x, lattice.length_y);
  return 2.0 * std::numbers::pi / (lattice.dimension == 3 ? std::max(longest, lattice.length_z) : longest);
}

}  // namespace granule::spectra
