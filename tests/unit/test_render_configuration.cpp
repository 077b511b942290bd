// Configuration pictures (src/render): disks land where the box→pixel map puts them, in the
// colour of their velocity direction; periodic and Lees–Edwards images appear across the edges;
// the ink on the picture equals the area fraction (an exact law for non-overlapping disks); and
// clustered and uniform configurations give clearly different pixel statistics.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "init/initial_state.hpp"
#include "unit/particle_rows.hpp"
#include "render/color_scales.hpp"
#include "render/configuration_picture.hpp"

namespace granule::render {
namespace {

ParticleState disks(std::initializer_list<std::array<double, 4>> rows) { return particles_from_rows(rows); }

PictureOptions bare(int width) {
  PictureOptions o;
  o.width_px = width;
  o.arrows = false;
  o.legend = false;
  return o;
}

void expect_color(const Pixel& p, const Rgb& c) {
  EXPECT_NEAR(p.r, 255.0 * c.r, 1.5);
  EXPECT_NEAR(p.g, 255.0 * c.g, 1.5);
  EXPECT_NEAR(p.b, 255.0 * c.b, 1.5);
}

bool white(const Pixel& p) { return p.r == 255 && p.g == 255 && p.b == 255; }

TEST(RenderConfiguration, SingleDisksSitWhereTheyShouldInTheirDirectionColour) {
  // σ = 0.2 in a unit box at 200 px: radius 20 px.  (0.25, 0.75) → pixel (50, 50) (y up).
  const ParticleState p = disks({{0.25, 0.75, 1.0, 0.0}, {0.7, 0.3, 0.0, 2.0}});
  const RasterImage image = render_configuration({p, 0.2, ShearFrame{1.0, 1.0, 0.0}, 0.0}, bare(200));
  ASSERT_EQ(image.width, 200);
  ASSERT_EQ(image.height, 200);
  expect_color(image.at(50, 50), direction_color(0.0));
  expect_color(image.at(50 + 15, 50), direction_color(0.0));  // inside the rim
  EXPECT_TRUE(white(image.at(50 + 23, 50)));                 // just outside
  EXPECT_TRUE(white(image.at(50, 50 + 23)));
  expect_color(image.at(140, 140), direction_color(0.5 * std::numbers::pi));
  EXPECT_TRUE(white(image.at(100, 100)));
  EXPECT_TRUE(white(image.at(5, 195)));
}

TEST(RenderConfiguration, HeightFollowsTheBoxAspectRatio) {
  const ParticleState p = disks({{0.5, 0.25, 0.0, -1.0}});
  const RasterImage image = render_configuration({p, 0.1, ShearFrame{2.0, 1.0, 0.0}, 0.0}, bare(300));
  EXPECT_EQ(image.width, 300);
  EXPECT_EQ(image.height, 150);
  expect_color(image.at(75, 112), direction_color(-0.5 * std::numbers::pi));
}

TEST(RenderConfiguration, DisksCrossingTheEdgesAppearOnTheOppositeSide) {
  // Periodic: a disk at x = 0.02 (radius 0.1) reaches x = 0.92 … 1 through the right edge.
  const ParticleState left = disks({{0.02, 0.5, 1.0, 0.0}});
  const RasterImage periodic = render_configuration({left, 0.2, ShearFrame{1.0, 1.0, 0.0}, 0.0}, bare(200));
  EXPECT_FALSE(white(periodic.at(198, 100)));
  EXPECT_TRUE(white(periodic.at(170, 100)));
  // Lees–Edwards (§1.4.2): a disk at the bottom, y = 0.02, has its image above at x + Δ.
  const ParticleState bottom = disks({{0.5, 0.02, 1.0, 0.0}});
  const RasterImage sheared = render_configuration({bottom, 0.2, ShearFrame{1.0, 1.0, 5.0}, 0.3}, bare(200));
  EXPECT_FALSE(white(sheared.at(160, 1)));  // x = 0.8 at the top edge
  EXPECT_TRUE(white(sheared.at(100, 1)));   // not above the disk itself
  EXPECT_FALSE(white(sheared.at(100, 198)));
}

TEST(RenderConfiguration, SpeedColouringRunsFromSlowToFast) {
  const ParticleState p = disks({{0.25, 0.5, 0.1, 0.0}, {0.75, 0.5, 0.0, -3.0}});
  PictureOptions options = bare(200);
  options.coloring = DiskColoring::kSpeed;
  const RasterImage image = render_configuration({p, 0.2, ShearFrame{1.0, 1.0, 0.0}, 0.0}, options);
  expect_color(image.at(50, 100), sequential_color(0.1 / 3.0));
  expect_color(image.at(150, 100), sequential_color(1.0));
}

// Fraction of ink (darkness of the uniform disk colour) in each of blocks × blocks squares.
std::vector<double> ink_per_block(const RasterImage& image, int blocks) {
  std::vector<double> ink(static_cast<std::size_t>(blocks * blocks), 0.0);
  const double disk_darkness = 1.0 - 0.15;  // DiskColoring::kNone draws grey 0.15
  for (int row = 0; row < image.height; ++row) {
    for (int column = 0; column < image.width; ++column) {
      const std::size_t b = static_cast<std::size_t>(column * blocks / image.width + (row * blocks / image.height) * blocks);
      ink[b] += (1.0 - image.at(column, row).r / 255.0) / disk_darkness;
    }
  }
  const double pixels_per_block = static_cast<double>(image.width) * image.height / (blocks * blocks);
  for (double& v : ink) v /= pixels_per_block;
  return ink;
}

double mean(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

double coefficient_of_variation(const std::vector<double>& v) {
  const double m = mean(v);
  double s = 0.0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / static_cast<double>(v.size())) / m;
}

TEST(RenderConfiguration, InkEqualsAreaFractionAndClustersStandOut) {
  // N = 4000 at ν = 0.05 in a unit box: σ = √(4ν/(πN)) ≈ 0.004, a radius of 2 px at 1000 px.
  const std::int64_t n = 4000;
  const double nu = 0.05;
  SystemParams params;
  params.particles = n;
  params.diameter = std::sqrt(4.0 * nu / (std::numbers::pi * static_cast<double>(n)));
  const InitialStateResult uniform = make_initial_state(params, 1.0, 7, Placement::kRandom);
  ASSERT_TRUE(uniform.error.empty());
  // The same disks packed into a square lattice in a 0.3 × 0.3 corner: a dense cluster.
  ParticleState cluster = uniform.state;
  const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  for (std::int64_t i = 0; i < n; ++i) {
    cluster.x[static_cast<std::size_t>(i)] = 0.05 + 1.1 * params.diameter * static_cast<double>(i % side);
    cluster.y[static_cast<std::size_t>(i)] = 0.05 + 1.1 * params.diameter * static_cast<double>(i / side);
  }
  PictureOptions options = bare(1000);
  options.coloring = DiskColoring::kNone;
  const ShearFrame box{1.0, 1.0, 0.0};
  const std::vector<double> ink_uniform = ink_per_block(render_configuration({uniform.state, params.diameter, box, 0.0}, options), 10);
  const std::vector<double> ink_cluster = ink_per_block(render_configuration({cluster, params.diameter, box, 0.0}, options), 10);
  // Non-overlapping disks cover exactly ν of the area (antialiasing conserves coverage; a 2%
  // allowance for the polygonal arcs and 8-bit rounding).
  EXPECT_NEAR(mean(ink_uniform), nu, 0.02 * nu);
  EXPECT_NEAR(mean(ink_cluster), nu, 0.02 * nu);
  // 40 disks per block: random sequential addition fluctuates by ≲ 1/√40 ≈ 0.16; the cluster
  // fills 9 blocks of 100 and leaves the rest empty (coefficient of variation ≈ 3).
  const double cv_uniform = coefficient_of_variation(ink_uniform), cv_cluster = coefficient_of_variation(ink_cluster);
  std::printf("ink: uniform %.4f (cv %.3f), cluster %.4f (cv %.3f), nu %.3f\n", mean(ink_uniform), cv_uniform,
              mean(ink_cluster), cv_cluster, nu);
  EXPECT_LT(cv_uniform, 0.3);
  EXPECT_GT(cv_cluster, 2.0);
}

TEST(RenderConfiguration, ArrowsFollowTheCoarseGrainedFlow) {
  // Every disk moves at +x: the arrows are horizontal strokes through the cell centres, absent
  // elsewhere (disks are too small to matter at radius 0.6 px).
  ParticleState p;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 1600; ++i) {
    p.x.push_back(u(rng));
    p.y.push_back(u(rng));
    p.vx.push_back(1.0);
    p.vy.push_back(0.0);
  }
  PictureOptions options = bare(400);
  options.arrows = true;
  options.coloring = DiskColoring::kNone;
  options.min_disk_radius_px = 0.0;
  options.cells_x = options.cells_y = 4;  // centres at 50, 150, 250, 350 px; arrows 90 px long
  const RasterImage image = render_configuration({p, 1e-6, ShearFrame{1.0, 1.0, 0.0}, 0.0}, options);
  // The 1 px shaft at y = 150 px straddles pixel rows 149 and 150: their ink adds to one pixel.
  const auto ink = [&](int column, int row) { return 255 - image.at(column, row).r; };
  EXPECT_NEAR(ink(50 + 45, 149) + ink(50 + 45, 150), 255, 30);  // on the shaft
  EXPECT_EQ(image.at(50 - 10, 150).r, 255);   // behind the tail
  EXPECT_EQ(image.at(50 + 45, 150 + 20).r, 255);  // beside the shaft
  EXPECT_THROW(render_configuration({p, 1e-6, ShearFrame{1.0, 1.0, 0.0}, 0.0}, bare(8)), std::invalid_argument);
}

}  // namespace
}  // namespace granule::render
