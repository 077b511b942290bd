// `granule theory shear-stability`, `shear-scales` and `steady-shear`: the sheared gas of thesis
// chapters 3 and 4 (steady temperature (3.1), (3.2), (4.5); the 4×4 system (4.19); the clustering
// time scales (4.36)–(4.41)).
#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "app/theory/theory_checks.hpp"
#include "app/theory/theory_clustering_lines.hpp"
#include "app/theory/theory_subcommands.hpp"
#include "app/theory/theory_table.hpp"
#include "theory/kinetic_scales.hpp"
#include "theory/shear_stability.hpp"
#include "theory/shear_time_scales.hpp"
#include "theory/steady_shear.hpp"

namespace granule::app {

namespace {

using namespace theory_checks;
using std::numbers::pi;
namespace th = granule::theory;

// δ̄ of the sheared gas, a dimensionless wavenumber.  The matrix holds O(1) and O(δ̄²) entries, so
// the weakest eigenvalue loses δ̄²·1e-16 of its value: up to 1e6 it keeps 4 digits (measured:
// re s_m = −3.92695 at δ̄ = 1e6 against −3.92699, −3.93 at 1e7).
constexpr NumberRange kDeltaBar{0.0, 1e6};

// --- shear-stability ------------------------------------------------------------------------
void add_shear_stability(CLI::App& theory) {
  struct Opts {
    double sqrt_eps = 0.8, restitution = -1.0, theta_deg = 135.0, delta_min = 0.0, delta_max = 1.0;
    int points = 21;
    std::string figure, scaling = "thesis";
    bool csv = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = theory.add_subcommand(
      "shear-stability",
      "Growth rates of the 4x4 shear-flow system (4.19): s_m(delta_bar, theta, sqrt(eps))");
  auto* r_opt = cmd->add_option("--sqrt-eps", o->sqrt_eps, "sqrt(1-e^2)")->capture_default_str();
  cmd->add_option("-e,--restitution", o->restitution, "restitution (instead of --sqrt-eps)")
      ->excludes(r_opt);
  cmd->add_option("--theta-deg", o->theta_deg, "wavevector angle from the flow [degrees]")
      ->capture_default_str();
  cmd->add_option("--delta-min", o->delta_min, "smallest delta_bar")->capture_default_str();
  cmd->add_option("--delta-max", o->delta_max, "largest delta_bar")->capture_default_str();
  cmd->add_option("--points", o->points, "points per axis")->capture_default_str();
  cmd->add_option("--figure", o->figure, "print the data of a thesis figure")
      ->check(CLI::IsMember({"4.1", "4.2", "4.3", "4.4"}));
  cmd->add_option("--scaling", o->scaling,
                  "pressure term of (4.17): thesis (delta*^2, as printed) or consistent "
                  "(delta*^2/pi)")
      ->check(CLI::IsMember({"thesis", "consistent"}))
      ->capture_default_str();
  cmd->add_flag("--csv", o->csv, "print CSV");
  cmd->callback([o, cmd] {
    require(*cmd, "--sqrt-eps", o->sqrt_eps, kInelasticity);
    require_if_given(*cmd, "--restitution", o->restitution, kDissipativeRestitution, " (e = 1 does not cool)");
    require(*cmd, "--theta-deg", o->theta_deg, NumberRange{0.0, 180.0}, " (k and −k are one mode)");
    require(*cmd, "--delta-min", o->delta_min, kDeltaBar);
    require(*cmd, "--delta-max", o->delta_max, kDeltaBar);
    require(*cmd, "--points", o->points, kPoints);
    const auto scaling = o->scaling == "thesis" ? th::ShearPressureScaling::thesis
                                                : th::ShearPressureScaling::consistent;
    const double r =
        o->restitution >= 0.0 ? std::sqrt(th::inelasticity(o->restitution)) : o->sqrt_eps;
    auto re_sm = [&](double d, double theta, double root) {
      return th::largest_shear_growth_rate(d, theta, root, scaling).real();
    };
    const auto deltas = linspace(o->delta_min, o->delta_max, o->points);
    Table table;
    table.summary.push_back(fmt::format("pressure scaling: {}", o->scaling));
    if (o->figure == "4.1") {
      table.columns = {"delta_bar", "re_sm_theta45", "re_sm_theta135"};
      table.summary.push_back("Fig. 4.1: Re s_m vs delta_bar at sqrt(eps) = 0.8");
      for (double d : deltas)
        table.rows.push_back({d, re_sm(d, pi / 4, 0.8), re_sm(d, 3 * pi / 4, 0.8)});
    } else if (o->figure == "4.2") {
      table.columns = {"theta_deg", "re_sm_delta0.5", "re_sm_delta0.1"};
      table.summary.push_back("Fig. 4.2: Re s_m vs theta at sqrt(eps) = 0.8");
      for (double deg : linspace(0.0, 180.0, o->points)) {
        table.rows.push_back(
            {deg, re_sm(0.5, deg * pi / 180, 0.8), re_sm(0.1, deg * pi / 180, 0.8)});
      }
    } else if (o->figure == "4.3") {
      table.columns = {"sqrt_eps", "delta_bar", "re_sm"};
      table.summary.push_back("Fig. 4.3: Re s_m vs sqrt(eps) and delta_bar at theta = 3pi/4");
      for (double root : linspace(1.0 / o->points, 1.0, o->points)) {
        for (double d : deltas) table.rows.push_back({root, d, re_sm(d, 3 * pi / 4, root)});
      }
    } else if (o->figure == "4.4") {
      table.columns = {"theta_deg", "delta_bar", "re_sm"};
      table.summary.push_back("Fig. 4.4: Re s_m vs theta and delta_bar at sqrt(eps) = 0.8");
      for (double deg : linspace(0.0, 180.0, o->points)) {
        for (double d : deltas) table.rows.push_back({deg, d, re_sm(d, deg * pi / 180, 0.8)});
      }
    } else {
      const double theta = o->theta_deg * pi / 180.0;
      table.columns = {"delta_bar", "re_sm",        "im_sm",
                       "s3_thesis", "s3_corrected", "best_theta_deg"};
      table.summary.push_back(fmt::format("sqrt(eps) = {:.6g}, theta = {} deg", r, o->theta_deg));
      table.summary.push_back(
          "s_m: root of largest real part; s3_thesis: (4.23); s3_corrected: with the O(delta^2) "
          "term; best_theta_deg: direction of largest Re s_m");
      const double marginal = th::marginal_delta_bar(theta, r, 4.0, 400, scaling);
      table.summary.push_back(fmt::format("Re s_m > 0 for delta_bar < {:.6g}", marginal));
      for (double d : deltas) {
        const auto sm = th::largest_shear_growth_rate(d, theta, r, scaling);
        table.rows.push_back({d, sm.real(), sm.imag(),
                              th::shear_small_delta_roots_thesis(d, theta, r, scaling).s3,
                              th::shear_small_delta_roots_corrected(d, theta, r, scaling).s3,
                              th::most_unstable_direction(d, r, 360, scaling) * 180.0 / pi});
      }
    }
    print_table(*cmd, table, o->csv);
  });
}

// --- shear-scales ---------------------------------------------------------------------------
void add_shear_scales(CLI::App& theory) {
  struct Opts {
    double restitution = 0.6, area_fraction = 0.05, diameter = 0.0, shear_rate = 100.0, box = 1.0,
           initial_temperature = -1.0;
    int particles = 20000, mode = 1;
  };
  auto o = std::make_shared<Opts>();
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
    const double eps = th::inelasticity(o->restitution);
    const double sigma = o->diameter > 0.0 ? o->diameter
                                           : th::diameter_for_area_fraction(
                                                 o->area_fraction, o->particles, o->box, o->box);
    const double l = th::mean_free_path(sigma, o->area_fraction);
    const double gamma = o->shear_rate;
    const double T0 =
        th::steady_shear_temperature_kinetic(o->restitution, gamma, sigma, o->area_fraction);
    const double Ti = o->initial_temperature > 0.0 ? o->initial_temperature : T0;
    const double k = 2.0 * pi * o->mode / o->box;
    const double h = th::shear_fluctuation_rate(k, Ti, o->particles);
    const auto scales = th::clustering_scales(k, l, eps, gamma, h);
    require_finite(*cmd, {"diameter", "l", "T0", "h", "tau_m", "1/s3"},
                   {sigma, l, T0, h, scales.mass_motion_time, scales.linear_growth_time});
    Table table;
    table.summary = {
        fmt::format("eps {:.6g}  sqrt(eps) {:.6g}  diameter {:.6g}  l = pi sigma/8nu {:.6g}", eps,
                    std::sqrt(eps), sigma, l),
        fmt::format("T0 = l^2 gamma^2/(pi eps) (4.5) {:.6g}   T_i {:.6g}", T0, Ti),
        fmt::format("mode n = {}: k l = {:.6g}  delta* = {:.6g}  delta_bar = {:.6g}", o->mode,
                    k * l, th::shear_delta_star(l, o->box, eps),
                    th::shear_delta_bar_of_mode(o->mode, l, o->box, eps)),
        fmt::format("shear fluctuation h ~ k sqrt(T_i/N) = {:.6g}   gamma/h = {:.6g} ({})", h,
                    gamma / h,
                    scales.hot ? "h >> gamma: (4.36), (4.37)" : "h << gamma: (4.39)-(4.41)")};
    for (auto& line : clustering_lines(scales, k, l, sigma, o->box)) {
      table.summary.push_back(std::move(line));
    }
    table.summary.push_back(fmt::format("cluster separation L0 = l/sqrt(eps) = {:.6g} = {:.6g} L",
                                        l / std::sqrt(eps), l / std::sqrt(eps) / o->box));
    print_table(*cmd, table, false);
  });
}

// --- steady-shear ---------------------------------------------------------------------------
void add_steady_shear(CLI::App& theory) {
  struct Opts {
    double restitution = -1.0, e_min = 0.5, e_max = 0.99, shear_rate = 100.0, diameter = 0.0,
           area_fraction = 0.05, box_x = 1.0, box_y = 1.0;
    int particles = 200000, points = 11;
    bool csv = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = theory.add_subcommand(
      "steady-shear",
      "Steady temperature of simple shear: fit (3.1), Jenkins-Richman (3.2), T0 (4.5)");
  cmd->add_option("-e,--restitution", o->restitution, "one restitution (default: a sweep)");
  cmd->add_option("--e-min", o->e_min, "sweep start")->capture_default_str();
  cmd->add_option("--e-max", o->e_max, "sweep end")->capture_default_str();
  cmd->add_option("--points", o->points, "sweep points")->capture_default_str();
  cmd->add_option("--shear-rate", o->shear_rate, "gamma = U/Ly [1/time]")->capture_default_str();
  cmd->add_option("--area-fraction", o->area_fraction, "nu = pi N sigma^2/(4 Lx Ly)")
      ->capture_default_str();
  cmd->add_option("--diameter", o->diameter, "disk diameter (default: from N, Lx, Ly, nu)");
  cmd->add_option("--particles", o->particles, "N")->capture_default_str();
  cmd->add_option("--box-x", o->box_x, "Lx")->capture_default_str();
  cmd->add_option("--box-y", o->box_y, "Ly")->capture_default_str();
  cmd->add_flag("--csv", o->csv, "print CSV");
  cmd->callback([o, cmd] {
    const char* why = " (e = 1 has no steady sheared state)";
    require_if_given(*cmd, "--restitution", o->restitution, kDissipativeRestitution, why);
    require(*cmd, "--e-min", o->e_min, kDissipativeRestitution, why);
    require(*cmd, "--e-max", o->e_max, kDissipativeRestitution, why);
    require(*cmd, "--points", o->points, kPoints);
    require(*cmd, "--shear-rate", o->shear_rate, kRateRange);
    require(*cmd, "--area-fraction", o->area_fraction, kAreaFraction);
    require_if_given(*cmd, "--diameter", o->diameter, kLengthRange);
    require(*cmd, "--particles", o->particles, kParticles);
    require(*cmd, "--box-x", o->box_x, kLengthRange);
    require(*cmd, "--box-y", o->box_y, kLengthRange);
    const double sigma =
        o->diameter > 0.0
            ? o->diameter
            : th::diameter_for_area_fraction(o->area_fraction, o->particles, o->box_x, o->box_y);
    Table table{{"restitution", "eps", "T_fit_3.1", "T_JR_3.2", "T0_4.5"}, {}, {}};
    table.summary = {fmt::format("shear rate {}  area fraction {}  diameter {:.6g}", o->shear_rate,
                                 o->area_fraction, sigma),
                     fmt::format("(3.1): A = {}, B = {}; T = <v'^2>/2 per unit mass", th::tan_fit_A,
                                 th::tan_fit_B)};
    const auto es = o->restitution >= 0.0 ? std::vector<double>{o->restitution}
                                          : linspace(o->e_min, o->e_max, o->points);
    for (double e : es) {
      table.rows.push_back(
          {e, th::inelasticity(e),
           th::steady_shear_temperature_tan_fit(e, o->shear_rate, sigma, o->area_fraction),
           th::steady_shear_temperature_jenkins_richman(e, o->shear_rate, sigma, o->area_fraction),
           th::steady_shear_temperature_kinetic(e, o->shear_rate, sigma, o->area_fraction)});
    }
    print_table(*cmd, table, o->csv);
  });
}

}  // namespace

void add_shear_theory(CLI::App& theory) {
  add_shear_stability(theory);
  add_shear_scales(theory);
  add_steady_shear(theory);
}

}  // namespace granule::app
