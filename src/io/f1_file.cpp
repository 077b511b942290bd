#include "io/f1_file.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "granule/version.hpp"
#include "io/atomic_file.hpp"
#include "io/file_schema.hpp"
#include "io/hdf5_util.hpp"

namespace granule {

namespace {

using namespace granule::distribution;
using namespace granule::h5;

constexpr const char* kFormat = "granule-f1";
constexpr int kFormatVersion = 1;
constexpr int kProfilePoints = 101;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

// The curves of one window in the snapshots' units, shared by the HDF5 and CSV writers.
struct Curves {
  std::vector<double> speed_edges, angle_edges;  // v_k, θ_l
  std::vector<double> h, h_fit;                  // (nv+1) × (nθ+1)
  std::vector<double> psi, psi_fit;              // (nv+1) × nθ
  std::vector<double> phi, phi_fit, j, j_fit;    // nv+1
  std::vector<double> theta, b, b_series, rms;   // nθ; b: nθ × 3
  std::vector<double> profile_speed, f_speed_once, f_speed_twice, f_speed_jr;  // at the profile angle
  std::vector<double> profile_angle, f_angle_once, f_angle_twice, f_angle_jr;  // at the profile speed
  double at_angle = 0.0, at_speed = 0.0;
  std::vector<double> table, table_error;  // 7 × 4: (ε_2j, b_2j^(0), b_2j^(1), b_2j^(2)), j = 0 … 6
  // The converged bootstrap replicates: R tables (R × 7 × 4), traces (R × 3: direct, once, twice), ratios.
  std::vector<double> replicate_tables, replicate_traces, replicate_ratios;
};

// Appendix B's layout of a sine series, 7 × 4: row j = 0 holds the means b_0^(i) (no phase), row j the
// phase ε_2j and the amplitudes b_2j^(i).
std::vector<double> appendix_b_rows(const SineSeries& b) {
  std::vector<double> rows = {kNaN, b.mean[0], b.mean[1], b.mean[2]};
  for (int j = 0; j < SineSeries::kHarmonics; ++j) {
    rows.insert(rows.end(), {b.phase[j], b.amplitude[j][0], b.amplitude[j][1], b.amplitude[j][2]});
  }
  return rows;
}

Curves curves_of(const WindowResult& r, const F1RunDescription& run) {
  const F1Estimate& e = r.estimate;
  const CumulativeFunction& c = e.cumulative;
  const int nv = c.grid.speed_bins, nt = c.grid.angle_bins;
  const double s = r.speed_scale;
  Curves out;
  for (int k = 0; k <= nv; ++k) out.speed_edges.push_back(s * c.grid.speed_edge(k));
  for (int l = 0; l <= nt; ++l) out.angle_edges.push_back(c.grid.angle_edge(l));
  for (int k = 0; k <= nv; ++k) {
    const double u = c.grid.speed_edge(k);
    for (int l = 0; l <= nt; ++l) {
      out.h.push_back(c.h(k, l));
      out.h_fit.push_back(e.once.cumulative(u, c.grid.angle_edge(l)));
    }
    for (int l = 0; l < nt; ++l) {
      out.psi.push_back(c.psi(k, l));
      out.psi_fit.push_back(e.once.angular.psi(c.grid.angle_edge(l), u));
    }
    out.phi.push_back(c.phi[k]);
    out.phi_fit.push_back(e.once.speed.phi(u));
    const double remaining = 1.0 - 2.0 * M_PI * c.phi[k];
    out.j.push_back(remaining > 0.0 ? -std::log(remaining) : kNaN);  // J(v) of (5.20) from the data (Fig 5.3)
    out.j_fit.push_back(e.once.speed.j(u));
  }
  // b^(i)(θ) of (5.27) in the snapshots' units, beside the series (5.29) (Fig 5.4).
  const double unit[3] = {1.0, 1.0 / s, 1.0 / (s * s)};
  for (Eigen::Index l = 0; l < e.angular.theta.size(); ++l) {
    const double theta = e.angular.theta[l];
    out.theta.push_back(theta);
    for (int i = 0; i < 3; ++i) {
      out.b.push_back(e.angular.b(l, i) * unit[i] + (i == 0 ? 2.0 * std::log(s) : 0.0));
      out.b_series.push_back(e.series.value(i, theta));
    }
    out.rms.push_back(e.angular.rms[l]);
  }
  // Figs 5.10, 5.11: f̃*, f̃** and the Jenkins–Richman f̃ along v at one θ and along θ at one v.
  out.at_angle = run.profile_angle;
  out.at_speed = run.profile_speed > 0.0 ? run.profile_speed : s;
  for (int k = 0; k < kProfilePoints; ++k) {
    const double v = r.fit_speed_max * k / (kProfilePoints - 1);
    out.profile_speed.push_back(v);
    out.f_speed_once.push_back(r.once_density(v, out.at_angle));
    out.f_speed_twice.push_back(r.twice_density(v, out.at_angle));
    out.f_speed_jr.push_back(r.jenkins_richman.density(v, out.at_angle));
    const double theta = 2.0 * M_PI * k / (kProfilePoints - 1);
    out.profile_angle.push_back(theta);
    out.f_angle_once.push_back(r.once_density(out.at_speed, theta));
    out.f_angle_twice.push_back(r.twice_density(out.at_speed, theta));
    out.f_angle_jr.push_back(r.jenkins_richman.density(out.at_speed, theta));
  }
  out.table = appendix_b_rows(e.series);
  out.table_error = appendix_b_rows(r.errors.series);
  for (const ReplicateNumbers& replicate : r.errors.replicate_numbers) {
    const std::vector<double> rows = appendix_b_rows(replicate.series);
    out.replicate_tables.insert(out.replicate_tables.end(), rows.begin(), rows.end());
    out.replicate_traces.insert(out.replicate_traces.end(),
                                {replicate.direct_trace, replicate.once_trace, replicate.twice_trace});
    out.replicate_ratios.push_back(replicate.ratio);
  }
  return out;
}

void write_int(hid_t object, const char* name, long long value) { write_attribute(object, name, H5T_NATIVE_LLONG, &value); }

void write_fit(hid_t group, const std::string& prefix, const FitReport& report) {
  write_int(group, (prefix + "_converged").c_str(), report.converged ? 1 : 0);
  write_double(group, (prefix + "_residual_rms").c_str(), report.residual_rms);
  write_int(group, (prefix + "_evaluations").c_str(), report.evaluations);
  write_string_attribute(group, (prefix + "_status").c_str(), report.status);
}

void write_window(hid_t file, int index, const WindowResult& r, const Curves& c) {
  Handle group(create_group(file, fmt::format("windows/{:03d}", index).c_str()), H5Gclose);
  const hid_t g = group.get();
  write_double(g, "density_center", r.density_window.center);
  write_double(g, "density_half_width", r.density_window.half_width);
  write_double(g, "temperature_center", r.temperature_window.center);
  write_double(g, "temperature_half_width", r.temperature_window.half_width);
  write_int(g, "samples", static_cast<long long>(r.samples));
  write_int(g, "snapshots", static_cast<long long>(r.snapshots));
  write_double(g, "density", r.density);
  write_double(g, "temperature", r.temperature);
  write_double(g, "cell_temperature", r.cell_temperature);
  write_double(g, "speed_scale", r.speed_scale);
  write_double(g, "speed_max", r.speed_max);
  write_double(g, "fit_speed_max", r.fit_speed_max);
  write_fit(g, "speed_fit", r.estimate.once.speed.report);
  write_fit(g, "angular_fit", r.estimate.once.angular.report);
  write_fit(g, "series_fit", r.estimate.series.report);
  write_int(g, "twice_fit_skipped_points", r.estimate.angular.skipped_points);
  write_double(g, "twice_fit_max_relative_deviation", r.estimate.angular.max_relative_deviation);
  write_double(g, "max_deviation_small_speed", r.quality.max_deviation_small_speed);
  write_double(g, "max_deviation_large_speed", r.quality.max_deviation_large_speed);
  write_int(g, "within_thesis_tolerance", r.quality.within_tolerance() ? 1 : 0);
  write_int(g, "bootstrap_replicates", r.errors.replicates);
  write_int(g, "bootstrap_converged_replicates", r.errors.converged_replicates);
  write_double(g, "ratio_b1_squared_over_b2", r.estimate.ratio);
  write_double(g, "ratio_error", r.errors.ratio);
  const auto nv = static_cast<hsize_t>(c.speed_edges.size()), nt = static_cast<hsize_t>(c.theta.size());
  write_dataset(g, "speed_edges", {nv}, c.speed_edges);
  write_dataset(g, "angle_edges", {nt + 1}, c.angle_edges);
  write_dataset(g, "h", {nv, nt + 1}, c.h);
  write_dataset(g, "h_fit", {nv, nt + 1}, c.h_fit);
  write_dataset(g, "psi", {nv, nt}, c.psi);
  write_dataset(g, "psi_fit", {nv, nt}, c.psi_fit);
  write_dataset(g, "phi", {nv}, c.phi);
  write_dataset(g, "phi_fit", {nv}, c.phi_fit);
  write_dataset(g, "J", {nv}, c.j);
  write_dataset(g, "J_fit", {nv}, c.j_fit);
  write_dataset(g, "theta", {nt}, c.theta);
  write_dataset(g, "b", {nt, 3}, c.b);
  write_dataset(g, "b_series", {nt, 3}, c.b_series);
  write_dataset(g, "twice_fit_rms", {nt}, c.rms);
  write_dataset(g, "table", {7, 4}, c.table);
  write_dataset(g, "table_error", {7, 4}, c.table_error);
  if (const auto replicates = static_cast<hsize_t>(c.replicate_ratios.size()); replicates > 0) {
    write_dataset(g, "bootstrap_table", {replicates, 7, 4}, c.replicate_tables);
    write_dataset(g, "bootstrap_traces", {replicates, 3}, c.replicate_traces);
    write_dataset(g, "bootstrap_ratio", {replicates}, c.replicate_ratios);
  }
  const F1Estimate& e = r.estimate;
  const auto tensor = [](const SecondMoment& m) { return std::vector<double>{m.xx, m.xy, m.yy}; };
  write_dataset(g, "stress_direct", {3}, tensor(e.direct));
  write_dataset(g, "stress_once", {3}, tensor(e.once_integrals.moment));
  write_dataset(g, "stress_twice", {3}, tensor(e.twice_integrals.moment));
  write_dataset(g, "stress_trace_error", {3}, {r.errors.direct_trace, r.errors.once_trace, r.errors.twice_trace});
  write_dataset(g, "normalisation", {2}, {e.once_integrals.normalisation, e.twice_integrals.normalisation});
  const JenkinsRichman& jr = r.jenkins_richman;
  write_dataset(g, "jenkins_richman", {4}, {jr.b0, jr.b2_mean, jr.b2_amplitude, jr.phase});
  const OnceFitted& once = e.once;
  write_dataset(g, "fit_a", {3}, {once.speed.a[0], once.speed.a[1], once.speed.a[2]});
  std::vector<double> alpha(once.angular.alpha.begin(), once.angular.alpha.end()), d;
  for (const auto& row : once.angular.d) d.insert(d.end(), row.begin(), row.end());
  write_dataset(g, "fit_alpha", {4}, alpha);
  write_dataset(g, "fit_d", {4, 5}, d);
  write_double(g, "fit_beta", once.angular.beta);
  write_double(g, "profile_angle", c.at_angle);
  write_double(g, "profile_speed", c.at_speed);
  const auto np = static_cast<hsize_t>(c.profile_speed.size());
  write_dataset(g, "profile_speeds", {np}, c.profile_speed);
  write_dataset(g, "f_once_vs_speed", {np}, c.f_speed_once);
  write_dataset(g, "f_twice_vs_speed", {np}, c.f_speed_twice);
  write_dataset(g, "f_jr_vs_speed", {np}, c.f_speed_jr);
  write_dataset(g, "profile_angles", {np}, c.profile_angle);
  write_dataset(g, "f_once_vs_angle", {np}, c.f_angle_once);
  write_dataset(g, "f_twice_vs_angle", {np}, c.f_angle_twice);
  write_dataset(g, "f_jr_vs_angle", {np}, c.f_angle_jr);
  group.close();
}

// Written as `<path>.partial` and given its final name only once its close succeeded; a failure
// (IoError) leaves the `.partial`.
void write_hdf5(const std::string& path, const F1RunDescription& run, const std::vector<WindowResult>& windows,
                const std::vector<Curves>& curves) {
  PartialFile partial(path, kFormat, kFormatVersion, kVersion);
  const hid_t file = partial.get();
  const SnapshotMetadata& m = run.metadata;
  write_string_attribute(file, "source", std::filesystem::absolute(run.source).string());
  write_int(file, "particles", m.system.particles);
  const double box[2] = {m.system.length_x, m.system.length_y};
  write_attribute(file, "box", H5T_NATIVE_DOUBLE, box, 2);
  write_double(file, "area_fraction", m.packing_fraction);
  write_double(file, "restitution", m.system.restitution);
  write_string_attribute(file, "boundary", m.boundary);
  write_double(file, "shear_velocity", m.system.shear_velocity);
  const int cells[2] = {run.cells_x, run.cells_y};
  write_attribute(file, "cells", H5T_NATIVE_INT, cells, 2);
  write_int(file, "from_frame", run.from_frame);
  write_int(file, "frames_used", run.frames_used);
  write_int(file, "subtract_shear_profile", run.subtract_shear_profile ? 1 : 0);
  write_int(file, "speed_bins", run.options.speed_bins);
  write_int(file, "angle_bins", run.options.angle_bins);
  write_double(file, "fit_quantile", run.options.fit_quantile);
  write_int(file, "bootstrap", run.options.bootstrap);
  write_int(file, "bootstrap_seed", static_cast<long long>(run.options.seed));
  write_int(file, "min_samples", static_cast<long long>(run.options.min_samples));
  Handle(create_group(file, "windows"), H5Gclose).close();
  for (std::size_t w = 0; w < windows.size(); ++w) write_window(file, static_cast<int>(w), windows[w], curves[w]);
  partial.publish();
}

std::string csv_number(double value) { return std::isnan(value) ? std::string() : fmt::format("{:.10g}", value); }

}  // namespace

const h5::FileSchema& f1_schema() {
  using h5::Values;
  static const h5::FileSchema schema = [] {
    h5::FileSchema s{kFormat, kFormatVersion, kFormatVersion, {"windows"}, {}, {}};
    for (const char* name : {"source", "boundary"}) s.attributes.push_back({".", name, Values::kText});
    for (const char* name : {"particles", "from_frame", "frames_used", "subtract_shear_profile", "speed_bins", "angle_bins",
                             "bootstrap", "bootstrap_seed", "min_samples"}) {
      s.attributes.push_back({".", name, Values::kIntegers});
    }
    for (const char* name : {"area_fraction", "restitution", "shear_velocity", "fit_quantile"}) {
      s.attributes.push_back({".", name, Values::kFinite});
    }
    s.attributes.push_back({".", "box", Values::kFinite, 2});
    s.attributes.push_back({".", "cells", Values::kIntegers, 2});

    // Each window: v speeds, t angle bins, r bootstrap replicates, p profile points.
    const std::string w = "windows/*";
    for (const char* name : {"density_center", "density_half_width", "temperature_center", "temperature_half_width", "density",
                             "temperature", "cell_temperature", "speed_scale", "speed_max", "fit_speed_max", "profile_angle",
                             "profile_speed"}) {
      s.attributes.push_back({w, name, Values::kFinite});
    }
    for (const char* name : {"samples", "snapshots", "twice_fit_skipped_points", "within_thesis_tolerance",
                             "bootstrap_replicates", "bootstrap_converged_replicates"}) {
      s.attributes.push_back({w, name, Values::kIntegers});
    }
    for (const char* name : {"twice_fit_max_relative_deviation", "max_deviation_small_speed", "max_deviation_large_speed",
                             "ratio_b1_squared_over_b2", "ratio_error", "fit_beta"}) {
      s.attributes.push_back({w, name, Values::kNumbers});
    }
    for (const char* fit : {"speed_fit", "angular_fit", "series_fit"}) {
      const std::string prefix(fit);
      s.attributes.push_back({w, prefix + "_converged", Values::kIntegers});
      s.attributes.push_back({w, prefix + "_evaluations", Values::kIntegers});
      s.attributes.push_back({w, prefix + "_residual_rms", Values::kNumbers});
      s.attributes.push_back({w, prefix + "_status", Values::kText});
    }
    const std::vector<std::pair<const char*, const char*>> axes{
        {"speed_edges", "v"}, {"angle_edges", "t+1"}, {"theta", "t"}, {"profile_speeds", "p"}, {"profile_angles", "p"}};
    for (const auto& [name, shape] : axes) s.datasets.push_back({w + "/" + name, shape});
    const std::vector<std::pair<const char*, const char*>> curves{
        {"h", "v,t+1"}, {"h_fit", "v,t+1"}, {"psi", "v,t"}, {"psi_fit", "v,t"}, {"phi", "v"}, {"phi_fit", "v"}, {"J", "v"},
        {"J_fit", "v"}, {"b", "t,3"}, {"b_series", "t,3"}, {"twice_fit_rms", "t"}, {"table", "7,4"}, {"table_error", "7,4"},
        {"stress_direct", "3"}, {"stress_once", "3"}, {"stress_twice", "3"}, {"stress_trace_error", "3"}, {"normalisation", "2"},
        {"jenkins_richman", "4"}, {"fit_a", "3"}, {"fit_alpha", "4"}, {"fit_d", "4,5"}, {"f_once_vs_speed", "p"},
        {"f_twice_vs_speed", "p"}, {"f_jr_vs_speed", "p"}, {"f_once_vs_angle", "p"}, {"f_twice_vs_angle", "p"},
        {"f_jr_vs_angle", "p"}};
    for (const auto& [name, shape] : curves) s.datasets.push_back({w + "/" + name, shape, Values::kNumbers});
    // Only when the window was bootstrapped.
    const std::vector<std::pair<const char*, const char*>> replicates{
        {"bootstrap_table", "r,7,4"}, {"bootstrap_traces", "r,3"}, {"bootstrap_ratio", "r"}};
    for (const auto& [name, shape] : replicates) s.datasets.push_back({w + "/" + name, shape, Values::kNumbers, false});
    return s;
  }();
  return schema;
}

std::vector<std::string> write_f1_outputs(const std::string& out, const F1RunDescription& run,
                                          const std::vector<WindowResult>& windows, const std::string& thesis_comparison) {
  std::vector<Curves> curves;
  for (const WindowResult& r : windows) curves.push_back(curves_of(r, run));
  const double e = run.metadata.system.restitution;
  std::string table = "e,rho_center,rho_half_width,T_center,T_half_width,j,epsilon_2j,b0_2j,b1_2j,b2_2j,"
                      "epsilon_2j_error,b0_2j_error,b1_2j_error,b2_2j_error\n";
  std::string summary =
      "window,rho_center,rho_half_width,T_center,T_half_width,samples,snapshots,rho,T,T_cells,b0_0,sqrt2T_b1_0,"
      "twoT_b2_0,ratio_b1sq_over_b2,ratio_error,trace_direct,trace_direct_error,trace_once,trace_once_error,"
      "trace_twice,trace_twice_error,normalisation_once,normalisation_twice,max_deviation_small_v,"
      "max_deviation_large_v,within_thesis_tolerance,speed_fit_converged,speed_fit_rms,angular_fit_converged,"
      "angular_fit_rms,series_fit_converged,series_fit_rms,twice_fit_max_relative_deviation,"
      "bootstrap_converged_replicates,bootstrap_replicates,jr_b0,jr_b2_mean,jr_b2_amplitude,jr_phase\n";
  std::string speed = "window,v,phi,phi_fit,J,J_fit\n";
  std::string cumulative = "window,v,theta,h,h_fit,psi,psi_fit\n";
  std::string angular = "window,theta,b0,b1,b2,b0_series,b1_series,b2_series,twice_fit_rms\n";
  std::string profiles = "window,along,v,theta,f_once,f_twice,f_jenkins_richman\n";
  for (std::size_t w = 0; w < windows.size(); ++w) {
    const WindowResult& r = windows[w];
    const Curves& c = curves[w];
    const ValueWindow &rho = r.density_window, &t = r.temperature_window;
    for (int j = 0; j <= SineSeries::kHarmonics; ++j) {
      table += fmt::format("{},{},{},{},{},{}", e, rho.center, rho.half_width, t.center, t.half_width, j);
      for (const std::vector<double>* values : {&c.table, &c.table_error})
        for (int q = 0; q < 4; ++q) table += fmt::format(",{}", csv_number((*values)[4 * j + q]));
      table += "\n";
    }
    const F1Estimate& est = r.estimate;
    const SineSeries& b = est.series;
    const JenkinsRichman& jr = r.jenkins_richman;
    summary += fmt::format(
        "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", w,
        rho.center, rho.half_width, t.center, t.half_width, r.samples, r.snapshots, csv_number(r.density), csv_number(r.temperature),
        csv_number(r.cell_temperature), csv_number(b.mean[0]), csv_number(r.speed_scale * b.mean[1]), csv_number(r.speed_scale * r.speed_scale * b.mean[2]),
        csv_number(est.ratio), csv_number(r.errors.ratio), csv_number(est.direct.trace()), csv_number(r.errors.direct_trace),
        csv_number(est.once_integrals.moment.trace()), csv_number(r.errors.once_trace), csv_number(est.twice_integrals.moment.trace()),
        csv_number(r.errors.twice_trace), csv_number(est.once_integrals.normalisation), csv_number(est.twice_integrals.normalisation),
        csv_number(r.quality.max_deviation_small_speed), csv_number(r.quality.max_deviation_large_speed),
        r.quality.within_tolerance() ? 1 : 0, est.once.speed.report.converged ? 1 : 0,
        csv_number(est.once.speed.report.residual_rms), est.once.angular.report.converged ? 1 : 0,
        csv_number(est.once.angular.report.residual_rms), b.report.converged ? 1 : 0, csv_number(b.report.residual_rms),
        csv_number(est.angular.max_relative_deviation), r.errors.converged_replicates, r.errors.replicates, csv_number(jr.b0),
        csv_number(jr.b2_mean), csv_number(jr.b2_amplitude), csv_number(jr.phase));
    const std::size_t nv = c.speed_edges.size(), nt = c.theta.size();
    for (std::size_t k = 0; k < nv; ++k) {
      speed += fmt::format("{},{},{},{},{},{}\n", w, csv_number(c.speed_edges[k]), csv_number(c.phi[k]), csv_number(c.phi_fit[k]), csv_number(c.j[k]), csv_number(c.j_fit[k]));
      for (std::size_t l = 0; l < nt; ++l)
        cumulative += fmt::format("{},{},{},{},{},{},{}\n", w, csv_number(c.speed_edges[k]), csv_number(c.angle_edges[l]),
                                  csv_number(c.h[k * (nt + 1) + l]), csv_number(c.h_fit[k * (nt + 1) + l]), csv_number(c.psi[k * nt + l]),
                                  csv_number(c.psi_fit[k * nt + l]));
    }
    for (std::size_t l = 0; l < nt; ++l)
      angular += fmt::format("{},{},{},{},{},{},{},{},{}\n", w, csv_number(c.theta[l]), csv_number(c.b[3 * l]), csv_number(c.b[3 * l + 1]),
                             csv_number(c.b[3 * l + 2]), csv_number(c.b_series[3 * l]), csv_number(c.b_series[3 * l + 1]),
                             csv_number(c.b_series[3 * l + 2]), csv_number(c.rms[l]));
    for (std::size_t k = 0; k < c.profile_speed.size(); ++k) {
      profiles += fmt::format("{},speed,{},{},{},{},{}\n", w, csv_number(c.profile_speed[k]), csv_number(c.at_angle), csv_number(c.f_speed_once[k]),
                              csv_number(c.f_speed_twice[k]), csv_number(c.f_speed_jr[k]));
      profiles += fmt::format("{},angle,{},{},{},{},{}\n", w, csv_number(c.at_speed), csv_number(c.profile_angle[k]), csv_number(c.f_angle_once[k]),
                              csv_number(c.f_angle_twice[k]), csv_number(c.f_angle_jr[k]));
    }
  }
  const std::filesystem::path parent = std::filesystem::path(out).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  const std::string stem = std::filesystem::path(out).replace_extension("").string();
  std::vector<std::string> written;
  for (const auto& [suffix, content] : {std::pair{"_table.csv", &table}, {"_windows.csv", &summary}, {"_speed.csv", &speed},
                                        {"_cumulative.csv", &cumulative}, {"_angular.csv", &angular},
                                        {"_profiles.csv", &profiles}}) {
    written.push_back(stem + suffix);
    write_file_atomically(written.back(), *content);
  }
  if (!thesis_comparison.empty()) {
    written.push_back(stem + "_thesis.csv");
    write_file_atomically(written.back(), thesis_comparison);
  }
  write_hdf5(out, run, windows, curves);
  written.push_back(out);
  return written;
}

}  // namespace granule
