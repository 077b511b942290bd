#include "spectra/shell_structure_factor.hpp"

#include <cmath>
#include <limits>

namespace granule::spectra {

namespace {

void average(const std::vector<double>& sums, const std::vector<std::int64_t>& modes, double level, double spread,
             std::vector<double>& mean, std::vector<double>& sd) {
  mean.assign(sums.size(), std::numeric_limits<double>::quiet_NaN());
  sd.assign(sums.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t b = 0; b < sums.size(); ++b) {
    if (modes[b] == 0) continue;
    const auto count = static_cast<double>(modes[b]);
    mean[b] = sums[b] / (count * level);
    sd[b] = spread * std::sqrt(2.0 / count);
  }
}

}  // namespace

ShellStructureFactor shell_structure_factor(const AnnulusSpectrum& shells, const PowerMaps& maps) {
  ShellStructureFactor out;
  average(shells.density, shells.modes, maps.ideal_density, 1.0, out.density, out.density_sd);
  average(shells.momentum, shells.momentum_modes, maps.ideal_momentum(), maps.ideal_momentum_spread, out.momentum,
          out.momentum_sd);
  return out;
}

}  // namespace granule::spectra
