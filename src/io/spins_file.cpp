#include "io/spins_file.hpp"

#include <filesystem>

#include "granule/version.hpp"

namespace granule {

namespace {

constexpr const char* kFormat = "granule-spins";
constexpr int kFormatVersion = 1;

std::string suffixed(const char* name, std::size_t direction) {
  return std::string(name) + spins_file::kDirectionSuffixes[direction];
}

}  // namespace

const h5::FileSchema& spins_file::spins_schema() {
  using h5::Values;
  static const h5::FileSchema schema = [] {
    h5::FileSchema s{kFormat, kFormatVersion, kFormatVersion, {"average"}, {}, {}};
    for (const char* name : {"source", "boundary", "normalization", "directions"}) s.attributes.push_back({".", name, Values::kText});
    for (const char* name : {"dimension", "particles", "bins"}) s.attributes.push_back({".", name, Values::kIntegers});
    for (const char* name : {"diameter", "restitution", "tangential_restitution", "shear_velocity", "max_distance",
                             "contact_shell", "contact_pairs"}) {
      s.attributes.push_back({".", name, Values::kFinite});
    }
    s.attributes.push_back({".", "box", Values::kFinite, 3});
    for (const char* name : {"C_contact", "C_contact_error"}) s.attributes.push_back({".", name, Values::kNumbers});
    // F frames, B bins of r.
    s.datasets.push_back({"r_edges", "B+1"});
    s.datasets.push_back({"r", "B"});
    s.datasets.push_back({"frame_index", "F", Values::kIntegers});
    for (const char* name : {"time", "collisions_per_particle", "shear_offset", "spin_variance", "contact_pairs"}) {
      s.datasets.push_back({name, "F"});
    }
    s.datasets.push_back({"mean_spin", "F,3"});
    s.datasets.push_back({"C_contact", "F", Values::kNumbers});
    for (std::size_t d = 0; d < kPairDirections; ++d) {
      s.datasets.push_back({suffixed("C", d), "F,B", Values::kNumbers});
      s.datasets.push_back({suffixed("pairs", d), "F,B"});
      s.datasets.push_back({suffixed("average/C", d), "B", Values::kNumbers});
      s.datasets.push_back({suffixed("average/pairs", d), "B"});
    }
    return s;
  }();
  return schema;
}

PairImages pair_images_of(const SystemParams& system, const SnapshotFrame& frame) {
  PairImages images;
  images.length = {system.length_x, system.length_y, system.dimension == 3 ? system.length_z : 1.0};
  images.walls = system.walls;
  images.shear_offset = system.walls[1] ? 0.0 : frame.shear_offset;
  return images;
}

SpinsFile::SpinsFile(const std::string& path, const std::string& source, const SnapshotMetadata& metadata,
                     const SpinCorrelationSettings& settings)
    : partial_(path, kFormat, kFormatVersion, kVersion), file_(partial_.get()), bins_(static_cast<std::size_t>(settings.bins)) {
  using namespace h5;
  const SystemParams& s = metadata.system;
  write_string_attribute(file_, "source", std::filesystem::absolute(source).string());
  write_string_attribute(file_, "boundary", metadata.boundary);
  write_string_attribute(file_, "normalization",
                         "C(r) = <dw_i . dw_j>_pairs at r / <|dw|^2>_grains, dw = w - <w> (the frame's mean spin, about "
                         "-gamma/2 under shear, removed); r = |r_ij| / sigma_ij, nearest (Lees-Edwards) image, no image "
                         "across walls; average over frames weighted by pairs");
  write_string_attribute(file_, "directions",
                         "_flow: pairs whose |dx| is the largest component of their separation; _gradient: |dy| the largest");
  write_attribute(file_, "dimension", H5T_NATIVE_INT, &s.dimension);
  write_attribute(file_, "particles", H5T_NATIVE_INT64, &s.particles);
  write_attribute(file_, "bins", H5T_NATIVE_INT, &settings.bins);
  write_double(file_, "diameter", s.diameter);
  write_double(file_, "restitution", s.restitution);
  write_double(file_, "tangential_restitution", s.roughness.tangential_restitution);
  write_double(file_, "shear_velocity", s.shear_velocity);
  write_double(file_, "max_distance", settings.max_distance);
  write_double(file_, "contact_shell", settings.contact_shell);
  const double box[3] = {s.length_x, s.length_y, s.dimension == 3 ? s.length_z : 0.0};
  write_attribute(file_, "box", H5T_NATIVE_DOUBLE, box, 3);
  const std::vector<double> edges = spin_correlation_edges(settings);
  std::vector<double> centres(bins_);
  for (std::size_t k = 0; k < bins_; ++k) centres[k] = 0.5 * (edges[k] + edges[k + 1]);
  write_vector(file_, "r_edges", edges);
  write_vector(file_, "r", centres);
  add_frames(file_, "frame_index", H5T_STD_I64LE, {});
  for (const char* name : {"time", "collisions_per_particle", "shear_offset", "spin_variance", "contact_pairs", "C_contact"}) {
    add_frames(file_, name, H5T_IEEE_F64LE, {});
  }
  add_frames(file_, "mean_spin", H5T_IEEE_F64LE, {3});
  for (std::size_t d = 0; d < kPairDirections; ++d) {
    add_frames(file_, suffixed("C", d).c_str(), H5T_IEEE_F64LE, {bins_});
    add_frames(file_, suffixed("pairs", d).c_str(), H5T_IEEE_F64LE, {bins_});
  }
  Handle(create_group(file_, "average"), H5Gclose).close();
  partial_.flush();
}

namespace {

// C of every bin of one direction.
std::vector<double> correlations(const SpinPairSums& sums, std::size_t direction) {
  std::vector<double> c(sums.pairs[direction].size());
  for (std::size_t k = 0; k < c.size(); ++k) c[k] = sums.correlation(static_cast<PairDirection>(direction), k);
  return c;
}

}  // namespace

void SpinsFile::append(std::int64_t index, const SnapshotFrame& frame, const SpinPairSums& sums) {
  using namespace h5;
  const auto k = static_cast<hsize_t>(partial_.frames());
  const double contact = sums.contact_correlation();
  append_frame(file_, "frame_index", H5T_NATIVE_INT64, &index, k);
  append_frame(file_, "time", H5T_NATIVE_DOUBLE, &frame.clock.time, k);
  append_frame(file_, "collisions_per_particle", H5T_NATIVE_DOUBLE, &frame.collisions_per_particle, k);
  append_frame(file_, "shear_offset", H5T_NATIVE_DOUBLE, &frame.shear_offset, k);
  append_frame(file_, "spin_variance", H5T_NATIVE_DOUBLE, &sums.spin_variance, k);
  append_frame(file_, "contact_pairs", H5T_NATIVE_DOUBLE, &sums.contact_pairs, k);
  append_frame(file_, "C_contact", H5T_NATIVE_DOUBLE, &contact, k);
  append_frame(file_, "mean_spin", H5T_NATIVE_DOUBLE, sums.mean_spin.data(), k);
  for (std::size_t d = 0; d < kPairDirections; ++d) {
    append_frame(file_, suffixed("C", d).c_str(), H5T_NATIVE_DOUBLE, correlations(sums, d).data(), k);
    append_frame(file_, suffixed("pairs", d).c_str(), H5T_NATIVE_DOUBLE, sums.pairs[d].data(), k);
  }
  partial_.end_frame();
}

void SpinsFile::publish(const SpinCorrelationAverage& average) {
  using namespace h5;
  for (std::size_t d = 0; d < kPairDirections; ++d) {
    write_vector(file_, suffixed("average/C", d).c_str(), correlations(average.total, d));
    write_vector(file_, suffixed("average/pairs", d).c_str(), average.total.pairs[d]);
  }
  write_double(file_, "C_contact", average.contact_mean());
  write_double(file_, "C_contact_error", average.contact_error());
  write_double(file_, "contact_pairs", average.total.contact_pairs);
  partial_.publish();
}

SpinsSummary read_spins_summary(const std::string& path) {
  using namespace h5;
  check_file_schema(path, spins_file::spins_schema());
  Handle file = open_file(path);
  SpinsSummary s;
  s.contact = read_attribute<double>(file.get(), "C_contact", H5T_NATIVE_DOUBLE);
  s.contact_error = read_attribute<double>(file.get(), "C_contact_error", H5T_NATIVE_DOUBLE);
  s.contact_pairs = read_attribute<double>(file.get(), "contact_pairs", H5T_NATIVE_DOUBLE);
  s.frames = complete_frames(file.get());
  s.r = read_vector(file.get(), "r");
  for (std::size_t d = 0; d < kPairDirections; ++d) s.correlation[d] = read_vector(file.get(), suffixed("average/C", d).c_str(), s.r.size());
  file.close();
  return s;
}

}  // namespace granule
