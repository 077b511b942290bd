// `granule theory shear-stability`, `shear-scales` and `steady-shear`: the options and checks of
// the sheared gas's predictions (theory/shear_tables.hpp).
#include <cmath>
#include <memory>
#include <string>

#include "app/theory/theory_checks.hpp"
#include "app/theory/theory_subcommands.hpp"
#include "theory/kinetic_scales.hpp"
#include "theory/shear_tables.hpp"

namespace granule::app {

namespace {

using namespace theory_checks;
namespace th = granule::theory;

// δ̄ of the sheared gas, a dimensionless wavenumber.  The matrix holds O(1) and O(δ̄²) entries, so
// the weakest eigenvalue loses δ̄²·1e-16 of its value: up to 1e6 it keeps 4 digits (measured:
// re s_m = −3.92695 at δ̄ = 1e6 against −3.92699, −3.93 at 1e7).
constexpr NumberRange kDeltaBar{0.0, 1e6};

void add_shear_stability(CLI::App& theory) {
  struct Opts {
    th::ShearStabilityInputs in;
    double restitution = -1.0;
    std::string scaling = "thesis";
    bool csv = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = theory.add_subcommand(
      "shear-stability",
      "Growth rates of the 4x4 shear-flow system (4.19): s_m(delta_bar, theta, sqrt(eps))");
  auto* r_opt = cmd->add_option("--sqrt-eps", o->in.sqrt_eps, "sqrt(1-e^2)")->capture_default_str();
  cmd->add_option("-e,--restitution", o->restitution, "restitution (instead of --sqrt-eps)")
      ->excludes(r_opt);
  cmd->add_option("--theta-deg", o->in.theta_deg, "wavevector angle from the flow [degrees]")
      ->capture_default_str();
  cmd->add_option("--delta-min", o->in.delta_min, "smallest delta_bar")->capture_default_str();
  cmd->add_option("--delta-max", o->in.delta_max, "largest delta_bar")->capture_default_str();
  cmd->add_option("--points", o->in.points, "points per axis")->capture_default_str();
  cmd->add_option("--figure", o->in.figure, "print the data of a thesis figure")
      ->check(CLI::IsMember({"4.1", "4.2", "4.3", "4.4"}));
  cmd->add_option("--scaling", o->scaling,
                  "pressure term of (4.17): thesis (delta*^2, as printed) or consistent "
                  "(delta*^2/pi)")
      ->check(CLI::IsMember({"thesis", "consistent"}))
      ->capture_default_str();
  cmd->add_flag("--csv", o->csv, "print CSV");
  cmd->callback([o, cmd] {
    require(*cmd, "--sqrt-eps", o->in.sqrt_eps, kInelasticity);
    require_if_given(*cmd, "--restitution", o->restitution, kDissipativeRestitution, " (e = 1 does not cool)");
    require(*cmd, "--theta-deg", o->in.theta_deg, NumberRange{0.0, 180.0}, " (k and −k are one mode)");
    require(*cmd, "--delta-min", o->in.delta_min, kDeltaBar);
    require(*cmd, "--delta-max", o->in.delta_max, kDeltaBar);
    require(*cmd, "--points", o->in.points, kPoints);
    th::ShearStabilityInputs in = o->in;
    in.scaling = o->scaling == "thesis" ? th::ShearPressureScaling::thesis : th::ShearPressureScaling::consistent;
    if (o->restitution >= 0.0) in.sqrt_eps = std::sqrt(th::inelasticity(o->restitution));
    print_table(*cmd, th::shear_stability_table(in), o->csv);
  });
}

void add_shear_scales(CLI::App& theory) {
  auto o = std::make_shared<th::ShearScalesInputs>();
  auto* cmd = theory.add_subcommand(
      "shear-scales", "Clustering time scales and windows of a sheared gas (4.6), (4.36)-(4.41)");
  cmd->add_option("-e,--restitution", o->restitution, "restitution")->capture_default_str();
  cmd->add_option("--area-fraction", o->area_fraction, "area fraction")->capture_default_str();
  cmd->add_option("--particles", o->particles, "number of disks N")->capture_default_str();
  cmd->add_option("--box", o->box, "side L of the square box [length]")->capture_default_str();
  cmd->add_option("--diameter", o->diameter, "disk diameter (default: from N, L, nu)");
  cmd->add_option("--shear-rate", o->shear_rate, "gamma = U/L [1/time]")->capture_default_str();
  cmd->add_option("--mode", o->mode, "Fourier mode n: k = 2 pi n/L")->capture_default_str();
  cmd->add_option("--initial-temperature", o->initial_temperature,
                  "initial temperature T_i (default: T0, a start near the steady state)");
  cmd->callback([o, cmd] {
    require(*cmd, "--restitution", o->restitution, kDissipativeRestitution, " (e = 1 has no steady sheared state)");
    require(*cmd, "--area-fraction", o->area_fraction, kAreaFraction);
    require(*cmd, "--particles", o->particles, kParticles);
    require(*cmd, "--box", o->box, kLengthRange);
    require_if_given(*cmd, "--diameter", o->diameter, kLengthRange);
    require(*cmd, "--shear-rate", o->shear_rate, kRateRange);
    require(*cmd, "--mode", o->mode, NumberRange{1.0, 2147483647.0});
    require_if_given(*cmd, "--initial-temperature", o->initial_temperature, kTemperatureRange);
    print_table(*cmd, th::shear_scales_table(*o), false);
  });
}

void add_steady_shear(CLI::App& theory) {
  struct Opts {
    th::SteadyShearInputs in;
    bool csv = false;
  };
  auto o = std::make_shared<Opts>();
  th::SteadyShearInputs& opt = o->in;
  auto* cmd = theory.add_subcommand(
      "steady-shear",
      "Steady temperature of simple shear: fit (3.1), Jenkins-Richman (3.2), T0 (4.5)");
  cmd->add_option("-e,--restitution", opt.restitution, "one restitution (default: a sweep)");
  cmd->add_option("--e-min", opt.e_min, "sweep start")->capture_default_str();
  cmd->add_option("--e-max", opt.e_max, "sweep end")->capture_default_str();
  cmd->add_option("--points", opt.points, "sweep points")->capture_default_str();
  cmd->add_option("--shear-rate", opt.shear_rate, "gamma = U/Ly [1/time]")->capture_default_str();
  cmd->add_option("--area-fraction", opt.area_fraction, "nu = pi N sigma^2/(4 Lx Ly)")
      ->capture_default_str();
  cmd->add_option("--diameter", opt.diameter, "disk diameter (default: from N, Lx, Ly, nu)");
  cmd->add_option("--particles", opt.particles, "N")->capture_default_str();
  cmd->add_option("--box-x", opt.box_x, "Lx")->capture_default_str();
  cmd->add_option("--box-y", opt.box_y, "Ly")->capture_default_str();
  cmd->add_flag("--csv", o->csv, "print CSV");
  cmd->callback([o, cmd] {
    const th::SteadyShearInputs& in = o->in;
    const char* why = " (e = 1 has no steady sheared state)";
    require_if_given(*cmd, "--restitution", in.restitution, kDissipativeRestitution, why);
    require(*cmd, "--e-min", in.e_min, kDissipativeRestitution, why);
    require(*cmd, "--e-max", in.e_max, kDissipativeRestitution, why);
    require(*cmd, "--points", in.points, kPoints);
    require(*cmd, "--shear-rate", in.shear_rate, kRateRange);
    require(*cmd, "--area-fraction", in.area_fraction, kAreaFraction);
    require_if_given(*cmd, "--diameter", in.diameter, kLengthRange);
    require(*cmd, "--particles", in.particles, kParticles);
    require(*cmd, "--box-x", in.box_x, kLengthRange);
    require(*cmd, "--box-y", in.box_y, kLengthRange);
    print_table(*cmd, th::steady_shear_table(in), o->csv);
  });
}

}  // namespace

void add_shear_theory(CLI::App& theory) {
  add_shear_stability(theory);
  add_shear_scales(theory);
  add_steady_shear(theory);
}

}  // namespace granule::app
