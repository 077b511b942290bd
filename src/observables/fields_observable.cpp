// The coarse-grained fields of [fields] (§1.4.3) with the collisional stress and heat flux (1.6),
// written to fields.h5 as the run goes: each frame holds the instantaneous fields and their
// average over the interval since the previous frame (the configurations sampled in between, and
// every collision for the collisional part).
#include <memory>
#include <utility>

#include "observers/schedule.hpp"
#include "granule/version.hpp"
#include "io/fields_file.hpp"
#include "observers/collisional_stress.hpp"
#include "observables/observables.hpp"

namespace granule {

namespace {

template <int D>
class FieldsObservable final : public Observable<D> {
 public:
  FieldsObservable(const RunConfig& config, std::string out_dir)
      : config_(config),
        out_dir_(std::move(out_dir)),
        frame_{config.system.length_x, config.system.length_y, config.system.shear_velocity},
        grid_(fields_grid(config)),
        collisional_(grid_, monodisperse_diameter(config), config.system.roughness.rough),
        interval_moments_(new_moments()) {
    // By default a fields frame goes with every snapshot.
    const FieldsConfig& f = config.fields;
    schedule_ = f.every_collisions_per_particle || f.every_time
                    ? driver::Schedule{f.every_collisions_per_particle, f.every_time}
                    : driver::Schedule{config.snapshot_every_collisions_per_particle, config.snapshot_every_time};
    schedule_.start(config.system.particles);
  }

  void on_collision(const CollisionRecord<D>& record) override { collisional_.on_collision(record); }

  void start(Simulation<D>& sim) override {
    schedule_.advance(sim);
    writer_ = std::make_unique<FieldsWriter>(out_dir_ + "/fields.h5", grid_, metadata(), true);
    write_frame(sim);
  }

  void continue_from_frame(Simulation<D>& sim, const FrameContinuation& kept) override {
    interval_start_t_ = sim.time();
    interval_start_c_ = sim.collisions_per_particle();
    collisional_.restart(sim.time());
    schedule_.advance(sim);
    writer_ = std::make_unique<FieldsWriter>(out_dir_ + "/fields.h5", kept.fields_frames);
    if (kept.fields_frame_at_start) last_frame_collisions_ = sim.collisions();
  }

  void restore(Simulation<D>& sim, const StateArchive& archive, const std::string& prefix) override {
    schedule_.restore(archive, prefix + "fields_schedule/", sim);
    interval_moments_->restore(archive, prefix + "interval_moments/");
    collisional_.restore(archive, prefix + "collisional_stress/");
    interval_start_t_ = archive.scalar(prefix + "interval_start_t");
    interval_start_c_ = archive.scalar(prefix + "interval_start_c");
    last_frame_collisions_ = archive.integer(prefix + "last_fields_collisions");
    last_sample_collisions_ = archive.integer(prefix + "last_sample_collisions");
    writer_ = std::make_unique<FieldsWriter>(out_dir_ + "/fields.h5", archive.count(prefix + "fields_frames"));
  }

  void save(StateArchive& archive, const std::string& prefix) const override {
    schedule_.save(archive, prefix + "fields_schedule/");
    interval_moments_->save(archive, prefix + "interval_moments/");
    collisional_.save(archive, prefix + "collisional_stress/");
    archive.put_scalar(prefix + "interval_start_t", interval_start_t_);
    archive.put_scalar(prefix + "interval_start_c", interval_start_c_);
    archive.put_integer(prefix + "last_fields_collisions", last_frame_collisions_);
    archive.put_integer(prefix + "last_sample_collisions", last_sample_collisions_);
    archive.put_integer(prefix + "fields_frames", writer_->frames());
  }

  std::int64_t next_collisions() const override { return schedule_.next_collisions; }
  double next_time() const override { return schedule_.next_time; }

  void after_step(Simulation<D>& sim, bool final) override {
    if (!schedule_.due(sim) && !final) return;
    // A frame needs at least one collision since the last one (the collisional stress is an
    // average over the interval); the schedule moves on either way, so it can never stall.
    if (sim.collisions() != last_frame_collisions_) write_frame(sim);
    schedule_.advance(sim);
  }

  void on_sample(const StateBlocks& state, std::int64_t collisions, double shear_velocity) override {
    frame_.shear_velocity = shear_velocity;  // the profile u(y) subtracted is that of U now
    interval_moments_->add(state, frame_, config_.fields.subtract_shear_profile);
    last_sample_collisions_ = collisions;
  }

  void finish(const Simulation<D>&, nlohmann::json& summary) override {
    writer_->finish();
    summary["fields_frames"] = writer_->frames();
  }

 private:
  std::unique_ptr<CellMoments> new_moments() const {
    return std::make_unique<CellMoments>(grid_, spin_inertia(config_.system));
  }

  FieldsMetadata metadata() const {
    return {config_.system, boundary_kind_name(config_), config_.fields.subtract_shear_profile, "run", kVersion};
  }

  void write_frame(const Simulation<D>& sim) {
    const bool subtract = config_.fields.subtract_shear_profile;
    const StateBlocks state = sim.state_blocks();
    frame_.shear_velocity = sim.image_velocity();
    CellMoments instant(grid_, spin_inertia(config_.system));
    instant.add(state, frame_, subtract);
    // The interval average includes the configuration that closes it (once).
    if (last_sample_collisions_ != sim.collisions()) interval_moments_->add(state, frame_, subtract);
    FieldsFrame frame;
    frame.t = sim.time();
    frame.c = sim.collisions_per_particle();
    frame.t_start = interval_start_t_;
    frame.c_start = interval_start_c_;
    frame.configurations = interval_moments_->configurations;
    frame.shear_offset = sim.shear_offset();
    frame.shear_velocity = sim.image_velocity();
    frame.instant = fields_from_moments(instant, frame_, sim.shear_offset(), subtract);
    frame.average = fields_from_moments(*interval_moments_, frame_, sim.shear_offset(), subtract);
    frame.collisional = collisional_.stress(sim.time());
    frame.heat_flux_collisional = collisional_heat_flux(*frame.collisional, frame.average, frame_, subtract);
    writer_->append(frame);
    last_frame_collisions_ = sim.collisions();
    interval_moments_ = new_moments();
    collisional_.restart(sim.time());
    interval_start_t_ = frame.t;
    interval_start_c_ = frame.c;
  }

  RunConfig config_;
  std::string out_dir_;
  ShearFrame frame_;
  FieldGrid grid_;
  CollisionalStressField<D> collisional_;
  std::unique_ptr<CellMoments> interval_moments_;
  driver::Schedule schedule_;
  std::unique_ptr<FieldsWriter> writer_;
  double interval_start_t_ = 0.0, interval_start_c_ = 0.0;
  std::int64_t last_frame_collisions_ = -1;
  std::int64_t last_sample_collisions_ = -1;  // the configuration last added to the interval
};

}  // namespace

template <int D>
std::unique_ptr<Observable<D>> make_fields_observable(const RunConfig& config, const std::string& out_dir) {
  if (!config.fields.enabled) return nullptr;
  return std::make_unique<FieldsObservable<D>>(config, out_dir);
}

template std::unique_ptr<Observable<2>> make_fields_observable(const RunConfig&, const std::string&);
template std::unique_ptr<Observable<3>> make_fields_observable(const RunConfig&, const std::string&);

}  // namespace granule
