// Non-overlapping initial positions of N disks of diameter σ in a periodic L_x × L_y box
// (thesis §1.4.2: uniformly distributed): random sequential addition, or a triangular lattice
// with random vacancies for dense systems.  Scratch memory is O(N) at any area fraction.
#pragma once

#include <cstdint>
#include <vector>

#include "engine/system_params.hpp"
#include "init/random.hpp"

namespace granule {

// The overlap-test grid of random sequential addition: cells of side ≥ σ (so a new disk can only
// overlap disks of its own and the 8 neighbouring cells) and ≥ √(L_x L_y / N) (so there are at
// most N cells, about one disk each when full): memory is O(N) whatever the area fraction.
// Each cell is a singly linked list of the disks placed in it (head per cell, next per disk).
struct PlacementGrid {
  int nx = 1;
  int ny = 1;
  double cell_width = 1.0;
  double cell_height = 1.0;
  std::vector<std::int32_t> head;  // first disk of each cell, −1 if empty
  std::vector<std::int32_t> next;  // next disk of the same cell, −1 at the end

  PlacementGrid(const SystemParams& params);
  std::size_t cell_of(int column, int row) const {
    return static_cast<std::size_t>(column) + static_cast<std::size_t>(row) * static_cast<std::size_t>(nx);
  }
};

// Random sequential addition: uniform trial positions, each rejected if it overlaps a disk
// already placed, until N are placed.  False if 1000 N + 10⁵ trials were not enough (jamming,
// ν ≳ 0.5).  Writes out.x, out.y (out must hold N entries).
bool place_randomly(const SystemParams& params, Random& rng, ParticleState& out);

// Triangular lattice with an even number of rows (so it is periodic), the row count chosen to
// maximise the nearest-neighbour distance; N of its sites are occupied at random.  False if no
// such lattice keeps the disks apart.
bool place_on_lattice(const SystemParams& params, Random& rng, ParticleState& out);

}  // namespace granule
