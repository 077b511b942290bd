// The coarse-graining grid of thesis §1.4.3: the box divided into nx × ny (× nz in 3D) identical
// rectangular cells, chosen by the user and independent of the engine's own cells.
// Cell c = ix + nx·(iy + ny·iz), x fastest (iz = 0 in 2D, where nz = 1).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace granule {

struct FieldGrid {
  int nx = 1;
  int ny = 1;
  double length_x = 1.0;
  double length_y = 1.0;
  // 3D only: the vorticity axis (layers iz); a 2D grid keeps nz = 1.
  int nz = 1;
  double length_z = 1.0;
  int dimension = 2;

  std::size_t cells() const {
    return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) * static_cast<std::size_t>(nz);
  }
  double cell_width() const { return length_x / nx; }
  double cell_height() const { return length_y / ny; }
  double cell_depth() const { return length_z / nz; }
  double cell_area() const { return cell_width() * cell_height(); }
  // The d-dimensional measure of a cell: its area in 2D, its volume in 3D (densities are per it).
  double cell_volume() const { return dimension == 3 ? cell_area() * cell_depth() : cell_area(); }
  int column(double x) const { return std::clamp(static_cast<int>(x / length_x * nx), 0, nx - 1); }
  int row(double y) const { return std::clamp(static_cast<int>(y / length_y * ny), 0, ny - 1); }
  int layer(double z) const { return std::clamp(static_cast<int>(z / length_z * nz), 0, nz - 1); }
  std::size_t index_of_cell(int ix, int iy, int iz) const {
    return static_cast<std::size_t>(ix) +
           static_cast<std::size_t>(nx) * (static_cast<std::size_t>(iy) + static_cast<std::size_t>(ny) * static_cast<std::size_t>(iz));
  }
  // Cell of a lab position inside the box (positions on the far edges belong to the last cell).
  std::size_t index(double x, double y) const { return index_of_cell(column(x), row(y), 0); }
  std::size_t index(double x, double y, double z) const { return index_of_cell(column(x), row(y), layer(z)); }
  // Centre of a cell: the position r the thesis attaches to its fields.
  double center_x(int ix) const { return (ix + 0.5) * cell_width(); }
  double center_y(int iy) const { return (iy + 0.5) * cell_height(); }
  double center_z(int iz) const { return (iz + 0.5) * cell_depth(); }
};

// The default coarse graining: about 20 disks per cell (enough for a temperature, fine enough
// for clusters), cells as square as the box allows.
inline FieldGrid default_field_grid(double length_x, double length_y, std::int64_t particles) {
  const double side = std::sqrt(20.0 * length_x * length_y / static_cast<double>(particles));
  return {std::max(1, static_cast<int>(std::lround(length_x / side))),
          std::max(1, static_cast<int>(std::lround(length_y / side))), length_x, length_y};
}

// The same in 3D: about 20 spheres per cell, cells as cubic as the box allows.
inline FieldGrid default_field_grid_3d(double length_x, double length_y, double length_z, std::int64_t particles) {
  const double side = std::cbrt(20.0 * length_x * length_y * length_z / static_cast<double>(particles));
  const auto cells_along = [side](double length) { return std::max(1, static_cast<int>(std::lround(length / side))); };
  return {cells_along(length_x), cells_along(length_y), length_x, length_y, cells_along(length_z), length_z, 3};
}

}  // namespace granule
