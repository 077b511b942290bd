// HDF5 file of coarse-grained fields (schema in README.md, "fields.h5"): per frame the
// instantaneous fields of the configuration, the fields averaged over the interval since the
// previous frame (with the collisional stress (1.6) and heat flux when collisions were observed),
// and the streamwise profiles; for rough grains (SystemParams::roughness) also the spin fields and
// the full (non-symmetric) collisional stress.  Maps are (K, ny, nx), in 3D (K, nz, ny, nx).  Written to `<name>.partial`, renamed by finish(); every failure throws
// IoError and leaves `<name>.partial`, never an incomplete `<name>`.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "analysis/cell_fields.hpp"
#include "observers/collisional_stress.hpp"
#include "io/hdf5_util.hpp"

namespace granule {

struct FieldsMetadata {
  SystemParams system;
  std::string boundary;  // "periodic" or "lees-edwards"
  bool subtract_shear_profile = false;
  std::string source;    // "run" (measured during the run) or the snapshot file analysed
  std::string version;
};

struct FieldsFrame {
  double t = 0.0, c = 0.0;              // time and collisions per particle of the frame
  double t_start = 0.0, c_start = 0.0;  // start of the averaging interval
  int configurations = 0;               // configurations in the interval average
  // The Lees–Edwards image offset Δ and velocity U(t) at the frame (0 in a periodic box), which the
  // pictures need to smooth across the images; written to 3D files only (/frames/shear_offset,
  // /frames/shear_velocity), so a 2D file stays what it was.
  double shear_offset = 0.0, shear_velocity = 0.0;
  CellFields instant;
  CellFields average;
  std::optional<CollisionalStress> collisional;  // only when collisions were observed
  std::optional<HeatFlux> heat_flux_collisional;  // q^(c) about the average's V(r), with `collisional`
};

class FieldsWriter {
 public:
  FieldsWriter(const std::string& path, const FieldGrid& grid, const FieldsMetadata& metadata, bool with_collisional);
  // Continues `path` (resume) keeping its first `keep_frames` frames (negative: every complete
  // frame), as SnapshotWriter does; grid and collisional stress as in the file.
  FieldsWriter(const std::string& path, std::int64_t keep_frames);
  // A writer not finished leaves `path`.partial, closed.

  void append(const FieldsFrame& frame);
  std::int64_t frames() const { return file_.frames(); }
  void finish() { file_.publish(); }

 private:
  h5::PartialFile file_;
  FieldGrid grid_;
  bool with_collisional_ = false;
  bool rough_ = false;  // rough grains: spin fields, and a full collisional stress tensor
};

// The coarse-graining grid of an open fields file (root attributes nx, ny, length_x, length_y; in
// 3D also dimension = 3, nz, length_z).
FieldGrid read_fields_grid(hid_t file);
// The shape of one frame of a cell map: (ny, nx) in 2D, (nz, ny, nx) in 3D (x fastest).
std::vector<hsize_t> field_map_shape(const FieldGrid& grid);
// Collisions per particle of each complete frame of a fields file (published or partial).
std::vector<double> read_fields_frame_c(const std::string& path);

}  // namespace granule
