#include "init/particle_sizes.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "init/portable_exp.hpp"
#include "init/random.hpp"

namespace granule {

namespace {

// The diameters draw from a stream of their own, so that they are not the same uniform numbers
// as the positions placed from the seed.
constexpr std::uint64_t kDiameterStream = 0xd1b54a32d192ed03ULL;

double power(double r, int d) {
  double out = r;
  for (int k = 1; k < d; ++k) out *= r;
  return out;
}

// Calls `emit` with each relative diameter r_i in the order of the draws (bidisperse: all of
// species A, then all of B).
void for_each_relative_diameter(const SizeDistribution& dist, std::int64_t n, std::uint64_t seed,
                                const std::function<void(double)>& emit) {
  Random rng(seed ^ kDiameterStream);
  switch (dist.kind) {
    case SizeDistributionKind::kMonodisperse:
      for (std::int64_t i = 0; i < n; ++i) emit(1.0);
      return;
    case SizeDistributionKind::kBidisperse: {
      const std::int64_t species_b = species_b_count(dist, n);
      for (std::int64_t i = 0; i < n; ++i) emit(i < n - species_b ? 1.0 : dist.ratio);
      return;
    }
    case SizeDistributionKind::kUniform:
      for (std::int64_t i = 0; i < n; ++i) emit(1.0 + dist.width * (2.0 * rng.uniform() - 1.0));
      return;
    case SizeDistributionKind::kLogNormal: {
      // ln r = s Z − s²/2 has ⟨r⟩ = 1: σ̄ is the mean diameter.
      const double shift = 0.5 * dist.width * dist.width;
      for (std::int64_t i = 0; i < n; ++i) emit(portable_exp(dist.width * rng.normal() - shift));
      return;
    }
  }
}

}  // namespace

std::int64_t species_b_count(const SizeDistribution& dist, std::int64_t n) {
  return static_cast<std::int64_t>(std::round(dist.fraction * static_cast<double>(n)));
}

RelativeSizeSummary summarize_relative_sizes(const SizeDistribution& dist, int dimension, std::int64_t n,
                                             std::uint64_t seed) {
  if (dist.monodisperse()) return {static_cast<double>(n), 1.0, 1.0};
  RelativeSizeSummary out{0.0, 0.0, INFINITY};
  for_each_relative_diameter(dist, n, seed, [&](double r) {
    out.sum_of_powers += power(r, dimension);
    out.largest = std::max(out.largest, r);
    out.smallest = std::min(out.smallest, r);
  });
  return out;
}

std::vector<double> relative_diameters(const SizeDistribution& dist, std::int64_t n, std::uint64_t seed) {
  std::vector<double> out;
  if (dist.monodisperse()) return out;
  out.reserve(static_cast<std::size_t>(n));
  for_each_relative_diameter(dist, n, seed, [&](double r) { out.push_back(r); });
  std::sort(out.begin(), out.end(), std::greater<>());
  return out;
}

ParticleSizes particle_sizes(const SizeDistribution& dist, int dimension, std::int64_t n, double reference_diameter,
                             std::uint64_t seed) {
  ParticleSizes out;
  out.diameter = relative_diameters(dist, n, seed);
  if (out.diameter.empty()) return out;
  out.mass.resize(out.diameter.size());
  double sum_of_powers = 0.0;
  for (double r : out.diameter) sum_of_powers += power(r, dimension);
  const double mean_power = sum_of_powers / static_cast<double>(n);
  // In decreasing order of size species B comes first when σ_B ≥ σ_A (also when equal).
  const auto species_b = static_cast<std::size_t>(species_b_count(dist, n));
  const std::size_t first_b = dist.ratio >= 1.0 ? 0 : out.diameter.size() - species_b;
  for (std::size_t i = 0; i < out.diameter.size(); ++i) {
    const double r = out.diameter[i];
    if (dist.species_masses) {
      const bool is_b = i >= first_b && i < first_b + species_b;
      out.mass[i] = is_b ? dist.species_masses->second : dist.species_masses->first;
    } else {
      out.mass[i] = power(r, dimension) / mean_power;
    }
    out.diameter[i] = reference_diameter * r;
  }
  return out;
}

double packing_fraction(int dimension, double sum_of_powers, double reference_diameter, double volume) {
  // Multiplied in this order so that 2D monodisperse systems keep the bits of πNσ²/(4 L_x L_y).
  double covered = M_PI * sum_of_powers;
  for (int k = 0; k < dimension; ++k) covered *= reference_diameter;
  return covered / ((dimension == 2 ? 4.0 : 6.0) * volume);
}

double reference_diameter_for(int dimension, double nu, double sum_of_powers, double volume) {
  return portable_root((dimension == 2 ? 4.0 : 6.0) * nu * volume / (M_PI * sum_of_powers), dimension);
}

double box_volume(const SystemParams& p) {
  const double area = p.length_x * p.length_y;
  return p.dimension == 3 ? area * p.length_z : area;
}

double packing_fraction(const SystemParams& p, const ParticleSizes& sizes) {
  if (sizes.monodisperse()) {
    return packing_fraction(p.dimension, static_cast<double>(p.particles), p.diameter, box_volume(p));
  }
  double sum_of_powers = 0.0;
  for (double sigma : sizes.diameter) sum_of_powers += power(sigma, p.dimension);
  return packing_fraction(p.dimension, sum_of_powers, 1.0, box_volume(p));
}

}  // namespace granule
