#include "io/spacetime_file.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <filesystem>

#include "analysis/cell_fields.hpp"
#include "analysis/field_grid.hpp"
#include "granule/version.hpp"
#include "io/fields_file.hpp"
#include "io/hdf5_util.hpp"
#include "io/run_files.hpp"
#include "io/snapshot_file.hpp"

namespace granule {

using h5::Handle;

SpacetimeProfiles spacetime_from_fields(const std::string& fields_path, const std::string& group) {
  Handle opened = h5::open_file(fields_path);
  const hid_t file = opened.get();
  SpacetimeProfiles out;
  out.source = "fields/" + group;
  CellFields maps;
  maps.grid = read_fields_grid(file);
  out.particles = h5::read_attribute<std::int64_t>(file, "particles", H5T_NATIVE_INT64);
  out.diameter = h5::read_attribute<double>(file, "diameter", H5T_NATIVE_DOUBLE);
  out.length_x = maps.grid.length_x;
  out.length_y = maps.grid.length_y;
  out.restitution = h5::read_attribute<double>(file, "restitution", H5T_NATIVE_DOUBLE);
  out.nominal_shear_velocity = h5::read_attribute<double>(file, "shear_velocity", H5T_NATIVE_DOUBLE);
  out.boundary = h5::read_string_attribute(file, "boundary");
  out.relative = h5::read_attribute<int>(file, "subtract_shear_profile", H5T_NATIVE_INT) != 0;
  out.t = h5::read_frame_series(fields_path, "frames/t");
  out.c = h5::read_frame_series(fields_path, "frames/c");
  const std::size_t frames = out.t.size();
  // Only the fields a streamwise profile uses are read; the others stay empty.
  const std::pair<const char*, std::vector<double>*> used[] = {
      {"density", &maps.density}, {"velocity_x", &maps.velocity_x}, {"velocity_y", &maps.velocity_y},
      {"temperature", &maps.temperature}};
  const std::vector<hsize_t> map = field_map_shape(maps.grid);
  for (std::size_t k = 0; k < frames; ++k) {
    for (auto& [name, values] : used) *values = h5::read_frame_values(file, (group + "/" + name).c_str(), k, map);
    append_profiles(out, streamwise_profiles(maps));
  }
  opened.close();
  return out;
}

SpacetimeProfiles spacetime_from_snapshots(const std::string& snapshots_path, int rows, bool relative) {
  SpacetimeProfiles out;
  out.source = "snapshots";
  out.relative = relative;
  read_shear_protocol(snapshots_path, out);
  const SnapshotRead first = read_snapshot(snapshots_path, 0);
  const SnapshotMetadata& m = first.metadata;
  out.particles = m.system.particles;
  out.diameter = m.system.diameter;
  out.length_x = m.system.length_x;
  out.length_y = m.system.length_y;
  out.restitution = m.system.restitution;
  out.nominal_shear_velocity = m.system.shear_velocity;
  out.boundary = m.boundary;
  for (std::int64_t k = 0; k < first.frames; ++k) {
    const SnapshotRead s = k == 0 ? first : read_snapshot(snapshots_path, k);  // frame 0 is read once
    const double shear_velocity = m.boundary != "lees-edwards" ? 0.0
                                  : out.shear_velocity.empty() ? m.system.shear_velocity
                                                               : out.shear_velocity[static_cast<std::size_t>(k)];
    const ShearFrame frame{m.system.length_x, m.system.length_y, shear_velocity};
    append_profiles(out, row_profiles(s.frame.particles, m.system, rows, frame, s.frame.shear_offset, relative));
    out.t.push_back(s.frame.clock.time);
    out.c.push_back(s.frame.collisions_per_particle);
  }
  return out;
}

void read_shear_protocol(const std::string& snapshots_path, SpacetimeProfiles& profiles) {
  profiles.shear_velocity = h5::read_frame_series(snapshots_path, "shear_velocity");
  if (profiles.shear_velocity.empty()) return;
  profiles.protocol_t = h5::read_frame_series(snapshots_path, "time");
  profiles.shear_offset = h5::read_frame_series(snapshots_path, "shear_offset");
}

SpacetimeSource spacetime_source(const std::string& input, const std::string& chosen) {
  namespace fs = std::filesystem;
  std::string from = chosen;
  if (from.empty()) {
    if (fs::is_directory(input)) {
      from = fs::exists(fs::path(input) / "fields.h5") || fs::exists(fs::path(input) / "fields.h5.partial") ? "fields"
                                                                                                          : "snapshots";
    } else {
      from = hdf5_format(input) == "granule-snapshots" ? "snapshots" : "fields";
    }
  }
  if (from != "fields" && from != "snapshots") throw InputError(fmt::format("--from {} is not one of fields, snapshots", from));
  const bool fields = from == "fields";
  const std::string path = locate_run_file(input, fields ? "fields.h5" : "snapshots.h5");
  require_hdf5_format(path, fields ? "granule-fields" : "granule-snapshots",
                      fields ? "`granule run` or `granule analyze fields`" : "`granule run`");
  return {from, path};
}

SpacetimeProfiles read_spacetime_profiles(const SpacetimeSource& source, const std::string& group, std::optional<int> rows,
                                          bool relative) {
  SpacetimeProfiles profiles;
  if (source.from == "fields") {
    profiles = spacetime_from_fields(source.path, group);
    const std::string snapshots = snapshots_beside(source.path);
    if (!snapshots.empty()) read_shear_protocol(snapshots, profiles);
  } else {
    const SnapshotMetadata m = read_snapshot(source.path, 0).metadata;
    const int binned = rows.value_or(default_field_grid(m.system.length_x, m.system.length_y, m.system.particles).ny);
    profiles = spacetime_from_snapshots(source.path, binned, relative);
  }
  if (profiles.t.empty()) throw InputError(fmt::format("{} has no complete frame yet", source.path));
  return profiles;
}

void write_spacetime_partial(const std::string& path, const SpacetimeProfiles& p) {
  Handle file(h5::create_partial_file(path, "granule-spacetime", 1, kVersion), H5Fclose);
  const hid_t f = file.get();
  h5::write_string_attribute(f, "source", p.source);
  h5::write_string_attribute(f, "boundary", p.boundary);
  h5::write_attribute(f, "particles", H5T_NATIVE_INT64, &p.particles);
  h5::write_double(f, "diameter", p.diameter);
  h5::write_double(f, "length_x", p.length_x);
  h5::write_double(f, "length_y", p.length_y);
  h5::write_double(f, "restitution", p.restitution);
  h5::write_double(f, "shear_velocity", p.nominal_shear_velocity);
  const int relative = p.relative ? 1 : 0;
  h5::write_attribute(f, "relative", H5T_NATIVE_INT, &relative);
  h5::write_vector(f, "t", p.t);
  h5::write_vector(f, "c", p.c);
  h5::write_vector(f, "y", p.y);
  const std::vector<hsize_t> shape{p.t.size(), p.y.size()};
  h5::write_dataset(f, "density", shape, p.density);
  h5::write_dataset(f, "velocity_x", shape, p.velocity_x);
  h5::write_dataset(f, "temperature", shape, p.temperature);
  if (!p.shear_velocity.empty()) {
    Handle(h5::create_group(f, "protocol"), H5Gclose).close();
    h5::write_vector(f, "protocol/t", p.protocol_t);
    h5::write_vector(f, "protocol/shear_velocity", p.shear_velocity);
    h5::write_vector(f, "protocol/shear_offset", p.shear_offset);
  }
  file.close();
}

}  // namespace granule
