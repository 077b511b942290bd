// Checkpoints of the engine: everything that decides its future — false positions at the clock base,
// pending events, the engine's numbering of the particles, cell-list order (it breaks ties between equal collision times), clocks, TC history, the collapse
// detector — so that a run restored from one continues bit for bit (tests/validation).
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <utility>

#include "boundary/surface_identity.hpp"
#include "engine/simulation.hpp"

namespace granule {

namespace {

// The grains' restitutions a checkpoint records (elastic during the pre-run), by name and reference; the
// surfaces' are in their identity (boundary/surface_identity.hpp).
template <typename Params, typename Visit>
void visit_restitutions(Params& p, Visit&& visit) {
  visit("restitution", p.restitution);
  if (p.roughness.rough) visit("tangential_restitution", p.roughness.tangential_restitution);
}

// The parameters a checkpoint must agree with: those the run has at the checkpoint, which the
// caller gives (during the elastic pre-run every restitution is elastic, elastic_prerun).
void check_matches(const StateArchive& archive, const std::string& prefix, const SystemParams& p, const CellGrid& g,
                   int dimension) {
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
  visit_restitutions(p, [&](const std::string& name, double value) { expect(name.c_str(), value); });
  if (dimension == 3) {
    expect("length_z", p.length_z);
    expect("grid_nz", g.nz);
    expect("grid_depth", g.depth);
  }
}

// The fixed parameters of spin and gravity a run has, by checkpoint name (none for a run of
// smooth grains without gravity: its checkpoint holds no such entries).
std::map<std::string, double> law_and_motion_parameters(const SystemParams& p, int dimension) {
  std::map<std::string, double> out;
  if (p.roughness.rough) {
    out["inertia_factor"] = p.roughness.inertia_factor;
    out["friction"] = p.roughness.friction;
  }
  if (p.has_gravity()) {
    for (int a = 0; a < dimension; ++a) out[std::string("gravity_") + "xyz"[a]] = p.gravity[static_cast<std::size_t>(a)];
  }
  if (p.rest.on()) {
    out["rest_speed"] = p.rest.speed;
    out["wake_speed"] = p.rest.wake_speed;
  }
  return out;
}

// Everything a checkpoint records of the surfaces, the collision law and the motion, by name.
std::map<std::string, std::vector<double>> recorded_parameters(const SystemParams& p, int dimension) {
  std::map<std::string, std::vector<double>> out = surface_identity(p.surfaces(), dimension);
  for (const auto& [name, value] : law_and_motion_parameters(p, dimension)) out[name] = {value};
  return out;
}

// Every name recorded_parameters can give (of wall schedules, the first point beyond p's).
std::set<std::string> recorded_parameter_names(const SystemParams& p, int dimension) {
  std::set<std::string> names = surface_identity_names(p.surfaces(), dimension);
  SystemParams every;
  every.roughness.rough = true;
  every.gravity = {1.0, 1.0, 1.0};
  every.rest.speed = 1.0;
  for (const auto& entry : law_and_motion_parameters(every, dimension)) names.insert(entry.first);
  return names;
}

void check_surfaces_match(const StateArchive& archive, const std::string& prefix, const SystemParams& p, int dimension) {
  const std::map<std::string, std::vector<double>> expected = recorded_parameters(p, dimension);
  // Shortest names first: the entry that marks a feature (walls_y) before its details (wall_2_…).
  const auto by_length = [](const std::string& a, const std::string& b) { return a.size() != b.size() ? a.size() < b.size() : a < b; };
  std::set<std::string, decltype(by_length)> names(by_length);
  for (const std::string& name : recorded_parameter_names(p, dimension)) names.insert(name);
  for (const auto& entry : expected) names.insert(entry.first);
  for (const std::string& name : names) {
    const bool recorded = archive.contains(prefix + name);
    const auto wanted = expected.find(name);
    if (recorded && wanted == expected.end()) {
      throw std::runtime_error("checkpoint was written with " + name + ", which the configuration does not have");
    }
    if (!recorded && wanted != expected.end()) {
      throw std::runtime_error("checkpoint was written without " + name + ", which the configuration has");
    }
    if (recorded && archive.get<double>(prefix + name) != wanted->second) {
      throw std::runtime_error("checkpoint was written with another " + name + " than the configuration gives");
    }
  }
}

// The fields of the particle records a checkpoint holds, one array each, by name and an accessor.
template <int D, typename Visit>
void visit_record_fields(Visit&& visit) {
  visit("x", [](auto& p) -> auto& { return p.r.x; });
  visit("y", [](auto& p) -> auto& { return p.r.y; });
  visit("vx", [](auto& p) -> auto& { return p.v.x; });
  visit("vy", [](auto& p) -> auto& { return p.v.y; });
  if constexpr (D == 3) {
    visit("z", [](auto& p) -> auto& { return p.r.z; });
    visit("vz", [](auto& p) -> auto& { return p.v.z; });
  }
  visit("collision_count", [](auto& p) -> auto& { return p.count; });
  visit("cell_list_next", [](auto& p) -> auto& { return p.next; });
  visit("event_partner", [](auto& p) -> auto& { return p.partner; });
  visit("event_partner_count", [](auto& p) -> auto& { return p.partner_count; });
}

// Each field of `items` as one array of the archive (generated when the archive is written: the
// view of the items must outlive this call, the items themselves are the engine's).
template <typename Item, typename Fields>
void put_fields(StateArchive& archive, const std::string& prefix, std::span<const Item> items, Fields&& visit_fields) {
  visit_fields([&](const char* name, auto field) {
    using Value = std::decay_t<decltype(field(items[0]))>;
    archive.put_generated<Value>(prefix + name, items.size(), [items, field](std::size_t first, std::span<Value> out) {
      for (std::size_t k = 0; k < out.size(); ++k) out[k] = field(items[first + k]);
    });
  });
}

bool optional_array(std::string_view name) {
  return name == "particle_diameter" || name == "particle_mass" || name.substr(0, 5) == "spin_";
}

template <typename T>
std::vector<T> array_of_size(const StateArchive& archive, const std::string& name, std::size_t n) {
  std::vector<T> values = archive.get<T>(name);
  if (values.size() != n) throw std::runtime_error("checkpoint entry " + name + " has the wrong length");
  return values;
}

}  // namespace

template <int D>
template <typename Self, typename Visit>
void Simulation<D>::visit_saved_state(Self& self, Visit&& visit) {
  visit("particle_diameter", self.diameter_);
  visit("particle_mass", self.mass_);
  if constexpr (D == 3) {
    visit("spin_x", self.spin_[0]);
    visit("spin_y", self.spin_[1]);
  }
  visit("spin_z", self.spin_[kSpinComponents - 1]);
  visit("last_collision", self.last_collision_);
  visit("t_now", self.t_now_);
  visit("clock_base", self.clock_base_);
  visit("t_ref", self.t_ref_);
  visit("strain_at_reference", self.strain_ref_);
  visit("image_velocity", self.boundaries_.image_velocity());
  visit("shear_segment_end", self.segment_end_);
  visit("collisions", self.collisions_);
  visit("events", self.events_);
  visit("events_since_rebase", self.events_since_rebase_);
}

template <int D>
void Simulation<D>::save(StateArchive& archive, const std::string& prefix) const {
  archive.put_scalar(prefix + "particles", static_cast<double>(params_.particles));
  archive.put_scalar(prefix + "diameter", params_.diameter);
  archive.put_scalar(prefix + "length_x", params_.length_x);
  archive.put_scalar(prefix + "length_y", params_.length_y);
  archive.put_scalar(prefix + "shear_velocity", params_.shear_velocity);
  archive.put_scalar(prefix + "tc_duration", params_.tc_duration);
  visit_restitutions(params_, [&](const std::string& name, double value) { archive.put_scalar(prefix + name, value); });
  for (auto& [name, values] : recorded_parameters(params_, D)) archive.put(prefix + name, std::move(values));
  archive.put_scalar(prefix + "grid_nx", grid_.nx);
  archive.put_scalar(prefix + "grid_ny", grid_.ny);
  archive.put_scalar(prefix + "grid_width", grid_.width);
  archive.put_scalar(prefix + "grid_height", grid_.height);
  archive.put_scalar(prefix + "grid_strain_period", grid_.strain_period);
  if constexpr (D == 3) {
    archive.put_scalar(prefix + "length_z", params_.length_z);
    archive.put_scalar(prefix + "grid_nz", grid_.nz);
    archive.put_scalar(prefix + "grid_depth", grid_.depth);
  }

  visit_saved_state(*this, [&](const char* name, const auto& value) {
    // Per-particle diameters and masses exist only in polydisperse runs, spins only for rough
    // grains: other checkpoints have no such entries.
    if constexpr (!std::is_arithmetic_v<std::decay_t<decltype(value)>>) {
      if (value.empty() && optional_array(name)) return;
    }
    if constexpr (std::is_same_v<std::decay_t<decltype(value)>, double>) {
      archive.put_scalar(prefix + name, value);
    } else if constexpr (std::is_same_v<std::decay_t<decltype(value)>, std::int64_t>) {
      archive.put_integer(prefix + name, value);
    } else {
      archive.put_view(prefix + name, value);
    }
  });
  put_fields(archive, prefix, std::span<const ParticleRecord<D>>(particles_), [](auto&& visit) { visit_record_fields<D>(visit); });
  // The event slots' cell and kind, packed in one word, and their times, the queue's, apart.
  const std::span<const EventSlot> slots = queue_.slots();
  archive.put_generated<std::int32_t>(prefix + "cell", slots.size(), [slots](std::size_t first, std::span<std::int32_t> out) {
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = slots[first + k].cell();
  });
  archive.put_generated<std::uint8_t>(prefix + "event_kind", slots.size(), [slots](std::size_t first, std::span<std::uint8_t> out) {
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = static_cast<std::uint8_t>(slots[first + k].kind());
  });
  archive.put_integer(prefix + "protocol_running", protocol_running_ ? 1 : 0);
  archive.put_scalar(prefix + "shear_segment_action", actions_.time_of(TimedAction::kShearSegment));
  // The engine's numbering (absent while it is the user's: checkpoints of runs that never
  // renumber hold no such entries).
  if (!user_id_.empty()) {
    archive.put_view(prefix + "particle_id", user_id_);
    archive.put_integer(prefix + "events_since_renumber", events_since_renumber_);
  }
  lists_.save(archive, prefix + "cell_list_");
  queue_.save(archive, prefix + "queue_");
  collapse_detector_.save(archive, prefix + "collapse_");
}

template <int D>
Simulation<D>::Simulation(const SystemParams& params, const CellGrid& grid, const StateArchive& archive,
                          const std::string& prefix)
    : params_(params),
      grid_(checked(grid)),
      by_columns_(static_cast<std::uint32_t>(grid.nx)),
      by_rows_(static_cast<std::uint32_t>(grid.ny)),
      boundaries_(boundaries_of(params, grid)),
      motion_(params.gravity),
      protocol_(image_protocol(params)) {
  check_matches(archive, prefix, params, grid, D);
  check_surfaces_match(archive, prefix, params, D);
  const bool polydisperse = archive.contains(prefix + "particle_diameter");
  set_surfaces(params_);
  const auto n = static_cast<std::size_t>(params.particles);
  particles_.assign(n, ParticleRecord<D>{});
  queue_.reset(static_cast<std::int32_t>(n));
  const auto get_fields = [&](auto& items, auto&& visit_fields) {
    visit_fields([&](const char* name, auto field) {
      const auto values = array_of_size<std::decay_t<decltype(field(items[0]))>>(archive, prefix + name, n);
      for (std::size_t i = 0; i < n; ++i) field(items[i]) = values[i];
    });
  };
  get_fields(particles_, [](auto&& visit) { visit_record_fields<D>(visit); });
  const std::span<EventSlot> slots = queue_.slots();
  visit_saved_state(*this, [&](const char* name, auto& value) {
    using Value = std::decay_t<decltype(value)>;
    if constexpr (std::is_same_v<Value, double>) {
      value = archive.scalar(prefix + name);
    } else if constexpr (std::is_same_v<Value, std::int64_t>) {
      value = archive.integer(prefix + name);
    } else {
      // Per-particle arrays; the TC history exists only with the TC model (saved empty otherwise),
      // sizes and masses only in polydisperse runs (not saved otherwise).
      const std::string_view key(name);
      const bool per_particle_sizes = key == "particle_diameter" || key == "particle_mass";
      if (per_particle_sizes && !polydisperse) return;
      if (key.substr(0, 5) == "spin_" && !params.roughness.rough) return;
      const bool absent = key == "last_collision" && params.tc_duration <= 0.0;
      const auto loaded = array_of_size<typename Value::value_type>(archive, prefix + name, absent ? 0 : n);
      value.assign(loaded.begin(), loaded.end());
    }
  });
  check_restored_clocks();
  shear_rate_ = image_velocity() / params.length_y;
  protocol_running_ = archive.integer(prefix + "protocol_running") != 0;
  boundaries_.set_drives_running(protocol_running_);
  actions_.schedule(TimedAction::kShearSegment, archive.scalar(prefix + "shear_segment_action"));
  schedule_realignment();
  const auto kinds = array_of_size<std::uint8_t>(archive, prefix + "event_kind", n);
  const auto cells = array_of_size<std::int32_t>(archive, prefix + "cell", n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!valid_event_kind(kinds[i], D)) throw std::runtime_error("checkpoint has an unknown event kind");
    const bool collision = kinds[i] == static_cast<std::uint8_t>(EventKind::kCollision);
    const std::int32_t partner = particles_[i].partner;
    const bool resting = partner == kAtRest && params.rest.on() && kinds[i] == static_cast<std::uint8_t>(EventKind::kNone);
    if (cells[i] < 0 || cells[i] >= grid.cell_count() || (partner < -1 && !resting) || partner >= params.particles ||
        (collision && partner < 0)) {
      throw std::runtime_error("checkpoint has a disk with an invalid cell or event partner");
    }
    slots[i].set_cell(cells[i]);
    slots[i].set_kind(static_cast<EventKind>(kinds[i]));
  }
  lists_.restore(archive, prefix + "cell_list_", grid.cell_count(), particles_);
  restore_numbering(archive, prefix);
  queue_.restore(archive, prefix + "queue_");
  collapse_detector_.restore(archive, prefix + "collapse_");
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::int32_t>(i);
    if (at_rest(k)) boundaries_.rest_grain(k, particles_[i].r, radius_of(k));
  }
  // A damaged or hand-edited checkpoint must not start a run that is silently wrong.
  try {
    check_invariants();
  } catch (const std::logic_error& error) {
    throw std::runtime_error(std::string("checkpoint fails the engine's invariants: ") + error.what());
  }
}

// Clocks and counters before anything runs on them: a NaN clock would stall the event loop, a
// negative count would be reported as collisions.
template <int D>
void Simulation<D>::check_restored_clocks() const {
  const auto refuse = [](const std::string& what) { throw std::runtime_error("checkpoint entry " + what); };
  const std::pair<const char*, double> clocks[] = {{"t_now", t_now_}, {"clock_base", clock_base_}, {"t_ref", t_ref_},
                                                   {"strain_at_reference", strain_ref_}, {"image_velocity", image_velocity()}};
  for (const auto& [name, value] : clocks) {
    if (!std::isfinite(value)) refuse(std::string(name) + " is not finite");
  }
  if (std::isnan(segment_end_)) refuse("shear_segment_end is not a number");
  if (collisions_ < 0 || events_ < collisions_ || events_since_rebase_ < 0) {
    refuse("collisions, events or events_since_rebase is not a count of this run's events");
  }
  for (const double t : last_collision_) {
    if (std::isnan(t) || t == INFINITY) refuse("last_collision holds a time that is not in the past");
  }
  for (std::size_t i = 0; i < diameter_.size(); ++i) {
    if (!(diameter_[i] > 0.0 && diameter_[i] <= params_.diameter) || !(mass_[i] > 0.0 && std::isfinite(mass_[i]))) {
      refuse("particle_diameter or particle_mass holds a size outside (0, diameter] or a mass that is not positive");
    }
  }
}

template <int D>
void Simulation<D>::restore_numbering(const StateArchive& archive, const std::string& prefix) {
  const auto n = static_cast<std::size_t>(params_.particles);
  renumber_interval_ = std::llround(params_.renumber_every * static_cast<double>(params_.particles));
  if (archive.contains(prefix + "particle_id")) {
    user_id_ = array_of_size<std::int32_t>(archive, prefix + "particle_id", n);
    std::vector<char> seen(n, 0);
    for (const std::int32_t id : user_id_) {
      if (id < 0 || static_cast<std::size_t>(id) >= n || seen[static_cast<std::size_t>(id)]++ != 0) {
        throw std::runtime_error("checkpoint entry particle_id is not a numbering of the particles");
      }
    }
    events_since_renumber_ = archive.integer(prefix + "events_since_renumber");
  } else if (renumber_interval_ > 0) {
    number_by_user_id();
  }
  queue_.set_tie_order(user_id_);
}

// The members defined in this file, for both dimensions (the class is instantiated in
// simulation.cpp, once).
template void Simulation<2>::save(StateArchive&, const std::string&) const;
template void Simulation<2>::restore_numbering(const StateArchive&, const std::string&);
template Simulation<2>::Simulation(const SystemParams&, const CellGrid&, const StateArchive&, const std::string&);
template void Simulation<3>::save(StateArchive&, const std::string&) const;
template void Simulation<3>::restore_numbering(const StateArchive&, const std::string&);
template Simulation<3>::Simulation(const SystemParams&, const CellGrid&, const StateArchive&, const std::string&);

}  // namespace granule
