// The dominant modes of a run's spectra frame by frame, as `granule analyze spectra` tabulates them
// (spectra_dominant CSV, docs/spectra.md), and when a field's dominant mode first stands above the
// noise of uncorrelated positions to stay: the thesis watches the momentum spectrum's mode appear
// before the mass spectrum's (Figs 2.8–2.9).
#pragma once

#include <string>
#include <vector>

namespace granule::reproduce {

struct DominantMode {
  double c = 0.0;       // collisions per particle of the frame
  double length = 0.0;  // 2π/|k| of the dominant mode
  bool significant = false;
  double noise_p_value = 1.0;  // of as much power in one mode from uncorrelated positions
};

// A run's frames, in the order of the file, of the mass spectrum R and the momentum spectrum P.
struct RunModes {
  std::vector<DominantMode> mass, momentum;
};

// The table at `path` (both empty when the file is missing).
RunModes dominant_modes(const std::string& path);

// A mode that is the dominant one and significant in this many consecutive frames has appeared: a
// single frame's 5 % false alarm would otherwise mark the first of ~100 frames in most runs.
inline constexpr int kPersistentFrames = 3;

// The first frame from which one mode (the same length) stays dominant and significant for
// kPersistentFrames frames; nullptr when none does.
const DominantMode* first_persistent_mode(const std::vector<DominantMode>& frames);

}  // namespace granule::reproduce
