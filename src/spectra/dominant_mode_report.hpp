// What is said about the dominant modes of a run's spectra (`granule analyze spectra` prints it):
// what their length is compared with (L0 of eq 1.1 and the mean free path it is built on), each
// frame's dominant mode with its significance against uncorrelated positions, and a closing count
// per field of the frames where the dominant mode stood above the noise — so that a length is
// never read off a spectrum of pure noise.
#pragma once

#include <string>

#include "engine/system_params.hpp"
#include "spectra/dominant_mode.hpp"

namespace granule::spectra {

// One line: the length scale L0 and the mean free path it uses, and the false-alarm level.
std::string describe_comparison(const SystemParams& system, double cluster_length, double false_alarm);

// One line for the dominant mode of field `name`: its length 2π/|k| over L0, power over the noise level,
// the false-alarm probability over the K modes compared, and "significant" or "no significant mode".
std::string describe_dominant(const char* name, const DominantMode& mode, double cluster_length,
                              double false_alarm);

// The significant frames of one field, and the mean of their length over L0.
class SignificanceTally {
 public:
  void add(const DominantMode& mode, double cluster_length);
  std::string summary(const char* name, double false_alarm) const;

 private:
  int frames_ = 0, significant_ = 0;
  double sum_length_over_l0_ = 0.0;
};

}  // namespace granule::spectra
