// `granule theory haff` and `granule theory free-stability`: the freely cooling gas of thesis
// chapter 2 (Haff's law (2.10) and the linearised Jenkins–Richman equations (2.28), (2.35)).
#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "app/theory/theory_checks.hpp"
#include "app/theory/theory_subcommands.hpp"
#include "app/theory/theory_table.hpp"
#include "theory/free_gas_stability.hpp"
#include "theory/haff.hpp"
#include "theory/kinetic_scales.hpp"

namespace granule::app {

namespace {

using namespace theory_checks;
namespace th = granule::theory;

// K = k l0 of the cooling gas, a dimensionless wavenumber.  The matrix holds O(1) and O(K²)
// entries, so the weakest eigenvalue loses K²·1e-16 of its value: up to 1e6 it keeps 4 digits
// (measured: re λ1 = −2.1801 at K = 1e6 against −2.1800, −2.19 at 1e7).
constexpr NumberRange kWavenumber{0.0, 1e6, true, false};
// Pair correlation at contact: 1 in the dilute limit, larger in a dense gas (Henderson: 60 at 0.9).
constexpr NumberRange kContactValue{1.0, 1e30};

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

}  // namespace

void add_cooling_theory(CLI::App& theory) {
  add_haff(theory);
  add_free_stability(theory);
}

}  // namespace granule::app
