// The simulation's cell grid on the sheared frame (ξ, y[, z]) and its per-cell particle lists
// (thesis Appendix A.1: collisions are searched in the 3×3 block of cells around a particle, the
// 3×3×3 block in 3D).  A particle's cell id has 28 bits (it shares a word with the event kind,
// events/event_slot.hpp; the configuration refuses grids of more than 2²⁸ cells), and grid
// arithmetic is 64-bit.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "memory/huge_page_allocator.hpp"
#include "memory/prefetch_lines.hpp"

#include "archive/state_archive.hpp"

namespace granule {

struct CellGrid {
  int nx = 0;           // columns in ξ
  int ny = 0;           // rows in y
  double width = 0.0;   // column width in ξ (length units)
  double height = 0.0;  // row height
  // Lees–Edwards: the grid is re-aligned whenever |strain| reaches strain_period/2; the period
  // is a multiple of L_x/L_y so that the sheared frame stays exactly periodic (shear_frame.hpp).
  double strain_period = 0.0;
  int nz = 1;           // layers in z (1 in 2D)
  double depth = 0.0;   // layer depth (3D)

  std::int64_t cell_count() const { return static_cast<std::int64_t>(nx) * ny * nz; }
  std::int32_t index(int column, int row, int layer = 0) const {
    return static_cast<std::int32_t>((static_cast<std::int64_t>(layer) * ny + row) * nx + column);
  }
  int count(int axis) const { return axis == 0 ? nx : (axis == 1 ? ny : nz); }
  double size(int axis) const { return axis == 0 ? width : (axis == 1 ? height : depth); }
};

// The default target occupancy of the engine's cells, 0.6 for disks and spheres (thesis A.2 found
// 1–2 optimal for disks with a whole 3×3 scan at every crossing; scanning only the layer ahead
// makes crossings cheap, and smaller cells pay): measured with granule bench at N = 10⁵ disks
// (alternating runs), 0.6 instead of 1 ran level at ν = 0.05 and 1.14× faster at ν = 0.5 (cells
// then as small as allowed, σ); at N = 108000 spheres, 0.5 instead of 1 ran 1.2–1.3× faster at
// φ = 0.05 and 0.30.  A cell head costs 4 B / occupancy per particle.
constexpr double kDefaultParticlesPerCell = 0.6;

struct CellGridRequest {
  double length_x = 1.0;
  double length_y = 1.0;
  double diameter = 0.0;
  std::int64_t particles = 0;
  bool sheared = false;
  double particles_per_cell = 1.0;           // target mean occupancy (thesis A.2: 1–2 is optimal)
  std::optional<std::pair<int, int>> forced;  // user override [nx, ny] (2D)
  int dimension = 2;
  double length_z = 1.0;
  // The most cells an automatic grid may have (an elongated box, whose short sides keep the
  // minimum of 3 cells, gets wider cells along its long sides instead).
  std::int64_t max_cells = std::numeric_limits<std::int64_t>::max();
};

// The grid for a box, or an explanation of why none fits (fewer than 3 cells per direction,
// or a forced grid with cells narrower than a disk can reach).  Contact pairs must always lie in
// neighbouring cells: rows (and layers) at least σ high, columns at least σ√(1 + s_max²) wide in
// ξ, with σ the largest diameter.
struct CellGridChoice {
  std::optional<CellGrid> grid;
  std::string error;
};
CellGridChoice choose_cell_grid(const CellGridRequest& request);

// Singly linked particle lists per cell: a head per cell here, and the link of each particle in
// its record (`records[i].next`, engine/particle_record.hpp), so that walking a list reads the
// records a collision test needs anyway.  Plain ids.
class CellLists {
 public:
  static constexpr std::int32_t kEnd = -1;

  void reset(std::int64_t cells) { head_.assign(static_cast<std::size_t>(cells), kEnd); }
  template <typename Records>
  void insert(Records& records, std::int32_t particle, std::int32_t cell) {
    auto& head = head_[static_cast<std::size_t>(cell)];
    records[static_cast<std::size_t>(particle)].next = head;
    head = particle;
  }
  template <typename Records>
  void remove(Records& records, std::int32_t particle, std::int32_t cell) {
    // Cells hold about one particle (thesis A.2), so a walk beats a back-link.
    std::int32_t* link = &head_[static_cast<std::size_t>(cell)];
    while (*link != particle) link = &records[static_cast<std::size_t>(*link)].next;
    *link = records[static_cast<std::size_t>(particle)].next;
  }
  std::int32_t first(std::int32_t cell) const { return head_[static_cast<std::size_t>(cell)]; }
  // A hint: start fetching the heads of cells first .. first + count - 1, clipped to the grid
  // (forced inline: GCC drops the call of a function that only prefetches).
  [[gnu::always_inline]] void prefetch_heads(std::int64_t first, std::int64_t count) const {
    const std::int64_t last = static_cast<std::int64_t>(head_.size()) - 1;
    __builtin_prefetch(head_.data() + std::clamp<std::int64_t>(first, 0, last));
    __builtin_prefetch(head_.data() + std::clamp<std::int64_t>(first + count - 1, 0, last));
  }
  // A hint: start fetching the first record of each of cells first .. first + count − 1, clipped to
  // the grid.  Their heads are read (and waited for, if they are not cached).
  template <typename Records>
  [[gnu::always_inline]] void prefetch_first_records(const Records& records, std::int64_t first, std::int64_t count) const {
    const std::int64_t last = static_cast<std::int64_t>(head_.size()) - 1;
    for (std::int64_t cell = first; cell < first + count; ++cell) {
      const std::int32_t head = head_[static_cast<std::size_t>(std::clamp<std::int64_t>(cell, 0, last))];
      prefetch_lines(records.data() + std::max(head, std::int32_t{0}));
    }
  }
  std::size_t bytes() const { return head_.capacity() * sizeof(std::int32_t); }
  // The order within each list decides the order of candidate partners, hence ties: a
  // checkpoint keeps it exactly (the links with the records, the heads here).
  void save(StateArchive& archive, const std::string& prefix) const;
  // Restores the heads and checks them and the records' links against the grid and N.
  template <typename Records>
  void restore(const StateArchive& archive, const std::string& prefix, std::int64_t cells, const Records& records) {
    std::vector<std::int32_t> links(records.size());
    for (std::size_t i = 0; i < links.size(); ++i) links[i] = records[i].next;
    restore(archive, prefix, cells, links);
  }

 private:
  void restore(const StateArchive& archive, const std::string& prefix, std::int64_t cells, const std::vector<std::int32_t>& links);

  HugePageVector<std::int32_t> head_;
};

}  // namespace granule
