#include "driver/stop_loop.hpp"

#include <algorithm>

namespace granule::driver {

template <int D>
StopReason advance_to_next_stop(Simulation<D>& sim, const std::vector<StopClient<D>*>& clients, const StopLimits& limits) {
  std::int64_t collisions = limits.collisions;
  double time = limits.time;
  for (const StopClient<D>* client : clients) {
    collisions = std::min(collisions, client->next_collisions());
    time = std::min(time, client->next_time());
  }
  const StopReason reason = sim.run(time, collisions);
  if (reason == StopReason::kInterrupted) return reason;
  for (StopClient<D>* client : clients) client->on_stop(sim);
  return reason;
}

template StopReason advance_to_next_stop(Simulation<2>&, const std::vector<StopClient<2>*>&, const StopLimits&);
template StopReason advance_to_next_stop(Simulation<3>&, const std::vector<StopClient<3>*>&, const StopLimits&);

}  // namespace granule::driver
