// The 2D cell fields by name: those a configuration picture can colour its disks by and an export
// of fields computed from snapshots writes, and the coarse-graining grid both use by default.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/cell_fields.hpp"
#include "analysis/field_grid.hpp"

namespace granule {

// "density", "temperature", "velocity_x", "velocity_y", "kinetic_xx", "kinetic_xy", "kinetic_yy",
// "pressure_kinetic", "vorticity", "count".
const std::vector<std::string>& cell_field_names();

// The field of that name (cell_field_names); nullptr if unknown.
const std::vector<double>* cell_field_by_name(const CellFields& fields, std::string_view name);

// The automatic coarse-graining grid of a picture: about 40 disks per cell, between 4 and 64 cells
// a side (32 × 32 for the thesis's N = 40000, as in Figs 2.2–2.3).
FieldGrid automatic_picture_grid(std::int64_t particles, double length_x, double length_y);

}  // namespace granule
