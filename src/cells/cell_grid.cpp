#include "cells/cell_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace granule {

namespace {
// Relative safety margin on the minimum cell size: round-off must never hide a contact pair.
constexpr double kCellMargin = 1e-9;
constexpr int kMinCells = 3;

std::string fmt_double(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}
}  // namespace

CellGridChoice choose_cell_grid(const CellGridRequest& request) {
  const double lx = request.length_x;
  const double ly = request.length_y;
  const double sigma = request.diameter * (1.0 + kCellMargin);
  // Minimum strain half-period: one box width of offset, |s| ≤ L_x / (2 L_y).
  const double s_min = request.sheared ? 0.5 * lx / ly : 0.0;
  const double min_width = sigma * std::sqrt(1.0 + s_min * s_min);
  const double min_height = sigma;
  const bool three_d = request.dimension == 3;
  const double lz = three_d ? request.length_z : 0.0;
  const int max_nx = static_cast<int>(std::floor(lx / min_width));
  const int max_ny = static_cast<int>(std::floor(ly / min_height));
  const int max_nz = three_d ? static_cast<int>(std::floor(lz / min_height)) : 1;

  CellGrid grid;
  if (request.forced) {
    grid.nx = request.forced->first;
    grid.ny = request.forced->second;
    if (grid.nx < kMinCells || grid.ny < kMinCells || grid.nx > max_nx || grid.ny > max_ny) {
      return {std::nullopt, "engine.cells = [" + std::to_string(grid.nx) + ", " +
                                std::to_string(grid.ny) + "] is not allowed: each count must be in [" +
                                std::to_string(kMinCells) + ", " + std::to_string(max_nx) +
                                "] × [" + std::to_string(kMinCells) + ", " +
                                std::to_string(max_ny) + "] for this box and diameter"};
    }
    if (three_d) return {std::nullopt, "engine.cells is for 2D runs only: 3D grids are always chosen automatically"};
  } else {
    if (max_nx < kMinCells || max_ny < kMinCells || (three_d && max_nz < kMinCells)) {
      return {std::nullopt,
              "the box " + fmt_double(lx) + " × " + fmt_double(ly) + (three_d ? " × " + fmt_double(lz) : "") +
                  " is too small for the cell grid: it needs at least 3 cells of size ≥ " +
                  fmt_double(min_width) + " × " + fmt_double(min_height) + (three_d ? " × " + fmt_double(min_height) : "") +
                  " per direction (largest diameter " + fmt_double(request.diameter) +
                  "); enlarge system.box or reduce the diameter"};
    }
    const double volume = lx * ly * (three_d ? lz : 1.0);
    const double cell_volume =
        request.particles_per_cell * volume / static_cast<double>(std::max<std::int64_t>(1, request.particles));
    const double side = three_d ? std::cbrt(cell_volume) : std::sqrt(cell_volume);
    grid.nx = std::clamp(static_cast<int>(std::floor(lx / side)), kMinCells, max_nx);
    grid.ny = std::clamp(static_cast<int>(std::floor(ly / side)), kMinCells, max_ny);
    if (three_d) grid.nz = std::clamp(static_cast<int>(std::floor(lz / side)), kMinCells, max_nz);
    while (grid.cell_count() > request.max_cells) {
      int& most = grid.nx >= grid.ny && grid.nx >= grid.nz ? grid.nx : (grid.ny >= grid.nz ? grid.ny : grid.nz);
      if (most == kMinCells) {
        return {std::nullopt, "no cell grid of at least 3 cells per direction has at most " +
                                  std::to_string(request.max_cells) + " cells"};
      }
      const double fitting = std::floor(most * (static_cast<double>(request.max_cells) / static_cast<double>(grid.cell_count())));
      most = std::max(kMinCells, std::min(most - 1, static_cast<int>(fitting)));
    }
  }
  grid.width = lx / grid.nx;
  grid.height = ly / grid.ny;
  if (three_d) grid.depth = lz / grid.nz;
  if (request.sheared) {
    // Largest strain at which a contact pair still spans at most one column: σ√(1+s²) ≤ width.
    const double ratio = grid.width / sigma;
    const double s_allowed = std::sqrt(std::max(0.0, ratio * ratio - 1.0));
    const int periods = std::max(1, static_cast<int>(std::floor(2.0 * s_allowed * ly / lx)));
    grid.strain_period = periods * lx / ly;
  }
  return {grid, {}};
}

void CellLists::save(StateArchive& archive, const std::string& prefix) const { archive.put_view(prefix + "head", head_); }

void CellLists::restore(const StateArchive& archive, const std::string& prefix, std::int64_t cells,
                        const std::vector<std::int32_t>& links) {
  const auto& heads = archive.get<std::int32_t>(prefix + "head");
  head_.assign(heads.begin(), heads.end());
  const auto particles = static_cast<std::int64_t>(links.size());
  const auto valid = [&](std::int32_t id) { return id == kEnd || (id >= 0 && id < particles); };
  if (head_.size() != static_cast<std::size_t>(cells) || !std::all_of(head_.begin(), head_.end(), valid) ||
      !std::all_of(links.begin(), links.end(), valid)) {
    throw std::runtime_error("checkpoint cell lists do not fit a grid of " + std::to_string(cells) + " cells and " +
                             std::to_string(particles) + " particles");
  }
}

}  // namespace granule
