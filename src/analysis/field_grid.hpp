// The coarse-graining grid of thesis §1.4.3: the box divided into nx × ny identical rectangular
// cells, chosen by the user and independent of the engine's own cells.  Cell c = ix + iy·nx.
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

  std::size_t cells() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
  double cell_width() const { return length_x / nx; }
  double cell_height() const { return length_y / ny; }
  double cell_area() const { return cell_width() * cell_height(); }
  int column(double x) const { return std::clamp(static_cast<int>(x / length_x * nx), 0, nx - 1); }
  int row(double y) const { return std::clamp(static_cast<int>(y / length_y * ny), 0, ny - 1); }
  // Cell of a lab position inside the box (positions on the far edges belong to the last cell).
  std::size_t index(double x, double y) const {
    return static_cast<std::size_t>(column(x)) + static_cast<std::size_t>(row(y)) * static_cast<std::size_t>(nx);
  }
  // Centre of a cell: the position r the thesis attaches to its fields.
  double center_x(int ix) const { return (ix + 0.5) * cell_width(); }
  double center_y(int iy) const { return (iy + 0.5) * cell_height(); }
};

// The default coarse graining: about 20 disks per cell (enough for a temperature, fine enough
// for clusters), cells as square as the box allows.
inline FieldGrid default_field_grid(double length_x, double length_y, std::int64_t particles) {
  const double side = std::sqrt(20.0 * length_x * length_y / static_cast<double>(particles));
  return {std::max(1, static_cast<int>(std::lround(length_x / side))),
          std::max(1, static_cast<int>(std::lround(length_y / side))), length_x, length_y};
}

}  // namespace granule
