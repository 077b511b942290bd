// An observable of a run as a plug-in: a measurement fed by the engine's events (collisions, wall
// collisions, boundary crossings, as EventObserver delivers them) and by the configurations the
// run samples, kept across checkpoints, and written to its own output file.  The driver holds the
// configured ones in a list (observables/observables.hpp) and calls each at the same points of the
// run; none of them changes the trajectory (they only read the engine and its records).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/observer.hpp"
#include "engine/simulation.hpp"
#include "archive/state_archive.hpp"

namespace granule {

// A run continued from its snapshot frame K keeps what its files held up to that frame.
struct FrameContinuation {
  std::int64_t fields_frames = 0;      // fields.h5 frames kept
  bool fields_frame_at_start = false;  // the last of them is at frame K itself
};

template <int D>
class Observable : public EventObserver<D> {
 public:
  // The engine delivers every event to every observable; most want collisions only.
  void on_collision(const CollisionRecord<D>&) override {}

  // Production starts at the engine's present state (a new run, or `granule analyze collisions`).
  virtual void start(Simulation<D>& sim) = 0;
  // Production continues from a snapshot frame: intervals and statistics start afresh there.
  virtual void continue_from_frame(Simulation<D>& sim, const FrameContinuation& kept) = 0;
  // Production continues from a checkpoint: everything as it was saved under `prefix`.
  virtual void restore(Simulation<D>& sim, const StateArchive& archive, const std::string& prefix) = 0;
  // What restore() needs, under `prefix` (a checkpoint holds all observables under one prefix, so
  // each names its datasets so that they do not collide with another's).
  virtual void save(StateArchive& archive, const std::string& prefix) const = 0;

  // The earliest collision count and time at which the engine must stop for this observable.
  virtual std::int64_t next_collisions() const = 0;
  virtual double next_time() const = 0;
  // The engine has stopped (here or for another client): act if due; `final` at the run's end
  // (write what is open).
  virtual void after_step(Simulation<D>& sim, bool final) = 0;
  // A configuration sampled by the run (output.every_*) at `collisions`, the images moving at
  // `shear_velocity`.
  virtual void on_sample(const StateBlocks&, std::int64_t /*collisions*/, double /*shear_velocity*/) {}
  // The run has ended: write the output files and add this observable's figures to `summary`
  // (summary.json's "measurements").
  virtual void finish(const Simulation<D>& sim, nlohmann::json& summary) = 0;
};

}  // namespace granule
