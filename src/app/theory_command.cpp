#include "app/theory_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "init/initial_state.hpp"
#include "io/input_ranges.hpp"
#include "theory/free_gas_stability.hpp"
#include "theory/haff.hpp"
#include "theory/kinetic_scales.hpp"
#include "theory/shear_stability.hpp"
#include "theory/shear_time_scales.hpp"
#include "theory/steady_shear.hpp"

namespace granule::app {

namespace {

using std::numbers::pi;
namespace th = granule::theory;

// --- option checks --------------------------------------------------------------------------
// Every numeric option is checked before anything is printed: a value outside the range its
// formulas hold in (NaN, ±∞, e = 2, a negative length) is bad input, exit 2, with a message
// naming the option and the range.  Lengths, speeds and rates share the ranges of `granule run`
// (io/input_ranges.hpp).
constexpr int kExitBadInput = 2;
// ε = 1 − e² > 0: the cooling and steady-shear formulas divide by ε (e = 1 neither cools nor
// reaches a steady sheared state).
constexpr NumberRange kDissipativeRestitution{0.0, 1.0, true, true};
constexpr NumberRange kInelasticity{0.0, 1.0, true, false};
constexpr NumberRange kAreaFraction{0.0, kClosePacking, true, true};
constexpr NumberRange kParticles{2.0, 2147483647.0};
constexpr NumberRange kPoints{1.0, 10000.0};
// K = k l0 of the cooling gas and δ̄ of the sheared one, dimensionless wavenumbers.  The
// matrices hold O(1) and O(K²) entries, so the weakest eigenvalue loses K²·1e-16 of its value:
// up to 1e6 it keeps 4 digits (measured: re λ1 = −2.1801 at K = 1e6 against −2.1800, −2.19 at 1e7;
// re s_m = −3.92695 at δ̄ = 1e6 against −3.92699, −3.93 at 1e7).
constexpr NumberRange kWavenumber{0.0, 1e6, true, false};
constexpr NumberRange kDeltaBar{0.0, 1e6};
// Pair correlation at contact: 1 in the dilute limit, larger in a dense gas (Henderson: 60 at 0.9).
constexpr NumberRange kContactValue{1.0, 1e30};

[[noreturn]] void refuse(const CLI::App& command, const std::string& message) {
  fmt::print(stderr, "granule theory {}: error: {}\n", command.get_name(), message);
  throw CLI::RuntimeError(kExitBadInput);
}

void require(const CLI::App& command, const std::string& option, double value, const NumberRange& range,
             const std::string& why = {}) {
  if (!range.contains(value)) refuse(command, fmt::format("{} = {} is out of range: allowed {}{}", option, value, range.text(), why));
}

// An option whose default means "not given" (derived from the others): checked only when given.
void require_if_given(const CLI::App& command, const std::string& option, double value, const NumberRange& range,
                      const std::string& why = {}) {
  if (command.count(option) > 0) require(command, option, value, range, why);
}

// The last guard: options inside their ranges may still combine into a result beyond double
// precision (say ν = 1e-300 with σ = 1e30); no infinite or NaN result is printed.
void require_finite(const CLI::App& command, const std::vector<std::string>& names, const std::vector<double>& values) {
  for (std::size_t j = 0; j < values.size(); ++j) {
    if (!std::isfinite(values[j])) {
      refuse(command, fmt::format("these options give {} = {}, beyond double precision: bring them nearer to "
                                  "ordinary values", names[j], values[j]));
    }
  }
}

// A table of numbers with named columns, printed aligned (with `# ` summary lines above it) or as
// CSV (header and rows only, so that any CSV reader takes it).
struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  std::vector<std::string> summary;
};

void print_table(const CLI::App& command, const Table& table, bool csv) {
  for (const auto& row : table.rows) require_finite(command, table.columns, row);
  if (csv) {
    std::string line;
    for (std::size_t j = 0; j < table.columns.size(); ++j) {
      line += (j ? "," : "") + table.columns[j];
    }
    fmt::print("{}\n", line);
    for (const auto& row : table.rows) {
      line.clear();
      for (std::size_t j = 0; j < row.size(); ++j) {
        line += fmt::format("{}{:.10g}", j ? "," : "", row[j] + 0.0);
      }
      fmt::print("{}\n", line);
    }
    return;
  }
  for (const auto& s : table.summary) fmt::print("# {}\n", s);
  if (table.columns.empty()) return;
  std::vector<std::size_t> width;
  for (const auto& c : table.columns) width.push_back(std::max<std::size_t>(14, c.size() + 2));
  std::string line;
  for (std::size_t j = 0; j < table.columns.size(); ++j) {
    line += fmt::format("{:>{}}", table.columns[j], width[j]);
  }
  fmt::print("{}\n", line);
  for (const auto& row : table.rows) {
    line.clear();
    // + 0.0 prints a negative zero as 0
    for (std::size_t j = 0; j < row.size(); ++j) {
      line += fmt::format("{:>{}.6g}", row[j] + 0.0, width[j]);
    }
    fmt::print("{}\n", line);
  }
}

// Evenly spaced values from lo to hi inclusive (one value when points == 1).
std::vector<double> linspace(double lo, double hi, int points) {
  std::vector<double> out;
  for (int j = 0; j < points; ++j) {
    out.push_back(points == 1 ? lo : lo + (hi - lo) * j / (points - 1));
  }
  return out;
}

std::vector<double> logspace(double lo, double hi, int points) {
  std::vector<double> out;
  for (double x : linspace(std::log(lo), std::log(hi), points)) out.push_back(std::exp(x));
  return out;
}

// --- haff -----------------------------------------------------------------------------------
void add_haff(CLI::App& theory) {
  struct Opts {
    double restitution = 0.9, area_fraction = 0.05, diameter = 1.26e-3, temperature = 1.0;
    double contact_value = 1.0, collisions = 0.0;
    bool enskog = false, csv = false;
    int points = 11;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = theory.add_subcommand(
      "haff",
      "Haff cooling of a free disk gas: T(t) = T0/(1+t/t0)^2 (2.10), T(c) = T0 exp(-eps c)");
  cmd->add_option("-e,--restitution", o->restitution, "coefficient of normal restitution")
      ->capture_default_str();
  cmd->add_option("--area-fraction", o->area_fraction, "area fraction nu")->capture_default_str();
  cmd->add_option("--diameter", o->diameter, "disk diameter sigma [length]")->capture_default_str();
  cmd->add_option("--temperature", o->temperature, "initial temperature T0 = <v'^2>/2")
      ->capture_default_str();
  cmd->add_option("--contact-value", o->contact_value, "pair correlation at contact chi")
      ->capture_default_str();
  cmd->add_flag("--enskog", o->enskog, "use Henderson's chi(nu) instead of --contact-value");
  cmd->add_option("--collisions", o->collisions,
                  "last row at this many collisions per particle c (default 3/eps)");
  cmd->add_option("--points", o->points, "rows, evenly spaced in c")->capture_default_str();
  cmd->add_flag("--csv", o->csv, "print CSV");
  cmd->callback([o, cmd] {
    require(*cmd, "--restitution", o->restitution, kDissipativeRestitution, " (e = 1 does not cool)");
    require(*cmd, "--area-fraction", o->area_fraction, kAreaFraction);
    require(*cmd, "--diameter", o->diameter, kLengthRange);
    require(*cmd, "--temperature", o->temperature, kTemperatureRange);
    require(*cmd, "--contact-value", o->contact_value, kContactValue);
    require(*cmd, "--points", o->points, kPoints);
    const double eps = th::inelasticity(o->restitution);
    // t(c) = t0 (exp(εc/2) − 1) must stay finite: εc ≤ 1000 (T has then fallen by e^−1000).
    require(*cmd, "--collisions", o->collisions, NumberRange{0.0, 1000.0 / eps},
            fmt::format(" (ε c ≤ 1000 with ε = 1 − e² = {:.6g}; 0: 3/ε)", eps));
    const double chi = o->enskog ? th::henderson_contact_value(o->area_fraction) : o->contact_value;
    const double t0 =
        th::haff_time_disks(o->temperature, o->restitution, o->diameter, o->area_fraction, chi);
    const double c_max = o->collisions > 0.0 ? o->collisions : 3.0 / eps;
    Table table{{"c", "t", "T", "collision_rate"}, {}, {}};
    table.summary = {
        fmt::format("restitution {}  eps = 1-e^2 = {:.6g}  area fraction {}  diameter {:.6g}",
                    o->restitution, eps, o->area_fraction, o->diameter),
        fmt::format(
            "T0 {:.6g}  chi {:.6g}  collision frequency omega0 {:.6g}", o->temperature, chi,
            th::disk_collision_frequency(o->temperature, o->diameter, o->area_fraction, chi)),
        fmt::format("Haff time t0 = 4/(eps omega0) = {:.6g}", t0),
        fmt::format("mean free path l = pi sigma/8nu = {:.6g}; cluster separation L0 = l/sqrt(eps)"
                    " = {:.6g} (1.1)",
                    th::mean_free_path(o->diameter, o->area_fraction),
                    th::cluster_separation(o->restitution, o->diameter, o->area_fraction)),
        "c = total collisions / N; T(t) from (2.10), t(c) = t0 (exp(eps c/2) - 1); "
        "collision_rate = dc/dt = omega(T)/2"};
    for (double c : linspace(0.0, c_max, o->points)) {
      const double t = t0 * std::expm1(eps * c / 2.0);
      const double T = th::haff_temperature(t, o->temperature, t0);
      table.rows.push_back(
          {c, t, T, 0.5 * th::disk_collision_frequency(T, o->diameter, o->area_fraction, chi)});
    }
    print_table(*cmd, table, o->csv);
  });
}

// --- free-stability -------------------------------------------------------------------------
void add_free_stability(CLI::App& theory) {
  struct Opts {
    double restitution = 0.9, eps = -1.0, k_min = 1e-3, k_max = 1.0;
    int points = 13;
    bool asymptotic = false, csv = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = theory.add_subcommand(
      "free-stability",
      "Eigenvalues of the linearised Jenkins-Richman equations of a cooling gas (2.28), (2.35)");
  auto* e_opt = cmd->add_option("-e,--restitution", o->restitution, "restitution (eps = 1-e^2)")
                    ->capture_default_str();
  cmd->add_option("--eps", o->eps, "inelasticity eps = 1-e^2 (instead of --restitution)")
      ->excludes(e_opt);
  cmd->add_option("--K-min", o->k_min, "smallest K = k l0")->capture_default_str();
  cmd->add_option("--K-max", o->k_max, "largest K = k l0")->capture_default_str();
  cmd->add_option("--points", o->points, "rows, log-spaced in K")->capture_default_str();
  cmd->add_flag("--asymptotic", o->asymptotic,
                "add the asymptotic forms (2.30)-(2.32) and (2.33)-(2.34)");
  cmd->add_flag("--csv", o->csv, "print CSV");
  cmd->callback([o, cmd] {
    require(*cmd, "--restitution", o->restitution, kDissipativeRestitution, " (e = 1 does not cool)");
    require_if_given(*cmd, "--eps", o->eps, kInelasticity);
    require(*cmd, "--K-min", o->k_min, kWavenumber);
    require(*cmd, "--K-max", o->k_max, kWavenumber);
    require(*cmd, "--points", o->points, kPoints);
    const double eps = o->eps > 0.0 ? o->eps : th::inelasticity(o->restitution);
    Table table{{"K", "re_l1", "im_l1", "re_l2", "im_l2", "re_l3", "im_l3", "l_shear", "p_density"},
                {},
                {}};
    if (o->asymptotic) {
      for (const char* c :
           {"long_l1", "long_l2", "long_l3", "short_heat", "short_sound_re", "short_sound_im"}) {
        table.columns.emplace_back(c);
      }
    }
    table.summary = {
        fmt::format("eps = {:.6g}; K = k l0, l0 = (sqrt(pi)/8) sigma/nu (2.13); rates per unit "
                    "s = ln(1+t/t0)/eps (2.19)",
                    eps),
        "l1..l3: eigenvalues of (2.28) by decreasing real part; l_shear: (2.35)",
        "p_density: delta rho ~ (1+t/t0)^p for the leading mode (2.36); p > 0 grows",
        fmt::format("shear mode outlives cooling for K^2 < 12eps/5 = {:.6g}; heat conduction "
                    "negligible for K^2 < 48eps/25 = {:.6g}",
                    th::shear_mode_outlives_cooling_bound(eps),
                    th::heat_conduction_negligible_bound(eps)),
        fmt::format("clustering scale kl ~ sqrt(eps) = {:.6g}, L0 = l/sqrt(eps) = {:.6g} l",
                    std::sqrt(eps), 1.0 / std::sqrt(eps))};
    for (double K : logspace(o->k_min, o->k_max, o->points)) {
      const auto l = th::free_gas_eigenvalues(K, eps);
      std::vector<double> row{
          K,
          l[0].real(),
          l[0].imag(),
          l[1].real(),
          l[1].imag(),
          l[2].real(),
          l[2].imag(),
          th::free_gas_shear_eigenvalue(K, eps),
          th::free_gas_growth_exponent(th::FreeGasField::density, l[0].real(), eps)};
      if (o->asymptotic) {
        const auto lw = th::free_gas_long_wave_eigenvalues(K, eps);
        const auto sw = th::free_gas_short_wave_eigenvalues(K, eps);
        row.insert(row.end(),
                   {lw.lambda1, lw.lambda2, lw.lambda3, sw.heat, sw.sound.real(), sw.sound.imag()});
      }
      table.rows.push_back(std::move(row));
    }
    print_table(*cmd, table, o->csv);
  });
}

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
    const bool hot = h > gamma;
    const auto window =
        hot ? th::clustering_window_hot(eps, gamma, h) : th::clustering_window_cold(eps, gamma, h);
    const double tau_m = hot ? th::mass_motion_time_hot(k, l, eps, h)
                             : th::mass_motion_time_cold(k, l, eps, h, gamma);
    require_finite(*cmd, {"diameter", "l", "T0", "h", "tau_m", "1/s3"},
                   {sigma, l, T0, h, tau_m, th::linear_growth_time(k, l, eps, gamma)});
    Table table;
    table.summary = {
        fmt::format("eps {:.6g}  sqrt(eps) {:.6g}  diameter {:.6g}  l = pi sigma/8nu {:.6g}", eps,
                    std::sqrt(eps), sigma, l),
        fmt::format("T0 = l^2 gamma^2/(pi eps) (4.5) {:.6g}   T_i {:.6g}", T0, Ti),
        fmt::format("mode n = {}: k l = {:.6g}  delta* = {:.6g}  delta_bar = {:.6g}", o->mode,
                    k * l, th::shear_delta_star(l, o->box, eps),
                    th::shear_delta_bar_of_mode(o->mode, l, o->box, eps)),
        fmt::format("shear fluctuation h ~ k sqrt(T_i/N) = {:.6g}   gamma/h = {:.6g} ({})", h,
                    gamma / h, hot ? "h >> gamma: (4.36), (4.37)" : "h << gamma: (4.39)-(4.41)"),
        fmt::format("tau_c = 1/gamma {:.6g}   tau_m {:.6g}   1/s3 ~ sqrt(eps)/(kl gamma) {:.6g}",
                    th::convective_time(gamma), tau_m, th::linear_growth_time(k, l, eps, gamma)),
        fmt::format("clustering window {:.6g} < kl < {:.6g}: {}; this mode {}", window.lower,
                    window.upper, window.open() ? "open" : "empty",
                    window.contains(k * l) ? "clusters" : "does not cluster"),
        fmt::format("cluster separation L0 = l/sqrt(eps) = {:.6g} = {:.6g} L", l / std::sqrt(eps),
                    l / std::sqrt(eps) / o->box)};
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

void add_theory_command(CLI::App& root) {
  auto* theory = root.add_subcommand(
      "theory", "Kinetic-theory predictions of Tan (1995): cooling, stability, steady shear");
  theory->require_subcommand(1);
  add_haff(*theory);
  add_free_stability(*theory);
  add_shear_stability(*theory);
  add_shear_scales(*theory);
  add_steady_shear(*theory);
}

}  // namespace granule::app
