#include "driver/stop_loop.hpp"

#include <algorithm>

namespace granule::driver {

StopReason advance_to_next_stop(Simulation<2>& sim, const std::vector<StopClient*>& clients, const StopLimits& limits) {
  std::int64_t collisions = limits.collisions;
  double time = limits.time;
  for (const StopClient* client : clients) {
    collisions = std::min(collisions, client->next_collisions());
    time = std::min(time, client->next_time());
  }
  const StopReason reason = sim.run(time, collisions);
  if (reason == StopReason::kInterrupted) return reason;
  for (StopClient* client : clients) client->on_stop(sim);
  return reason;
}

}  // namespace granule::driver
