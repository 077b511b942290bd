// Inline members of Simulation<D> on the hot path of prediction: the prefetches one event ahead and
// the scan of the cells within reach of a particle, with the images the boundaries put beyond the
// faces of the grid (boundary/box_boundaries.hpp).  Included by engine/simulation.hpp only.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

#include "engine/simulation.hpp"
#include "memory/prefetch_lines.hpp"

namespace granule {

// Forced inline: GCC 12 finds a function that only prefetches pure, and drops its call.
template <int D>
[[gnu::always_inline]] inline void Simulation<D>::prefetch_next_event() const {
  const std::int32_t walked = queue_.prefetch_ahead();
  const bool records = prefetches_records();
  const std::int64_t rows = grid_.nx;
  const std::int64_t layers = rows * grid_.ny;
  // An event of the next bucket: its record and block heads, a bucket ahead, so that they are
  // cached when it becomes the hint below and its heads are read.
  if (records && walked >= 0 && queue_.in_next_bucket(walked)) {
    prefetch_lines(particles_.data() + walked);
    const std::int64_t cell = slot(walked).cell();
    for (std::int64_t dr = -1; dr <= 1; ++dr) lists_.prefetch_heads(cell + dr * rows - 1, 3);
  }
  std::int32_t k = queue_.runner_up();
  // Only where the records are fetched ahead: where everything is cached, the walk only costs.
  if (k < 0 && records) k = queue_.earliest_walked();
  if (k < 0) return;
  const EventSlot& next = slot(k);
  prefetch_lines(particles_.data() + k, records);  // its partner, in the record, is fetched when it runs
  const std::int64_t cell = next.cell();
  // Few disks, very many, or spheres: the heads of the block around its cell.  The records stay in
  // cache below about 6·10⁴ disks, where reading the heads now only costs (1–3 % at 3·10⁴ and
  // 5·10⁴); heads out of the cache (10⁷ disks) would stall the current event when read; with 27 heads to
  // read, spheres gained nothing measurable at 1.08·10⁵ and 5·10⁵.
  if (!records) {
    for (std::int64_t dl = D == 3 ? -1 : 0; dl <= (D == 3 ? 1 : 0); ++dl) {
      for (std::int64_t dr = -1; dr <= 1; ++dr) lists_.prefetch_heads(cell + dl * layers + dr * rows - 1, 3);
    }
    return;
  }
  // Otherwise the first record of each cell its scan will read, one event ahead (the scan's
  // first loads from a record were 45 % of its time at 10⁶), the heads read now (they are mostly
  // in cache: 4 bytes a cell where a record is 48).  A crossing (most events in a dilute gas)
  // changes the lists of the cell it leaves and the one it enters and scans the layer beyond the
  // latter (predict_after_crossing), outside the block.  Across a face of the grid the indices are
  // wrong (clipped or another cell's): a wasted hint, never a wrong result.
  std::array<std::int64_t, 3> low{-1, -1, D == 3 ? -1 : 0};
  std::array<std::int64_t, 3> high{1, 1, D == 3 ? 1 : 0};
  if (is_crossing(next.kind())) {
    const auto axis = static_cast<std::size_t>(crossing_axis(next.kind()));
    const std::int64_t direction = crossing_direction(next.kind());
    lists_.prefetch_first_records(particles_, cell, 1);
    lists_.prefetch_heads(cell + direction * std::array<std::int64_t, 3>{1, rows, layers}[axis], 1);
    low[axis] = high[axis] = 2 * direction;
  }
  for (std::int64_t dl = low[2]; dl <= high[2]; ++dl) {
    for (std::int64_t dr = low[1]; dr <= high[1]; ++dr) {
      lists_.prefetch_first_records(particles_, cell + dl * layers + dr * rows + low[0], high[0] - low[0] + 1);
    }
  }
}

template <int D>
inline void Simulation<D>::block_cells(const std::array<int, D>& cell, const Reach& reach, BlockCells& block) const {
  const double s = strain();
  // Visiting order: layers (z, 3D only) outermost, then rows (y), then columns (x).  The order
  // decides which of two partners at equal times is taken, so it is the 2D engine's order.
  // The head of every cell is read, and its first record prefetched, before any list is followed:
  // the lists are chains through the records, and read one after the other their cache misses
  // would not overlap (without a branch, which an empty cell would mispredict).
  const bool every_line = prefetches_records();  // both lines of a record out of the cache
  int visited = 0;  // cells so far: the place of the next one in visiting order
  const auto visit = [&](std::int32_t cell_index) {
    const std::int32_t head = lists_.first(cell_index);
    prefetch_lines(particles_.data() + std::max(head, std::int32_t{0}), every_line);
    // Written at the next free entry, which the next non-empty list overwrites if this one is empty.
    block.head[static_cast<std::size_t>(block.count)] = head;
    block.place[static_cast<std::size_t>(block.count)] = static_cast<std::uint8_t>(visited++);
    block.count += head != CellLists::kEnd ? 1 : 0;
  };
  const int lowest_layer = D == 3 ? reach.lowest[D - 1] : 0;
  const int highest_layer = D == 3 ? reach.highest[D - 1] : 0;
  block.count = 0;
  // A cell away from every face of the grid (nine in ten at N = 10⁵) sees no image: its block is
  // a fixed pattern of indices around its own, and every shift is zero.
  block.imaged = !is_interior(cell);
  if (!block.imaged) {
    const std::int32_t own = grid_.index(cell[0], cell[1], D == 3 ? cell[D - 1] : 0);
    for (int dl = lowest_layer; dl <= highest_layer; ++dl) {
      for (int dr = reach.lowest[1]; dr <= reach.highest[1]; ++dr) {
        const std::int32_t row = own + (dl * grid_.ny + dr) * grid_.nx;
        for (int dc = reach.lowest[0]; dc <= reach.highest[0]; ++dc) visit(row + dc);
      }
    }
    return;
  }
  for (int dl = lowest_layer; dl <= highest_layer; ++dl) {
    int layer = 0;
    double shift_z = 0.0;
    if constexpr (D == 3) {
      layer = cell[2] + dl;
      if (layer < 0 || layer >= grid_.nz) {
        if (!boundaries_.has_images(2)) continue;
        const int direction = layer < 0 ? -1 : 1;
        layer -= direction * grid_.nz;
        shift_z = boundaries_.image_across(2, direction, s).position[2];
      }
    }
    for (int dr = reach.lowest[1]; dr <= reach.highest[1]; ++dr) {
      int r = cell[1] + dr;
      int iy = 0;
      if ((r < 0 || r >= grid_.ny) && !boundaries_.has_images(1)) continue;
      if (r < 0) {
        r += grid_.ny;
        iy = -1;
      } else if (r >= grid_.ny) {
        r -= grid_.ny;
        iy = 1;
      }
      const auto row_shift = boundaries_.image_across(1, iy, s);
      for (int dc = reach.lowest[0]; dc <= reach.highest[0]; ++dc) {
        int c = cell[0] + dc;
        Vector shift;
        shift[0] = row_shift.position[0];
        shift[1] = row_shift.position[1];
        if constexpr (D == 3) shift[2] = shift_z;
        if (c < 0 || c >= grid_.nx) {
          if (!boundaries_.has_images(0)) continue;
          const int direction = c < 0 ? -1 : 1;
          c -= direction * grid_.nx;
          shift[0] += boundaries_.image_across(0, direction, s).position[0];
        }
        CellImage& image = block.image[static_cast<std::size_t>(visited)];
        for (int a = 0; a < D; ++a) image.position[static_cast<std::size_t>(a)] = shift[a];
        image.velocity_x = row_shift.velocity_x;
        visit(grid_.index(c, r, layer));
      }
    }
  }
}

template <int D>
template <typename Visit>
void Simulation<D>::for_each_neighbour(std::int32_t i, const std::array<int, D>& cell, const Reach& reach,
                                       Visit&& visit) const {
  BlockCells block;
  block_cells(cell, reach, block);
  for (int k = 0; k < block.count; ++k) {
    const auto at = static_cast<std::size_t>(k);
    const std::size_t place = block.place[at];
    Vector shift{};
    if (block.imaged) {
      for (int a = 0; a < D; ++a) shift[a] = block.image[place].position[static_cast<std::size_t>(a)];
    }
    const double shift_vx = block.imaged ? block.image[place].velocity_x : 0.0;
    for (std::int32_t j = block.head[at]; j != CellLists::kEnd; j = particles_[static_cast<std::size_t>(j)].next) {
      if (j != i) visit(j, shift, shift_vx);
    }
  }
}

template <int D>
inline bool Simulation<D>::is_interior(const std::array<int, D>& cell) const {
  bool interior = true;
  for (int a = 0; a < D; ++a) interior = interior && cell[a] >= 1 && cell[a] <= grid_.count(a) - 2;
  return interior;
}

}  // namespace granule
