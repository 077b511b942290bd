#include "bindings/interactive_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <csignal>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "granule/version.hpp"
#include "io/input_ranges.hpp"
#include "io/snapshot_file.hpp"

namespace granule::bindings {

namespace {

RunConfig parsed_or_thrown(const ConfigResult& parsed) {
  if (!parsed.config) throw ConfigError(parsed.error);
  return *parsed.config;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// While it lives, the engine is paused (StopReason::kInterrupted after a whole event, a stop that
// changes nothing of the trajectory) every kInterval of wall time, so that the loops below ask
// keep_going (Ctrl-C) that often.  Chunks of collisions alone do not bound the wait: a gas that
// falls freely under gravity, or one whose grains no longer meet, runs events without collisions.
template <int D>
class Heartbeat {
 public:
  static constexpr std::chrono::milliseconds kInterval{100};

  explicit Heartbeat(Simulation<D>& sim) : sim_(sim), thread_([this] { beat(); }) { sim_.set_interrupt_flag(&paused_); }
  ~Heartbeat() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    wake_.notify_one();
    thread_.join();
    sim_.set_interrupt_flag(nullptr);
  }
  Heartbeat(const Heartbeat&) = delete;
  Heartbeat& operator=(const Heartbeat&) = delete;

  // After the engine paused: let it run on.
  void resume() { paused_ = 0; }

 private:
  void beat() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, kInterval, [this] { return done_; })) paused_ = 1;
  }

  Simulation<D>& sim_;
  // Read by the engine before each event (the flag it takes is a signal handler's kind).
  volatile std::sig_atomic_t paused_ = 0;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  std::thread thread_;
};

}  // namespace

RunConfig parse_run_config(const std::string& toml_text, const std::vector<std::string>& overrides) {
  return parsed_or_thrown(parse_config(toml_text, overrides));
}

RunConfig load_run_config(const std::string& path, const std::vector<std::string>& overrides) {
  return parsed_or_thrown(load_config_file(path, overrides));
}

template <int D>
InteractiveRun<D>::InteractiveRun(const RunConfig& config)
    : config_(config), grid_(driver::run_cell_grid(config)), run_(config, grid_, driver::run_start(config), std::nullopt) {}

template <int D>
StopReason InteractiveRun<D>::equilibrate(const std::function<bool()>& keep_going) {
  const auto start = std::chrono::steady_clock::now();
  const std::int64_t chunk = std::max<std::int64_t>(1000, config_.system.particles / 4);
  StopReason reason = StopReason::kCollisionsReached;
  Heartbeat<D> heartbeat(run_.engine());
  while (!in_production()) {
    if (!keep_going()) {
      reason = StopReason::kInterrupted;
      break;
    }
    reason = run_.prerun(chunk);
    heartbeat.resume();
  }
  wall_seconds_ += seconds_since(start);
  return reason;
}

template <int D>
RunTargets InteractiveRun<D>::targets(const RunLimits& limits) const {
  const Simulation<D>& sim = run_.engine();
  const bool given = limits.collisions_per_particle || limits.time;
  // The names in the messages: the argument of run(), or the configuration's key.
  const std::string c_name = given ? "until_collisions_per_particle" : "the configuration's run.until_collisions_per_particle";
  const std::string t_name = given ? "until_time" : "the configuration's run.until_time";
  const std::optional<double> c = given ? limits.collisions_per_particle : config_.until_collisions_per_particle;
  const std::optional<double> t = given ? limits.time : config_.until_time;
  RunTargets targets;
  if (c) {
    // The range of the configuration's collision counts (io/config.cpp): from one collision to
    // 2^62, so that the engine's int64 counters hold the target and a chunk beyond it.
    const auto n = static_cast<double>(config_.system.particles);
    const NumberRange counts{1.0 / n, kMaxCollisions / n};
    if (!counts.contains(*c)) {
      throw std::invalid_argument(fmt::format("{} = {}: must be a number of collisions per particle in {} for N = {} "
                                              "(from one collision, c·N ≥ 1, to 2^62 collisions)",
                                              c_name, *c, counts.text(), config_.system.particles));
    }
    targets.collisions = driver::collisions_for(config_, c);
    if (targets.collisions <= sim.collisions()) {
      throw std::invalid_argument(fmt::format("{} = {} is reached already: the run is at c = {} ({} collisions); "
                                              "targets are absolute, counted from the start of production",
                                              c_name, *c, sim.collisions_per_particle(), sim.collisions()));
    }
  }
  if (t) {
    if (!std::isfinite(*t) || *t <= 0.0) {
      throw std::invalid_argument(fmt::format("{} = {}: must be a time in (0, ∞)", t_name, *t));
    }
    targets.time = *t;
    if (targets.time <= sim.time()) {
      throw std::invalid_argument(fmt::format("{} = {} is reached already: the run is at t = {}; targets are absolute, "
                                              "counted from the start of production", t_name, *t, sim.time()));
    }
  }
  return targets;
}

template <int D>
StopReason InteractiveRun<D>::run(const RunTargets& targets, const std::function<bool()>& keep_going) {
  if (!in_production()) throw std::logic_error("InteractiveRun::run before equilibrate");
  const auto start = std::chrono::steady_clock::now();
  const Simulation<D>& sim = run_.engine();
  const std::int64_t until_collisions = targets.collisions;
  const double until_time = targets.time;
  const std::int64_t chunk = std::max<std::int64_t>(1000, config_.system.particles / 4);
  StopReason reason = StopReason::kCollisionsReached;
  Heartbeat<D> heartbeat(run_.engine());
  while (sim.collisions() < until_collisions && sim.time() < until_time) {
    if (!keep_going()) {
      reason = StopReason::kInterrupted;
      break;
    }
    reason = run_.advance({}, {std::min(until_collisions, sim.collisions() + chunk), until_time});
    heartbeat.resume();
    if (reason == StopReason::kInelasticCollapse || reason == StopReason::kNoEvents) break;
  }
  // The last row of a run's end, as RunSession::finish takes it.
  run_.sample_at_stop();
  wall_seconds_ += seconds_since(start);
  return reason;
}

template <int D>
nlohmann::json InteractiveRun<D>::summary(StopReason reason) const {
  const Simulation<D>& sim = run_.engine();
  const driver::RunFacts facts{wall_seconds_,           wall_seconds_,
                               sim.collisions(),        run_.prerun_collisions(),
                               run_.equilibrate_collisions(), 0};
  return driver::summary_json(config_, sim, grid_, reason, facts, samples());
}

namespace {

// A frame may be appended only to a file of the same system: the writer reopens a published file
// as `path`.partial and a refused frame would leave it under that name.  So the file's metadata
// is read and compared first.
void check_appendable(const std::string& path, const SnapshotMetadata& ours) {
  const SnapshotRead existing = read_snapshot(path);
  const SnapshotMetadata& theirs = existing.metadata;
  const SystemParams& a = theirs.system;
  const SystemParams& b = ours.system;
  const bool same = a.dimension == b.dimension && a.particles == b.particles && a.length_x == b.length_x &&
                    a.length_y == b.length_y && a.length_z == b.length_z && a.roughness.rough == b.roughness.rough &&
                    (a.tc_duration > 0.0) == (b.tc_duration > 0.0) &&
                    existing.frame.particles.diameter == ours.diameters;
  if (!same) {
    throw std::invalid_argument(fmt::format("{} holds snapshots of another system ({}D, N = {}, box {} × {}): a frame "
                                            "of this run ({}D, N = {}) is not appended to it", path, a.dimension,
                                            a.particles, a.length_x, a.length_y, b.dimension, b.particles));
  }
}

}  // namespace

template <int D>
void InteractiveRun<D>::write_snapshot(const std::string& path) const {
  const Simulation<D>& sim = run_.engine();
  const ParticleState now = sim.state();
  const SnapshotFrame frame{now, sim.clock_state(), sim.collisions_per_particle(), sim.shear_offset(), sim.strain(),
                            sim.image_velocity()};
  SnapshotMetadata metadata;
  metadata.system = config_.system;
  metadata.packing_fraction = config_.packing_fraction;
  metadata.boundary = boundary_kind_name(config_);
  metadata.seed = config_.seed;
  metadata.version = kVersion;
  metadata.diameters = now.diameter;
  metadata.masses = now.mass;
  if (std::filesystem::exists(path)) {
    check_appendable(path, metadata);
    SnapshotWriter writer(path);
    writer.append(frame);
    writer.finish();
    return;
  }
  SnapshotWriter writer(path, metadata);
  writer.append(frame);
  writer.finish();
}

template class InteractiveRun<2>;
template class InteractiveRun<3>;

}  // namespace granule::bindings
