#include "driver/run_measurements.hpp"

#include <algorithm>
#include <utility>

#include "analysis/collision_statistics_fits.hpp"
#include "granule/version.hpp"
#include "io/collision_statistics_file.hpp"

namespace granule::driver {

namespace {
// fields.cells in 2D; in 3D the default of ~20 spheres per cell.
FieldGrid fields_grid(const RunConfig& config) {
  const SystemParams& s = config.system;
  if (s.dimension == 3) return default_field_grid_3d(s.length_x, s.length_y, s.length_z, s.particles);
  return FieldGrid{config.fields.cells.first, config.fields.cells.second, s.length_x, s.length_y};
}
}  // namespace

template <int D>
RunMeasurements<D>::RunMeasurements(const RunConfig& config, std::string out_dir)
    : config_(config),
      out_dir_(std::move(out_dir)),
      frame_{config.system.length_x, config.system.length_y, config.system.shear_velocity},
      grid_(fields_grid(config)) {}

template <int D>
void RunMeasurements<D>::set_up(Simulation<D>& sim) {
  const SystemParams& s = config_.system;
  if (config_.fields.enabled) {
    // By default a fields frame goes with every snapshot.
    const bool own = config_.fields.every_collisions_per_particle || config_.fields.every_time;
    fields_schedule_ = own ? Schedule{config_.fields.every_collisions_per_particle, config_.fields.every_time}
                           : Schedule{config_.snapshot_every_collisions_per_particle, config_.snapshot_every_time};
    fields_schedule_.start(s.particles);
    collisional_ = std::make_unique<CollisionalStressField<D>>(grid_, monodisperse_diameter(), config_.system.roughness.rough);
    sim.add_observer(collisional_.get());
    interval_moments_ = std::make_unique<CellMoments>(grid_, spin_inertia(config_.system));
  }
  const CollisionStatisticsConfig& k = config_.collisions;
  if (k.impact_parameters || k.free_paths) {
    density_ = std::make_unique<LocalDensity>(grid_);
    statistics_start_ = std::max<std::int64_t>(sim.collisions(), std::llround(k.from_collisions_per_particle * static_cast<double>(s.particles)));
    const std::int64_t window = std::max<std::int64_t>(1, std::llround(k.window_collisions_per_particle * static_cast<double>(s.particles)));
    if (k.impact_parameters) {
      impacts_ = std::make_unique<ImpactParameterStatistics<D>>(monodisperse_diameter(), k.impact_bins, window,
                                                                k.density_windows, density_.get());
    }
    if (k.free_paths) {
      // Attached from the start: a path's beginning is the disk's previous collision.
      paths_ = std::make_unique<FreePathStatistics<D>>(
          s.particles, FreePathSettings{k.length_bins, k.angle_bins, k.max_length, k.widen_max_length, k.density_windows,
                                       k.speed_windows},
          density_.get());
      sim.add_observer(paths_.get());
    }
  }
}

template <int D>
std::optional<double> RunMeasurements<D>::monodisperse_diameter() const {
  if (config_.diameters.monodisperse()) return config_.system.diameter;
  return std::nullopt;
}

template <int D>
FieldsMetadata RunMeasurements<D>::fields_metadata() const {
  return {config_.system, boundary_kind_name(config_), config_.fields.subtract_shear_profile, "run",
          kVersion};
}

template <int D>
void RunMeasurements<D>::start(Simulation<D>& sim) {
  set_up(sim);
  if (config_.fields.enabled) {
    fields_schedule_.advance(sim);
    fields_writer_ = std::make_unique<FieldsWriter>(out_dir_ + "/fields.h5", grid_, fields_metadata(), true);
    write_fields_frame(sim);
  }
  if (density_) {
    density_->update(sim.state_blocks());
    after_step(sim, false);
  }
}

template <int D>
void RunMeasurements<D>::continue_from_frame(Simulation<D>& sim, std::int64_t fields_frames, bool frame_written) {
  set_up(sim);
  interval_start_t_ = sim.time();
  interval_start_c_ = sim.collisions_per_particle();
  if (collisional_) collisional_->restart(sim.time());
  if (config_.fields.enabled) {
    fields_schedule_.advance(sim);
    fields_writer_ = std::make_unique<FieldsWriter>(out_dir_ + "/fields.h5", fields_frames);
    if (frame_written) last_fields_collisions_ = sim.collisions();
  }
  if (density_) {
    density_->update(sim.state_blocks());
    after_step(sim, false);
  }
}

template <int D>
void RunMeasurements<D>::resume(Simulation<D>& sim, const StateArchive& archive, const std::string& prefix) {
  set_up(sim);
  if (config_.fields.enabled) {
    fields_schedule_.restore(archive, prefix + "fields_schedule/", sim);
    interval_moments_->restore(archive, prefix + "interval_moments/");
    if (collisional_) collisional_->restore(archive, prefix + "collisional_stress/");
    interval_start_t_ = archive.scalar(prefix + "interval_start_t");
    interval_start_c_ = archive.scalar(prefix + "interval_start_c");
    last_fields_collisions_ = archive.integer(prefix + "last_fields_collisions");
    last_sample_collisions_ = archive.integer(prefix + "last_sample_collisions");
    fields_writer_ = std::make_unique<FieldsWriter>(out_dir_ + "/fields.h5", archive.integer(prefix + "fields_frames"));
  }
  if (density_) {
    density_->restore(archive, prefix + "density/");
    statistics_start_ = archive.integer(prefix + "statistics_start");
    statistics_started_ = archive.integer(prefix + "statistics_started") != 0;
    statistics_from_t_ = archive.scalar(prefix + "statistics_from_t");
    statistics_from_c_ = archive.scalar(prefix + "statistics_from_c");
    if (impacts_) impacts_->restore(archive, prefix + "impact_parameters/");
    if (paths_) paths_->restore(archive, prefix + "free_paths/");
    if (statistics_started_) {
      windows_ = Schedule{config_.collisions.window_collisions_per_particle, std::nullopt};
      windows_.start(config_.system.particles);
      windows_.restore(archive, prefix + "windows/", sim);
      if (impacts_) sim.add_observer(impacts_.get());
    }
  }
}

template <int D>
void RunMeasurements<D>::save(StateArchive& archive, const std::string& prefix) const {
  if (fields_writer_) {
    fields_schedule_.save(archive, prefix + "fields_schedule/");
    interval_moments_->save(archive, prefix + "interval_moments/");
    if (collisional_) collisional_->save(archive, prefix + "collisional_stress/");
    archive.put_scalar(prefix + "interval_start_t", interval_start_t_);
    archive.put_scalar(prefix + "interval_start_c", interval_start_c_);
    archive.put_integer(prefix + "last_fields_collisions", last_fields_collisions_);
    archive.put_integer(prefix + "last_sample_collisions", last_sample_collisions_);
    archive.put_integer(prefix + "fields_frames", fields_writer_->frames());
  }
  if (density_) {
    density_->save(archive, prefix + "density/");
    archive.put_integer(prefix + "statistics_start", statistics_start_);
    archive.put_integer(prefix + "statistics_started", statistics_started_ ? 1 : 0);
    archive.put_scalar(prefix + "statistics_from_t", statistics_from_t_);
    archive.put_scalar(prefix + "statistics_from_c", statistics_from_c_);
    if (impacts_) impacts_->save(archive, prefix + "impact_parameters/");
    if (paths_) paths_->save(archive, prefix + "free_paths/");
    if (statistics_started_) windows_.save(archive, prefix + "windows/");
  }
}

template <int D>
std::int64_t RunMeasurements<D>::next_collisions() const {
  std::int64_t next = fields_writer_ ? fields_schedule_.next_collisions : kNoLimit;
  if (density_) next = std::min(next, statistics_started_ ? windows_.next_collisions : statistics_start_);
  return next;
}

template <int D>
double RunMeasurements<D>::next_time() const { return fields_writer_ ? fields_schedule_.next_time : kInf; }

template <int D>
void RunMeasurements<D>::after_step(Simulation<D>& sim, bool final) {
  if (density_ && !statistics_started_ && sim.collisions() >= statistics_start_) {
    statistics_started_ = true;
    statistics_from_t_ = sim.time();
    statistics_from_c_ = sim.collisions_per_particle();
    if (impacts_) sim.add_observer(impacts_.get());
    if (paths_) paths_->start();
    windows_ = Schedule{config_.collisions.window_collisions_per_particle, std::nullopt};
    windows_.start(config_.system.particles, sim.collisions());
    density_->update(sim.state_blocks());
  } else if (statistics_started_ && windows_.due(sim)) {
    // Classify the next window's collisions by the density at its start.
    density_->update(sim.state_blocks());
    windows_.advance(sim);
  }
  if (fields_writer_ && (fields_schedule_.due(sim) || final)) {
    // A frame needs at least one collision since the last one (the collisional stress is an
    // average over the interval); the schedule moves on either way, so it can never stall.
    if (sim.collisions() != last_fields_collisions_) write_fields_frame(sim);
    fields_schedule_.advance(sim);
  }
}

template <int D>
void RunMeasurements<D>::on_sample(const StateBlocks& state, std::int64_t collisions, double shear_velocity) {
  if (!interval_moments_) return;
  frame_.shear_velocity = shear_velocity;  // the profile u(y) subtracted is that of U now
  interval_moments_->add(state, frame_, config_.fields.subtract_shear_profile);
  last_sample_collisions_ = collisions;
}

template <int D>
void RunMeasurements<D>::write_fields_frame(const Simulation<D>& sim) {
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
  if (collisional_) {
    frame.collisional = collisional_->stress(sim.time());
    frame.heat_flux_collisional = collisional_heat_flux(*frame.collisional, frame.average, frame_, subtract);
  }
  fields_writer_->append(frame);
  last_fields_collisions_ = sim.collisions();
  interval_moments_ = std::make_unique<CellMoments>(grid_, spin_inertia(config_.system));
  if (collisional_) collisional_->restart(sim.time());
  interval_start_t_ = frame.t;
  interval_start_c_ = frame.c;
}

template <int D>
nlohmann::json RunMeasurements<D>::finish(const Simulation<D>& sim) {
  nlohmann::json j = nlohmann::json::object();
  if (fields_writer_) {
    fields_writer_->finish();
    j["fields_frames"] = fields_writer_->frames();
  }
  if (!density_) return j;
  const SystemParams& s = config_.system;
  write_collision_statistics<D>(out_dir_,
                                {s, boundary_kind_name(config_), kVersion, statistics_from_t_,
                                 statistics_from_c_, sim.time(), sim.collisions_per_particle(), grid_,
                                 !config_.diameters.monodisperse()},
                                impacts_.get(), paths_.get());
  if (impacts_) {
    const ImpactParameterSummary b = summarize_impact_parameters(impacts_->total(), impacts_->bins());
    j["impact_parameters"] = {{"collisions", b.samples}, {"max_abs_B_minus_uniform", b.ks_uniform}};
  }
  if (paths_) {
    const FreePathSummary p = summarize_free_paths(paths_->total(), paths_->length_bins(), paths_->angle_bins(), D);
    j["free_paths"] = {{"paths", p.paths},           {"mean_length", p.mean_length},  {"l0_matched_eq_3_36", p.l0_matched},
                       {"alpha0_eq_3_24", p.alpha0}, {"lbar_eq_3_24", p.lbar},        {"ks_matched", p.ks_matched},
                       {"ks_exponential", p.ks_exponential},
                       // The histogram's range, widened from collisions.max_length as long paths came.
                       {"histogram_max_length", paths_->length_bins().high},
                       {"histogram_range_doublings", paths_->range_doublings()},
                       {"dropped_fraction", paths_->dropped_fraction()}};
    if constexpr (D == 2) {
      j["free_paths"]["thesis_mean_free_path"] = s.length_x * s.length_y / (2.0 * static_cast<double>(s.particles) * s.diameter);
    } else {
      j["free_paths"]["ks_isotropic_cos_theta"] = p.ks_isotropic;
      if (config_.diameters.monodisperse()) {
        const ReferenceMeanFreePaths reference = sphere_mean_free_paths(s);
        j["free_paths"]["boltzmann_mean_free_path"] = reference.boltzmann;
        j["free_paths"]["enskog_mean_free_path"] = reference.enskog;
      }
    }
  }
  j["collision_statistics_from_c"] = statistics_from_c_;
  return j;
}

template class RunMeasurements<2>;
template class RunMeasurements<3>;

}  // namespace granule::driver
