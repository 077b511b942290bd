#include "io/collision_statistics_file.hpp"

#include <fmt/format.h>

#include "observers/collision_statistics_fits.hpp"
#include "io/atomic_file.hpp"
#include "io/file_schema.hpp"
#include "io/hdf5_util.hpp"
#include "theory/hard_spheres.hpp"

namespace granule {

using namespace h5;

namespace {

constexpr const char* kFormat = "granule-collisions";
constexpr int kFormatVersion = 1;

hsize_t size(std::size_t n) { return static_cast<hsize_t>(n); }

std::vector<double> edges(const UniformBins& bins) {
  std::vector<double> out;
  for (int k = 0; k <= bins.bins; ++k) out.push_back(bins.edge(k));
  return out;
}

void write_impact_summary(hid_t group, const std::vector<double>& counts, const UniformBins& bins) {
  const ImpactParameterSummary s = summarize_impact_parameters(counts, bins);
  write_vector(group, "counts", counts);
  write_vector(group, "density", s.density);
  write_vector(group, "cumulative_minus_uniform", s.cumulative_minus_uniform);
  write_double(group, "samples", s.samples);
  write_double(group, "ks_uniform", s.ks_uniform);
}

// A group, closed (checked) by the caller.
Handle group(hid_t location, const char* name) { return Handle(create_group(location, name), H5Gclose); }

template <int D>
void write_impacts(hid_t file, const ImpactParameterStatistics<D>& impacts) {
  Handle impact_group = group(file, "impact_parameters");
  const hid_t g = impact_group.get();
  if (D == 3) write_string_attribute(g, "variable", "b_over_sigma_squared");
  const UniformBins& bins = impacts.bins();
  const auto window = impacts.window_collisions();
  write_attribute(g, "window_collisions", H5T_NATIVE_INT64, &window);
  write_vector(g, "bin_edges", edges(bins));
  Handle total = group(g, "total");
  write_impact_summary(total.get(), impacts.total(), bins);
  total.close();

  Handle windows = group(g, "windows");
  std::vector<double> t_start, t_end, collisions, counts;
  for (const auto& w : impacts.windows()) {
    t_start.push_back(w.t_start);
    t_end.push_back(w.t_end);
    collisions.push_back(static_cast<double>(w.collisions));
    counts.insert(counts.end(), w.counts.begin(), w.counts.end());
  }
  write_vector(windows.get(), "t_start", t_start);
  write_vector(windows.get(), "t_end", t_end);
  write_vector(windows.get(), "collisions", collisions);
  write_dataset(windows.get(), "counts", {size(t_start.size()), size(bins.bins)}, counts);
  windows.close();

  for (std::size_t w = 0; w < impacts.density_windows().size(); ++w) {
    Handle d = group(g, fmt::format("density_window_{}", w).c_str());
    write_double(d.get(), "density_low", impacts.density_windows()[w].low);
    write_double(d.get(), "density_high", impacts.density_windows()[w].high);
    write_impact_summary(d.get(), impacts.by_density()[w], bins);
    d.close();
  }
  impact_group.close();
}

template <int D>
void write_path_summary(hid_t group, const PathHistogram& h, const FreePathStatistics<D>& paths) {
  const FreePathSummary s = summarize_free_paths(h, paths.length_bins(), paths.angle_bins(), D);
  const std::vector<hsize_t> joint{size(static_cast<std::size_t>(paths.length_bins().bins)),
                                   size(static_cast<std::size_t>(paths.angle_bins().bins))};
  write_dataset(group, "counts", joint, h.counts);
  write_vector(group, "overflow", h.overflow);
  write_dataset(group, "cumulative", joint, s.cumulative);
  write_vector(group, "magnitude_density", s.magnitude_density);
  write_vector(group, "matched_density", s.matched_density);
  write_vector(group, "exponential_density", s.exponential_density);
  write_vector(group, "length_cumulative", s.length_cumulative);
  write_vector(group, "angular_cumulative", s.angular_cumulative);
  write_vector(group, "angular_fit", s.angular_fit);
  const std::vector<std::pair<const char*, double>> scalars{
      {"paths", s.paths}, {"mean_length", s.mean_length}, {"mean_speed", s.mean_speed},
      {"mean_length_squared", h.paths > 0 ? h.sum_length_squared / h.paths : 0.0},
      {"alpha0", s.alpha0}, {"alpha0_rms", s.alpha0_rms}, {"lbar", s.lbar}, {"lbar_rms", s.lbar_rms},
      {"l0_matched", s.l0_matched}, {"lambda_exponential", s.lambda_exponential},
      {"ks_matched", s.ks_matched}, {"ks_exponential", s.ks_exponential}};
  for (const auto& [name, value] : scalars) write_double(group, name, value);
  if (D == 3) write_double(group, "ks_isotropic", s.ks_isotropic);
}

template <int D>
void write_paths(hid_t file, const FreePathStatistics<D>& paths, const CollisionStatisticsMetadata& m) {
  Handle path_group = group(file, "free_paths");
  const hid_t g = path_group.get();
  if (D == 3) {
    write_string_attribute(g, "angle_variable", "cos_theta_x");
    if (!m.polydisperse) {
      const ReferenceMeanFreePaths reference = sphere_mean_free_paths(m.system);
      write_double(g, "boltzmann_mean_free_path", reference.boltzmann);
      write_double(g, "enskog_mean_free_path", reference.enskog);
    }
  }
  write_vector(g, "length_edges", edges(paths.length_bins()));
  write_double(g, "initial_max_length", paths.settings().max_length);
  write_double(g, "dropped_fraction", paths.dropped_fraction());
  write_vector(g, "angle_edges", edges(paths.angle_bins()));
  Handle total = group(g, "total");
  write_path_summary(total.get(), paths.total(), paths);
  total.close();
  const FreePathSettings& s = paths.settings();
  for (std::size_t w = 0; w < s.density_windows.size(); ++w) {
    Handle d = group(g, fmt::format("density_window_{}", w).c_str());
    write_double(d.get(), "density_low", s.density_windows[w].low);
    write_double(d.get(), "density_high", s.density_windows[w].high);
    write_path_summary(d.get(), paths.by_density()[w], paths);
    d.close();
  }
  for (std::size_t w = 0; w < s.speed_windows.size(); ++w) {
    Handle d = group(g, fmt::format("speed_window_{}", w).c_str());
    write_double(d.get(), "speed_low", s.speed_windows[w].low);
    write_double(d.get(), "speed_high", s.speed_windows[w].high);
    write_path_summary(d.get(), paths.by_speed()[w], paths);
    d.close();
  }
  path_group.close();
}

template <int D>
std::string impact_csv(const ImpactParameterStatistics<D>& impacts) {
  const UniformBins& bins = impacts.bins();
  std::vector<ImpactParameterSummary> columns{summarize_impact_parameters(impacts.total(), bins)};
  std::string out = D == 3 ? "b2_over_sigma2,beta,B_minus_uniform" : "b_over_sigma,beta,B_minus_uniform";
  for (std::size_t w = 0; w < impacts.density_windows().size(); ++w) {
    columns.push_back(summarize_impact_parameters(impacts.by_density()[w], bins));
    out += fmt::format(",beta_rho{0},B_minus_uniform_rho{0}", w);
  }
  out += "\n";
  for (int k = 0; k < bins.bins; ++k) {
    out += fmt::format("{:.6g}", bins.center(k));
    for (const auto& c : columns) {
      out += fmt::format(",{:.9g},{:.9g}", c.density[static_cast<std::size_t>(k)], c.cumulative_minus_uniform[static_cast<std::size_t>(k)]);
    }
    out += "\n";
  }
  return out;
}

template <int D>
std::string paths_csv(const FreePathStatistics<D>& paths) {
  const FreePathSummary s = summarize_free_paths(paths.total(), paths.length_bins(), paths.angle_bins(), D);
  std::string out = "l,P_measured,P_matched_eq_3_36,P_exponential,L_cumulative\n";
  for (int k = 0; k < paths.length_bins().bins; ++k) {
    const auto i = static_cast<std::size_t>(k);
    out += fmt::format("{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", paths.length_bins().center(k), s.magnitude_density[i],
                       s.matched_density[i], s.exponential_density[i], s.length_cumulative[i]);
  }
  return out;
}

}  // namespace

namespace {

using h5::Values;

// The summaries of one set of impact parameters (the total, a density window) in group `g`.
void describe_impact_summary(h5::FileSchema& schema, const std::string& g) {
  for (const char* name : {"counts", "density", "cumulative_minus_uniform"}) {
    schema.datasets.push_back({g + "/" + name, "B", Values::kNumbers});
  }
  schema.attributes.push_back({g, "samples", Values::kFinite});
  schema.attributes.push_back({g, "ks_uniform", Values::kNumbers});
}

// The summaries of one set of free paths (the total, a density or speed window) in group `g`.
void describe_path_summary(h5::FileSchema& schema, const std::string& g) {
  for (const char* name : {"counts", "cumulative"}) schema.datasets.push_back({g + "/" + name, "L,A", Values::kNumbers});
  for (const char* name : {"magnitude_density", "matched_density", "exponential_density", "length_cumulative"}) {
    schema.datasets.push_back({g + "/" + name, "L", Values::kNumbers});
  }
  for (const char* name : {"overflow", "angular_cumulative", "angular_fit"}) {
    schema.datasets.push_back({g + "/" + name, "A", Values::kNumbers});
  }
  for (const char* name : {"paths", "mean_length", "mean_speed", "mean_length_squared", "alpha0", "alpha0_rms", "lbar",
                           "lbar_rms", "l0_matched", "lambda_exponential", "ks_matched", "ks_exponential"}) {
    schema.attributes.push_back({g, name, Values::kNumbers});
  }
  schema.attributes.push_back({g, "ks_isotropic", Values::kNumbers, 1, false});
}

void describe_window_bounds(h5::FileSchema& schema, const std::string& g, const std::string& quantity) {
  for (const char* end : {"_low", "_high"}) schema.attributes.push_back({g, quantity + end, Values::kFinite});
}

}  // namespace

const h5::FileSchema& collision_statistics_schema() {
  static const h5::FileSchema schema = [] {
    h5::FileSchema s{kFormat, kFormatVersion, kFormatVersion, {}, {}, {}};
    s.attributes.push_back({".", "boundary", Values::kText});
    s.attributes.push_back({".", "particles", Values::kIntegers});
    for (const char* name : {"diameter", "restitution", "shear_velocity", "length_x", "length_y", "from_t", "from_c", "to_t", "to_c"}) {
      s.attributes.push_back({".", name, Values::kFinite});
    }
    for (const char* name : {"density_cells_nx", "density_cells_ny"}) s.attributes.push_back({".", name, Values::kIntegers});
    s.attributes.push_back({".", "dimension", Values::kIntegers, 1, false});
    s.attributes.push_back({".", "length_z", Values::kFinite, 1, false});
    s.attributes.push_back({".", "density_cells_nz", Values::kIntegers, 1, false});

    // Either statistics may be switched off; each present has its total.
    s.groups = {"impact_parameters/total", "impact_parameters/windows", "free_paths/total"};
    // Impact parameters: B bins, W windows of collisions.
    s.datasets.push_back({"impact_parameters/bin_edges", "B+1"});
    s.attributes.push_back({"impact_parameters", "window_collisions", Values::kIntegers});
    s.attributes.push_back({"impact_parameters", "variable", Values::kText, 1, false});
    describe_impact_summary(s, "impact_parameters/total");
    describe_impact_summary(s, "impact_parameters/density_window_*");
    describe_window_bounds(s, "impact_parameters/density_window_*", "density");
    for (const char* name : {"t_start", "t_end", "collisions"}) {
      s.datasets.push_back({std::string("impact_parameters/windows/") + name, "W", Values::kFinite});
    }
    s.datasets.push_back({"impact_parameters/windows/counts", "W,B", Values::kFinite});

    // Free paths: L length bins, A angle bins.
    s.datasets.push_back({"free_paths/length_edges", "L+1"});
    s.datasets.push_back({"free_paths/angle_edges", "A+1"});
    for (const char* name : {"initial_max_length", "dropped_fraction"}) s.attributes.push_back({"free_paths", name, Values::kFinite});
    s.attributes.push_back({"free_paths", "angle_variable", Values::kText, 1, false});
    for (const char* name : {"boltzmann_mean_free_path", "enskog_mean_free_path"}) {
      s.attributes.push_back({"free_paths", name, Values::kFinite, 1, false});
    }
    describe_path_summary(s, "free_paths/total");
    describe_path_summary(s, "free_paths/density_window_*");
    describe_window_bounds(s, "free_paths/density_window_*", "density");
    describe_path_summary(s, "free_paths/speed_window_*");
    describe_window_bounds(s, "free_paths/speed_window_*", "speed");
    return s;
  }();
  return schema;
}

ReferenceMeanFreePaths sphere_mean_free_paths(const SystemParams& s) {
  const double volume = s.length_x * s.length_y * s.length_z;
  const double n = static_cast<double>(s.particles) / volume;
  const double phi = n * theory::particle_volume(3, s.diameter);
  return {theory::hard_sphere_mean_free_path(3, n, s.diameter, 1.0),
          theory::hard_sphere_mean_free_path(3, n, s.diameter, theory::carnahan_starling_contact_value(phi))};
}

template <int D>
void write_collision_statistics(const std::string& dir, const CollisionStatisticsMetadata& m,
                                const ImpactParameterStatistics<D>* impacts, const FreePathStatistics<D>* paths) {
  if (!impacts && !paths) return;
  const std::string path = dir + "/collisions.h5";
  Handle partial(create_partial_file(path, kFormat, kFormatVersion, m.version), H5Fclose);
  const hid_t file = partial.get();
  write_string_attribute(file, "boundary", m.boundary);
  write_attribute(file, "particles", H5T_NATIVE_INT64, &m.system.particles);
  for (const auto& [name, value] : std::vector<std::pair<const char*, double>>{
           {"diameter", m.system.diameter}, {"restitution", m.system.restitution},
           {"shear_velocity", m.system.shear_velocity}, {"length_x", m.system.length_x}, {"length_y", m.system.length_y},
           {"from_t", m.from_t}, {"from_c", m.from_c}, {"to_t", m.to_t}, {"to_c", m.to_c}}) {
    write_double(file, name, value);
  }
  write_attribute(file, "density_cells_nx", H5T_NATIVE_INT, &m.density_grid.nx);
  write_attribute(file, "density_cells_ny", H5T_NATIVE_INT, &m.density_grid.ny);
  if (D == 3) {  // a 2D file has no 3D attribute, not even `dimension`
    write_attribute(file, "dimension", H5T_NATIVE_INT, &m.system.dimension);
    write_double(file, "length_z", m.system.length_z);
    write_attribute(file, "density_cells_nz", H5T_NATIVE_INT, &m.density_grid.nz);
  }
  if (impacts) write_impacts(file, *impacts);
  if (paths) write_paths(file, *paths, m);
  publish_partial_file(partial.release(), path);
  if (impacts) write_file_atomically(dir + "/impact_parameters.csv", impact_csv(*impacts));
  if (paths) write_file_atomically(dir + "/free_paths.csv", paths_csv(*paths));
}

template void write_collision_statistics(const std::string&, const CollisionStatisticsMetadata&,
                                         const ImpactParameterStatistics<2>*, const FreePathStatistics<2>*);
template void write_collision_statistics(const std::string&, const CollisionStatisticsMetadata&,
                                         const ImpactParameterStatistics<3>*, const FreePathStatistics<3>*);

}  // namespace granule
