#include "spectra/spectral_transforms.hpp"

#include <numbers>

#include "spectra/exact_mode_sums.hpp"

namespace granule::spectra {

DensityMomentumTransforms transform_fields(const ParticleState& state, const ShearFrame& frame, double shear_offset,
                                           const TransformOptions& options) {
  DensityMomentumTransforms out{lattice_for_frame(frame, shear_offset), ModeGrid{options.max_mode}, {}, {}, {}};
  std::vector<double> peculiar_vx;
  if (options.subtract_shear_profile) {
    peculiar_vx.resize(state.size());
    for (std::size_t j = 0; j < state.size(); ++j) peculiar_vx[j] = state.vx[j] - frame.mean_flow(state.y[j]);
  }
  const WeightedPoints points{state.x, state.y, {{}, options.subtract_shear_profile ? peculiar_vx : state.vx, state.vy}};
  std::vector<ModeValues> sums = options.method == SpectralMethod::exact
                                     ? exact_mode_sums(points, out.lattice, options.max_mode)
                                     : fast_mode_sums(points, out.lattice, options.max_mode, options.gridding);
  // The thesis's prefactor m/2π of (3.4)–(3.5), m = 1.
  for (ModeValues& values : sums) {
    for (auto& value : values) value *= 0.5 / std::numbers::pi;
  }
  out.density = std::move(sums[0]);
  out.momentum_x = std::move(sums[1]);
  out.momentum_y = std::move(sums[2]);
  return out;
}

}  // namespace granule::spectra
