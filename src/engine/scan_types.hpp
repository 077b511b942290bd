// The plain data of a prediction's scan (engine/simulation_prediction.cpp and
// engine/simulation_neighbours.hpp): what a scan returns, which cells it visits, the candidate it
// starts from, and the block of cell heads and images it reads.  Simulation<D> names them as its
// own (Simulation<D>::Prediction, ...).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>

#include "events/event.hpp"

namespace granule::scan {

// The earliest event of a particle from the current state (kind, partner, delay), without
// storing it: Simulation::predict() stores it, check_invariants() compares with it.  Both parts
// are kept: after a change of U only the crossing needs recomputing.
struct Crossing {
  EventKind kind;  // kNone when the particle never leaves its cell
  double delay;
};
struct Prediction {
  Crossing crossing;
  std::int32_t partner;    // the earliest collision found (−1: none)
  double collision_delay;  // +inf when none
  EventKind kind() const { return collision_delay < crossing.delay ? EventKind::kCollision : crossing.kind; }
  double delay() const { return std::min(collision_delay, crossing.delay); }
};
// The cell offsets (each −1..1 per axis) around a particle's cell that a scan visits: the whole
// 3^D block, or, after a crossing, only the layer of cells that has just become adjacent.
template <int D>
struct Reach {
  std::array<int, D> lowest;
  std::array<int, D> highest;
  static Reach block() {
    Reach reach;
    reach.lowest.fill(-1);
    reach.highest.fill(1);
    return reach;
  }
  static Reach layer_ahead(int axis, int direction) {
    Reach reach = block();
    reach.lowest[static_cast<std::size_t>(axis)] = reach.highest[static_cast<std::size_t>(axis)] = direction;
    return reach;
  }
};
// The best collision known before a scan: a kept candidate (partner −1: none).
struct Candidate {
  std::int32_t partner = -1;
  double delay = std::numeric_limits<double>::infinity();
};
// The cells within reach of a cell: the first particle of each non-empty list, in visiting order,
// with the cell's place in that order; and, when the block is `imaged` (some of it lies across a
// face of the grid), the image each cell is seen at, by place.  The lists are compacted as the
// heads are read, without a branch (about half the cells are empty, at random).
template <int D>
inline constexpr int kStencil = D == 3 ? 27 : 9;
template <int D>
struct CellImage {
  std::array<double, D> position;  // where the cell's particles are seen, relative to their own place
  double velocity_x;               // and how fast that image moves along x
};
// (No member initialisers: a scan writes only what it uses; zeroing 27 images cost 2 % of a run.)
template <int D>
struct BlockCells {
  std::array<std::int32_t, kStencil<D>> head;     // of the non-empty lists
  std::array<std::uint8_t, kStencil<D>> place;    // of their cells in visiting order
  std::array<CellImage<D>, kStencil<D>> image;    // by place
  int count;  // non-empty lists
  bool imaged;  // otherwise every image is the cell itself and not written
};

}  // namespace granule::scan
