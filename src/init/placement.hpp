// Non-overlapping initial positions of N disks (d = 2) or spheres (d = 3) in a periodic box
// (thesis §1.4.2: uniformly distributed): random sequential addition, or a lattice with random
// vacancies for dense systems (triangular in 2D, face-centred cubic in 3D).  Along a wall axis
// (params.walls) every centre stays at least its own radius from each wall, and no periodic image
// is seen across the walls; no centre is closer to an obstacle than contact (boundary/obstacle.hpp:
// random trials inside one are rejected, lattice sites inside one are not used).  Per-particle
// diameters (polydisperse systems) come in out.diameter; otherwise every σ = params.diameter,
// which is always the largest diameter.  Scratch memory is O(N) at any packing fraction.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "engine/system_params.hpp"
#include "init/random.hpp"

namespace granule {

// The overlap-test grid of random sequential addition: cells of side ≥ σ_max (so a new particle
// can only overlap particles of its own and the 3^d − 1 neighbouring cells) and ≥ (V/N)^(1/d) (so
// there are at most N cells, about one particle each when full): one int32 per cell and one per
// particle, whatever the packing fraction.  Each cell is a singly linked list of the particles
// placed in it.
struct PlacementGrid {
  int dimension = 2;
  std::array<int, 3> count{1, 1, 1};        // cells along x, y, z (1 along z in 2D)
  std::array<double, 3> width{1.0, 1.0, 1.0};
  std::vector<std::int32_t> head;  // first particle of each cell, −1 if empty
  std::vector<std::int32_t> next;  // next particle of the same cell, −1 at the end

  explicit PlacementGrid(const SystemParams& params);
  std::size_t cell_of(const std::array<int, 3>& cell) const {
    return static_cast<std::size_t>(cell[0]) +
           static_cast<std::size_t>(count[0]) *
               (static_cast<std::size_t>(cell[1]) + static_cast<std::size_t>(count[1]) * static_cast<std::size_t>(cell[2]));
  }
};

// Random sequential addition in the order of the particles (largest first when the diameters are
// sorted): uniform trial positions, each rejected if it overlaps a particle already placed, until
// N are placed.  False if 1000 N + 10⁵ trials were not enough (jamming: ν ≳ 0.5 in 2D, φ ≳ 0.35 in
// 3D).  Writes the positions of out (which must hold N entries).
bool place_randomly(const SystemParams& params, Random& rng, ParticleState& out);

// The lattice of at least N sites whose nearest-neighbour distance (`spacing`) is the largest
// this box allows: in 2D a triangular lattice of `cells[0]` columns and an even number `cells[1]`
// of rows (so it is periodic); in 3D an FCC lattice of cells[0] × cells[1] × cells[2] cubic cells
// of 4 sites (stretched to the box: any counts are periodic).  It depends on N and the box only.
struct Lattice {
  int dimension = 2;
  std::array<std::int64_t, 3> cells{1, 1, 1};
  double spacing = 0.0;
  std::int64_t sites() const { return cells[0] * cells[1] * cells[2] * (dimension == 3 ? 4 : 1); }
};
Lattice densest_lattice(const SystemParams& params);

// N of the sites of densest_lattice, chosen at random.  False if its spacing is below the
// (largest) diameter.  With walls the lattice is the densest one of the centres' region (each
// side along a wall axis shortened by the largest diameter), a radius in from the walls.
bool place_on_lattice(const SystemParams& params, Random& rng, ParticleState& out);

}  // namespace granule
