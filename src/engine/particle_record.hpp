// One record per particle with what a neighbour's collision test reads: position and velocity at
// the particle's local time t, and the link of its cell list; with its collision counter.  A test
// then touches one record, 48 bytes for disks and 64 (one cache line, aligned to it) for spheres, where it read
// six separate arrays before (issue 18; docs/performance.md).  The rest of a particle's data
// (its pending event, cell, candidate time) is read only when its own event runs and stays in
// its EventSlot (events/event_slot.hpp).
#pragma once

#include <cstdint>

#include "geometry/vec.hpp"

namespace granule {

// A sphere's record is aligned to its cache line: the allocator aligns to 16 bytes only, and a
// record at an offset of 16 straddled two lines, so every neighbour test missed twice.
template <int D>
struct alignas(D == 3 ? 64 : 16) ParticleRecord {
  Vec<D> r;                 // position at local time t
  Vec<D> v;                 // velocity at local time t
  double t = 0.0;           // local time (relative to the engine's clock base)
  std::int32_t next = -1;   // the next particle in the same cell (CellLists), −1 at the end
  std::uint32_t count = 0;  // collisions so far: invalidates predictions that involve this particle
};

static_assert(sizeof(ParticleRecord<2>) == 48 && sizeof(ParticleRecord<3>) == 64);

}  // namespace granule
