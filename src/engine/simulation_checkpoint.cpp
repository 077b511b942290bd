// Checkpoints of the engine: everything that decides its future — positions at local times,
// pending events, cell-list and heap order (they break ties), clocks, TC history, the collapse
// detector — so that a run restored from one continues bit for bit (tests/validation).
#include <stdexcept>

#include "engine/simulation.hpp"

namespace granule {

namespace {

// The parameters a checkpoint must agree with (the restitution is restored: during the elastic
// pre-run it is 1, not the configured value).
void check_matches(const StateArchive& archive, const std::string& prefix, const SystemParams& p, const CellGrid& g) {
  const auto expect = [&](const char* name, double value) {
    if (archive.scalar(prefix + name) != value) {
      throw std::runtime_error(std::string("checkpoint was written with another ") + name +
                               " than the configuration gives");
    }
  };
  expect("particles", static_cast<double>(p.particles));
  expect("diameter", p.diameter);
  expect("length_x", p.length_x);
  expect("length_y", p.length_y);
  expect("shear_velocity", p.shear_velocity);
  expect("tc_duration", p.tc_duration);
  expect("grid_nx", g.nx);
  expect("grid_ny", g.ny);
  expect("grid_width", g.width);
  expect("grid_height", g.height);
  expect("grid_strain_period", g.strain_period);
}

template <typename T>
std::vector<T> array_of_size(const StateArchive& archive, const std::string& name, std::size_t n) {
  std::vector<T> values = archive.get<T>(name);
  if (values.size() != n) throw std::runtime_error("checkpoint entry " + name + " has the wrong length");
  return values;
}

}  // namespace

void Simulation::save(StateArchive& archive, const std::string& prefix) const {
  archive.put_scalar(prefix + "particles", static_cast<double>(params_.particles));
  archive.put_scalar(prefix + "diameter", params_.diameter);
  archive.put_scalar(prefix + "length_x", params_.length_x);
  archive.put_scalar(prefix + "length_y", params_.length_y);
  archive.put_scalar(prefix + "shear_velocity", params_.shear_velocity);
  archive.put_scalar(prefix + "tc_duration", params_.tc_duration);
  archive.put_scalar(prefix + "restitution", params_.restitution);
  archive.put_scalar(prefix + "grid_nx", grid_.nx);
  archive.put_scalar(prefix + "grid_ny", grid_.ny);
  archive.put_scalar(prefix + "grid_width", grid_.width);
  archive.put_scalar(prefix + "grid_height", grid_.height);
  archive.put_scalar(prefix + "grid_strain_period", grid_.strain_period);

  archive.put(prefix + "x", x_);
  archive.put(prefix + "y", y_);
  archive.put(prefix + "vx", vx_);
  archive.put(prefix + "vy", vy_);
  archive.put(prefix + "local_time", t_);
  archive.put(prefix + "collision_count", count_);
  archive.put(prefix + "cell", cell_);
  archive.put(prefix + "last_collision", last_collision_);
  std::vector<std::uint8_t> kinds(kind_.size());
  for (std::size_t i = 0; i < kinds.size(); ++i) kinds[i] = static_cast<std::uint8_t>(kind_[i]);
  archive.put(prefix + "event_kind", std::move(kinds));
  archive.put(prefix + "event_partner", partner_);
  archive.put(prefix + "event_partner_count", partner_count_);
  lists_.save(archive, prefix + "cell_list_");
  heap_.save(archive, prefix + "heap_");
  collapse_detector_.save(archive, prefix + "collapse_");

  archive.put_scalar(prefix + "t_now", t_now_);
  archive.put_scalar(prefix + "clock_base", clock_base_);
  archive.put_scalar(prefix + "t_ref", t_ref_);
  archive.put_integer(prefix + "collisions", collisions_);
  archive.put_integer(prefix + "events", events_);
  archive.put_integer(prefix + "events_since_rebase", events_since_rebase_);
}

Simulation::Simulation(const SystemParams& params, const CellGrid& grid, const StateArchive& archive,
                       const std::string& prefix)
    : params_(params),
      grid_(grid),
      frame_{params.length_x, params.length_y, params.shear_velocity},
      shear_rate_(params.shear_velocity / params.length_y) {
  check_matches(archive, prefix, params, grid);
  params_.restitution = archive.scalar(prefix + "restitution");
  const auto n = static_cast<std::size_t>(params.particles);
  x_ = array_of_size<double>(archive, prefix + "x", n);
  y_ = array_of_size<double>(archive, prefix + "y", n);
  vx_ = array_of_size<double>(archive, prefix + "vx", n);
  vy_ = array_of_size<double>(archive, prefix + "vy", n);
  t_ = array_of_size<double>(archive, prefix + "local_time", n);
  count_ = array_of_size<std::uint32_t>(archive, prefix + "collision_count", n);
  cell_ = array_of_size<std::int32_t>(archive, prefix + "cell", n);
  last_collision_ = array_of_size<double>(archive, prefix + "last_collision", params.tc_duration > 0.0 ? n : 0);
  const auto kinds = array_of_size<std::uint8_t>(archive, prefix + "event_kind", n);
  kind_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (kinds[i] > static_cast<std::uint8_t>(EventKind::kCrossUp)) throw std::runtime_error("checkpoint has an unknown event kind");
    kind_[i] = static_cast<EventKind>(kinds[i]);
  }
  partner_ = array_of_size<std::int32_t>(archive, prefix + "event_partner", n);
  partner_count_ = array_of_size<std::uint32_t>(archive, prefix + "event_partner_count", n);
  for (std::size_t i = 0; i < n; ++i) {
    const bool collision = kind_[i] == EventKind::kCollision;
    if (cell_[i] < 0 || cell_[i] >= grid.cell_count() || partner_[i] < -1 || partner_[i] >= params.particles ||
        (collision && partner_[i] < 0)) {
      throw std::runtime_error("checkpoint has a disk with an invalid cell or event partner");
    }
  }
  lists_.restore(archive, prefix + "cell_list_", grid.cell_count(), params.particles);
  heap_.restore(archive, prefix + "heap_", static_cast<std::int32_t>(params.particles));
  collapse_detector_.restore(archive, prefix + "collapse_");
  t_now_ = archive.scalar(prefix + "t_now");
  clock_base_ = archive.scalar(prefix + "clock_base");
  t_ref_ = archive.scalar(prefix + "t_ref");
  collisions_ = archive.integer(prefix + "collisions");
  events_ = archive.integer(prefix + "events");
  events_since_rebase_ = archive.integer(prefix + "events_since_rebase");
  // A damaged or hand-edited checkpoint must not start a run that is silently wrong.
  try {
    check_invariants();
  } catch (const std::logic_error& error) {
    throw std::runtime_error(std::string("checkpoint fails the engine's invariants: ") + error.what());
  }
}

}  // namespace granule
