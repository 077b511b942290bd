// Reads one frame of a fields file (fields.h5: root attributes nx, ny, length_x, length_y (3D: also
// nz, length_z); /frames/t, /frames/c (K,); groups /instant and /average of (K, ny, nx) maps, 3D
// (K, nz, ny, nx)) for export.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "analysis/field_grid.hpp"
#include "io/export_vtk.hpp"

namespace granule {

struct FieldFileFrame {
  FieldGrid grid;
  std::int64_t frames = 0;  // K, frames in the file
  double time = 0.0;
  double collisions_per_particle = 0.0;
  // Every map of /instant and /average, named "instant_<name>" / "average_<name>".
  std::vector<NamedCellArray> arrays;
};

// Frame `index` (negative counts from the end).  Throws std::runtime_error on a missing file,
// a frame out of range or a file of another layout.
FieldFileFrame read_field_file_frame(const std::string& path, std::int64_t index);

}  // namespace granule
