// The event loop of the thesis's Appendix A for disks (D = 2) and spheres (D = 3), monodisperse
// or polydisperse: one pending event per particle (its earliest collision, cell crossing or wall
// hit) in a calendar queue (events/event_queue.hpp); lazy flights stored as false positions at a
// common clock base (engine/particle_record.hpp); stale events caught by collision counters;
// periodic re-basing of the clock; a sheared cell grid that follows the mean Lees–Edwards flow
// (boundary/shear_frame.hpp); and a time-dependent image velocity U(t) in constant segments
// (boundary/shear_protocol.hpp), its changes and the grid's re-alignments kept as global timed
// actions beside the queue.  The physics comes from three policies (ARCHITECTURE.md, "Physics as
// policies"): the boundaries per axis (boundary/box_boundaries.hpp), the motion between events
// (motion/motion.hpp) and the collision law (physics/collision_law.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <csignal>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "archive/state_archive.hpp"
#include "boundary/box_boundaries.hpp"
#include "boundary/shear_protocol.hpp"
#include "cells/cell_grid.hpp"
#include "cells/exact_divisor.hpp"
#include "engine/collapse_detector.hpp"
#include "engine/event_plans.hpp"
#include "engine/observer.hpp"
#include "engine/particle_record.hpp"
#include "engine/scan_types.hpp"
#include "memory/huge_page_allocator.hpp"
#include "engine/state_blocks.hpp"
#include "engine/stop_reason.hpp"
#include "engine/system_params.hpp"
#include "events/event.hpp"
#include "events/event_queue.hpp"
#include "events/timed_actions.hpp"
#include "motion/motion.hpp"
#include "physics/collision_law.hpp"

namespace granule {

// The trajectory depends only on the initial state, the parameters and the grid: never on how
// often run() is stopped, on observers, or on reading the state (tested, tests/validation).
// D is fixed at compile time (the stencil, the crossings and the vectors unroll); the command
// line picks the instantiation from system.dimension.  Flow along x, gradient along y (the
// Lees–Edwards images sit above and below in y), z plainly periodic.
template <int D>
class Simulation {
  static_assert(D == 2 || D == 3, "disks or spheres");

 public:
  using Vector = Vec<D>;
  static constexpr int kSpinComponents = D == 3 ? 3 : 1;

  // Start from lab positions and velocities free of overlaps; `clock` places the start on the
  // time line of an earlier run (a restart from a snapshot frame: same physics, new round-off).
  Simulation(const SystemParams& params, const CellGrid& grid, const ParticleState& state,
             const ClockState& clock = {});
  // Continue bit for bit from a checkpoint written by save(); throws std::runtime_error when the
  // archive does not fit `params` and `grid`.
  Simulation(const SystemParams& params, const CellGrid& grid, const StateArchive& archive,
             const std::string& prefix);
  // Moved, never copied: the queue orders ties by the engine's own array of user ids, which a
  // move carries along and a copy would leave behind.
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;
  Simulation(Simulation&&) noexcept = default;
  Simulation& operator=(Simulation&&) noexcept = default;
  void save(StateArchive& archive, const std::string& prefix) const;

  // Advance until the absolute time `until_time` or until `until_collisions` collisions have
  // been executed since the restitution was switched on, whichever comes first.  Returns after a
  // whole event, so the engine can be saved or read at once.
  StopReason run(double until_time, std::int64_t until_collisions);
  // run() checks `*flag` before each event and stops with kInterrupted when it is non-zero
  // (signal handlers set it); nullptr switches the check off.
  void set_interrupt_flag(const volatile std::sig_atomic_t* flag) { interrupt_ = flag; }

  // Lab positions (x ∈ [0, L_x), y ∈ [0, L_y), z ∈ [0, L_z)) and velocities at the current time,
  // extrapolated from each particle's last event without touching the engine; with the
  // per-particle diameters and masses of a polydisperse run.
  ParticleState state() const;
  // state() in blocks of consecutive ids, each extrapolated when it is read: valid while the
  // engine stands still.
  StateBlocks state_blocks() const;
  ClockState clock_state() const;
  // Per-particle diameters and masses of a polydisperse run (empty otherwise), by particle id.
  std::vector<double> diameters() const { return by_user_id(diameter_); }
  std::vector<double> masses() const { return by_user_id(mass_); }

  // Switch on the restitutions of `production` (normal, tangential, walls: the thesis's elastic
  // pre-run ends here), restart t and c at 0 and start the shear protocol: from here on U follows
  // U(t).
  void start_production(const SystemParams& production);
  // The same with only the normal restitution changed (the other restitutions stay as they are).
  void start_production(double restitution) {
    SystemParams production = params_;
    production.restitution = restitution;
    start_production(production);
  }

  // Checks every invariant of the engine — no overlaps beyond round-off, each disk in the cell
  // its position gives, lists and queue consistent, every pending event still valid and not
  // later than a fresh prediction — and throws std::logic_error describing the first violation.
  // O(N) with the 3^D stencil; the GRANULE_PARANOID build runs it at every re-base.
  void check_invariants() const;

  void add_observer(EventObserver<D>* observer) { observers_.push_back(observer); }

  double time() const { return clock_base_ + t_now_; }
  // Absolute time of the earliest pending event (+inf when nothing will happen).
  double next_event_time() const { return clock_base_ + queue_.top_time(); }
  std::int64_t collisions() const { return collisions_; }
  std::int64_t events() const { return events_; }
  double collisions_per_particle() const {
    return static_cast<double>(collisions_) / static_cast<double>(params_.particles);
  }
  // Strain of the sheared cell grid, |s| ≤ strain_period/2; Δ ≡ s L_y (mod L_x).
  double strain() const { return strain_ref_ + shear_rate_ * (t_now_ - t_ref_); }
  // The velocity U of the upper images now (the current segment's Ū of the protocol).
  double image_velocity() const { return boundaries_.frame().shear_velocity; }
  // Current Lees–Edwards image offset Δ ∈ [0, L_x) (thesis §1.4.2).
  double shear_offset() const;
  const SystemParams& params() const { return params_; }
  const CellGrid& grid() const { return grid_; }
  const CollapseReport& collapse() const { return collapse_; }
  // The grains at rest on static supports now (physics/rest_rule.hpp).
  std::int64_t grains_at_rest() const { return boundaries_.resting_grains().count(); }
  // Memory held per particle by the engine (all arrays, cells and queue), in bytes.
  double bytes_per_particle() const;
  // The number of times the particles have been renumbered in this engine's life (restored ones
  // count from the restore).
  std::int64_t renumberings() const { return renumberings_; }

 private:
  // The arrays and clocks a checkpoint holds by name (simulation_checkpoint.cpp); the event kinds,
  // cell lists, queue and collapse detector are saved by their own code.
  template <typename Self, typename Visit>
  static void visit_saved_state(Self& self, Visit&& visit);
  // The grid, if its cell ids fit beside the event kind in an EventSlot (the configuration
  // refuses larger grids with a message; this guards direct use of the class).
  static const CellGrid& checked(const CellGrid& grid) {
    if (grid.cell_count() > EventSlot::kCellLimit) throw std::invalid_argument("the engine's cell grid has more than 2^28 cells");
    return grid;
  }
  void load(const ParticleState& state);
  void rebuild();
  // Particles are numbered inside the engine along the cell curve (cells/cell_curve.hpp), afresh
  // every SystemParams::renumber_every events per particle, so that the records a prediction
  // reads lie close in memory; everything handed out (states, records, reports) is by the user's
  // id, which the engine keeps (user_id_).  Renumbering moves every per-particle array and slot
  // and re-links the cell lists and the calendar; the trajectory does not change (the queue
  // breaks ties by user id; tests/validation/test_renumbering.cpp).
  void renumber();
  // The numbering a checkpoint holds (the user's when it holds none), and the cadence.
  void restore_numbering(const StateArchive& archive, const std::string& prefix);
  void check_restored_clocks() const;
  // Engine numbers equal to the user's ids, stored (the start of a renumbering engine).
  void number_by_user_id() {
    user_id_.resize(particles_.size());
    std::iota(user_id_.begin(), user_id_.end(), 0);
  }
  std::int32_t user_id(std::int32_t i) const { return user_id_.empty() ? i : user_id_[static_cast<std::size_t>(i)]; }
  // The engine's number of each user id (the inverse of user_id_), empty while they agree.
  std::vector<std::int32_t> engine_ids() const;
  // A per-particle array of the engine's, in the order of user ids.
  std::vector<double> by_user_id(const std::vector<double>& values) const;
  // Particles first .. first + count − 1 by user id, with `engine_ids` from engine_ids().
  ParticleState state(std::size_t first, std::size_t count, const std::vector<std::int32_t>& engine_ids) const;
  std::int64_t collapse_window() const { return std::max<std::int64_t>(1000, params_.particles); }
  void rebase();
  EventSlot& slot(std::int32_t i) { return queue_.slot(i); }
  const EventSlot& slot(std::int32_t i) const { return queue_.slot(i); }
  // Start fetching what the event after the top will read (its record — its partner's is fetched
  // when it is popped, the partner being named in the record —, the cell heads of its block or, for many disks, the first records of the cells its scan reads), so that
  // its cache misses overlap the top's work (engine/simulation_neighbours.hpp).
  void prefetch_next_event() const;
  // Whether the first records of the next scan's cells are prefetched (rather than the heads of
  // its block): for disks, from kPrefetchRecordsFrom on (the records are cached below: measured
  // 1.08× at 7.5·10⁴, 0.97–0.99× at 3·10⁴ and 5·10⁴), while the heads, read then, stay cached
  // (16 MiB of them, about 2.4·10⁶ disks; at 10⁷, where they are not, four pairs gave 0.79–1.16×,
  // unresolved; docs/performance.md).  Evaluated per event: a load and a predicted branch.
  static constexpr std::int64_t kPrefetchRecordsFrom = 65536;
  static constexpr std::int64_t kPrefetchRecordsCells = std::int64_t{1} << 22;
  bool prefetches_records() const {
    return D == 2 && params_.particles >= kPrefetchRecordsFrom && grid_.cell_count() <= kPrefetchRecordsCells;
  }
  void predict(std::int32_t i);
  // The events, each planned from the state without changing it and then committed
  // (engine/event_plans.hpp, engine/simulation_events.cpp).
  CrossingPlan<D> plan_crossing(std::int32_t i, EventKind kind) const;
  // Particle i entering the box from the image across the face of `axis` in `direction`.
  ImageEntry<D> image_entry(std::int32_t i, int axis, int direction) const;
  void commit(const CrossingPlan<D>& plan);
  CollisionPlan<D> plan_collision(std::int32_t i, std::int32_t j) const;
  bool commit(const CollisionPlan<D>& plan);  // true if a physical collision was executed
  // A hit of a surface of infinite mass (a wall, an obstacle) moving at `surface_velocity`, normal
  // k̂ from the grain into it, under `law`; applied (false: stale, the grain predicted again) and
  // described to observers.
  SurfaceHit<D> plan_surface_hit(std::int32_t i, const Vector& before, const Vector& k_hat, const CollisionLaw& law,
                                 const Vector& surface_velocity) const;
  bool apply(const SurfaceHit<D>& hit);
  // A hit of a surface of kind `kind` (boundary/surface_id.hpp), whose contact the boundaries
  // describe, and what observers are told of it.
  SurfaceHitPlan<D> plan_surface_hit(std::int32_t i, int kind) const;
  SurfaceHitRecord<D> describe(const SurfaceHitPlan<D>& plan) const;
  void commit(const SurfaceHitPlan<D>& plan);
  // Grains at rest (physics/rest_rule.hpp; engine/simulation_rest.cpp): the rule holds in
  // production; whether a hit leaves grain i at rest; putting it at rest; waking grain j and the
  // grains at rest it carries (they fly from rest, predicted); the direction of gravity; the gap
  // within which a grain touches a support: the height a grain at the rest speed rises.
  bool rest_rule_active() const { return protocol_running_ && params_.rest.on(); }
  bool at_rest(std::int32_t i) const { return particles_[static_cast<std::size_t>(i)].partner == kAtRest; }
  bool comes_to_rest(std::int32_t i, const SurfaceHit<D>& hit) const;
  // A grain that slides along a static support gravity presses it into (its leaving speed ever
  // smaller, its hits ever closer) leaves each hit at least at g_n t_c, so that it stays off the
  // support for twice the TC duration and its next hit there is outside the TC window: the TC
  // model's micro-bounce at a sustained contact, which a grain set moving from near rest would not
  // reach by itself.  The speed to add along −k̂ (0: none).
  double sliding_lift(const Vector& velocity, const Vector& k_hat) const;
  // The static support other than `struck` that grain i touches and would move into at once at
  // `velocity`, when one of the two is a grain at rest: of the two, the grain at rest to wake (the
  // struck one if both are).  None: no wedge.
  SurfaceId wedging_support(std::int32_t i, const Vector& velocity, const SurfaceId& struck) const;
  // Whether grain i at r leans on a static support below its centre (itself, if at rest, excluded).
  bool leans_on_static_support(std::int32_t i, const Vector& r) const;
  void put_at_rest(std::int32_t i);
  void wake(std::int32_t j);
  Vector down() const;
  double support_gap() const;
  // The collision law of a grain with a grain at rest: the grains' own, the one at rest of infinite mass.
  CollisionLaw resting_grain_law() const {
    return {params_.restitution, params_.tc_duration, {params_.roughness.tangential_restitution, params_.roughness.friction},
            true, params_.restitution_law};
  }
  // The flight of particle i through its position now with a new velocity, and storing it.
  FlightState<D> flight_through_now(std::int32_t i, const Vector& velocity) const;
  void set_flight(std::int32_t i, const FlightState<D>& flight);
  void realign_sheared_grid();
  // When |strain| reaches strain_period/2 at the present image velocity.
  void schedule_realignment();
  // Move to the protocol's segment starting now (absolute production time `t`).
  void enter_shear_segment(const ShearSegment& segment);
  // A new image velocity from now on: the strain stays continuous, crossings in ξ and pairs across
  // the boundary change, collisions inside the box do not (only they are kept, re-predicted).
  void change_image_velocity(double velocity);
  void repredict_after_shear_change();
  std::int32_t cell_of(const Vector& position) const;
  // The cell coordinates (column, row, layer) of a cell id.
  std::array<int, D> cell_coordinates(std::int32_t cell) const {
    const auto id = static_cast<std::uint32_t>(cell);
    const std::uint32_t rows = by_columns_.quotient(id);  // rows of all layers before the cell's
    const auto column = static_cast<int>(id - rows * by_columns_.divisor());
    if constexpr (D == 2) {
      return {column, static_cast<int>(rows)};
    } else {
      const std::uint32_t layer = by_rows_.quotient(rows);
      return {column, static_cast<int>(rows - layer * by_rows_.divisor()), static_cast<int>(layer)};
    }
  }
  Vector position_now(std::int32_t i) const;
  // Position of particle i at `time` on its present flight (parabolic under gravity) and its
  // velocity now (particle_record.hpp).
  Vector position_at(std::int32_t i, double time) const;
  Vector velocity_now(std::int32_t i) const;
  Spin<D> spin(std::int32_t i) const;
  void set_spin(std::int32_t i, const Spin<D>& w);
  double mass_of(std::int32_t i) const { return mass_.empty() ? 1.0 : mass_[static_cast<std::size_t>(i)]; }
  double radius_of(std::int32_t i) const {
    return 0.5 * (diameter_.empty() ? params_.diameter : diameter_[static_cast<std::size_t>(i)]);
  }
  // Particle i moving at `velocity` as one side of a contact (with its spin, if grains are rough),
  // and its spin after one.
  ContactSide<D> contact_side(std::int32_t i, const Vector& velocity) const;
  void store_spin(std::int32_t i, const ContactSide<D>& side) {
    if (side.spins()) set_spin(i, side.spin);
  }
  // The collision laws (physics/collision_law.hpp): between grains, and between a grain and the
  // surface of the boundaries (a wall, an obstacle: its own restitutions, the grains' TC model).
  CollisionLaw pair_law() const {
    return {params_.restitution, params_.tc_duration, {params_.roughness.tangential_restitution, params_.roughness.friction},
            mass_.empty(), params_.restitution_law};
  }
  CollisionLaw surface_law(double restitution, double tangential_restitution) const {
    return {restitution, params_.tc_duration, {tangential_restitution, std::numeric_limits<double>::infinity()}, true,
            params_.restitution_law};
  }
  // Whether a contact of i with j (j < 0: a wall or an obstacle) now falls within the TC model's duration, and
  // marking the contact: the two places where the TC model's history is read and written.
  bool recent_contact(const CollisionLaw& law, std::int32_t i, std::int32_t j) const;
  void mark_contact(std::int32_t i, std::int32_t j);
  // Contact distance σ_ij = (σ_i + σ_j)/2 (σ for a monodisperse run).
  double contact_distance(std::int32_t i, std::int32_t j) const {
    return diameter_.empty() ? params_.diameter : 0.5 * (diameter_[static_cast<std::size_t>(i)] + diameter_[static_cast<std::size_t>(j)]);
  }
  // The plain data of a scan (engine/scan_types.hpp).
  using Crossing = scan::Crossing;
  using Prediction = scan::Prediction;
  using Reach = scan::Reach<D>;
  using Candidate = scan::Candidate;
  using CellImage = scan::CellImage<D>;
  using BlockCells = scan::BlockCells<D>;
  static constexpr int kStencil = scan::kStencil<D>;
  // The earliest event of particle i from a scan of the whole block.
  Prediction next_event(std::int32_t i) const { return next_event(i, Reach::block(), Candidate{}); }
  // The earliest of `known` and the collisions with the particles within `reach`, and the crossing;
  // compiled without and with gravity (the plain case pays nothing).  Flattened: the neighbour
  // loop, its visitor and the pair test inline into one loop (the hot path).
  Prediction next_event(std::int32_t i, const Reach& reach, Candidate known) const;
  template <typename Flight>
  [[gnu::flatten]] Prediction next_event_in(const Flight& flight, std::int32_t i, const Reach& reach, Candidate known) const;
  void store(std::int32_t i, const Prediction& next);
  // After a crossing (Isobe 1999): the collision candidate found before stays the best among the
  // cells that stay adjacent (ARCHITECTURE.md, "One event per particle"), so only the layer of
  // cells ahead is scanned; a stale candidate asks for a whole scan.
  void predict_after_crossing(std::int32_t i, int axis, int direction);
  // Whether particle i's kept candidate is still a valid collision: its partner has not collided since.
  bool candidate_valid(std::int32_t i) const {
    const ParticleRecord<D>& p = particles_[static_cast<std::size_t>(i)];
    return p.partner < 0 || particles_[static_cast<std::size_t>(p.partner)].count == p.partner_count;
  }
  // Particle i's valid candidate with its time from now, computed from the two flights (+inf: none,
  // or a grazing pair that round-off now misses).  The pair's image is the nearest one: from its
  // prediction to its contact the pair's lab separation runs along a straight segment from a
  // point within two cells (|Δ| < 2 cells per axis, in ξ for x) to contact, so with at least
  // kCandidateCells cells along every periodic axis the image is unambiguous.  Under Lees–Edwards
  // ξ = x − s y adds |s Δy| ≤ S·2h at both ends (|s| ≤ S, half the strain period, before the
  // grid is re-aligned and everything predicted afresh): |Δξ| < 2w + 4Sh, unambiguous while
  // L_x > 4w + 8Sh.  Smaller grids scan whole blocks (recomputes_candidates()).
  static constexpr int kCandidateCells = 5;
  Candidate candidate(std::int32_t i) const;
  bool recomputes_candidates() const {
    for (int a = 0; a < D; ++a) {
      if (boundaries_.has_images(a) && grid_.count(a) < kCandidateCells) return false;
    }
    const bool sheared = grid_.strain_period > 0.0 && boundaries_.sheared();
    return !sheared || params_.length_x > 4.0 * grid_.width + 4.0 * grid_.strain_period * grid_.height;
  }
  // The first cell face particle i (now at `position`, moving at `velocity`) reaches, or the
  // first wall or obstacle it hits (the wall faces of boundary cells are never crossed).
  Crossing next_crossing(std::int32_t i, const std::array<int, D>& cell, const Vector& position,
                         const Vector& velocity) const;
  template <typename Flight>
  Crossing next_crossing(const Flight& flight, std::int32_t i, const std::array<int, D>& cell, const Vector& position,
                         const Vector& velocity) const;
  // Calls visit(j, shift, shift_vx) for every particle j ≠ i of the 3^D block of cells around
  // i's cell, with the image shift (position, and velocity along x) that brings j next to i.
  // The sheared frame is plainly periodic, so images follow from the cell offsets alone; a wall
  // axis has no images (the block stops at the wall).
  template <typename Visit>
  void for_each_neighbour(std::int32_t i, Visit&& visit) const {
    for_each_neighbour(i, Reach::block(), visit);
  }
  // The same over the offsets within `reach`.
  template <typename Visit>
  void for_each_neighbour(std::int32_t i, const Reach& reach, Visit&& visit) const {
    for_each_neighbour(i, cell_coordinates(slot(i).cell()), reach, visit);
  }
  // The same with the coordinates of i's cell known (their divisions are paid once per prediction).
  template <typename Visit>
  void for_each_neighbour(std::int32_t i, const std::array<int, D>& cell, const Reach& reach, Visit&& visit) const;
  void block_cells(const std::array<int, D>& cell, const Reach& reach, BlockCells& block) const;
  // Whether a cell is away from every face of the grid: its block then sees no image.
  bool is_interior(const std::array<int, D>& cell) const;
  // The image of a partner at lab offset `offset` from a particle in contact with it, now.
  using PartnerImage = typename BoxBoundaries<D>::PartnerImage;
  PartnerImage nearest_image(const Vector& offset) const { return boundaries_.nearest_image(offset, strain()); }
  // The surfaces' parameters of p in params_ (what params() reports and checkpoints hold) and in the
  // boundaries (what the engine applies).
  void set_surfaces(const SystemParams& p);
  // The boundaries of p's box with its surfaces listed by the cells of `grid` (the largest grain
  // radius is σ/2).
  static BoxBoundaries<D> boundaries_of(const SystemParams& p, const CellGrid& grid);
  // GRANULE_PARANOID: the popped event, re-derived from the state before it runs.
  void check_popped_event(std::int32_t i) const;

  SystemParams params_;
  CellGrid grid_;
  ExactDivisor by_columns_, by_rows_;  // by grid_.nx and grid_.ny (cell_coordinates)
  // What lies beyond each face of the box (its frame's shear_velocity is the current U) and how
  // particles fly: the boundary and motion policies (ARCHITECTURE.md, "Physics as policies").
  BoxBoundaries<D> boundaries_;
  Motion<D> motion_;
  double shear_rate_ = 0.0;
  ShearProtocol protocol_;
  bool protocol_running_ = false;
  double segment_end_ = std::numeric_limits<double>::infinity();  // absolute production time

  // Particles by plain id: the records a neighbour's collision test reads (position and velocity
  // at the clock base, cell-list link, collision counter), then the arrays of optional features.
  // What only a particle's own events read is its EventSlot, held by queue_.
  HugePageVector<ParticleRecord<D>> particles_;
  std::vector<double> diameter_, mass_;  // polydisperse runs only
  // Angular velocities (ω_z; ω_x, ω_y, ω_z for spheres), valid at all times (no torque between
  // events); rough grains only.
  std::array<std::vector<double>, kSpinComponents> spin_;
  std::vector<double> last_collision_;  // TC model only
  // The user's id of each engine particle (empty: the same), and the renumbering's cadence.  The
  // queue reads it in place (set_tie_order): it is sized once, at construction or restore.
  std::vector<std::int32_t> user_id_;
  std::int64_t renumber_interval_ = 0;  // events (0: never)
  std::int64_t events_since_renumber_ = 0;
  std::int64_t renumberings_ = 0;

  CellLists lists_;
  EventQueue queue_;
  TimedActions actions_;
  CollapseDetector collapse_detector_;
  CollapseReport collapse_;
  std::vector<EventObserver<D>*> observers_;
  const volatile std::sig_atomic_t* interrupt_ = nullptr;

  double t_now_ = 0.0;       // relative to clock_base_
  double clock_base_ = 0.0;  // absolute time of t_now_ = 0
  double t_ref_ = 0.0;       // relative time at which the grid strain was strain_ref_
  double strain_ref_ = 0.0;
  std::int64_t collisions_ = 0;
  std::int64_t events_ = 0;
  std::int64_t events_since_rebase_ = 0;
};

}  // namespace granule

// The inline neighbour scan and the face images it uses (the hot path of prediction).
#include "engine/simulation_neighbours.hpp"
