// Prediction: the next event of a particle — the first cell face or wall it reaches and the
// earliest collision in the cells it scans — and storing it as the particle's one pending event
// (ARCHITECTURE.md, "One event per particle": the layer scan after a crossing).
#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/simulation.hpp"
#include "physics/collision_batch.hpp"
#include "physics/collision_time.hpp"
#include "physics/crossing_time.hpp"

namespace granule {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
inline std::size_t at(std::int32_t i) { return static_cast<std::size_t>(i); }
}  // namespace

template <int D>
typename Simulation<D>::Crossing Simulation<D>::next_crossing(std::int32_t i, const std::array<int, D>& cell,
                                                              const Vector& r, const Vector& v) const {
  return motion_.visit([&](const auto& flight) { return next_crossing(flight, i, cell, r, v); });
}

template <int D>
template <typename Flight>
typename Simulation<D>::Crossing Simulation<D>::next_crossing(const Flight& flight, std::int32_t i,
                                                              const std::array<int, D>& cell, const Vector& r,
                                                              const Vector& v) const {
  const double vyi = v[1];

  // In the sheared frame ξ(τ) = ξ0 + bτ + aτ² (shear_frame.hpp); periodic boxes have a = 0 and
  // b = v_x (plus ½g_x in a field, which Lees–Edwards allows only with g_y = 0).
  const double s = strain();
  const double y_rel = r[1] - 0.5 * params_.length_y;
  const double xi0 = r[0] - s * y_rel;
  const double a = -shear_rate_ * vyi + flight.half_acceleration(0);
  const double b = v[0] - shear_rate_ * y_rel - s * vyi;
  const double left = cell[0] * grid_.width;
  const double right = left + grid_.width;
  // The outer face of a cell at the edge of the grid is crossed only into an image; at a wall the
  // wall is hit first (below).
  const bool images_x = boundaries_.has_images(0);
  double best = !images_x && cell[0] == grid_.nx - 1 ? kInf : first_exit_time(a, b, xi0 - right);
  EventKind kind = crossing_through(0, 1);
  if (const double t = !images_x && cell[0] == 0 ? kInf : first_exit_time(-a, -b, left - xi0); t < best) {
    best = t;
    kind = crossing_through(0, 0);
  }
  // The other axes are not sheared: flights between planes.
  for (int axis = 1; axis < D; ++axis) {
    const double size = grid_.size(axis);
    const bool images = boundaries_.has_images(axis);
    const SlabExit exit = flight.exit_from_slab(axis, r[axis], v[axis], cell[axis] * size, (cell[axis] + 1) * size,
                                                images || cell[axis] > 0, images || cell[axis] < grid_.count(axis) - 1);
    if (exit.delay < best) {
      best = exit.delay;
      kind = crossing_through(axis, exit.direction > 0 ? 1 : 0);
    }
  }
  int surface = -1;
  boundaries_.earliest_surface_hit(flight, slot(i).cell(), r, v, [&] { return radius_of(i); }, time(), best, surface);
  if (surface >= 0) kind = surface_hit(surface);
  if (best == kInf) kind = EventKind::kNone;
  return {kind, best};
}

template <int D>
typename Simulation<D>::Prediction Simulation<D>::next_event(std::int32_t i, const Reach& reach, Candidate known) const {
  return motion_.visit([&](const auto& flight) { return next_event_in(flight, i, reach, known); });
}

template <int D>
template <typename Flight>
typename Simulation<D>::Prediction Simulation<D>::next_event_in(const Flight& flight, std::int32_t i,
                                                                const Reach& reach, Candidate known) const {
  const double now = t_now_;  // every position is its false position moved to now
  const ParticleRecord<D>& pi = particles_[at(i)];
  Vector ri;
  Vector vi;
  for (int a = 0; a < D; ++a) {
    ri[a] = flight.coordinate_at(a, pi.r[a], pi.v[a], now);
    vi[a] = flight.velocity_at(a, pi.v[a], now);
  }
  const std::array<int, D> cell = cell_coordinates(slot(i).cell());
  const Crossing crossing = next_crossing(flight, i, cell, ri, vi);

  // Collisions with the particles of the cells within reach, tested in batches (CollisionBatch).
  // In a uniform field the relative motion of two grains is still a straight line: only their
  // present states need it.
  std::int32_t partner = known.partner;
  double best = known.delay;
  const bool polydisperse = !diameter_.empty();
  const double sigma = params_.diameter;
  BlockCells block;
  block_cells(cell, reach, block);
  CollisionBatch<D> batch;
  const CellImage itself{};
  for (int list = 0; list < block.count; ++list) {
    const CellImage& image = block.imaged ? block.image[block.place[static_cast<std::size_t>(list)]] : itself;
    const auto& shift = image.position;
    const double shift_vx = image.velocity_x;
    std::int32_t j = block.head[static_cast<std::size_t>(list)];
    do {
      const ParticleRecord<D>& pj = particles_[at(j)];
      const auto slot = static_cast<std::size_t>(batch.size);
      for (int a = 0; a < D; ++a) {
        batch.r[a][slot] = flight.coordinate_at(a, pj.r[a], pj.v[a], now) + shift[static_cast<std::size_t>(a)] - ri[a];
        const double vj = flight.velocity_at(a, pj.v[a], now);
        batch.v[a][slot] = a == 0 ? vj + shift_vx - vi[a] : vj - vi[a];
      }
      batch.contact[slot] = polydisperse ? contact_distance(i, j) : sigma;
      batch.partner[slot] = j;
      batch.size += j != i ? 1 : 0;  // the particle itself is written over
      if (batch.full()) batch.take_earliest(best, partner);
      j = pj.next;
    } while (j != CellLists::kEnd);
  }
  batch.take_earliest(best, partner);
  return {crossing, partner, best};
}

template <int D>
void Simulation<D>::predict(std::int32_t i) {
  store(i, next_event(i));
}

template <int D>
void Simulation<D>::store(std::int32_t i, const Prediction& next) {
  slot(i).set_kind(next.kind());
  ParticleRecord<D>& p = particles_[at(i)];
  p.partner = next.partner;
  p.partner_count = next.partner >= 0 ? particles_[at(next.partner)].count : 0;
  queue_.update(i, t_now_ + next.delay());
}

template <int D>
typename Simulation<D>::Candidate Simulation<D>::candidate(std::int32_t i) const {
  const std::int32_t k = particles_[at(i)].partner;
  if (k < 0) return {};
  const Vector offset = position_now(k) - position_now(i);
  const PartnerImage image = nearest_image(offset);
  Vector v = velocity_now(k) - velocity_now(i);
  v[0] += image.shift.velocity_x;
  return {k, collision_time<D>(offset + image.shift.position, v, contact_distance(i, k))};
}

// Why the layer ahead suffices: every pair (i, j) of neighbours is covered, meaning that the event
// slot of i or of j is no later than their collision.  A whole scan covers i's pairs; a collision
// ends the coverage of its two particles' pairs only, and they are scanned whole again; a crossing
// leaves every trajectory as it was, so a pair j that stays adjacent is covered as it was before —
// by j's slot, or by i's candidate, which is kept here (while it is valid, that is while its
// partner has not collided: otherwise i's slot, no later than the candidate, would have lost the
// pairs the candidate stood for, and the whole block is scanned again).  The pairs of the layer
// ahead are new to i and are scanned.  The candidate's time is computed again from the two
// flights (candidate()), equal to the one first predicted up to round-off.
template <int D>
void Simulation<D>::predict_after_crossing(std::int32_t i, int axis, int direction) {
  if (!candidate_valid(i) || !recomputes_candidates()) {
    predict(i);
    return;
  }
  store(i, next_event(i, Reach::layer_ahead(axis, direction), candidate(i)));
}

// The members defined in this file, for both dimensions (the class is instantiated in
// simulation.cpp, once).
template Simulation<2>::Crossing Simulation<2>::next_crossing(std::int32_t, const std::array<int, 2>&, const Vec<2>&,
                                                               const Vec<2>&) const;
template Simulation<2>::Prediction Simulation<2>::next_event(std::int32_t, const Reach&, Candidate) const;
template void Simulation<2>::predict(std::int32_t);
template void Simulation<2>::store(std::int32_t, const Prediction&);
template void Simulation<2>::predict_after_crossing(std::int32_t, int, int);
template Simulation<3>::Crossing Simulation<3>::next_crossing(std::int32_t, const std::array<int, 3>&, const Vec<3>&,
                                                               const Vec<3>&) const;
template Simulation<3>::Prediction Simulation<3>::next_event(std::int32_t, const Reach&, Candidate) const;
template void Simulation<3>::predict(std::int32_t);
template void Simulation<3>::store(std::int32_t, const Prediction&);
template void Simulation<3>::predict_after_crossing(std::int32_t, int, int);

}  // namespace granule
