// The fixed obstacles a grain can touch from each cell of the engine's grid (boundary/obstacle.hpp):
// an obstacle is listed in every cell whose box comes within its radius plus the largest grain
// radius of its centre, once per periodic image that does (an obstacle near a periodic face is
// touched across it).  A grain's prediction searches the obstacles of its own cell only, up to its
// crossing out of it (BoxBoundaries::earliest_surface_hit): a hit after that is found from the next
// cell, where the obstacle is listed again if the grain can touch it from there.  So the lists
// change nothing at a crossing and nothing at a renumbering, and hold no per-particle state.
// Grids that follow a Lees–Edwards flow are not supported: the obstacle would move through them
// (the configuration refuses the combination).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "boundary/obstacle.hpp"
#include "geometry/vec.hpp"

namespace granule {

// The engine's cells as the lists see them: counts and sizes per axis (x, y, z; one layer in 2D),
// cell id (layer · n_y + row) · n_x + column (cells/cell_grid.hpp).
struct CellLayout {
  std::array<int, 3> count{1, 1, 1};
  std::array<double, 3> size{1.0, 1.0, 1.0};
  std::int64_t cells() const { return static_cast<std::int64_t>(count[0]) * count[1] * count[2]; }
  std::int32_t index(int column, int row, int layer) const {
    return static_cast<std::int32_t>((static_cast<std::int64_t>(layer) * count[1] + row) * count[0] + column);
  }
};

// Calls visit(cell) for every cell of `grid` whose box lies within `reach` of `centre` (cells
// outside the grid are skipped: periodic images are the caller's).
template <int D, typename Visit>
void for_each_cell_within(const Vec<D>& centre, double reach, const CellLayout& grid, Visit&& visit) {
  std::array<int, 3> low{};
  std::array<int, 3> high{};
  for (int a = 0; a < D; ++a) {
    const double size = grid.size[static_cast<std::size_t>(a)];
    const double from = std::floor((centre[a] - reach) / size);
    const double to = std::floor((centre[a] + reach) / size);
    if (to < 0.0 || from > grid.count[static_cast<std::size_t>(a)] - 1) return;
    low[static_cast<std::size_t>(a)] = static_cast<int>(std::max(from, 0.0));
    high[static_cast<std::size_t>(a)] = static_cast<int>(std::min(to, static_cast<double>(grid.count[static_cast<std::size_t>(a)] - 1)));
  }
  std::array<int, 3> c{};
  for (c[2] = low[2]; c[2] <= high[2]; ++c[2]) {
    for (c[1] = low[1]; c[1] <= high[1]; ++c[1]) {
      for (c[0] = low[0]; c[0] <= high[0]; ++c[0]) {
        double distance_sq = 0.0;  // from the centre to the cell's box
        for (int a = 0; a < D; ++a) {
          const double lower = c[static_cast<std::size_t>(a)] * grid.size[static_cast<std::size_t>(a)];
          const double upper = lower + grid.size[static_cast<std::size_t>(a)];
          const double outside = std::max({lower - centre[a], 0.0, centre[a] - upper});
          distance_sq += outside * outside;
        }
        // A margin of 10⁻⁹ of the reach: a cell at the edge of the reach by round-off is listed.
        if (distance_sq <= reach * reach * (1.0 + 1e-9)) visit(grid.index(c[0], c[1], c[2]));
      }
    }
  }
}

// Calls visit(image) for a point and each of its periodic images one period away along the axes
// with `images` (box `lengths`): what a surface near a periodic face is touched through.
template <int D, typename Visit>
void for_each_periodic_image(const Vec<D>& point, const std::array<bool, 3>& images, const std::array<double, 3>& lengths,
                             Visit&& visit) {
  std::array<int, 3> shifts{};
  for (std::size_t a = 0; a < static_cast<std::size_t>(D); ++a) shifts[a] = images[a] ? 1 : 0;
  std::array<int, 3> shift{};
  for (shift[2] = -shifts[2]; shift[2] <= shifts[2]; ++shift[2]) {
    for (shift[1] = -shifts[1]; shift[1] <= shifts[1]; ++shift[1]) {
      for (shift[0] = -shifts[0]; shift[0] <= shifts[0]; ++shift[0]) {
        Vec<D> image = point;
        for (std::size_t a = 0; a < static_cast<std::size_t>(D); ++a) image[static_cast<int>(a)] += shift[a] * lengths[a];
        visit(image);
      }
    }
  }
}

// A fixed sphere as the grains of a cell see it (an obstacle, a grain at rest): which one, and where
// its centre (or the image of it they touch) lies in box coordinates.
template <int D>
struct RoundSurface {
  std::int32_t index = 0;
  Vec<D> centre;
  double radius = 0.0;
};

// How close a grain must come to a round surface to count as touching (the search's stopping gap):
// round-off of a coordinate of the box.
inline double round_surface_tolerance(const std::array<double, 3>& lengths, int dimension) {
  double largest_length = 0.0;
  for (int a = 0; a < dimension; ++a) largest_length = std::max(largest_length, lengths[static_cast<std::size_t>(a)]);
  return 1e-12 * largest_length;
}

template <int D>
class ObstacleLists {
 public:
  using Entry = RoundSurface<D>;

  ObstacleLists() = default;
  // `images[a]`: whether axis a is periodic (else walled); `lengths`: the box.
  ObstacleLists(const std::vector<Obstacle>& obstacles, const CellLayout& grid, const std::array<bool, 3>& images,
                const std::array<double, 3>& lengths, double largest_grain_radius) {
    if (obstacles.empty()) return;
    // Two passes over the listings, counting then filling, so the lists take their own size only.
    first_.assign(static_cast<std::size_t>(grid.cells()) + 1, 0);
    for_each_listing(obstacles, grid, images, lengths, largest_grain_radius,
                     [&](std::int32_t cell, const Entry&) { ++first_[static_cast<std::size_t>(cell) + 1]; });
    for (std::size_t c = 1; c < first_.size(); ++c) first_[c] += first_[c - 1];
    entries_.resize(first_.back());
    std::vector<std::uint32_t> filled(first_.begin(), first_.end() - 1);
    for_each_listing(obstacles, grid, images, lengths, largest_grain_radius,
                     [&](std::int32_t cell, const Entry& entry) { entries_[filled[static_cast<std::size_t>(cell)]++] = entry; });
    tolerance_ = round_surface_tolerance(lengths, D);
  }

  bool empty() const { return entries_.empty(); }
  std::span<const Entry> in_cell(std::int32_t cell) const {
    if (first_.empty()) return {};
    const auto c = static_cast<std::size_t>(cell);
    return {entries_.data() + first_[c], entries_.data() + first_[c + 1]};
  }
  // How close a grain must come to count as touching (the search's stopping gap).
  double tolerance() const { return tolerance_; }
  std::size_t bytes() const { return first_.capacity() * sizeof(std::uint32_t) + entries_.capacity() * sizeof(Entry); }

 private:
  // Calls visit(cell, entry) for every cell that lists an obstacle or one of its periodic images:
  // each cell whose box lies within the obstacle's radius plus `largest_grain_radius` of the centre.
  template <typename Visit>
  static void for_each_listing(const std::vector<Obstacle>& obstacles, const CellLayout& grid, const std::array<bool, 3>& images,
                               const std::array<double, 3>& lengths, double largest_grain_radius, Visit&& visit) {
    for (std::size_t k = 0; k < obstacles.size(); ++k) {
      const Obstacle& o = obstacles[k];
      const double reach = 0.5 * o.diameter + largest_grain_radius;
      Vec<D> centre;
      for (int a = 0; a < D; ++a) centre[a] = o.centre[static_cast<std::size_t>(a)];
      for_each_periodic_image<D>(centre, images, lengths, [&](const Vec<D>& image) {
        const Entry entry{static_cast<std::int32_t>(k), image, 0.5 * o.diameter};
        for_each_cell_within<D>(image, reach, grid, [&](std::int32_t cell) { visit(cell, entry); });
      });
    }
  }

  std::vector<std::uint32_t> first_;  // entries of cell c: first_[c] .. first_[c + 1] − 1
  std::vector<Entry> entries_;
  double tolerance_ = 0.0;
};

}  // namespace granule
