// One record per particle with what a neighbour's collision test reads: position and velocity,
// and the link of its cell list; with its collision counter.  A test then touches one record, 48
// bytes for disks and 64 (one cache line, aligned to it) for spheres, rather than six separate
// arrays (docs/performance.md).  The record also holds the particle's collision candidate (partner
// and the partner's counter), read at its own events: in a sphere's record those 8 bytes fill what
// alignment would leave empty, and out of the EventSlot they leave it 16 bytes (its pending
// event's time, kind and cell, and the calendar's link; events/event_slot.hpp).
//
// The record holds the particle's state extrapolated back to the engine's clock base (t = 0 of
// `t_now_`) along its present flight — a "false position" — so the position now is r + v·t_now
// (+ g·t_now²/2 in a field: motion/motion.hpp), and no local time is stored: a flight's state is
// written only when its velocity changes.  The clock is re-based every few events per particle
// (engine/simulation.cpp), which keeps |v·t_now| to a few free paths and the round-off of
// r + v·t_now at that of a position.
#pragma once

#include <cstdint>

#include "geometry/vec.hpp"

namespace granule {

// A sphere's record is aligned to its cache line: the allocator aligns to 16 bytes only, and a
// record at an offset of 16 straddled two lines, so every neighbour test missed twice.
template <int D>
struct alignas(D == 3 ? 64 : 8) ParticleRecord {
  Vec<D> r;                 // position at the clock base, on the present flight
  Vec<D> v;                 // velocity at the clock base (the velocity now, without gravity)
  std::int32_t next = -1;   // the next particle in the same cell (CellLists), −1 at the end
  std::uint32_t count = 0;  // collisions so far: invalidates predictions that involve this particle
  // The collision candidate, pending or not, kept through crossings while it is valid (the
  // partner's count unchanged); its time is computed again when needed, not stored
  // (Simulation::candidate).
  std::int32_t partner = -1;        // −1: none; kAtRest: the grain is at rest (r its position, v 0)
  std::uint32_t partner_count = 0;  // the partner's count when predicted
};

// The partner of a grain at rest (physics/rest_rule.hpp): it has no flight and no event; its record
// holds its position itself and a zero velocity, which the motion does not move.
inline constexpr std::int32_t kAtRest = -2;

static_assert(sizeof(ParticleRecord<2>) == 48 && sizeof(ParticleRecord<3>) == 64);

}  // namespace granule
