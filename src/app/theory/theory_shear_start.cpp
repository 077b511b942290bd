// `granule theory shear-start`: the early-time temperature of a sheared gas after a hot or a
// cold start, (4.26)–(4.30), and the clustering scales of that start, (4.25), (4.36)–(4.41)
// (thesis §4.2). The system comes from options or from a run's config file (`--config`), so
// that the prediction sits beside the run.
#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <utility>

#include "app/theory/theory_checks.hpp"
#include "app/theory/theory_clustering_lines.hpp"
#include "app/theory/theory_subcommands.hpp"
#include "app/theory/theory_table.hpp"
#include "io/config.hpp"
#include "theory/kinetic_scales.hpp"
#include "theory/shear_start.hpp"
#include "theory/shear_time_scales.hpp"
#include "theory/steady_shear.hpp"

namespace granule::app {

namespace {

using namespace theory_checks;
namespace th = granule::theory;

// kl of the shear fluctuation: like δ̄ in shear-stability, up to 1e6 (far beyond kl < √ε ≤ 1,
// where the neglect of diffusion in (4.26) holds, (4.31)).
constexpr NumberRange kKl{0.0, 1e6, true, false};
// T_i/T0: any ratio that keeps T_i inside the temperature range is allowed (checked on T_i).
constexpr NumberRange kTemperatureRatio{0.0, 1e120, true, false};
// The curve ends after this many saturation times 1/r of (4.26) unless --time-max says otherwise:
// A(t) is then within 3e-2 of 1 for any start (|α| < 1, so |A − 1| ≤ 4e^{−rt}/(1 − e^{−rt})²).
constexpr double kSaturationTimes = 5.0;

struct Opts {
  std::string config;
  double restitution = 0.6, area_fraction = 0.05, diameter = 0.0, shear_rate = 100.0;
  double box_x = 1.0, box_y = 1.0, initial_temperature = 0.0, temperature_over_steady = 0.0;
  double kl = 0.0, time_max = 0.0;
  int particles = 20000, mode = 0, points = 21;
  bool csv = false;
};

// The options a run config supplies when they are not given on the command line: ẽ, ν, σ, N,
// the box, γ = U/L_y and T_i of `granule run` (README.md, configuration reference).
void take_from_config(const CLI::App& cmd, Opts& o) {
  const ConfigResult loaded = load_config_file(o.config, {});
  if (!loaded.config) refuse(cmd, "--config: " + loaded.error);
  const RunConfig& c = *loaded.config;
  const auto given = [&](const char* option) { return cmd.count(option) > 0; };
  if (!given("--restitution")) o.restitution = c.system.restitution;
  if (!given("--particles")) o.particles = static_cast<int>(c.system.particles);
  if (!given("--box-x")) o.box_x = c.system.length_x;
  if (!given("--box-y")) o.box_y = c.system.length_y;
  const bool geometry_given = given("--area-fraction") || given("--particles") ||
                              given("--box-x") || given("--box-y");
  if (!given("--area-fraction")) o.area_fraction = c.packing_fraction;
  // The config's σ holds only while N, ν and the box are its own; otherwise σ follows from them.
  if (!given("--diameter") && !geometry_given) o.diameter = c.system.diameter;
  if (!given("--shear-rate")) {
    if (!c.lees_edwards || c.system.shear_velocity == 0.0) {
      refuse(cmd, fmt::format("--config {}: boundary.kind is not \"lees-edwards\" with a "
                              "shear_velocity: give --shear-rate",
                              o.config));
    }
    o.shear_rate = std::abs(c.system.shear_velocity) / c.system.length_y;
  }
  if (!given("--initial-temperature") && !given("--temperature-over-steady")) {
    o.initial_temperature = c.initial_temperature;
  }
}

void check_options(const CLI::App& cmd, const Opts& o) {
  // A value the config supplied is named by its key, so that the message says what to change.
  const auto name = [&](const std::string& option, const char* key) {
    return o.config.empty() || cmd.count(option) > 0
               ? option
               : fmt::format("{} ({} in {})", option, key, o.config);
  };
  require(cmd, name("--restitution", "system.restitution"), o.restitution, kDissipativeRestitution,
          " (e = 1 has no steady sheared state)");
  require(cmd, name("--area-fraction", "system.area_fraction"), o.area_fraction, kAreaFraction);
  require_if_given(cmd, "--diameter", o.diameter, kLengthRange);
  require(cmd, "--particles", o.particles, kParticles);
  require(cmd, "--box-x", o.box_x, kLengthRange);
  require(cmd, "--box-y", o.box_y, kLengthRange);
  require(cmd, name("--shear-rate", "boundary.shear_velocity / system.box[1]"), o.shear_rate, kRateRange);
  require_if_given(cmd, "--initial-temperature", o.initial_temperature, kTemperatureRange);
  require_if_given(cmd, "--temperature-over-steady", o.temperature_over_steady, kTemperatureRatio);
  require_if_given(cmd, "--kl", o.kl, kKl);
  require_if_given(cmd, "--mode", o.mode, NumberRange{1.0, 2147483647.0});
  require_if_given(cmd, "--time-max", o.time_max, NumberRange{0.0, 1e300, true, false});
  require(cmd, "--points", o.points, kPoints);
  if (o.config.empty() && cmd.count("--initial-temperature") == 0 &&
      cmd.count("--temperature-over-steady") == 0) {
    refuse(cmd, "give the start: --initial-temperature T_i, --temperature-over-steady T_i/T0, or "
                "--config FILE (its initial.temperature)");
  }
}

void run_shear_start(const CLI::App& cmd, Opts& o) {
  if (!o.config.empty()) take_from_config(cmd, o);
  check_options(cmd, o);
  const double eps = th::inelasticity(o.restitution);
  const double sigma = o.diameter > 0.0 ? o.diameter
                                        : th::diameter_for_area_fraction(
                                              o.area_fraction, o.particles, o.box_x, o.box_y);
  const double l = th::mean_free_path(sigma, o.area_fraction);
  const double gamma = o.shear_rate;
  const double T0 =
      th::steady_shear_temperature_kinetic(o.restitution, gamma, sigma, o.area_fraction);
  const bool ratio_given = cmd.count("--temperature-over-steady") > 0;
  const double Ti = ratio_given ? o.temperature_over_steady * T0 : o.initial_temperature;
  if (ratio_given) require(cmd, "T_i = --temperature-over-steady * T0", Ti, kTemperatureRange);
  // k: the expected dominant scale, the cluster separation 1/k = l/√ε (kl ~ √ε, §4.2), unless
  // --kl or a box mode --mode n (k = 2πn/L_x, along the fluctuation (0, v0 sin kx)) is given.
  const double kl = o.kl > 0.0 ? o.kl
                    : o.mode > 0 ? 2.0 * std::numbers::pi * o.mode / o.box_x * l
                                 : std::sqrt(eps);
  const double k = kl / l;
  const double h = th::shear_fluctuation_rate(k, Ti, o.particles);
  const auto hot_start =
      th::early_shear_temperature(Ti, th::hot_start_heating_function(gamma, h), l, eps);
  const auto any_start =
      th::early_shear_temperature(Ti, th::shear_heating_function(gamma, h), l, eps);
  const auto scales = th::clustering_scales(k, l, eps, gamma, h);
  // h = γ where T_i = N(γ/k)²: the start is hot (γ/h < 1) above it.
  const double Ti_hot_edge = o.particles * (gamma / k) * (gamma / k);
  const double t_max = o.time_max > 0.0 ? o.time_max : kSaturationTimes / any_start.rate;
  require_finite(cmd, {"diameter", "l", "T0", "T_i", "h", "T_sat", "rate", "tau_m", "1/s3",
                       "t_max"},
                 {sigma, l, T0, Ti, h, any_start.saturation, any_start.rate,
                  scales.mass_motion_time, scales.linear_growth_time, t_max});

  Table table{{"t", "strain", "A_4.29", "T_4.28", "T_4.26"}, {}, {}};
  table.summary = {
      fmt::format("e {}  eps = 1-e^2 = {:.6g}  nu {:.6g}  N {}  box {:.6g} x {:.6g}  diameter "
                  "{:.6g}  l = pi sigma/8nu {:.6g}",
                  o.restitution, eps, o.area_fraction, o.particles, o.box_x, o.box_y, sigma, l),
      fmt::format("gamma {:.6g}  T0 = l^2 gamma^2/(pi eps) (4.5) {:.6g}  T_i {:.6g} = {:.6g} T0 = "
                  "{:.6g} sqrt(N) T0",
                  gamma, T0, Ti, Ti / T0, Ti / (std::sqrt(o.particles) * T0)),
      fmt::format("k l = {:.6g} ({})  1/k = {:.6g}  2 pi/k = {:.6g} sigma = {:.6g} L_x", kl,
                  o.kl > 0.0 ? "--kl" : o.mode > 0 ? fmt::format("mode n = {}", o.mode)
                                                   : "sqrt(eps): the cluster separation",
                  1.0 / k, 2.0 * std::numbers::pi / k / sigma,
                  2.0 * std::numbers::pi / k / o.box_x),
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
  for (auto& line : clustering_lines(scales, k, l, sigma, o.box_x)) {
    table.summary.push_back(std::move(line));
  }
  table.summary.push_back("strain = gamma t; T = <v'^2>/2 per unit mass");
  for (double t : linspace(0.0, t_max, o.points)) {
    table.rows.push_back({t, gamma * t, hot_start.relaxation(t), hot_start.temperature(t),
                          any_start.temperature(t)});
  }
  print_table(cmd, table, o.csv);
}

}  // namespace

void add_shear_start(CLI::App& theory) {
  auto o = std::make_shared<Opts>();
  auto* cmd = theory.add_subcommand(
      "shear-start",
      "Early-time temperature of a hot or cold start under shear (4.26)-(4.30) and its "
      "clustering window (4.37), (4.39)-(4.40)");
  cmd->add_option("--config", o->config,
                  "a run config (TOML): e, nu, sigma, N, box, U and T_i from it; options override");
  auto* ti = cmd->add_option("--initial-temperature", o->initial_temperature,
                             "initial temperature T_i = <v'^2>/2");
  cmd->add_option("--temperature-over-steady", o->temperature_over_steady,
                  "T_i as a multiple of T0 (4.5)")
      ->excludes(ti);
  cmd->add_option("-e,--restitution", o->restitution, "restitution")->capture_default_str();
  cmd->add_option("--area-fraction", o->area_fraction, "nu = pi N sigma^2/(4 Lx Ly)")
      ->capture_default_str();
  cmd->add_option("--diameter", o->diameter, "disk diameter (default: from N, Lx, Ly, nu)");
  cmd->add_option("--particles", o->particles, "number of disks N")->capture_default_str();
  cmd->add_option("--box-x", o->box_x, "Lx")->capture_default_str();
  cmd->add_option("--box-y", o->box_y, "Ly")->capture_default_str();
  cmd->add_option("--shear-rate", o->shear_rate, "gamma = U/Ly [1/time]")->capture_default_str();
  auto* kl = cmd->add_option("--kl", o->kl,
                             "k l of the shear fluctuation (default sqrt(eps): the cluster "
                             "separation)");
  cmd->add_option("--mode", o->mode, "Fourier mode n instead: k = 2 pi n/Lx")->excludes(kl);
  cmd->add_option("--time-max", o->time_max, "last row's t (default: 5 saturation times 1/rate)");
  cmd->add_option("--points", o->points, "rows, evenly spaced in t")->capture_default_str();
  cmd->add_flag("--csv", o->csv, "print CSV");
  cmd->callback([o, cmd] { run_shear_start(*cmd, *o); });
}

}  // namespace granule::app
