// `granule theory haff` and `granule theory free-stability`: the options and checks of the
// freely cooling gas's predictions (theory/cooling_tables.hpp).
#include <fmt/format.h>

#include <memory>

#include "app/theory/theory_checks.hpp"
#include "app/theory/theory_subcommands.hpp"
#include "theory/cooling_tables.hpp"
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

void add_haff(CLI::App& theory) {
  struct Opts {
    th::HaffInputs in;
    bool csv = false;
  };
  auto o = std::make_shared<Opts>();
  th::HaffInputs& opt = o->in;
  auto* cmd = theory.add_subcommand(
      "haff",
      "Haff cooling of a free disk gas: T(t) = T0/(1+t/t0)^2 (2.10), T(c) = T0 exp(-eps c)");
  cmd->add_option("-e,--restitution", opt.restitution, "coefficient of normal restitution")
      ->capture_default_str();
  cmd->add_option("--area-fraction", opt.area_fraction, "area fraction nu")->capture_default_str();
  cmd->add_option("--diameter", opt.diameter, "disk diameter sigma [length]")->capture_default_str();
  cmd->add_option("--temperature", opt.temperature, "initial temperature T0 = <v'^2>/2")
      ->capture_default_str();
  cmd->add_option("--contact-value", opt.contact_value, "pair correlation at contact chi")
      ->capture_default_str();
  cmd->add_flag("--enskog", opt.enskog, "use Henderson's chi(nu) instead of --contact-value");
  cmd->add_option("--collisions", opt.collisions,
                  "last row at this many collisions per particle c (default 3/eps)");
  cmd->add_option("--points", opt.points, "rows, evenly spaced in c")->capture_default_str();
  cmd->add_flag("--csv", o->csv, "print CSV");
  cmd->callback([o, cmd] {
    const th::HaffInputs& in = o->in;
    require(*cmd, "--restitution", in.restitution, kDissipativeRestitution, " (e = 1 does not cool)");
    require(*cmd, "--area-fraction", in.area_fraction, kAreaFraction);
    require(*cmd, "--diameter", in.diameter, kLengthRange);
    require(*cmd, "--temperature", in.temperature, kTemperatureRange);
    require(*cmd, "--contact-value", in.contact_value, kContactValue);
    require(*cmd, "--points", in.points, kPoints);
    const double eps = th::inelasticity(in.restitution);
    // t(c) = t0 (exp(εc/2) − 1) must stay finite: εc ≤ 1000 (T has then fallen by e^−1000).
    require(*cmd, "--collisions", in.collisions, NumberRange{0.0, 1000.0 / eps},
            fmt::format(" (ε c ≤ 1000 with ε = 1 − e² = {:.6g}; 0: 3/ε)", eps));
    print_table(*cmd, th::haff_table(in), o->csv);
  });
}

void add_free_stability(CLI::App& theory) {
  struct Opts {
    double restitution = 0.9, eps = -1.0;
    th::FreeStabilityInputs in;
    bool csv = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = theory.add_subcommand(
      "free-stability",
      "Eigenvalues of the linearised Jenkins-Richman equations of a cooling gas (2.28), (2.35)");
  auto* e_opt = cmd->add_option("-e,--restitution", o->restitution, "restitution (eps = 1-e^2)")
                    ->capture_default_str();
  cmd->add_option("--eps", o->eps, "inelasticity eps = 1-e^2 (instead of --restitution)")
      ->excludes(e_opt);
  cmd->add_option("--K-min", o->in.k_min, "smallest K = k l0")->capture_default_str();
  cmd->add_option("--K-max", o->in.k_max, "largest K = k l0")->capture_default_str();
  cmd->add_option("--points", o->in.points, "rows, log-spaced in K")->capture_default_str();
  cmd->add_flag("--asymptotic", o->in.asymptotic,
                "add the asymptotic forms (2.30)-(2.32) and (2.33)-(2.34)");
  cmd->add_flag("--csv", o->csv, "print CSV");
  cmd->callback([o, cmd] {
    require(*cmd, "--restitution", o->restitution, kDissipativeRestitution, " (e = 1 does not cool)");
    require_if_given(*cmd, "--eps", o->eps, kInelasticity);
    require(*cmd, "--K-min", o->in.k_min, kWavenumber);
    require(*cmd, "--K-max", o->in.k_max, kWavenumber);
    require(*cmd, "--points", o->in.points, kPoints);
    th::FreeStabilityInputs in = o->in;
    in.eps = o->eps > 0.0 ? o->eps : th::inelasticity(o->restitution);
    print_table(*cmd, th::free_stability_table(in), o->csv);
  });
}

}  // namespace

void add_cooling_theory(CLI::App& theory) {
  add_haff(theory);
  add_free_stability(theory);
}

}  // namespace granule::app
