// The one loop that drives the engine between stops, for `granule run`, `granule analyze
// collisions` and future bindings: everything that needs the engine stopped (snapshots, samples
// of the time series, field frames, measurement windows) is a StopClient naming its next stop;
// the loop runs the engine to the earliest of them and lets each client act, in order.  The
// engine's own global actions (grid re-alignment, shear-protocol segments) never stop it: they
// live beside its event queue (events/timed_actions.hpp).  A stop changes no bit of the
// trajectory (tests/validation/test_exact_continuation.cpp).
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "engine/simulation.hpp"

namespace granule::driver {

template <int D>
class StopClient {
 public:
  virtual ~StopClient() = default;
  // The next collision count and time at which this client needs the engine stopped.
  virtual std::int64_t next_collisions() const = 0;
  virtual double next_time() const = 0;
  // The engine has stopped (at its stop or another client's): act if due.
  virtual void on_stop(Simulation<D>& sim) = 0;
};

struct StopLimits {
  std::int64_t collisions = std::numeric_limits<std::int64_t>::max();
  double time = std::numeric_limits<double>::infinity();
};

// Runs `sim` to the earliest stop of `clients` within `limits`, then calls on_stop of every
// client in order, unless the run was interrupted (then nothing is written: the caller saves).
template <int D>
StopReason advance_to_next_stop(Simulation<D>& sim, const std::vector<StopClient<D>*>& clients, const StopLimits& limits);

}  // namespace granule::driver
