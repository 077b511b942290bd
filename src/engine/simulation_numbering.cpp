// The engine's numbering of its particles (Simulation::renumber): along the cell curve, so that
// the particles of neighbouring cells sit in neighbouring records and slots, which prediction reads
// together (docs/performance.md, "Particles renumbered along the cells").
#include <utility>

#include "cells/cell_curve.hpp"
#include "engine/simulation.hpp"
#include "memory/permute_in_place.hpp"

namespace granule {

namespace {
inline std::size_t at(std::int32_t i) { return static_cast<std::size_t>(i); }

template <typename Array>
void swap_entries(Array& values, std::size_t a, std::size_t b) {
  if (!values.empty()) std::swap(values[a], values[b]);
}
}  // namespace

template <int D>
void Simulation<D>::renumber() {
  const std::size_t n = particles_.size();
  // The new number of each particle: its rank along the curve, and within a cell its list order.
  std::vector<std::int32_t> destination(n);
  std::int32_t next = 0;
  std::array<int, D> counts;
  for (int a = 0; a < D; ++a) counts[static_cast<std::size_t>(a)] = grid_.count(a);
  for_each_cell_along_curve<D>(counts, [&](const std::array<int, D>& cell) {
    std::int32_t id = 0;
    if constexpr (D == 2) {
      id = grid_.index(cell[0], cell[1]);
    } else {
      id = grid_.index(cell[0], cell[1], cell[2]);
    }
    for (std::int32_t p = lists_.first(id); p != CellLists::kEnd; p = particles_[at(p)].next) destination[at(p)] = next++;
  });
  // Grains at rest are in no cell list: they follow, in their present order.
  for (std::size_t k = 0; k < n; ++k) {
    if (particles_[k].partner == kAtRest) destination[k] = next++;
  }
  boundaries_.resting_grains().renumber(destination);
  const std::span<EventSlot> slots = queue_.slots();
  for (ParticleRecord<D>& p : particles_) {
    if (p.partner >= 0) p.partner = destination[at(p.partner)];
  }
  permute_in_place(destination, [&](std::size_t a, std::size_t b) {
    std::swap(particles_[a], particles_[b]);
    std::swap(slots[a], slots[b]);
    swap_entries(diameter_, a, b);
    swap_entries(mass_, a, b);
    for (auto& w : spin_) swap_entries(w, a, b);
    swap_entries(last_collision_, a, b);
    swap_entries(user_id_, a, b);
  });
  // Each list in increasing numbers: a cell's particles are then read in memory order.
  lists_.reset(grid_.cell_count());
  for (std::size_t k = n; k-- > 0;) {
    if (particles_[k].partner != kAtRest) lists_.insert(particles_, static_cast<std::int32_t>(k), slots[k].cell());
  }
  queue_.relink();
  events_since_renumber_ = 0;
  ++renumberings_;
}

template <int D>
std::vector<std::int32_t> Simulation<D>::engine_ids() const {
  std::vector<std::int32_t> engine_id(user_id_.size());
  for (std::size_t i = 0; i < user_id_.size(); ++i) engine_id[at(user_id_[i])] = static_cast<std::int32_t>(i);
  return engine_id;
}

template <int D>
std::vector<double> Simulation<D>::by_user_id(const std::vector<double>& values) const {
  if (user_id_.empty() || values.empty()) return values;
  std::vector<double> out(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) out[at(user_id_[i])] = values[i];
  return out;
}

template void Simulation<2>::renumber();
template std::vector<std::int32_t> Simulation<2>::engine_ids() const;
template std::vector<double> Simulation<2>::by_user_id(const std::vector<double>&) const;
template void Simulation<3>::renumber();
template std::vector<std::int32_t> Simulation<3>::engine_ids() const;
template std::vector<double> Simulation<3>::by_user_id(const std::vector<double>&) const;

}  // namespace granule
