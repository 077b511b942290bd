// `granule theory shear-start`: the options and checks of the early-time temperature of a sheared
// gas after a hot or a cold start (theory/shear_start_table.hpp). The system comes from options or
// from a run's config file (`--config`), so that the prediction sits beside the run.
#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <string>

#include "app/theory/theory_checks.hpp"
#include "app/theory/theory_subcommands.hpp"
#include "io/config.hpp"
#include "theory/shear_start_table.hpp"

namespace granule::app {

namespace {

using namespace theory_checks;
namespace th = granule::theory;

// kl of the shear fluctuation: like δ̄ in shear-stability, up to 1e6 (far beyond kl < √ε ≤ 1,
// where the neglect of diffusion in (4.26) holds, (4.31)).
constexpr NumberRange kKl{0.0, 1e6, true, false};
// T_i/T0: any ratio that keeps T_i inside the temperature range is allowed (checked on T_i).
constexpr NumberRange kTemperatureRatio{0.0, 1e120, true, false};

struct Opts {
  std::string config;
  th::ShearStartInputs in;
  bool csv = false;
};

// The options a run config supplies when they are not given on the command line: ẽ, ν, σ, N,
// the box, γ = U/L_y and T_i of `granule run` (README.md, configuration reference).
void take_from_config(const CLI::App& cmd, Opts& o) {
  const ConfigResult loaded = load_config_file(o.config, {});
  if (!loaded.config) refuse(cmd, "--config: " + loaded.error);
  const RunConfig& c = *loaded.config;
  const auto given = [&](const char* option) { return cmd.count(option) > 0; };
  if (!given("--restitution")) o.in.restitution = c.system.restitution;
  if (!given("--particles")) o.in.particles = static_cast<int>(c.system.particles);
  if (!given("--box-x")) o.in.box_x = c.system.length_x;
  if (!given("--box-y")) o.in.box_y = c.system.length_y;
  const bool geometry_given = given("--area-fraction") || given("--particles") ||
                              given("--box-x") || given("--box-y");
  if (!given("--area-fraction")) o.in.area_fraction = c.packing_fraction;
  // The config's σ holds only while N, ν and the box are its own; otherwise σ follows from them.
  if (!given("--diameter") && !geometry_given) o.in.diameter = c.system.diameter;
  if (!given("--shear-rate")) {
    if (!c.lees_edwards || c.system.shear_velocity == 0.0) {
      refuse(cmd, fmt::format("--config {}: boundary.kind is not \"lees-edwards\" with a "
                              "shear_velocity: give --shear-rate",
                              o.config));
    }
    o.in.shear_rate = std::abs(c.system.shear_velocity) / c.system.length_y;
  }
  if (!given("--initial-temperature") && !given("--temperature-over-steady")) {
    o.in.initial_temperature = c.initial_temperature;
  }
}

void check_options(const CLI::App& cmd, const Opts& o) {
  // A value the config supplied is named by its key, so that the message says what to change.
  const auto name = [&](const std::string& option, const char* key) {
    return o.config.empty() || cmd.count(option) > 0
               ? option
               : fmt::format("{} ({} in {})", option, key, o.config);
  };
  require(cmd, name("--restitution", "system.restitution"), o.in.restitution, kDissipativeRestitution,
          " (e = 1 has no steady sheared state)");
  require(cmd, name("--area-fraction", "system.area_fraction"), o.in.area_fraction, kAreaFraction);
  require_if_given(cmd, "--diameter", o.in.diameter, kLengthRange);
  require(cmd, "--particles", o.in.particles, kParticles);
  require(cmd, "--box-x", o.in.box_x, kLengthRange);
  require(cmd, "--box-y", o.in.box_y, kLengthRange);
  require(cmd, name("--shear-rate", "boundary.shear_velocity / system.box[1]"), o.in.shear_rate, kRateRange);
  require_if_given(cmd, "--initial-temperature", o.in.initial_temperature, kTemperatureRange);
  require_if_given(cmd, "--temperature-over-steady", o.in.temperature_over_steady, kTemperatureRatio);
  require_if_given(cmd, "--kl", o.in.kl, kKl);
  require_if_given(cmd, "--mode", o.in.mode, NumberRange{1.0, 2147483647.0});
  require_if_given(cmd, "--time-max", o.in.time_max, NumberRange{0.0, 1e300, true, false});
  require(cmd, "--points", o.in.points, kPoints);
  if (o.config.empty() && cmd.count("--initial-temperature") == 0 &&
      cmd.count("--temperature-over-steady") == 0) {
    refuse(cmd, "give the start: --initial-temperature T_i, --temperature-over-steady T_i/T0, or "
                "--config FILE (its initial.temperature)");
  }
}

void run_shear_start(const CLI::App& cmd, Opts& o) {
  if (!o.config.empty()) take_from_config(cmd, o);
  check_options(cmd, o);
  const th::ShearStartPrediction prediction = th::shear_start_table(o.in);
  if (cmd.count("--temperature-over-steady") > 0) {
    require(cmd, "T_i = --temperature-over-steady * T0", prediction.initial_temperature, kTemperatureRange);
  }
  print_table(cmd, prediction.table, o.csv);
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
  auto* ti = cmd->add_option("--initial-temperature", o->in.initial_temperature,
                             "initial temperature T_i = <v'^2>/2");
  cmd->add_option("--temperature-over-steady", o->in.temperature_over_steady,
                  "T_i as a multiple of T0 (4.5)")
      ->excludes(ti);
  cmd->add_option("-e,--restitution", o->in.restitution, "restitution")->capture_default_str();
  cmd->add_option("--area-fraction", o->in.area_fraction, "nu = pi N sigma^2/(4 Lx Ly)")
      ->capture_default_str();
  cmd->add_option("--diameter", o->in.diameter, "disk diameter (default: from N, Lx, Ly, nu)");
  cmd->add_option("--particles", o->in.particles, "number of disks N")->capture_default_str();
  cmd->add_option("--box-x", o->in.box_x, "Lx")->capture_default_str();
  cmd->add_option("--box-y", o->in.box_y, "Ly")->capture_default_str();
  cmd->add_option("--shear-rate", o->in.shear_rate, "gamma = U/Ly [1/time]")->capture_default_str();
  auto* kl = cmd->add_option("--kl", o->in.kl,
                             "k l of the shear fluctuation (default sqrt(eps): the cluster "
                             "separation)");
  cmd->add_option("--mode", o->in.mode, "Fourier mode n instead: k = 2 pi n/Lx")->excludes(kl);
  cmd->add_option("--time-max", o->in.time_max, "last row's t (default: 5 saturation times 1/rate)");
  cmd->add_option("--points", o->in.points, "rows, evenly spaced in t")->capture_default_str();
  cmd->add_flag("--csv", o->csv, "print CSV");
  cmd->callback([o, cmd] { run_shear_start(*cmd, *o); });
}

}  // namespace granule::app
