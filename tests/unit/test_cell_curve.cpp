// The order in which the engine renumbers its particles: every cell once, Morton's Z order on
// square grids of 2^k cells (an independent construction: interleaved coordinate bits), and
// halves of the box visited one after the other on any grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "cells/cell_curve.hpp"
#include "memory/permute_in_place.hpp"

namespace granule {
namespace {

template <int D>
std::vector<std::array<int, D>> curve(const std::array<int, D>& counts) {
  std::vector<std::array<int, D>> cells;
  for_each_cell_along_curve<D>(counts, [&](const std::array<int, D>& c) { cells.push_back(c); });
  return cells;
}

template <int D>
void expect_every_cell_once(const std::array<int, D>& counts) {
  const auto cells = curve<D>(counts);
  std::int64_t total = 1;
  for (int n : counts) total *= n;
  ASSERT_EQ(static_cast<std::int64_t>(cells.size()), total);
  std::vector<char> seen(static_cast<std::size_t>(total), 0);
  for (const auto& c : cells) {
    std::int64_t index = 0;
    for (int a = D - 1; a >= 0; --a) {
      ASSERT_GE(c[a], 0);
      ASSERT_LT(c[a], counts[a]);
      index = index * counts[a] + c[a];
    }
    ASSERT_EQ(seen[static_cast<std::size_t>(index)]++, 0) << "a cell visited twice";
  }
}

TEST(CellCurve, VisitsEveryCellOnce) {
  expect_every_cell_once<2>({1, 1});
  expect_every_cell_once<2>({3, 3});
  expect_every_cell_once<2>({7, 5});
  expect_every_cell_once<2>({1000, 3});
  expect_every_cell_once<2>({3, 1291});
  expect_every_cell_once<3>({3, 3, 3});
  expect_every_cell_once<3>({5, 4, 7});
  expect_every_cell_once<3>({40, 3, 3});
}

// Morton's order: the bits of the coordinates interleaved, x above y (above z) at every level.
template <int D>
std::uint64_t morton_key(const std::array<int, D>& c, int bits) {
  std::uint64_t key = 0;
  for (int b = bits - 1; b >= 0; --b) {
    for (int a = 0; a < D; ++a) key = (key << 1) | ((static_cast<std::uint64_t>(c[a]) >> b) & 1u);
  }
  return key;
}

TEST(CellCurve, IsMortonsOrderOnPowerOfTwoGrids) {
  for (int bits = 1; bits <= 5; ++bits) {
    const int n = 1 << bits;
    const auto square = curve<2>({n, n});
    for (std::size_t k = 0; k < square.size(); ++k) ASSERT_EQ(morton_key<2>(square[k], bits), k) << n;
    if (bits > 3) continue;
    const auto cube = curve<3>({n, n, n});
    for (std::size_t k = 0; k < cube.size(); ++k) ASSERT_EQ(morton_key<3>(cube[k], bits), k) << n;
  }
}

// Any grid: the first ⌊n/2⌋ columns of a wide grid come first, and within them the same holds again.
TEST(CellCurve, VisitsTheHalvesOfTheLongestSideInTurn) {
  const auto cells = curve<2>({13, 5});
  for (std::size_t k = 0; k < cells.size(); ++k) EXPECT_EQ(cells[k][0] < 6, k < 30u) << k;
  // The left 6 × 5 is halved across its columns again; its first 3 × 5 then across its rows.
  for (std::size_t k = 0; k < 30; ++k) EXPECT_EQ(cells[k][0] < 3, k < 15u) << k;
  for (std::size_t k = 0; k < 15; ++k) EXPECT_EQ(cells[k][1] < 2, k < 6u) << k;
}

TEST(PermuteInPlace, MovesEveryItemOfEveryArrayToItsDestination) {
  std::mt19937_64 random(5);
  for (std::size_t n : {0u, 1u, 2u, 17u, 1000u}) {
    std::vector<std::int32_t> destination(n);
    for (std::size_t i = 0; i < n; ++i) destination[i] = static_cast<std::int32_t>(i);
    std::shuffle(destination.begin(), destination.end(), random);
    const std::vector<std::int32_t> wanted = destination;
    std::vector<double> values(n);
    std::vector<std::int32_t> tags(n);
    for (std::size_t i = 0; i < n; ++i) {
      values[i] = 0.5 * static_cast<double>(i);
      tags[i] = static_cast<std::int32_t>(i);
    }
    std::size_t swaps = 0;
    permute_in_place(destination, [&](std::size_t a, std::size_t b) {
      std::swap(values[a], values[b]);
      std::swap(tags[a], tags[b]);
      ++swaps;
    });
    EXPECT_LE(swaps + (n > 0 ? 1 : 0), std::max<std::size_t>(n, 1));
    for (std::size_t i = 0; i < n; ++i) {
      ASSERT_EQ(destination[i], static_cast<std::int32_t>(i));
      const auto place = static_cast<std::size_t>(wanted[i]);
      ASSERT_EQ(tags[place], static_cast<std::int32_t>(i));
      ASSERT_EQ(values[place], 0.5 * static_cast<double>(i));
    }
  }
}

}  // namespace
}  // namespace granule
