#include "init/placement.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace granule {

PlacementGrid::PlacementGrid(const SystemParams& p) {
  const double side = std::max(p.diameter, std::sqrt(p.length_x * p.length_y / static_cast<double>(p.particles)));
  // nx ny ≤ L_x L_y / side² ≤ N, so both fit an int.
  nx = std::max(1, static_cast<int>(std::floor(p.length_x / side)));
  ny = std::max(1, static_cast<int>(std::floor(p.length_y / side)));
  cell_width = p.length_x / nx;
  cell_height = p.length_y / ny;
  head.assign(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny), -1);
  next.assign(static_cast<std::size_t>(p.particles), -1);
}

namespace {

// The columns (or rows) within one cell of `cell` in a periodic grid of `cells`, each once.
int neighbour_count(int cells) { return std::min(cells, 3); }
int neighbour(int cell, int k, int cells) { return cells >= 3 ? (cell + k - 1 + cells) % cells : k; }

bool overlaps_placed_disk(const SystemParams& p, const PlacementGrid& grid, const ParticleState& placed,
                          double x, double y, int column, int row) {
  const double contact = p.diameter * p.diameter * (1.0 + 1e-9);
  for (int ky = 0; ky < neighbour_count(grid.ny); ++ky) {
    for (int kx = 0; kx < neighbour_count(grid.nx); ++kx) {
      const std::size_t c = grid.cell_of(neighbour(column, kx, grid.nx), neighbour(row, ky, grid.ny));
      for (std::int32_t j = grid.head[c]; j >= 0; j = grid.next[static_cast<std::size_t>(j)]) {
        double rx = placed.x[static_cast<std::size_t>(j)] - x;
        double ry = placed.y[static_cast<std::size_t>(j)] - y;
        rx -= p.length_x * std::round(rx / p.length_x);  // nearest periodic image
        ry -= p.length_y * std::round(ry / p.length_y);
        if (rx * rx + ry * ry < contact) return true;
      }
    }
  }
  return false;
}

}  // namespace

bool place_randomly(const SystemParams& p, Random& rng, ParticleState& out) {
  PlacementGrid grid(p);
  const auto n = static_cast<std::size_t>(p.particles);
  const std::uint64_t max_attempts = 1000 * static_cast<std::uint64_t>(n) + 100000;
  std::uint64_t attempts = 0;
  for (std::size_t placed = 0; placed < n;) {
    if (++attempts > max_attempts) return false;
    const double x = rng.uniform() * p.length_x;
    const double y = rng.uniform() * p.length_y;
    const int column = std::min(grid.nx - 1, static_cast<int>(x / grid.cell_width));
    const int row = std::min(grid.ny - 1, static_cast<int>(y / grid.cell_height));
    if (overlaps_placed_disk(p, grid, out, x, y, column, row)) continue;
    out.x[placed] = x;
    out.y[placed] = y;
    const std::size_t c = grid.cell_of(column, row);
    grid.next[placed] = grid.head[c];
    grid.head[c] = static_cast<std::int32_t>(placed);
    ++placed;
  }
  return true;
}

bool place_on_lattice(const SystemParams& p, Random& rng, ParticleState& out) {
  const auto n = static_cast<std::int64_t>(p.particles);
  std::int64_t best_rows = 0;
  double best_distance = 0.0;
  for (std::int64_t rows = 2; rows <= 2 * n + 2; rows += 2) {
    const std::int64_t columns = (n + rows - 1) / rows;
    const double ax = p.length_x / static_cast<double>(columns);
    const double ay = p.length_y / static_cast<double>(rows);
    const double distance = std::min({ax, std::sqrt(0.25 * ax * ax + ay * ay), 2.0 * ay});
    if (distance > best_distance) {
      best_distance = distance;
      best_rows = rows;
    }
    if (ay < 0.5 * p.diameter) break;
  }
  if (best_distance < p.diameter * (1.0 + 1e-9)) return false;
  const std::int64_t rows = best_rows;
  const std::int64_t columns = (n + rows - 1) / rows;
  const double ax = p.length_x / static_cast<double>(columns);
  const double ay = p.length_y / static_cast<double>(rows);
  std::vector<std::int64_t> sites(static_cast<std::size_t>(rows * columns));
  std::iota(sites.begin(), sites.end(), 0);
  for (std::size_t k = 0; k < static_cast<std::size_t>(n); ++k) {  // partial Fisher–Yates
    const std::size_t pick = k + static_cast<std::size_t>(rng.below(sites.size() - k));
    std::swap(sites[k], sites[pick]);
    const std::int64_t row = sites[k] / columns;
    const std::int64_t column = sites[k] % columns;
    out.x[k] = (static_cast<double>(column) + 0.25 + 0.5 * static_cast<double>(row % 2)) * ax;
    out.y[k] = (static_cast<double>(row) + 0.5) * ay;
  }
  return true;
}

}  // namespace granule
