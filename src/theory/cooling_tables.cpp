#include "theory/cooling_tables.hpp"

#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "theory/free_gas_stability.hpp"
#include "theory/haff.hpp"
#include "theory/kinetic_scales.hpp"

namespace granule::theory {

PredictionTable haff_table(const HaffInputs& in) {
  const double eps = inelasticity(in.restitution);
  const double chi = in.enskog ? henderson_contact_value(in.area_fraction) : in.contact_value;
  const double t0 = haff_time_disks(in.temperature, in.restitution, in.diameter, in.area_fraction, chi);
  const double c_max = in.collisions > 0.0 ? in.collisions : 3.0 / eps;
  PredictionTable table{{"c", "t", "T", "collision_rate"}, {}, {}, {}, {}};
  table.summary = {
      fmt::format("restitution {}  eps = 1-e^2 = {:.6g}  area fraction {}  diameter {:.6g}",
                  in.restitution, eps, in.area_fraction, in.diameter),
      fmt::format("T0 {:.6g}  chi {:.6g}  collision frequency omega0 {:.6g}", in.temperature, chi,
                  disk_collision_frequency(in.temperature, in.diameter, in.area_fraction, chi)),
      fmt::format("Haff time t0 = 4/(eps omega0) = {:.6g}", t0),
      fmt::format("mean free path l = pi sigma/8nu = {:.6g}; cluster separation L0 = l/sqrt(eps)"
                  " = {:.6g} (1.1)",
                  mean_free_path(in.diameter, in.area_fraction),
                  cluster_separation(in.restitution, in.diameter, in.area_fraction)),
      "c = total collisions / N; T(t) from (2.10), t(c) = t0 (exp(eps c/2) - 1); "
      "collision_rate = dc/dt = omega(T)/2"};
  for (double c : linspace(0.0, c_max, in.points)) {
    const double t = t0 * std::expm1(eps * c / 2.0);
    const double T = haff_temperature(t, in.temperature, t0);
    table.rows.push_back({c, t, T, 0.5 * disk_collision_frequency(T, in.diameter, in.area_fraction, chi)});
  }
  return table;
}

PredictionTable free_stability_table(const FreeStabilityInputs& in) {
  const double eps = in.eps;
  PredictionTable table{
      {"K", "re_l1", "im_l1", "re_l2", "im_l2", "re_l3", "im_l3", "l_shear", "p_density"}, {}, {}, {}, {}};
  if (in.asymptotic) {
    for (const char* c : {"long_l1", "long_l2", "long_l3", "short_heat", "short_sound_re", "short_sound_im"}) {
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
                  shear_mode_outlives_cooling_bound(eps), heat_conduction_negligible_bound(eps)),
      fmt::format("clustering scale kl ~ sqrt(eps) = {:.6g}, L0 = l/sqrt(eps) = {:.6g} l", std::sqrt(eps),
                  1.0 / std::sqrt(eps))};
  for (double K : logspace(in.k_min, in.k_max, in.points)) {
    const auto l = free_gas_eigenvalues(K, eps);
    std::vector<double> row{K,
                            l[0].real(),
                            l[0].imag(),
                            l[1].real(),
                            l[1].imag(),
                            l[2].real(),
                            l[2].imag(),
                            free_gas_shear_eigenvalue(K, eps),
                            free_gas_growth_exponent(FreeGasField::density, l[0].real(), eps)};
    if (in.asymptotic) {
      const auto lw = free_gas_long_wave_eigenvalues(K, eps);
      const auto sw = free_gas_short_wave_eigenvalues(K, eps);
      row.insert(row.end(), {lw.lambda1, lw.lambda2, lw.lambda3, sw.heat, sw.sound.real(), sw.sound.imag()});
    }
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace granule::theory
