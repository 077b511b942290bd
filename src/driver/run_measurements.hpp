// The measurements of a run beyond its time series: the observables its configuration switches on
// (observables/observables.hpp: today the fields of [fields] and the collision statistics of
// [collisions]), the same for disks and spheres.  The run loop asks when it must stop for them and
// calls back after each step; each observable sees every event and writes its own file.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "driver/stop_loop.hpp"
#include "engine/simulation.hpp"
#include "io/config.hpp"
#include "observables/observable.hpp"

namespace granule::driver {

template <int D>
class RunMeasurements final : public StopClient<D> {
 public:
  // `out_dir` receives the observables' files (fields.h5, collisions.h5 and CSV tables).
  RunMeasurements(const RunConfig& config, const std::string& out_dir);

  // Attach the observables and let them start (the first fields frame).
  void start(Simulation<D>& sim);
  // Continue from a snapshot frame instead: files keep what `kept` says, averaging intervals and
  // collision statistics start afresh here.
  void continue_from_frame(Simulation<D>& sim, const FrameContinuation& kept);
  // Continue from a checkpoint instead: the files keep the frames written before it.
  void resume(Simulation<D>& sim, const StateArchive& archive, const std::string& prefix);
  void save(StateArchive& archive, const std::string& prefix) const;
  // The earliest collision count and time at which the loop must stop for a measurement.
  std::int64_t next_collisions() const override;
  double next_time() const override;
  void on_stop(Simulation<D>& sim) override { after_step(sim, false); }
  // After every step of the loop: each observable acts if due (`final` forces what is open out).
  void after_step(Simulation<D>& sim, bool final);
  // A configuration sampled by the run (output.every_*), the images moving at `shear_velocity`.
  void on_sample(const StateBlocks& state, std::int64_t collisions, double shear_velocity);
  // Write the observables' files.  Returns the summary figures for summary.json.
  nlohmann::json finish(const Simulation<D>& sim);

 private:
  void attach(Simulation<D>& sim);

  std::vector<std::unique_ptr<Observable<D>>> observables_;
};

}  // namespace granule::driver
