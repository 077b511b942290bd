// The file of `granule analyze spectra` (format "granule-spectra", schema in docs/spectra.md): per
// frame the power maps R, P_x, P_y (, P_z), P, their annulus (2D) or shell (3D) sums against |k|,
// the averages S(k) with the band of an ideal gas, and the dominant mode of each field with its
// significance; 3D maps on the plane k_z = 0 only.  Beside it the dominant modes as CSV rows.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "io/file_schema.hpp"
#include "io/hdf5_util.hpp"
#include "io/snapshot_file.hpp"
#include "spectra/dominant_mode.hpp"
#include "spectra/power_spectra.hpp"
#include "spectra/shell_structure_factor.hpp"

namespace granule {

// What the analysis was asked, recorded in the file's attributes.
struct SpectraFileSettings {
  std::string source;  // the snapshots analysed
  std::string method;  // "fast" or "exact"
  bool subtract_shear = false;
  bool exclude_ky_axis = false;
  double false_alarm = 0.0;
};

// The tables that describe the file: its spectra, the columns of a dominant mode and the shell
// averages, in the file's order (the command computes what they name).
namespace spectra_file {

using spectra::AnnulusSpectrum;
using spectra::DominantMode;
using spectra::ModeNoise;
using spectra::PowerMaps;
using spectra::ShellStructureFactor;

// The spectra, in output order: name in the file, the map of PowerMaps and the sum of AnnulusSpectrum
// it comes from, and its power for uncorrelated positions.
struct FieldChoice {
  const char* name;
  const std::vector<double> PowerMaps::*map;
  const std::vector<double> AnnulusSpectrum::*annulus;
  ModeNoise (*noise)(const PowerMaps&);
};
inline constexpr FieldChoice kSpectrumFields[] = {
    {"R", &PowerMaps::density, &AnnulusSpectrum::density, [](const PowerMaps& p) { return p.density_noise(); }},
    {"Px", &PowerMaps::momentum_x, &AnnulusSpectrum::momentum_x, [](const PowerMaps& p) { return p.momentum_component_noise(0); }},
    {"Py", &PowerMaps::momentum_y, &AnnulusSpectrum::momentum_y, [](const PowerMaps& p) { return p.momentum_component_noise(1); }},
    {"P", &PowerMaps::momentum, &AnnulusSpectrum::momentum, [](const PowerMaps& p) { return p.momentum_noise(); }}};
inline constexpr FieldChoice kSpectrumFields3d[] = {
    kSpectrumFields[0], kSpectrumFields[1], kSpectrumFields[2],
    {"Pz", &PowerMaps::momentum_z, &AnnulusSpectrum::momentum_z, [](const PowerMaps& p) { return p.momentum_component_noise(2); }},
    kSpectrumFields[3]};

// The columns of a dominant mode after its indices, in the file (dominant/<field>/<column>) and the CSV.
inline constexpr std::pair<const char*, double DominantMode::*> kDominantColumns[] = {
    {"kx", &DominantMode::kx}, {"ky", &DominantMode::ky}, {"kz", &DominantMode::kz}, {"k", &DominantMode::k},
    {"angle_deg", &DominantMode::angle_deg}, {"length", &DominantMode::length}, {"power", &DominantMode::power},
    {"power_over_ideal_gas", &DominantMode::power_over_ideal_gas}, {"independent_modes", &DominantMode::independent_modes},
    {"noise_p_value", &DominantMode::noise_p_value}, {"noise_threshold", &DominantMode::noise_threshold}};

inline std::span<const FieldChoice> fields_of(int dimension) {
  return dimension == 3 ? std::span<const FieldChoice>(kSpectrumFields3d) : std::span<const FieldChoice>(kSpectrumFields);
}

// The shell-averaged spectra: name, and the member of ShellStructureFactor.
inline constexpr std::pair<const char*, const std::vector<double> ShellStructureFactor::*> kShellAverages[] = {
    {"S_R", &ShellStructureFactor::density}, {"S_R_sd", &ShellStructureFactor::density_sd},
    {"S_P", &ShellStructureFactor::momentum}, {"S_P_sd", &ShellStructureFactor::momentum_sd}};

// What spectra.h5 of a run of `dimension` holds (io/file_schema.hpp), checked before a figure
// script reads it.
const h5::FileSchema& spectra_schema(int dimension);

// The dominant-mode CSV: its header line, and the line of one field's dominant mode in a frame.
std::string dominant_csv_header();
std::string dominant_csv_row(std::int64_t index, const SnapshotFrame& frame, const char* field, const DominantMode& d,
                             double l0);

}  // namespace spectra_file

// The spectra file as it grows: `<path>.partial`, flushed after its layout and after every frame,
// given its final name only once its close succeeded (h5::PartialFile); a failure leaves the
// `.partial` with the frames done so far.  Every HDF5 call is checked and throws IoError.
class SpectraFile {
 public:
  // The root attributes (the analysis's settings and the run's parameters) and the empty
  // per-frame datasets, `bins` the annuli (shells) of the first frame.
  SpectraFile(const std::string& path, const SpectraFileSettings& settings, const SnapshotMetadata& metadata,
              const spectra::TransformOptions& transform, double dk, const spectra::AnnulusSpectrum& bins);
  // Frame `index` of the snapshots, its spectra and their dominant modes (one per field of
  // fields_of), L0 the length they are compared with.
  void append(std::int64_t index, const SnapshotFrame& frame, const spectra::PowerMaps& maps,
              const spectra::AnnulusSpectrum& annulus, const std::vector<spectra::DominantMode>& dominant, double l0);
  void publish() { partial_.publish(); }

 private:
  void write_layout(const SpectraFileSettings& settings, const SnapshotMetadata& metadata,
                    const spectra::TransformOptions& transform, double dk, const spectra::AnnulusSpectrum& bins);

  h5::PartialFile partial_;
  hid_t file_;  // partial_'s identifier, owned by it
  bool depth_;         // a 3D run
  std::string rings_;  // "annulus_" (2D) or "shell_" (3D)
};

}  // namespace granule
