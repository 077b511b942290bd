// VTK XML files for ParaView: particles as PolyData (.vtp: points with velocity and radius, one
// vertex cell each), coarse-grained fields as ImageData (.vti: one value per coarse-graining cell,
// CellData, x fastest as in FieldGrid), and a collection (.pvd) that makes a time series of either.
// Arrays are Float64, appended raw little-endian with UInt64 block sizes.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "analysis/field_grid.hpp"
#include "engine/system_params.hpp"

namespace granule {

// Positions (x, y, 0), "velocity" (v_x, v_y, 0) and "radius" σ/2; the frame's time as TimeValue.
void write_vtp_particles(const std::string& path, const ParticleState& particles, double diameter, double time);

struct NamedCellArray {
  std::string name;
  std::vector<double> values;  // grid.cells() values, cell ix + iy·nx
};

// An nx × ny image of cells spanning the box [0, L_x] × [0, L_y].
void write_vti_fields(const std::string& path, const FieldGrid& grid, const std::vector<NamedCellArray>& arrays, double time);

// A ParaView collection: (time, file name relative to the .pvd) per frame.
void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& frames);

}  // namespace granule
