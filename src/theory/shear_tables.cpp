#include "theory/shear_tables.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "theory/clustering_summary.hpp"
#include "theory/kinetic_scales.hpp"
#include "theory/shear_time_scales.hpp"
#include "theory/steady_shear.hpp"

namespace granule::theory {

using std::numbers::pi;

PredictionTable shear_stability_table(const ShearStabilityInputs& in) {
  const double r = in.sqrt_eps;
  auto re_sm = [&](double d, double theta, double root) {
    return largest_shear_growth_rate(d, theta, root, in.scaling).real();
  };
  const auto deltas = linspace(in.delta_min, in.delta_max, in.points);
  PredictionTable table;
  table.summary.push_back(fmt::format(
      "pressure scaling: {}", in.scaling == ShearPressureScaling::thesis ? "thesis" : "consistent"));
  if (in.figure == "4.1") {
    table.columns = {"delta_bar", "re_sm_theta45", "re_sm_theta135"};
    table.summary.push_back("Fig. 4.1: Re s_m vs delta_bar at sqrt(eps) = 0.8");
    for (double d : deltas) table.rows.push_back({d, re_sm(d, pi / 4, 0.8), re_sm(d, 3 * pi / 4, 0.8)});
  } else if (in.figure == "4.2") {
    table.columns = {"theta_deg", "re_sm_delta0.5", "re_sm_delta0.1"};
    table.summary.push_back("Fig. 4.2: Re s_m vs theta at sqrt(eps) = 0.8");
    for (double deg : linspace(0.0, 180.0, in.points)) {
      table.rows.push_back({deg, re_sm(0.5, deg * pi / 180, 0.8), re_sm(0.1, deg * pi / 180, 0.8)});
    }
  } else if (in.figure == "4.3") {
    table.columns = {"sqrt_eps", "delta_bar", "re_sm"};
    table.summary.push_back("Fig. 4.3: Re s_m vs sqrt(eps) and delta_bar at theta = 3pi/4");
    for (double root : linspace(1.0 / in.points, 1.0, in.points)) {
      for (double d : deltas) table.rows.push_back({root, d, re_sm(d, 3 * pi / 4, root)});
    }
  } else if (in.figure == "4.4") {
    table.columns = {"theta_deg", "delta_bar", "re_sm"};
    table.summary.push_back("Fig. 4.4: Re s_m vs theta and delta_bar at sqrt(eps) = 0.8");
    for (double deg : linspace(0.0, 180.0, in.points)) {
      for (double d : deltas) table.rows.push_back({deg, d, re_sm(d, deg * pi / 180, 0.8)});
    }
  } else {
    const double theta = in.theta_deg * pi / 180.0;
    table.columns = {"delta_bar", "re_sm", "im_sm", "s3_thesis", "s3_corrected", "best_theta_deg"};
    table.summary.push_back(fmt::format("sqrt(eps) = {:.6g}, theta = {} deg", r, in.theta_deg));
    table.summary.push_back(
        "s_m: root of largest real part; s3_thesis: (4.23); s3_corrected: with the O(delta^2) "
        "term; best_theta_deg: direction of largest Re s_m");
    const double marginal = marginal_delta_bar(theta, r, 4.0, 400, in.scaling);
    table.summary.push_back(fmt::format("Re s_m > 0 for delta_bar < {:.6g}", marginal));
    for (double d : deltas) {
      const auto sm = largest_shear_growth_rate(d, theta, r, in.scaling);
      table.rows.push_back({d, sm.real(), sm.imag(), shear_small_delta_roots_thesis(d, theta, r, in.scaling).s3,
                            shear_small_delta_roots_corrected(d, theta, r, in.scaling).s3,
                            most_unstable_direction(d, r, 360, in.scaling) * 180.0 / pi});
    }
  }
  return table;
}

PredictionTable shear_scales_table(const ShearScalesInputs& in) {
  const double eps = inelasticity(in.restitution);
  const double sigma = in.diameter > 0.0
                           ? in.diameter
                           : diameter_for_area_fraction(in.area_fraction, in.particles, in.box, in.box);
  const double l = mean_free_path(sigma, in.area_fraction);
  const double gamma = in.shear_rate;
  const double T0 = steady_shear_temperature_kinetic(in.restitution, gamma, sigma, in.area_fraction);
  const double Ti = in.initial_temperature > 0.0 ? in.initial_temperature : T0;
  const double k = 2.0 * pi * in.mode / in.box;
  const double h = shear_fluctuation_rate(k, Ti, in.particles);
  const auto scales = clustering_scales(k, l, eps, gamma, h);
  PredictionTable table;
  table.derived_names = {"diameter", "l", "T0", "h", "tau_m", "1/s3"};
  table.derived = {sigma, l, T0, h, scales.mass_motion_time, scales.linear_growth_time};
  table.summary = {
      fmt::format("eps {:.6g}  sqrt(eps) {:.6g}  diameter {:.6g}  l = pi sigma/8nu {:.6g}", eps, std::sqrt(eps),
                  sigma, l),
      fmt::format("T0 = l^2 gamma^2/(pi eps) (4.5) {:.6g}   T_i {:.6g}", T0, Ti),
      fmt::format("mode n = {}: k l = {:.6g}  delta* = {:.6g}  delta_bar = {:.6g}", in.mode, k * l,
                  shear_delta_star(l, in.box, eps), shear_delta_bar_of_mode(in.mode, l, in.box, eps)),
      fmt::format("shear fluctuation h ~ k sqrt(T_i/N) = {:.6g}   gamma/h = {:.6g} ({})", h, gamma / h,
                  scales.hot ? "h >> gamma: (4.36), (4.37)" : "h << gamma: (4.39)-(4.41)")};
  for (auto& line : clustering_lines(scales, k, l, sigma, in.box)) table.summary.push_back(std::move(line));
  table.summary.push_back(fmt::format("cluster separation L0 = l/sqrt(eps) = {:.6g} = {:.6g} L", l / std::sqrt(eps),
                                      l / std::sqrt(eps) / in.box));
  return table;
}

PredictionTable steady_shear_table(const SteadyShearInputs& in) {
  const double sigma = in.diameter > 0.0 ? in.diameter
                                         : diameter_for_area_fraction(in.area_fraction, in.particles, in.box_x,
                                                                      in.box_y);
  PredictionTable table{{"restitution", "eps", "T_fit_3.1", "T_JR_3.2", "T0_4.5"}, {}, {}, {}, {}};
  table.summary = {fmt::format("shear rate {}  area fraction {}  diameter {:.6g}", in.shear_rate,
                               in.area_fraction, sigma),
                   fmt::format("(3.1): A = {}, B = {}; T = <v'^2>/2 per unit mass", tan_fit_A, tan_fit_B)};
  const auto es = in.restitution >= 0.0 ? std::vector<double>{in.restitution}
                                        : linspace(in.e_min, in.e_max, in.points);
  for (double e : es) {
    table.rows.push_back({e, inelasticity(e),
                          steady_shear_temperature_tan_fit(e, in.shear_rate, sigma, in.area_fraction),
                          steady_shear_temperature_jenkins_richman(e, in.shear_rate, sigma, in.area_fraction),
                          steady_shear_temperature_kinetic(e, in.shear_rate, sigma, in.area_fraction)});
  }
  return table;
}

}  // namespace granule::theory
