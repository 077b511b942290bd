// The engine's cell grid (src/cells/cell_grid.hpp): contact pairs always lie in neighbouring
// cells, and an automatic grid stays within the cell count its ids allow.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "cells/cell_grid.hpp"

namespace granule {
namespace {

// A box 1e6 diameters long and 3.5 wide holding 10^6 disks: 3 rows (the minimum) of about 700,000
// columns at the default occupancy, 2.1 million cells, where the occupancy alone asks for 1.7 million.
CellGridRequest elongated(int dimension) {
  CellGridRequest request;
  request.length_x = 1e6;
  request.length_y = 3.5;
  request.length_z = 3.5;
  request.diameter = 1.0;
  request.particles = 1'000'000;
  request.particles_per_cell = kDefaultParticlesPerCell;
  request.dimension = dimension;
  return request;
}

TEST(CellGrid, AnElongatedBoxWidensItsLongCellsToStayWithinTheLimit) {
  for (const int dimension : {2, 3}) {
    CellGridRequest request = elongated(dimension);
    const CellGridChoice unlimited = choose_cell_grid(request);
    ASSERT_TRUE(unlimited.grid) << unlimited.error;
    request.max_cells = 100'000;
    ASSERT_GT(unlimited.grid->cell_count(), request.max_cells);  // else the limit is not tried
    const CellGridChoice limited = choose_cell_grid(request);
    ASSERT_TRUE(limited.grid) << limited.error;
    const CellGrid& g = *limited.grid;
    EXPECT_LE(g.cell_count(), request.max_cells);
    // As close to the limit as whole columns allow: one column more would exceed it.
    EXPECT_GT((g.nx + 1) * static_cast<std::int64_t>(g.ny) * g.nz, request.max_cells);
    // Only the long side's cells are widened.
    EXPECT_EQ(g.ny, unlimited.grid->ny);
    EXPECT_EQ(g.nz, unlimited.grid->nz);
    EXPECT_GT(g.width, unlimited.grid->width);
  }
}

TEST(CellGrid, ALimitBelowTheSmallestGridIsRefused) {
  CellGridRequest request = elongated(2);
  request.max_cells = 8;  // 3 × 3 cells is the smallest grid
  const CellGridChoice choice = choose_cell_grid(request);
  EXPECT_FALSE(choice.grid);
  EXPECT_NE(choice.error.find("at most 8 cells"), std::string::npos) << choice.error;
  request.max_cells = 9;
  ASSERT_TRUE(choose_cell_grid(request).grid);
  EXPECT_EQ(choose_cell_grid(request).grid->cell_count(), 9);
}

TEST(CellGrid, ALimitThatFitsChangesNothing) {
  CellGridRequest request = elongated(2);
  const CellGridChoice unlimited = choose_cell_grid(request);
  ASSERT_TRUE(unlimited.grid);
  request.max_cells = unlimited.grid->cell_count();
  const CellGridChoice limited = choose_cell_grid(request);
  ASSERT_TRUE(limited.grid);
  EXPECT_EQ(limited.grid->nx, unlimited.grid->nx);
  EXPECT_EQ(limited.grid->ny, unlimited.grid->ny);
}

TEST(CellGrid, CellsAreNeverNarrowerThanTheLargestContactDistance) {
  for (const double phi : {0.3, 0.6}) {  // dense enough for 0.1 per cell to ask for cells below σ
    CellGridRequest request;
    request.particles = 10'000;
    request.dimension = 3;
    request.diameter = 1.0;
    request.particles_per_cell = 0.1;  // asks for cells smaller than σ: the grid must refuse to
    const double side = std::cbrt(static_cast<double>(request.particles) * (M_PI / 6.0) / phi);
    request.length_x = request.length_y = request.length_z = side;
    const CellGridChoice choice = choose_cell_grid(request);
    ASSERT_TRUE(choice.grid) << choice.error;
    EXPECT_GE(choice.grid->width, 1.0);
    EXPECT_GE(choice.grid->height, 1.0);
    EXPECT_GE(choice.grid->depth, 1.0);
  }
}

}  // namespace
}  // namespace granule
