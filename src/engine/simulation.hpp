// The event loop of the thesis's Appendix A: one pending event per particle (its earliest
// collision or cell crossing) in an indexed heap; lazy free flight with per-particle local
// times; stale events caught by collision counters; periodic re-basing of the clock; and a
// sheared cell grid that follows the mean Lees–Edwards flow (boundary/shear_frame.hpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "boundary/shear_frame.hpp"
#include "cells/cell_grid.hpp"
#include "engine/collapse_detector.hpp"
#include "engine/observer.hpp"
#include "engine/system_params.hpp"
#include "events/event.hpp"
#include "events/event_heap.hpp"

namespace granule {

enum class StopReason {
  kTimeReached,        // the requested time
  kCollisionsReached,  // the requested number of collisions
  kNoEvents,           // nothing will ever happen (all disks at rest relative to each other)
  kInelasticCollapse,  // collisions piled up in vanishing time (see CollapseDetector)
};

struct CollapseReport {
  double time = 0.0;
  std::int32_t first = -1;
  std::int32_t second = -1;
  Vec2 position;
};

class Simulation {
 public:
  // `state` must be free of overlaps; `clock` restores a synchronised run (restart).
  Simulation(const SystemParams& params, const CellGrid& grid, const ParticleState& state,
             const ClockState& clock = {});

  // Advance until the absolute time `until_time` or until `until_collisions` collisions have
  // been executed since the restitution was switched on, whichever comes first.
  StopReason run(double until_time, std::int64_t until_collisions);

  // Bring every particle to the current time, re-base the clock, re-bin and re-predict all.
  // Snapshots are taken here, so a restart from one continues exactly the same trajectory.
  void synchronize();
  // Lab positions (x ∈ [0, L_x), y ∈ [0, L_y)) and velocities at the current time; exact
  // after synchronize(), extrapolated otherwise.
  ParticleState state() const;
  ClockState clock_state() const;

  // Switch the restitution (the thesis's elastic pre-run ends here) and restart t and c at 0.
  void start_production(double restitution);

  void add_observer(EventObserver* observer) { observers_.push_back(observer); }

  double time() const { return clock_base_ + t_now_; }
  std::int64_t collisions() const { return collisions_; }
  std::int64_t events() const { return events_; }
  double collisions_per_particle() const {
    return static_cast<double>(collisions_) / static_cast<double>(params_.particles);
  }
  double strain() const { return frame_.shear_rate() * (t_now_ - t_ref_); }
  // Current Lees–Edwards image offset Δ ∈ [0, L_x) (thesis §1.4.2).
  double shear_offset() const;
  const SystemParams& params() const { return params_; }
  const CellGrid& grid() const { return grid_; }
  const CollapseReport& collapse() const { return collapse_; }
  // Memory held per particle by the engine (all arrays, cells and queue), in bytes.
  double bytes_per_particle() const;

 private:
  void load(const ParticleState& state);
  void rebuild();
  std::int64_t collapse_window() const { return std::max<std::int64_t>(1000, params_.particles); }
  void rebase();
  void advance(std::int32_t i);
  void predict(std::int32_t i);
  void execute_crossing(std::int32_t i, EventKind kind);
  // Returns true if a physical collision was executed.
  bool execute_collision(std::int32_t i, std::int32_t j);
  void realign_sheared_grid();
  std::int32_t cell_of(double x, double y) const;

  SystemParams params_;
  CellGrid grid_;
  ShearFrame frame_;
  double shear_rate_ = 0.0;

  // Particle arrays (struct of arrays, plain ids).  Positions are valid at local time t_[i].
  std::vector<double> x_, y_, vx_, vy_, t_;
  std::vector<std::uint32_t> count_;  // collisions of each particle: invalidates stale events
  std::vector<std::int32_t> cell_;
  std::vector<double> last_collision_;  // TC model only
  // Pending event of each particle (its time lives in the heap).
  std::vector<EventKind> kind_;
  std::vector<std::int32_t> partner_;
  std::vector<std::uint32_t> partner_count_;

  CellLists lists_;
  EventHeap heap_;
  CollapseDetector collapse_detector_;
  CollapseReport collapse_;
  std::vector<EventObserver*> observers_;

  double t_now_ = 0.0;       // relative to clock_base_
  double clock_base_ = 0.0;  // absolute time of t_now_ = 0
  double t_ref_ = 0.0;       // relative time at which the sheared grid had zero strain
  std::int64_t collisions_ = 0;
  std::int64_t events_ = 0;
  std::int64_t events_since_rebase_ = 0;
};

}  // namespace granule
