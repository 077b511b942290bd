// The collision statistics of [collisions] (thesis §3.2): impact parameters and free paths, from
// collisions.from_collisions_per_particle on, classified by the local density at the start of
// each window of collisions, written to collisions.h5 (and CSV tables) at the run's end.  The two
// share their start, their windows and their density, and one file: they are one observable.
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>

#include "observers/collision_statistics_fits.hpp"
#include "observers/schedule.hpp"
#include "granule/version.hpp"
#include "io/collision_statistics_file.hpp"
#include "observers/free_paths.hpp"
#include "observers/impact_parameters.hpp"
#include "observables/observables.hpp"

namespace granule {

namespace {

template <int D>
class CollisionStatisticsObservable final : public Observable<D> {
 public:
  CollisionStatisticsObservable(const RunConfig& config, std::string out_dir)
      : config_(config), out_dir_(std::move(out_dir)), density_(fields_grid(config)) {
    const CollisionStatisticsConfig& k = config.collisions;
    const double n = static_cast<double>(config.system.particles);
    const std::int64_t window = std::max<std::int64_t>(1, std::llround(k.window_collisions_per_particle * n));
    if (k.impact_parameters) {
      impacts_.emplace(monodisperse_diameter(config), k.impact_bins, window, k.density_windows, &density_);
    }
    if (k.free_paths) {
      paths_.emplace(config.system.particles,
                     FreePathSettings{k.length_bins, k.angle_bins, k.max_length, k.widen_max_length, k.density_windows,
                                      k.speed_windows},
                     &density_);
    }
  }
  // The statistics hold the address of density_.
  CollisionStatisticsObservable(const CollisionStatisticsObservable&) = delete;
  CollisionStatisticsObservable& operator=(const CollisionStatisticsObservable&) = delete;

  void on_collision(const CollisionRecord<D>& record) override {
    if (impacts_ && started_) impacts_->on_collision(record);
    // Free paths see every collision: a path's beginning is the particle's previous collision.
    if (paths_) paths_->on_collision(record);
  }

  void start(Simulation<D>& sim) override {
    set_start(sim);
    density_.update(sim.state_blocks());
    after_step(sim, false);
  }

  void continue_from_frame(Simulation<D>& sim, const FrameContinuation&) override { start(sim); }

  void restore(Simulation<D>& sim, const StateArchive& archive, const std::string& prefix) override {
    density_.restore(archive, prefix + "density/");
    start_collisions_ = archive.integer(prefix + "statistics_start");
    started_ = archive.integer(prefix + "statistics_started") != 0;
    from_t_ = archive.scalar(prefix + "statistics_from_t");
    from_c_ = archive.scalar(prefix + "statistics_from_c");
    if (impacts_) impacts_->restore(archive, prefix + "impact_parameters/");
    if (paths_) paths_->restore(archive, prefix + "free_paths/");
    if (started_) {
      windows_ = window_schedule();
      windows_.restore(archive, prefix + "windows/", sim);
    }
  }

  void save(StateArchive& archive, const std::string& prefix) const override {
    density_.save(archive, prefix + "density/");
    archive.put_integer(prefix + "statistics_start", start_collisions_);
    archive.put_integer(prefix + "statistics_started", started_ ? 1 : 0);
    archive.put_scalar(prefix + "statistics_from_t", from_t_);
    archive.put_scalar(prefix + "statistics_from_c", from_c_);
    if (impacts_) impacts_->save(archive, prefix + "impact_parameters/");
    if (paths_) paths_->save(archive, prefix + "free_paths/");
    if (started_) windows_.save(archive, prefix + "windows/");
  }

  std::int64_t next_collisions() const override { return started_ ? windows_.next_collisions : start_collisions_; }
  double next_time() const override { return driver::kInf; }

  void after_step(Simulation<D>& sim, bool) override {
    if (!started_ && sim.collisions() >= start_collisions_) {
      started_ = true;
      from_t_ = sim.time();
      from_c_ = sim.collisions_per_particle();
      if (paths_) paths_->start();
      windows_ = window_schedule();
      windows_.start(config_.system.particles, sim.collisions());
      density_.update(sim.state_blocks());
    } else if (started_ && windows_.due(sim)) {
      // Classify the next window's collisions by the density at its start.
      density_.update(sim.state_blocks());
      windows_.advance(sim);
    }
  }

  void finish(const Simulation<D>& sim, nlohmann::json& summary) override {
    const SystemParams& s = config_.system;
    write_collision_statistics<D>(out_dir_,
                                  {s, boundary_kind_name(config_), kVersion, from_t_, from_c_, sim.time(),
                                   sim.collisions_per_particle(), density_.grid(), !config_.diameters.monodisperse()},
                                  impacts_ ? &*impacts_ : nullptr, paths_ ? &*paths_ : nullptr);
    if (impacts_) {
      const ImpactParameterSummary b = summarize_impact_parameters(impacts_->total(), impacts_->bins());
      summary["impact_parameters"] = {{"collisions", b.samples}, {"max_abs_B_minus_uniform", b.ks_uniform}};
    }
    if (paths_) summary["free_paths"] = free_path_figures();
    summary["collision_statistics_from_c"] = from_c_;
  }

 private:
  // Recording starts at collisions.from_collisions_per_particle, or now if that has passed.
  void set_start(const Simulation<D>& sim) {
    const double n = static_cast<double>(config_.system.particles);
    start_collisions_ = std::max<std::int64_t>(sim.collisions(), std::llround(config_.collisions.from_collisions_per_particle * n));
  }

  driver::Schedule window_schedule() const {
    driver::Schedule windows{config_.collisions.window_collisions_per_particle, std::nullopt};
    windows.start(config_.system.particles);
    return windows;
  }

  nlohmann::json free_path_figures() const {
    const SystemParams& s = config_.system;
    const FreePathSummary p = summarize_free_paths(paths_->total(), paths_->length_bins(), paths_->angle_bins(), D);
    nlohmann::json j = {{"paths", p.paths},           {"mean_length", p.mean_length},  {"l0_matched_eq_3_36", p.l0_matched},
                        {"alpha0_eq_3_24", p.alpha0}, {"lbar_eq_3_24", p.lbar},        {"ks_matched", p.ks_matched},
                        {"ks_exponential", p.ks_exponential},
                        // The histogram's range, widened from collisions.max_length as long paths came.
                        {"histogram_max_length", paths_->length_bins().high},
                        {"histogram_range_doublings", paths_->range_doublings()},
                        {"dropped_fraction", paths_->dropped_fraction()}};
    if constexpr (D == 2) {
      j["thesis_mean_free_path"] = s.length_x * s.length_y / (2.0 * static_cast<double>(s.particles) * s.diameter);
    } else {
      j["ks_isotropic_cos_theta"] = p.ks_isotropic;
      if (config_.diameters.monodisperse()) {
        const ReferenceMeanFreePaths reference = sphere_mean_free_paths(s);
        j["boltzmann_mean_free_path"] = reference.boltzmann;
        j["enskog_mean_free_path"] = reference.enskog;
      }
    }
    return j;
  }

  RunConfig config_;
  std::string out_dir_;
  LocalDensity density_;
  std::optional<ImpactParameterStatistics<D>> impacts_;
  std::optional<FreePathStatistics<D>> paths_;
  std::int64_t start_collisions_ = 0;  // collision count at which recording starts
  bool started_ = false;
  double from_t_ = 0.0, from_c_ = 0.0;
  driver::Schedule windows_;
};

}  // namespace

template <int D>
std::unique_ptr<Observable<D>> make_collision_statistics_observable(const RunConfig& config, const std::string& out_dir) {
  if (!config.collisions.impact_parameters && !config.collisions.free_paths) return nullptr;
  return std::make_unique<CollisionStatisticsObservable<D>>(config, out_dir);
}

template std::unique_ptr<Observable<2>> make_collision_statistics_observable(const RunConfig&, const std::string&);
template std::unique_ptr<Observable<3>> make_collision_statistics_observable(const RunConfig&, const std::string&);

}  // namespace granule
