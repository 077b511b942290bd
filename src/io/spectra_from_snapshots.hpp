// The spectra of a run's snapshots (`granule analyze spectra`, thesis §2.2, §3.2.1), frame by
// frame: the power maps of mass and momentum on the allowed (sheared) reciprocal lattice, their
// annulus (2D) or shell (3D) sums, the dominant mode of each field with its significance, written
// to the spectra file (spectra_file.hpp) and the dominant modes to a CSV beside it.  The file grows
// as `<out>.partial`; the CSV and the final name come only when every frame is done.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/snapshot_file.hpp"
#include "io/spectra_file.hpp"
#include "spectra/dominant_mode_report.hpp"

namespace granule {

// Modes |l|, |m| (, |n|) ≤ M: 64 in 2D by default, at most 2048; 32 in 3D, at most 256 (an n³ FFT
// grid of 16 n³ bytes per pair of fields: 20 GB at M = 256).
inline int default_max_mode(int dimension) { return dimension == 3 ? 32 : 64; }
inline int max_mode_limit(int dimension) { return dimension == 3 ? 256 : 2048; }

struct SpectraRequest {
  std::string snapshots;
  std::string method = "fast";  // "fast" (gridded FFT) or "exact" (direct sums)
  int max_mode = 64;
  std::optional<double> dk;     // annulus (shell) width; default 2π/max(L_x, L_y (, L_z))
  bool subtract_shear = false;  // momentum relative to the linear shear profile, p'(k) of (3.17)
  bool exclude_ky_axis = false; // the k_y axis left out of P_x and P (§3.2.1)
  double false_alarm = spectra::kDefaultFalseAlarm;
  std::string out = "spectra.h5";
  std::string csv;              // "": <out stem>_dominant.csv
};

// One frame's time and c, and its dominant modes, one per field of spectra_file::fields_of.
struct FrameSpectra {
  double time = 0.0;
  double collisions_per_particle = 0.0;
  std::vector<spectra::DominantMode> dominant;
};

class SpectraFromSnapshots {
 public:
  // `first` is frame 0 of the snapshots (read by the caller, which keeps it while this lives).
  SpectraFromSnapshots(const SpectraRequest& request, const SnapshotRead& first);
  ~SpectraFromSnapshots();

  // L0 = l/√(1 − ẽ²) (1.1) of the run, which dominant lengths are compared with.
  double cluster_length() const { return l0_; }
  const std::string& csv_path() const { return csv_path_; }

  // Frame `index` of the snapshots, analysed and appended to the file.
  FrameSpectra add_frame(std::int64_t index);
  // Per field, the frames whose dominant mode was significant so far.
  const std::vector<spectra::SignificanceTally>& tallies() const { return tallies_; }
  // Writes the CSV and gives the file its final name.
  void publish();

 private:
  SpectraRequest request_;
  const SnapshotRead& first_;
  ShearFrame box_;
  spectra::TransformOptions transform_;
  double dk_ = 0.0, radius_ = 0.0, l0_ = 0.0;
  std::string csv_path_, csv_;
  std::unique_ptr<SpectraFile> file_;
  std::vector<spectra::SignificanceTally> tallies_;
};

}  // namespace granule
