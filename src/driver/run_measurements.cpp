#include "driver/run_measurements.hpp"

#include <algorithm>

#include "observers/schedule.hpp"
#include "observables/observables.hpp"

namespace granule::driver {

template <int D>
RunMeasurements<D>::RunMeasurements(const RunConfig& config, const std::string& out_dir)
    : observables_(configured_observables<D>(config, out_dir)) {}

template <int D>
void RunMeasurements<D>::attach(Simulation<D>& sim) {
  for (const auto& observable : observables_) sim.add_observer(observable.get());
}

template <int D>
void RunMeasurements<D>::start(Simulation<D>& sim) {
  attach(sim);
  for (const auto& observable : observables_) observable->start(sim);
}

template <int D>
void RunMeasurements<D>::continue_from_frame(Simulation<D>& sim, const FrameContinuation& kept) {
  attach(sim);
  for (const auto& observable : observables_) observable->continue_from_frame(sim, kept);
}

template <int D>
void RunMeasurements<D>::resume(Simulation<D>& sim, const StateArchive& archive, const std::string& prefix) {
  attach(sim);
  for (const auto& observable : observables_) observable->restore(sim, archive, prefix);
}

template <int D>
void RunMeasurements<D>::save(StateArchive& archive, const std::string& prefix) const {
  for (const auto& observable : observables_) observable->save(archive, prefix);
}

template <int D>
std::int64_t RunMeasurements<D>::next_collisions() const {
  std::int64_t next = kNoLimit;
  for (const auto& observable : observables_) next = std::min(next, observable->next_collisions());
  return next;
}

template <int D>
double RunMeasurements<D>::next_time() const {
  double next = kInf;
  for (const auto& observable : observables_) next = std::min(next, observable->next_time());
  return next;
}

template <int D>
void RunMeasurements<D>::after_step(Simulation<D>& sim, bool final) {
  for (const auto& observable : observables_) observable->after_step(sim, final);
}

template <int D>
void RunMeasurements<D>::on_sample(const StateBlocks& state, std::int64_t collisions, double shear_velocity) {
  for (const auto& observable : observables_) observable->on_sample(state, collisions, shear_velocity);
}

template <int D>
nlohmann::json RunMeasurements<D>::finish(const Simulation<D>& sim) {
  nlohmann::json summary = nlohmann::json::object();
  for (const auto& observable : observables_) observable->finish(sim, summary);
  return summary;
}

template class RunMeasurements<2>;
template class RunMeasurements<3>;

}  // namespace granule::driver
