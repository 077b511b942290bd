#include "io/snapshot_file.hpp"

#include "io/hdf5_util.hpp"

#include <hdf5.h>

#include <filesystem>
#include <stdexcept>
#include <vector>

namespace granule {

namespace {

using namespace h5;

constexpr const char* kFormat = "granule-snapshots";
constexpr int kFormatVersion = 1;

// The per-frame scalars of the schema, in one list for writing and reading.
template <typename Frame, typename Visit>
void for_each_scalar(Frame& frame, Visit&& visit) {
  visit("time", H5T_NATIVE_DOUBLE, &frame.clock.time);
  visit("collisions_per_particle", H5T_NATIVE_DOUBLE, &frame.collisions_per_particle);
  visit("shear_offset", H5T_NATIVE_DOUBLE, &frame.shear_offset);
  visit("strain", H5T_NATIVE_DOUBLE, &frame.strain);
  visit("strain_reference", H5T_NATIVE_DOUBLE, &frame.clock.strain_reference);
  visit("collisions", H5T_NATIVE_INT64, &frame.clock.collisions);
  visit("events", H5T_NATIVE_INT64, &frame.clock.events);
}

std::vector<double> interleave(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> out(2 * a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    out[2 * i] = a[i];
    out[2 * i + 1] = b[i];
  }
  return out;
}

}  // namespace

struct SnapshotWriter::Handles {
  hid_t file = -1;
};

SnapshotWriter::SnapshotWriter(const std::string& path, const SnapshotMetadata& m)
    : handles_(std::make_unique<Handles>()), path_(path), particles_(m.system.particles), tc_(m.system.tc_duration > 0.0) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are reported through exceptions
  handles_->file = create_partial_file(path, kFormat, kFormatVersion, m.version);
  const hid_t f = handles_->file;
  write_attribute(f, "particles", H5T_NATIVE_INT64, &m.system.particles);
  write_attribute(f, "diameter", H5T_NATIVE_DOUBLE, &m.system.diameter);
  const double box[2] = {m.system.length_x, m.system.length_y};
  write_attribute(f, "box", H5T_NATIVE_DOUBLE, box, 2);
  write_attribute(f, "area_fraction", H5T_NATIVE_DOUBLE, &m.area_fraction);
  write_attribute(f, "restitution", H5T_NATIVE_DOUBLE, &m.system.restitution);
  write_attribute(f, "tc_duration", H5T_NATIVE_DOUBLE, &m.system.tc_duration);
  write_string_attribute(f, "boundary", m.boundary);
  write_attribute(f, "shear_velocity", H5T_NATIVE_DOUBLE, &m.system.shear_velocity);
  write_attribute(f, "seed", H5T_NATIVE_UINT64, &m.seed);
  const auto n = static_cast<hsize_t>(m.system.particles);
  for (const char* name : {"positions", "velocities"}) H5Dclose(create_frames(f, name, H5T_IEEE_F64LE, {n, 2}));
  const SnapshotFrame layout;
  for_each_scalar(layout, [&](const char* name, hid_t memory_type, const void*) {
    const hid_t file_type = H5Tequal(memory_type, H5T_NATIVE_INT64) > 0 ? H5T_STD_I64LE : H5T_IEEE_F64LE;
    H5Dclose(create_frames(f, name, file_type, {}));
  });
  if (tc_) H5Dclose(create_frames(f, "last_collision", H5T_IEEE_F64LE, {n}));
  check(H5Fflush(f, H5F_SCOPE_GLOBAL), "flushing " + path + ".partial");
}

std::unique_ptr<SnapshotWriter> SnapshotWriter::reopen(const std::string& path, std::int64_t keep_frames) {
  std::unique_ptr<SnapshotWriter> writer(new SnapshotWriter());
  writer->handles_ = std::make_unique<Handles>();
  writer->path_ = path;
  writer->handles_->file = reopen_frames_file(path, keep_frames);
  writer->particles_ = read_attribute<std::int64_t>(writer->handles_->file, "particles", H5T_NATIVE_INT64);
  writer->tc_ = read_attribute<double>(writer->handles_->file, "tc_duration", H5T_NATIVE_DOUBLE) > 0.0;
  writer->frames_ = keep_frames;
  return writer;
}

SnapshotWriter::~SnapshotWriter() {
  if (handles_ && handles_->file >= 0) H5Fclose(handles_->file);
}

void SnapshotWriter::append(const SnapshotFrame& frame) {
  const hid_t f = handles_->file;
  const auto k = static_cast<hsize_t>(frames_);
  append_frame(f, "positions", H5T_NATIVE_DOUBLE, interleave(frame.particles.x, frame.particles.y).data(), k);
  append_frame(f, "velocities", H5T_NATIVE_DOUBLE, interleave(frame.particles.vx, frame.particles.vy).data(), k);
  for_each_scalar(frame, [&](const char* name, hid_t type, const void* value) { append_frame(f, name, type, value, k); });
  if (tc_) append_frame(f, "last_collision", H5T_NATIVE_DOUBLE, frame.clock.last_collision.data(), k);
  ++frames_;
  check(H5Fflush(f, H5F_SCOPE_GLOBAL), "flushing " + path_ + ".partial");
}

void SnapshotWriter::finish() {
  if (handles_->file < 0) return;
  publish_partial_file(handles_->file, path_);
  handles_->file = -1;
}

SnapshotRead read_snapshot(const std::string& path, std::int64_t index) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t f = check_id(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "opening " + path);
  SnapshotRead out;
  try {
    if (read_string_attribute(f, "format") != kFormat) throw std::runtime_error(path + " is not a Granule snapshot file");
    SnapshotMetadata& m = out.metadata;
    m.version = read_string_attribute(f, "granule_version");
    m.boundary = read_string_attribute(f, "boundary");
    m.system.particles = read_attribute<std::int64_t>(f, "particles", H5T_NATIVE_INT64);
    m.system.diameter = read_attribute<double>(f, "diameter", H5T_NATIVE_DOUBLE);
    double box[2] = {0.0, 0.0};
    const hid_t attribute = H5Aopen(f, "box", H5P_DEFAULT);
    check(H5Aread(attribute, H5T_NATIVE_DOUBLE, box), "reading box");
    H5Aclose(attribute);
    m.system.length_x = box[0];
    m.system.length_y = box[1];
    m.area_fraction = read_attribute<double>(f, "area_fraction", H5T_NATIVE_DOUBLE);
    m.system.restitution = read_attribute<double>(f, "restitution", H5T_NATIVE_DOUBLE);
    m.system.tc_duration = read_attribute<double>(f, "tc_duration", H5T_NATIVE_DOUBLE);
    m.system.shear_velocity = read_attribute<double>(f, "shear_velocity", H5T_NATIVE_DOUBLE);
    m.seed = read_attribute<std::uint64_t>(f, "seed", H5T_NATIVE_UINT64);

    const hid_t dataset = check_id(H5Dopen2(f, "time", H5P_DEFAULT), "opening time");
    const hid_t space = H5Dget_space(dataset);
    hsize_t frames = 0;
    H5Sget_simple_extent_dims(space, &frames, nullptr);
    H5Sclose(space);
    H5Dclose(dataset);
    out.frames = static_cast<std::int64_t>(frames);
    const std::int64_t k = index < 0 ? out.frames + index : index;
    if (k < 0 || k >= out.frames) throw std::runtime_error(path + " has no frame " + std::to_string(index));
    const auto frame = static_cast<hsize_t>(k);

    const auto n = static_cast<std::size_t>(m.system.particles);
    SnapshotFrame& s = out.frame;
    std::vector<double> buffer(2 * n);
    s.particles.resize(n);
    read_frame(f, "positions", H5T_NATIVE_DOUBLE, buffer.data(), frame);
    for (std::size_t i = 0; i < n; ++i) {
      s.particles.x[i] = buffer[2 * i];
      s.particles.y[i] = buffer[2 * i + 1];
    }
    read_frame(f, "velocities", H5T_NATIVE_DOUBLE, buffer.data(), frame);
    for (std::size_t i = 0; i < n; ++i) {
      s.particles.vx[i] = buffer[2 * i];
      s.particles.vy[i] = buffer[2 * i + 1];
    }
    for_each_scalar(s, [&](const char* name, hid_t type, void* value) { read_frame(f, name, type, value, frame); });
    if (m.system.tc_duration > 0.0) {
      s.clock.last_collision.resize(n);
      read_frame(f, "last_collision", H5T_NATIVE_DOUBLE, s.clock.last_collision.data(), frame);
    }
  } catch (...) {
    H5Fclose(f);
    throw;
  }
  H5Fclose(f);
  return out;
}

}  // namespace granule
