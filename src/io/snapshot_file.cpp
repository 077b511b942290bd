#include "io/snapshot_file.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "io/hdf5_util.hpp"
#include "io/io_error.hpp"
#include "io/surface_attributes.hpp"
#include "io/system_checks.hpp"

namespace granule {

namespace {

using namespace h5;

constexpr const char* kFormat = "granule-snapshots";
// 2: per-frame shear_velocity and strain_at_reference; 3: `dimension`, rows of d in positions and
// velocities, `packing_fraction`, per-particle `diameters` and `masses` (polydisperse runs).
// Files of version 2 (no `dimension`) are read as 2D.  Rough grains, walls and gravity
// add attributes and a `spins` dataset only to the files of runs that have them: their presence
// says what the file holds, so the version stays 3 and files of other runs keep their bytes.
constexpr int kFormatVersion = 3;

// The per-frame scalars of the schema, in one list for writing and reading.
template <typename Frame, typename Visit>
void for_each_scalar(Frame& frame, Visit&& visit) {
  visit("time", H5T_NATIVE_DOUBLE, &frame.clock.time);
  visit("collisions_per_particle", H5T_NATIVE_DOUBLE, &frame.collisions_per_particle);
  visit("shear_offset", H5T_NATIVE_DOUBLE, &frame.shear_offset);
  visit("strain", H5T_NATIVE_DOUBLE, &frame.strain);
  visit("strain_reference", H5T_NATIVE_DOUBLE, &frame.clock.strain_reference);
  visit("strain_at_reference", H5T_NATIVE_DOUBLE, &frame.clock.strain_at_reference);
  visit("shear_velocity", H5T_NATIVE_DOUBLE, &frame.shear_velocity);
  visit("collisions", H5T_NATIVE_INT64, &frame.clock.collisions);
  visit("events", H5T_NATIVE_INT64, &frame.clock.events);
}

// Rows of `components` values per particle, as the (S, N, d) and (S, N, 3) datasets store them;
// `column(a)` is the array of component a.
template <typename Column>
std::vector<double> interleave(std::size_t n, int components, Column&& column) {
  const auto width = static_cast<std::size_t>(components);
  std::vector<double> out(width * n);
  for (std::size_t a = 0; a < width; ++a) {
    const std::vector<double>& values = column(static_cast<int>(a));
    for (std::size_t i = 0; i < n; ++i) out[width * i + a] = values[i];
  }
  return out;
}

template <typename Column>
void deinterleave(const std::vector<double>& rows, std::size_t n, int components, Column&& column) {
  const auto width = static_cast<std::size_t>(components);
  for (std::size_t a = 0; a < width; ++a) {
    std::vector<double>& values = column(static_cast<int>(a));
    values.resize(n);
    for (std::size_t i = 0; i < n; ++i) values[i] = rows[width * i + a];
  }
}

// The spin components in the order of the `spins` rows: ω_z of disks; ω_x, ω_y, ω_z of spheres.
template <typename State>
auto& spin_column(State& state, int k) { return state.spin(state.dimension == 3 ? k : 2); }

// What is wrong with a frame's clock and counters: times, strains, offsets and U(t) finite, counts
// not negative, the TC model's times of last collision in the past (−∞: none yet).
std::vector<std::string> frame_problems(const SnapshotFrame& frame, std::size_t particles) {
  std::vector<std::string> problems;
  for_each_scalar(frame, [&](const char* name, hid_t type, const void* value) {
    const bool integer = H5Tequal(type, H5T_NATIVE_INT64) > 0;
    const double v = integer ? static_cast<double>(*static_cast<const std::int64_t*>(value)) : *static_cast<const double*>(value);
    const bool count = integer || std::string_view(name) == "collisions_per_particle" || std::string_view(name) == "time";
    if (!std::isfinite(v) || (count && v < 0.0)) {
      problems.push_back(fmt::format("{} is {}; expected a finite{} number", name, v, count ? " non-negative" : ""));
    }
  });
  for (std::size_t i = 0; i < frame.clock.last_collision.size() && i < particles; ++i) {
    const double t = frame.clock.last_collision[i];
    if (std::isnan(t) || t == INFINITY) {
      problems.push_back(fmt::format("last_collision of particle {} is {}; expected a time before the frame", i, t));
      break;
    }
  }
  return problems;
}

// The metadata of an open snapshot file.
SnapshotMetadata read_metadata(hid_t f, const std::string& path) {
  if (read_string_attribute(f, "format") != kFormat) throw InputError(path + " is not a Granule snapshot file");
  SnapshotMetadata m;
  m.version = read_string_attribute(f, "granule_version");
  m.boundary = read_string_attribute(f, "boundary");
  m.system.particles = read_attribute<std::int64_t>(f, "particles", H5T_NATIVE_INT64);
  m.system.diameter = read_attribute<double>(f, "diameter", H5T_NATIVE_DOUBLE);
  m.system.dimension = has_attribute(f, "dimension") ? read_attribute<int>(f, "dimension", H5T_NATIVE_INT) : 2;
  if (m.system.dimension != 2 && m.system.dimension != 3) {
    throw InputError(path + ": attribute dimension is " + std::to_string(m.system.dimension) + "; expected 2 or 3");
  }
  double box[3] = {0.0, 0.0, 1.0};
  read_attribute_values(f, "box", H5T_NATIVE_DOUBLE, box, static_cast<hsize_t>(m.system.dimension));
  m.system.length_x = box[0];
  m.system.length_y = box[1];
  m.system.length_z = box[2];
  m.packing_fraction = read_attribute<double>(f, m.system.dimension == 2 ? "area_fraction" : "packing_fraction", H5T_NATIVE_DOUBLE);
  m.polydisperse = has_link(f, "diameters");
  m.system.restitution = read_attribute<double>(f, "restitution", H5T_NATIVE_DOUBLE);
  m.system.tc_duration = read_attribute<double>(f, "tc_duration", H5T_NATIVE_DOUBLE);
  m.system.shear_velocity = read_attribute<double>(f, "shear_velocity", H5T_NATIVE_DOUBLE);
  m.seed = read_attribute<std::uint64_t>(f, "seed", H5T_NATIVE_UINT64);
  read_grains_walls_gravity_attributes(f, m.system);
  refuse_problems(path, system_problems(m.system));
  if (m.boundary != "periodic" && m.boundary != "lees-edwards" && m.boundary != "walls") {
    throw InputError(path + ": attribute boundary is \"" + m.boundary + "\"; expected periodic, lees-edwards or walls");
  }
  return m;
}

}  // namespace

SnapshotWriter::SnapshotWriter(const std::string& path, const SnapshotMetadata& m)
    : file_(std::make_unique<PartialFile>(path, kFormat, kFormatVersion, m.version)),
      particles_(m.system.particles),
      tc_(m.system.tc_duration > 0.0),
      rough_(m.system.roughness.rough) {
  const hid_t f = file_->get();
  write_attribute(f, "particles", H5T_NATIVE_INT64, &m.system.particles);
  write_attribute(f, "diameter", H5T_NATIVE_DOUBLE, &m.system.diameter);
  write_attribute(f, "dimension", H5T_NATIVE_INT, &m.system.dimension);
  const double box[3] = {m.system.length_x, m.system.length_y, m.system.length_z};
  write_attribute(f, "box", H5T_NATIVE_DOUBLE, box, static_cast<hsize_t>(m.system.dimension));
  write_attribute(f, "packing_fraction", H5T_NATIVE_DOUBLE, &m.packing_fraction);
  if (m.system.dimension == 2) write_attribute(f, "area_fraction", H5T_NATIVE_DOUBLE, &m.packing_fraction);
  write_attribute(f, "restitution", H5T_NATIVE_DOUBLE, &m.system.restitution);
  write_attribute(f, "tc_duration", H5T_NATIVE_DOUBLE, &m.system.tc_duration);
  write_string_attribute(f, "boundary", m.boundary);
  write_attribute(f, "shear_velocity", H5T_NATIVE_DOUBLE, &m.system.shear_velocity);
  write_attribute(f, "seed", H5T_NATIVE_UINT64, &m.seed);
  const auto n = static_cast<hsize_t>(m.system.particles);
  const auto d = static_cast<hsize_t>(m.system.dimension);
  for (const char* name : {"positions", "velocities"}) add_frames(f, name, H5T_IEEE_F64LE, {n, d});
  if (!m.diameters.empty()) {
    write_vector(f, "diameters", m.diameters);
    write_vector(f, "masses", m.masses);
  }
  const SnapshotFrame layout;
  for_each_scalar(layout, [&](const char* name, hid_t memory_type, const void*) {
    add_frames(f, name, H5Tequal(memory_type, H5T_NATIVE_INT64) > 0 ? H5T_STD_I64LE : H5T_IEEE_F64LE, {});
  });
  if (tc_) add_frames(f, "last_collision", H5T_IEEE_F64LE, {n});
  write_grains_walls_gravity_attributes(f, m.system);
  if (rough_) add_frames(f, "spins", H5T_IEEE_F64LE, d == 3 ? std::vector<hsize_t>{n, 3} : std::vector<hsize_t>{n});
  file_->flush();
}

SnapshotWriter::SnapshotWriter(const std::string& path, std::int64_t keep_frames)
    : file_(std::make_unique<PartialFile>(path, kFormat, keep_frames)) {
  const SnapshotMetadata m = read_metadata(file_->get(), path + ".partial");
  particles_ = m.system.particles;
  tc_ = m.system.tc_duration > 0.0;
  rough_ = m.system.roughness.rough;
}

SnapshotWriter::~SnapshotWriter() = default;

std::int64_t SnapshotWriter::frames() const { return file_->frames(); }

void SnapshotWriter::append(const SnapshotFrame& frame) { append(frame, StateBlocks(frame.particles)); }

void SnapshotWriter::append(const SnapshotFrame& frame, const StateBlocks& particles) {
  if (particles.size() != static_cast<std::size_t>(particles_)) throw std::logic_error("a snapshot frame of the wrong size");
  const hid_t f = file_->get();
  const auto k = static_cast<hsize_t>(file_->frames());
  particles.for_each([&](const ParticleState& p, std::size_t first) {
    if (rough_ && !p.rough()) throw std::logic_error("a frame of smooth grains in a snapshot file of rough ones");
    const std::size_t count = p.size();
    const int d = p.dimension;
    const auto write = [&](const char* name, const std::vector<double>& rows) {
      append_frame_rows(f, name, H5T_NATIVE_DOUBLE, rows.data(), k, first, count);
    };
    write("positions", interleave(count, d, [&](int a) -> auto& { return p.position(a); }));
    write("velocities", interleave(count, d, [&](int a) -> auto& { return p.velocity(a); }));
    if (rough_) write("spins", interleave(count, p.spin_components(), [&](int a) -> auto& { return spin_column(p, a); }));
  });
  for_each_scalar(frame, [&](const char* name, hid_t type, const void* value) { append_frame(f, name, type, value, k); });
  if (tc_) append_frame(f, "last_collision", H5T_NATIVE_DOUBLE, frame.clock.last_collision.data(), k);
  file_->end_frame();
}

void SnapshotWriter::finish() { file_->publish(); }

SnapshotRead read_snapshot(const std::string& path, std::int64_t index) {
  Handle file = open_file(path);
  const hid_t f = file.get();
  SnapshotRead out;
  SnapshotMetadata& m = out.metadata;
  m = read_metadata(f, path);
  out.frames = complete_frames(f);
  const std::int64_t k = index < 0 ? out.frames + index : index;
  if (k < 0 || k >= out.frames) throw std::runtime_error(path + " has no frame " + std::to_string(index));
  const auto frame = static_cast<hsize_t>(k);

  const auto n = static_cast<std::size_t>(m.system.particles);
  const auto rows = static_cast<hsize_t>(n);
  const int d = m.system.dimension;
  SnapshotFrame& s = out.frame;
  ParticleState& p = s.particles;
  p.dimension = d;
  if (m.polydisperse) {
    p.diameter = read_vector(f, "diameters", rows);
    p.mass = read_vector(f, "masses", rows);
  }
  // Each read checks the dataset's shape against the particles attribute before it allocates.
  deinterleave(read_frame_values(f, "positions", frame, {rows, static_cast<hsize_t>(d)}), n, d,
               [&](int a) -> auto& { return p.position(a); });
  deinterleave(read_frame_values(f, "velocities", frame, {rows, static_cast<hsize_t>(d)}), n, d,
               [&](int a) -> auto& { return p.velocity(a); });
  if (m.system.roughness.rough) {
    const int components = p.spin_components();
    const std::vector<hsize_t> row = d == 3 ? std::vector<hsize_t>{rows, 3} : std::vector<hsize_t>{rows};
    deinterleave(read_frame_values(f, "spins", frame, row), n, components, [&](int a) -> auto& { return spin_column(p, a); });
  }
  for_each_scalar(s, [&](const char* name, hid_t type, void* value) { read_frame(f, name, type, value, frame, {}); });
  s.clock.protocol_running = true;  // frames are written in production only
  if (m.system.tc_duration > 0.0) s.clock.last_collision = read_frame_values(f, "last_collision", frame, {rows});
  file.close();
  const std::string where = path + " frame " + std::to_string(k);
  refuse_problems(where, particle_problems(p, m.system));
  refuse_problems(where, frame_problems(s, n));
  return out;
}

}  // namespace granule
