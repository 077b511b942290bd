// The measurements of a run beyond its time series (configured in [fields] and [collisions]):
// coarse-grained fields (with the collisional stress and heat flux) written to fields.h5 as the run
// goes, and the collision statistics (impact parameters, free paths) written to collisions.h5 at
// its end; the same for disks and spheres.  The run loop asks when it
// must stop for them and calls back after each step; the observers see every collision.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "analysis/cell_fields.hpp"
#include "analysis/collisional_stress.hpp"
#include "analysis/free_paths.hpp"
#include "analysis/impact_parameters.hpp"
#include "driver/schedule.hpp"
#include "driver/stop_loop.hpp"
#include "engine/simulation.hpp"
#include "io/config.hpp"
#include "io/fields_file.hpp"

namespace granule::driver {

template <int D>
class RunMeasurements final : public StopClient<D> {
 public:
  // `out_dir` receives fields.h5 and collisions.h5 (+ CSV tables).
  RunMeasurements(const RunConfig& config, std::string out_dir);

  // Attach the observers and write the first fields frame.
  void start(Simulation<D>& sim);
  // Continue from a snapshot frame instead: fields.h5 keeps its first `fields_frames` frames (the
  // last of them at this frame if `frame_written`), averaging intervals and collision statistics
  // start afresh here.
  void continue_from_frame(Simulation<D>& sim, std::int64_t fields_frames, bool frame_written);
  // Continue from a checkpoint instead: the files keep the frames written before it.
  void resume(Simulation<D>& sim, const StateArchive& archive, const std::string& prefix);
  void save(StateArchive& archive, const std::string& prefix) const;
  // The earliest collision count and time at which the loop must stop for a measurement.
  std::int64_t next_collisions() const override;
  double next_time() const override;
  void on_stop(Simulation<D>& sim) override { after_step(sim, false); }
  // After every step of the loop: start the collision statistics, refresh the local density at
  // window boundaries, write a fields frame when one is due (`final` forces one).
  void after_step(Simulation<D>& sim, bool final);
  // A configuration sampled by the run (output.every_*), the images moving at `shear_velocity`:
  // added to the fields' interval average.
  void on_sample(const StateBlocks& state, std::int64_t collisions, double shear_velocity);
  // Write collisions.h5 and close fields.h5.  Returns the summary figures for summary.json.
  nlohmann::json finish(const Simulation<D>& sim);

 private:
  void write_fields_frame(const Simulation<D>& sim);
  // The parts common to start() and resume(): schedules, accumulators, observers.
  void set_up(Simulation<D>& sim);
  FieldsMetadata fields_metadata() const;
  // σ of a monodisperse run; none when polydisperse (the observers take each collision's σ_ij).
  std::optional<double> monodisperse_diameter() const;

  RunConfig config_;
  std::string out_dir_;
  ShearFrame frame_;
  FieldGrid grid_;
  // fields
  Schedule fields_schedule_;
  std::unique_ptr<FieldsWriter> fields_writer_;
  std::unique_ptr<CellMoments> interval_moments_;
  std::unique_ptr<CollisionalStressField<D>> collisional_;
  double interval_start_t_ = 0.0, interval_start_c_ = 0.0;
  std::int64_t last_fields_collisions_ = -1;
  std::int64_t last_sample_collisions_ = -1;  // the configuration last added to the interval
  // collision statistics
  std::unique_ptr<LocalDensity> density_;
  std::unique_ptr<ImpactParameterStatistics<D>> impacts_;
  std::unique_ptr<FreePathStatistics<D>> paths_;
  std::int64_t statistics_start_ = 0;  // collision count at which recording starts
  bool statistics_started_ = false;
  double statistics_from_t_ = 0.0, statistics_from_c_ = 0.0;
  Schedule windows_;
};

}  // namespace granule::driver
