// How the density of a run's last fields frame is structured, measured against its first frame (the
// homogeneous start): the excess variance of the cell counts and of their profiles along each axis
// over what the start's fluctuations give, so that "the gas clusters", "it forms layers normal to z"
// or "a dense plug in the centre" (thesis Figs C.1–C.5) become numbers.  Reads fields.h5 ("instant/
// count" of the first and last frames).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace granule::reproduce {

struct DensityLayers {
  int dimension = 2;
  std::array<int, 3> cells{1, 1, 1};  // nx, ny, nz
  double c_last = 0.0;                 // collisions per particle of the last frame
  // var(n/n̄) of the cells' counts at the last frame minus the noise of a homogeneous gas of the start's
  // structure, and that noise's standard deviation over the cells (sampling of a variance).
  double map_excess = 0.0, map_noise_sd = 0.0;
  double map_homogeneous = 0.0;  // that noise: var(n/n̄) of the cells of a gas structured as the start
  // The same for the profiles along x, y, z (counts summed over the other axes; nz = 1 in 2D).
  std::array<double, 3> profile_excess{}, profile_noise_sd{};
  // The same for the map averaged along the flow x (over (y, z) in 3D, the y profile in 2D): what a
  // structure uniform along the flow (a streamwise plug, layer or tube) holds of the cells' variance.
  double flow_averaged_excess = 0.0, flow_averaged_noise_sd = 0.0;
  std::array<std::vector<double>, 3> profiles;  // ρ/ρ̄ along each axis at the last frame, cell centres in `positions`
  std::array<std::vector<double>, 3> positions;

  // Resolved: the excess exceeds three noise standard deviations.
  // var(n/n̄) of the last frame's cells over a homogeneous gas's: 1 until the gas clusters.
  double clustering_index() const { return (map_excess + map_homogeneous) / map_homogeneous; }
  bool clustered() const { return map_excess > 3.0 * map_noise_sd; }
  bool layered(int axis) const { return profile_excess[axis] > 3.0 * profile_noise_sd[axis]; }
  // The fraction of the cells' excess variance that layers normal to `axis` carry: 1 for pure layers
  // (the profile holds all of it), ≈ 0 for structure that averages out along the other axes.
  double layer_share(int axis) const { return profile_excess[axis] / map_excess; }
  // The fraction held by the flow-averaged map: 1 for structure that does not vary along x.
  double streamwise_share() const { return flow_averaged_excess / map_excess; }
  // The centre of the densest band of `fraction` of the rows along `axis` (wrapping round when
  // `periodic`), in units of the box side: in [0, 1).
  double densest_band_centre(int axis, double fraction, bool periodic) const;
};

// Throws IoError when the file cannot be read; needs two frames at least (std::runtime_error).
DensityLayers read_density_layers(const std::string& fields_path);

}  // namespace granule::reproduce
