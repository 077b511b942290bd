#include "theory/shear_start_table.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "theory/clustering_summary.hpp"
#include "theory/kinetic_scales.hpp"
#include "theory/shear_start.hpp"
#include "theory/shear_time_scales.hpp"
#include "theory/steady_shear.hpp"

namespace granule::theory {

ShearStartPrediction shear_start_table(const ShearStartInputs& in) {
  const double eps = inelasticity(in.restitution);
  const double sigma = in.diameter > 0.0 ? in.diameter
                                         : diameter_for_area_fraction(in.area_fraction, in.particles, in.box_x,
                                                                      in.box_y);
  const double l = mean_free_path(sigma, in.area_fraction);
  const double gamma = in.shear_rate;
  const double T0 = steady_shear_temperature_kinetic(in.restitution, gamma, sigma, in.area_fraction);
  const double Ti = in.temperature_over_steady > 0.0 ? in.temperature_over_steady * T0 : in.initial_temperature;
  // k: the expected dominant scale, the cluster separation 1/k = l/√ε (kl ~ √ε, §4.2), unless
  // kl or a box mode n (k = 2πn/L_x, along the fluctuation (0, v0 sin kx)) is given.
  const double kl = in.kl > 0.0     ? in.kl
                    : in.mode > 0 ? 2.0 * std::numbers::pi * in.mode / in.box_x * l
                                  : std::sqrt(eps);
  const double k = kl / l;
  const double h = shear_fluctuation_rate(k, Ti, in.particles);
  const auto hot_start = early_shear_temperature(Ti, hot_start_heating_function(gamma, h), l, eps);
  const auto any_start = early_shear_temperature(Ti, shear_heating_function(gamma, h), l, eps);
  const auto scales = clustering_scales(k, l, eps, gamma, h);
  // h = γ where T_i = N(γ/k)²: the start is hot (γ/h < 1) above it.
  const double Ti_hot_edge = in.particles * (gamma / k) * (gamma / k);
  const double t_max = in.time_max > 0.0 ? in.time_max : kSaturationTimes / any_start.rate;

  ShearStartPrediction out{Ti, {{"t", "strain", "A_4.29", "T_4.28", "T_4.26"}, {}, {}, {}, {}}};
  PredictionTable& table = out.table;
  table.derived_names = {"diameter", "l", "T0", "T_i", "h", "T_sat", "rate", "tau_m", "1/s3", "t_max"};
  table.derived = {sigma, l, T0, Ti, h, any_start.saturation, any_start.rate, scales.mass_motion_time,
                   scales.linear_growth_time, t_max};
  table.summary = {
      fmt::format("e {}  eps = 1-e^2 = {:.6g}  nu {:.6g}  N {}  box {:.6g} x {:.6g}  diameter "
                  "{:.6g}  l = pi sigma/8nu {:.6g}",
                  in.restitution, eps, in.area_fraction, in.particles, in.box_x, in.box_y, sigma, l),
      fmt::format("gamma {:.6g}  T0 = l^2 gamma^2/(pi eps) (4.5) {:.6g}  T_i {:.6g} = {:.6g} T0 = "
                  "{:.6g} sqrt(N) T0",
                  gamma, T0, Ti, Ti / T0, Ti / (std::sqrt(in.particles) * T0)),
      fmt::format("k l = {:.6g} ({})  1/k = {:.6g}  2 pi/k = {:.6g} sigma = {:.6g} L_x", kl,
                  in.kl > 0.0    ? "--kl"
                  : in.mode > 0 ? fmt::format("mode n = {}", in.mode)
                                : "sqrt(eps): the cluster separation",
                  1.0 / k, 2.0 * std::numbers::pi / k / sigma, 2.0 * std::numbers::pi / k / in.box_x),
      fmt::format("h ~ k sqrt(T_i/N) (4.25) {:.6g}  gamma/h {:.6g}: {} start (hot when T_i > "
                  "N (gamma/k)^2 = {:.6g} = {:.6g} T0)",
                  h, gamma / h, scales.hot ? "hot" : "cold", Ti_hot_edge, Ti_hot_edge / T0),
      fmt::format("(4.28): T_sat = l^2 h^2 (1 + 2 gamma/h)/(pi eps) {:.6g}  rate sqrt(eps) h "
                  "sqrt(1 + 2 gamma/h) {:.6g}  alpha (4.30) {:.6g}{}",
                  hot_start.saturation, hot_start.rate, hot_start.alpha(),
                  scales.hot ? "" : "  (assumes gamma/h << 1: use T_4.26)"),
      fmt::format("(4.26) with Tr D^2 = 2 (gamma + h)^2: T_sat {:.6g}  rate sqrt(eps) (gamma + h) "
                  "{:.6g}",
                  any_start.saturation, any_start.rate)};
  for (auto& line : clustering_lines(scales, k, l, sigma, in.box_x)) table.summary.push_back(std::move(line));
  table.summary.push_back("strain = gamma t; T = <v'^2>/2 per unit mass");
  for (double t : linspace(0.0, t_max, in.points)) {
    table.rows.push_back({t, gamma * t, hot_start.relaxation(t), hot_start.temperature(t), any_start.temperature(t)});
  }
  return out;
}

}  // namespace granule::theory
