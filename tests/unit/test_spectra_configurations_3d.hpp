// 3D particle configurations with known spectra, shared by the 3D spectra tests (unit and validation).
#pragma once

#include <cmath>
#include <cstdint>

#include "engine/system_params.hpp"
#include "init/random.hpp"
#include "spectra/reciprocal_lattice.hpp"

namespace granule::spectra::testing {

struct Box3 {
  double x = 1.0, y = 1.0, z = 1.0;
};

inline double wrapped(double coordinate, double period) { return coordinate - period * std::floor(coordinate / period); }

// N positions uniform in the box (uncorrelated: ⟨|Σ e^{ik·r}|²⟩ = N at every k ≠ 0), Gaussian velocities.
inline ParticleState uniform_gas_3d(std::size_t n, Box3 box, std::uint64_t seed) {
  Random random(seed);
  ParticleState state;
  state.dimension = 3;
  state.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    state.x[j] = random.uniform() * box.x;
    state.y[j] = random.uniform() * box.y;
    state.z[j] = random.uniform() * box.z;
    state.vx[j] = random.normal();
    state.vy[j] = random.normal();
    state.vz[j] = random.normal();
  }
  return state;
}

// N positions in a few Gaussian blobs of width `width` (wrapped into the box): strong coherent modes.
inline ParticleState clustered_gas_3d(std::size_t n, Box3 box, int clusters, double width, std::uint64_t seed) {
  Random random(seed);
  ParticleState state = uniform_gas_3d(n, box, seed + 1);
  std::vector<double> centres(3 * static_cast<std::size_t>(clusters));
  for (double& c : centres) c = random.uniform();
  for (std::size_t j = 0; j < n; ++j) {
    const auto c = 3 * static_cast<std::size_t>(random.below(static_cast<std::uint64_t>(clusters)));
    state.x[j] = wrapped(centres[c] * box.x + width * random.normal(), box.x);
    state.y[j] = wrapped(centres[c + 1] * box.y + width * random.normal(), box.y);
    state.z[j] = wrapped(centres[c + 2] * box.z + width * random.normal(), box.z);
  }
  return state;
}

// The n³ points (i a1 + j a2 + k a3)/n of the 3D Lees–Edwards image lattice a1 = (L_x, 0, 0),
// a2 = (tilt L_y, L_y, 0), a3 = (0, 0, L_z), mapped into the box; velocities follow the mean flow
// u(y) x̂ = (y − L_y/2) x̂ (γ = 1).  The point set repeats under a1, a2 and a3, so its transform lives only
// on k = n × (reciprocal lattice): l, m, n' all multiples of n.
inline ParticleState sheared_lattice_3d(int n, Box3 box, double tilt) {
  ParticleState state;
  state.dimension = 3;
  state.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  std::size_t p = 0;
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i, ++p) {
        state.x[p] = wrapped((i * box.x + j * tilt * box.y) / n, box.x);
        state.y[p] = j * box.y / n;
        state.z[p] = k * box.z / n;
        state.vx[p] = state.y[p] - 0.5 * box.y;
        state.vy[p] = 0.0;
        state.vz[p] = 0.0;
      }
    }
  }
  return state;
}

// N positions drawn from the density ∝ 1 + a cos(k·r) of one allowed wavevector k = (l, m, n') of
// `lattice` (rejection from uniform positions), Gaussian velocities.  As k·a_i ∈ 2πZ the density is a
// periodic field of the (sheared) box.  Then ⟨|Σ_j e^{iq·r_j}|²⟩ = N for every allowed q ≠ 0, ±k, and
// N + N(N − 1) a²/4 at q = ±k: a peak of height ≈ N a²/4 times the uncorrelated level.
inline ParticleState planted_wave_3d(std::size_t n, const ReciprocalLattice& lattice, int l, int m, int nz,
                                     double amplitude, std::uint64_t seed) {
  Random random(seed);
  ParticleState state = uniform_gas_3d(n, Box3{lattice.length_x, lattice.length_y, lattice.length_z}, seed + 1);
  for (std::size_t j = 0; j < n; ++j) {
    double x = 0.0, y = 0.0, z = 0.0;
    do {
      x = random.uniform() * lattice.length_x;
      y = random.uniform() * lattice.length_y;
      z = random.uniform() * lattice.length_z;
    } while (random.uniform() * (1.0 + amplitude) > 1.0 + amplitude * std::cos(lattice.phase(l, m, nz, x, y, z)));
    state.x[j] = x;
    state.y[j] = y;
    state.z[j] = z;
  }
  return state;
}

}  // namespace granule::spectra::testing
