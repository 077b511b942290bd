#include "io/snapshot_file.hpp"

#include "io/hdf5_util.hpp"

#include <hdf5.h>

#include <stdexcept>
#include <vector>

namespace granule {

namespace {

using namespace h5;

constexpr const char* kFormat = "granule-snapshots";
// 2: per-frame shear_velocity and strain_at_reference; 3: `dimension`, rows of d in positions and
// velocities, `packing_fraction`, per-particle `diameters` and `masses` (polydisperse runs).
// Files of version 2 (no `dimension`) are read as 2D.
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

// Rows of d components per particle, as the (S, N, d) datasets store them.
std::vector<double> interleave(const ParticleState& state, bool velocities) {
  const int d = state.dimension;
  std::vector<double> out(static_cast<std::size_t>(d) * state.size());
  for (int a = 0; a < d; ++a) {
    const std::vector<double>& component = velocities ? state.velocity(a) : state.position(a);
    for (std::size_t i = 0; i < state.size(); ++i) out[static_cast<std::size_t>(d) * i + static_cast<std::size_t>(a)] = component[i];
  }
  return out;
}

void deinterleave(const std::vector<double>& rows, ParticleState& state, bool velocities) {
  const int d = state.dimension;
  for (int a = 0; a < d; ++a) {
    std::vector<double>& component = velocities ? state.velocity(a) : state.position(a);
    for (std::size_t i = 0; i < state.size(); ++i) component[i] = rows[static_cast<std::size_t>(d) * i + static_cast<std::size_t>(a)];
  }
}

// The metadata of an open snapshot file.
SnapshotMetadata read_metadata(hid_t f, const std::string& path) {
  if (read_string_attribute(f, "format") != kFormat) throw std::runtime_error(path + " is not a Granule snapshot file");
  SnapshotMetadata m;
  m.version = read_string_attribute(f, "granule_version");
  m.boundary = read_string_attribute(f, "boundary");
  m.system.particles = read_attribute<std::int64_t>(f, "particles", H5T_NATIVE_INT64);
  m.system.diameter = read_attribute<double>(f, "diameter", H5T_NATIVE_DOUBLE);
  m.system.dimension = has_attribute(f, "dimension") ? read_attribute<int>(f, "dimension", H5T_NATIVE_INT) : 2;
  if (m.system.dimension != 2 && m.system.dimension != 3) throw std::runtime_error(path + " has an invalid dimension");
  double box[3] = {0.0, 0.0, 1.0};
  read_attribute_values(f, "box", H5T_NATIVE_DOUBLE, box);
  m.system.length_x = box[0];
  m.system.length_y = box[1];
  m.system.length_z = box[2];
  m.packing_fraction = read_attribute<double>(f, m.system.dimension == 2 ? "area_fraction" : "packing_fraction", H5T_NATIVE_DOUBLE);
  m.polydisperse = has_link(f, "diameters");
  m.system.restitution = read_attribute<double>(f, "restitution", H5T_NATIVE_DOUBLE);
  m.system.tc_duration = read_attribute<double>(f, "tc_duration", H5T_NATIVE_DOUBLE);
  m.system.shear_velocity = read_attribute<double>(f, "shear_velocity", H5T_NATIVE_DOUBLE);
  m.seed = read_attribute<std::uint64_t>(f, "seed", H5T_NATIVE_UINT64);
  return m;
}

}  // namespace

SnapshotWriter::SnapshotWriter(const std::string& path, const SnapshotMetadata& m)
    : file_(std::make_unique<PartialFile>(path, kFormat, kFormatVersion, m.version)),
      particles_(m.system.particles),
      tc_(m.system.tc_duration > 0.0) {
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
  file_->flush();
}

SnapshotWriter::SnapshotWriter(const std::string& path, std::int64_t keep_frames)
    : file_(std::make_unique<PartialFile>(path, kFormat, keep_frames)) {
  const SnapshotMetadata m = read_metadata(file_->get(), path + ".partial");
  particles_ = m.system.particles;
  tc_ = m.system.tc_duration > 0.0;
}

SnapshotWriter::~SnapshotWriter() = default;

std::int64_t SnapshotWriter::frames() const { return file_->frames(); }

void SnapshotWriter::append(const SnapshotFrame& frame) {
  const hid_t f = file_->get();
  const auto k = static_cast<hsize_t>(file_->frames());
  append_frame(f, "positions", H5T_NATIVE_DOUBLE, interleave(frame.particles, false).data(), k);
  append_frame(f, "velocities", H5T_NATIVE_DOUBLE, interleave(frame.particles, true).data(), k);
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
  SnapshotFrame& s = out.frame;
  s.particles.dimension = m.system.dimension;
  if (m.polydisperse) {
    s.particles.diameter = read_vector(f, "diameters");
    s.particles.mass = read_vector(f, "masses");
    if (s.particles.diameter.size() != n || s.particles.mass.size() != n) {
      throw std::runtime_error(path + " has diameters or masses of the wrong length");
    }
  }
  s.particles.resize(n);
  std::vector<double> buffer(static_cast<std::size_t>(m.system.dimension) * n);
  read_frame(f, "positions", H5T_NATIVE_DOUBLE, buffer.data(), frame);
  deinterleave(buffer, s.particles, false);
  read_frame(f, "velocities", H5T_NATIVE_DOUBLE, buffer.data(), frame);
  deinterleave(buffer, s.particles, true);
  for_each_scalar(s, [&](const char* name, hid_t type, void* value) { read_frame(f, name, type, value, frame); });
  s.clock.protocol_running = true;  // frames are written in production only
  if (m.system.tc_duration > 0.0) {
    s.clock.last_collision.resize(n);
    read_frame(f, "last_collision", H5T_NATIVE_DOUBLE, s.clock.last_collision.data(), frame);
  }
  file.close();
  return out;
}

}  // namespace granule
