// Particle configurations with known spectra, shared by the spectra tests (unit and validation).
#pragma once

#include <cmath>
#include <cstdint>

#include "engine/system_params.hpp"
#include "init/random.hpp"

namespace granule::spectra::testing {

// N positions uniform in the box (uncorrelated: ⟨|Σ e^{ik·r}|²⟩ = N at every k ≠ 0), Gaussian velocities.
inline ParticleState uniform_gas(std::size_t n, double length_x, double length_y, std::uint64_t seed) {
  Random random(seed);
  ParticleState state;
  state.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    state.x[j] = random.uniform() * length_x;
    state.y[j] = random.uniform() * length_y;
    state.vx[j] = random.normal();
    state.vy[j] = random.normal();
  }
  return state;
}

// N positions in a few Gaussian blobs of width `width` (wrapped into the box): strong coherent modes.
inline ParticleState clustered_gas(std::size_t n, double length_x, double length_y, int clusters, double width,
                                   std::uint64_t seed) {
  Random random(seed);
  ParticleState state = uniform_gas(n, length_x, length_y, seed + 1);
  std::vector<double> cx(static_cast<std::size_t>(clusters)), cy(static_cast<std::size_t>(clusters));
  for (int c = 0; c < clusters; ++c) {
    cx[static_cast<std::size_t>(c)] = random.uniform() * length_x;
    cy[static_cast<std::size_t>(c)] = random.uniform() * length_y;
  }
  for (std::size_t j = 0; j < n; ++j) {
    const auto c = static_cast<std::size_t>(random.below(static_cast<std::uint64_t>(clusters)));
    const double x = cx[c] + width * random.normal();
    const double y = cy[c] + width * random.normal();
    state.x[j] = x - length_x * std::floor(x / length_x);
    state.y[j] = y - length_y * std::floor(y / length_y);
  }
  return state;
}

// The n² points (i/n) a1 + (j/n) a2 of the Lees–Edwards image lattice a1 = (L_x, 0), a2 = (tilt L_y, L_y)
// (3.6)–(3.7), mapped into the box; velocities follow the mean flow u(y) = γ (y − L_y/2) with γ = 1.
// The point set repeats under a1 and a2, so its transform lives only on k = n × (reciprocal lattice).
inline ParticleState sheared_lattice(int n, double length_x, double length_y, double tilt) {
  ParticleState state;
  state.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const auto p = static_cast<std::size_t>(i + n * j);
      const double x = (i * length_x + j * tilt * length_y) / n;
      state.x[p] = x - length_x * std::floor(x / length_x);
      state.y[p] = j * length_y / n;
      state.vx[p] = state.y[p] - 0.5 * length_y;
      state.vy[p] = 0.0;
    }
  }
  return state;
}

}  // namespace granule::spectra::testing
