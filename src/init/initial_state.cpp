#include "init/initial_state.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "boundary/shear_frame.hpp"
#include "init/random.hpp"

namespace granule {

namespace {

double area_fraction(const SystemParams& p) {
  return M_PI * static_cast<double>(p.particles) * p.diameter * p.diameter / (4.0 * p.length_x * p.length_y);
}

// Random sequential addition with a grid of cells of side ≥ σ for the overlap test.
bool place_randomly(const SystemParams& p, Random& rng, ParticleState& out) {
  const double sigma = p.diameter;
  const int nx = std::max(1, static_cast<int>(p.length_x / sigma));
  const int ny = std::max(1, static_cast<int>(p.length_y / sigma));
  const double wx = p.length_x / nx;
  const double wy = p.length_y / ny;
  std::vector<std::vector<std::int32_t>> cells(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
  const auto n = static_cast<std::size_t>(p.particles);
  const std::uint64_t max_attempts = 1000 * static_cast<std::uint64_t>(n) + 100000;
  std::uint64_t attempts = 0;
  for (std::size_t placed = 0; placed < n;) {
    if (++attempts > max_attempts) return false;
    const double x = rng.uniform() * p.length_x;
    const double y = rng.uniform() * p.length_y;
    const int cx = std::min(nx - 1, static_cast<int>(x / wx));
    const int cy = std::min(ny - 1, static_cast<int>(y / wy));
    bool free = true;
    for (int dy = -1; dy <= 1 && free; ++dy) {
      for (int dx = -1; dx <= 1 && free; ++dx) {
        const int c = (cx + dx + nx) % nx + ((cy + dy + ny) % ny) * nx;
        for (std::int32_t j : cells[static_cast<std::size_t>(c)]) {
          double rx = out.x[static_cast<std::size_t>(j)] - x;
          double ry = out.y[static_cast<std::size_t>(j)] - y;
          rx -= p.length_x * std::round(rx / p.length_x);
          ry -= p.length_y * std::round(ry / p.length_y);
          if (rx * rx + ry * ry < sigma * sigma * (1.0 + 1e-9)) {
            free = false;
            break;
          }
        }
      }
    }
    if (!free) continue;
    out.x[placed] = x;
    out.y[placed] = y;
    cells[static_cast<std::size_t>(cx + cy * nx)].push_back(static_cast<std::int32_t>(placed));
    ++placed;
  }
  return true;
}

// Triangular lattice with an even number of rows (so it is periodic), the row count chosen to
// maximise the nearest-neighbour distance; N of its sites are occupied at random.
bool place_on_lattice(const SystemParams& p, Random& rng, ParticleState& out) {
  const auto n = static_cast<std::int64_t>(p.particles);
  std::int64_t best_rows = 0;
  double best_distance = 0.0;
  for (std::int64_t rows = 2; rows <= 2 * n + 2; rows += 2) {
    const std::int64_t columns = (n + rows - 1) / rows;
    const double ax = p.length_x / static_cast<double>(columns);
    const double ay = p.length_y / static_cast<double>(rows);
    const double distance = std::min({ax, std::sqrt(0.25 * ax * ax + ay * ay), 2.0 * ay});
    if (distance > best_distance) {
      best_distance = distance;
      best_rows = rows;
    }
    if (ay < 0.5 * p.diameter) break;
  }
  if (best_distance < p.diameter * (1.0 + 1e-9)) return false;
  const std::int64_t rows = best_rows;
  const std::int64_t columns = (n + rows - 1) / rows;
  const double ax = p.length_x / static_cast<double>(columns);
  const double ay = p.length_y / static_cast<double>(rows);
  std::vector<std::int64_t> sites(static_cast<std::size_t>(rows * columns));
  std::iota(sites.begin(), sites.end(), 0);
  for (std::size_t k = 0; k < static_cast<std::size_t>(n); ++k) {  // partial Fisher–Yates
    const std::size_t pick = k + static_cast<std::size_t>(rng.below(sites.size() - k));
    std::swap(sites[k], sites[pick]);
    const std::int64_t row = sites[k] / columns;
    const std::int64_t column = sites[k] % columns;
    out.x[k] = (static_cast<double>(column) + 0.25 + 0.5 * static_cast<double>(row % 2)) * ax;
    out.y[k] = (static_cast<double>(row) + 0.5) * ay;
  }
  return true;
}

}  // namespace

InitialStateResult make_initial_state(const SystemParams& params, double temperature,
                                      std::uint64_t seed, Placement placement) {
  InitialStateResult result;
  ParticleState& s = result.state;
  const auto n = static_cast<std::size_t>(params.particles);
  s.resize(n);
  Random rng(seed);
  const double nu = area_fraction(params);
  if (placement == Placement::kAuto) {
    placement = nu <= kRandomPlacementLimit ? Placement::kRandom : Placement::kLattice;
  }
  const bool placed = placement == Placement::kRandom ? place_randomly(params, rng, s)
                                                       : place_on_lattice(params, rng, s);
  if (!placed) {
    result.error = placement == Placement::kRandom
                       ? "random placement jammed at area fraction " + std::to_string(nu) +
                             "; use initial.placement = \"lattice\" for dense systems"
                       : "no triangular lattice of " + std::to_string(params.particles) +
                             " sites fits disks of this diameter in this box";
    return result;
  }

  // Gaussian peculiar velocities, rescaled to exactly T_i = ½⟨v'²⟩ after removing their mean.
  double mean_x = 0.0, mean_y = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    s.vx[i] = rng.normal();
    s.vy[i] = rng.normal();
    mean_x += s.vx[i];
    mean_y += s.vy[i];
  }
  mean_x /= static_cast<double>(n);
  mean_y /= static_cast<double>(n);
  double sum_sq = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    s.vx[i] -= mean_x;
    s.vy[i] -= mean_y;
    sum_sq += s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i];
  }
  const double scale = sum_sq > 0.0 ? std::sqrt(2.0 * temperature * static_cast<double>(n) / sum_sq) : 0.0;
  const ShearFrame frame{params.length_x, params.length_y, params.shear_velocity};
  double total_x = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    s.vx[i] = scale * s.vx[i] + frame.mean_flow(s.y[i]);  // linear shear profile (§1.4.2)
    s.vy[i] *= scale;
    total_x += s.vx[i];
  }
  // The profile's sample mean is not exactly zero: remove the total momentum P/N per disk.
  for (std::size_t i = 0; i < n; ++i) s.vx[i] -= total_x / static_cast<double>(n);
  return result;
}

}  // namespace granule
