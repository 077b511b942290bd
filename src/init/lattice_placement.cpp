// Lattices with random vacancies for dense initial states (placement.hpp): the triangular lattice
// of 2D runs and the face-centred cubic lattice of 3D runs, each with the largest nearest-neighbour
// distance the box allows for N sites.
#include <algorithm>
#include <cmath>

#include "init/placement.hpp"

namespace granule {

namespace {

// Even row counts keep the alternating offset of the rows periodic.  The nearest-neighbour
// distance is at most 2 a_y, so once 2 a_y falls below the best distance no later row count
// can win.
Lattice densest_triangular_lattice(const SystemParams& p) {
  const std::int64_t n = p.particles;
  Lattice best;
  for (std::int64_t rows = 2; rows <= 2 * n + 2; rows += 2) {
    const std::int64_t columns = (n + rows - 1) / rows;
    const double ax = p.length_x / static_cast<double>(columns);
    const double ay = p.length_y / static_cast<double>(rows);
    const double distance = std::min({ax, std::sqrt(0.25 * ax * ax + ay * ay), 2.0 * ay});
    if (distance > best.spacing) best = Lattice{2, {columns, rows, 1}, distance};
    if (2.0 * ay < best.spacing) break;
  }
  return best;
}

// Cubic cells a_x × a_y × a_z with sites at (0,0,0), (½,½,0), (½,0,½), (0,½,½): the nearest
// neighbours are at half a face diagonal or at a whole cell edge.  For each n_x, n_y the fewest
// layers n_z that hold N sites are best; a count whose edge L/n is already below the best
// distance cannot win, which bounds both loops.
Lattice densest_fcc_lattice(const SystemParams& p) {
  const std::int64_t n = p.particles;
  Lattice best{3, {1, 1, 1}, 0.0};
  for (std::int64_t nx = 1; p.length_x / static_cast<double>(nx) >= best.spacing && nx <= n; ++nx) {
    for (std::int64_t ny = 1; p.length_y / static_cast<double>(ny) >= best.spacing && nx * ny <= n; ++ny) {
      const std::int64_t nz = std::max<std::int64_t>(1, (n + 4 * nx * ny - 1) / (4 * nx * ny));
      const double ax = p.length_x / static_cast<double>(nx);
      const double ay = p.length_y / static_cast<double>(ny);
      const double az = p.length_z / static_cast<double>(nz);
      const double distance = std::min({ax, ay, az, 0.5 * std::sqrt(ax * ax + ay * ay),
                                        0.5 * std::sqrt(ax * ax + az * az), 0.5 * std::sqrt(ay * ay + az * az)});
      if (distance > best.spacing) best = Lattice{3, {nx, ny, nz}, distance};
    }
  }
  return best;
}

// The region the centres may occupy: the box, each side along a wall axis shortened by the
// (largest) diameter, so that a centre stays a radius from each wall.
SystemParams centre_region(SystemParams p) {
  if (p.walls[0]) p.length_x -= p.diameter;
  if (p.walls[1]) p.length_y -= p.diameter;
  if (p.walls[2]) p.length_z -= p.diameter;
  return p;
}

}  // namespace

Lattice densest_lattice(const SystemParams& p) {
  return p.dimension == 3 ? densest_fcc_lattice(p) : densest_triangular_lattice(p);
}

namespace {

// The centre of lattice site `site` (placement.hpp): in 2D a triangular lattice of rows offset by
// half a column, in 3D an FCC lattice a quarter cell off the box faces; `offset` moves it a radius
// in from the walls.
std::array<double, 3> site_position(int dimension, const Lattice& lattice, const std::array<double, 3>& edge,
                                    const std::array<double, 3>& offset, std::int64_t site) {
  const auto& cells = lattice.cells;
  std::array<double, 3> r{};
  if (dimension == 2) {
    const std::int64_t row = site / cells[0];
    const std::int64_t column = site % cells[0];
    r[0] = (static_cast<double>(column) + 0.25 + 0.5 * static_cast<double>(row % 2)) * edge[0] + offset[0];
    r[1] = (static_cast<double>(row) + 0.5) * edge[1] + offset[1];
    return r;
  }
  // The FCC basis in units of the cell edges: site = 4 (i_x + n_x (i_y + n_y i_z)) + basis.
  constexpr double kBasis[4][3] = {{0.0, 0.0, 0.0}, {0.5, 0.5, 0.0}, {0.5, 0.0, 0.5}, {0.0, 0.5, 0.5}};
  const std::int64_t cell = site / 4;
  const double* basis = kBasis[site % 4];
  const std::array<std::int64_t, 3> index{cell % cells[0], (cell / cells[0]) % cells[1], cell / (cells[0] * cells[1])};
  for (std::size_t a = 0; a < 3; ++a) r[a] = (static_cast<double>(index[a]) + 0.25 + basis[a]) * edge[a] + offset[a];
  return r;
}

}  // namespace

bool place_on_lattice(const SystemParams& p, Random& rng, ParticleState& out) {
  // Between walls the lattice fills the centres' region, a radius in from each wall (its
  // periodicity across the walls is then unused).  Sites inside obstacles are not used: the
  // lattice then has as many more sites as it needs.
  SystemParams region = centre_region(p);
  const std::array<bool, 3> images{!p.walls[0], !p.walls[1], !p.walls[2]};
  const std::array<double, 3> box{p.length_x, p.length_y, p.length_z};
  std::array<double, 3> offset{};
  for (std::size_t a = 0; a < 3; ++a) offset[a] = p.walls[a] ? 0.5 * p.diameter : 0.0;
  std::vector<std::int64_t> sites;
  Lattice lattice;
  std::array<double, 3> edge{};
  for (std::int64_t wanted = p.particles;;) {
    region.particles = wanted;
    lattice = densest_lattice(region);
    if (lattice.spacing < p.diameter * (1.0 + 1e-9)) return false;
    const auto& cells = lattice.cells;
    edge = {region.length_x / static_cast<double>(cells[0]), region.length_y / static_cast<double>(cells[1]),
            region.length_z / static_cast<double>(cells[2])};
    sites.clear();
    for (std::int64_t site = 0; site < lattice.sites(); ++site) {
      if (p.obstacles.empty() ||
          !overlaps_obstacle(p.obstacles, site_position(p.dimension, lattice, edge, offset, site), p.diameter, p.dimension, images, box)) {
        sites.push_back(site);
      }
    }
    const auto free = static_cast<std::int64_t>(sites.size());
    if (free >= p.particles) break;
    wanted += p.particles - free;
  }
  for (std::size_t k = 0; k < static_cast<std::size_t>(p.particles); ++k) {  // partial Fisher–Yates
    const std::size_t pick = k + static_cast<std::size_t>(rng.below(sites.size() - k));
    std::swap(sites[k], sites[pick]);
    const std::array<double, 3> r = site_position(p.dimension, lattice, edge, offset, sites[k]);
    for (int a = 0; a < p.dimension; ++a) out.position(a)[k] = r[static_cast<std::size_t>(a)];
  }
  return true;
}

}  // namespace granule
