// The tables `granule theory` prints, built in the theory library: their grids, shapes and the
// values they must reproduce exactly (the start of Haff cooling, T(0) = T0; a start at the
// steady temperature, T_i = T0 (4.5)).
#include <gtest/gtest.h>

#include <cmath>

#include "theory/cooling_tables.hpp"
#include "theory/prediction_table.hpp"
#include "theory/shear_start_table.hpp"
#include "theory/shear_tables.hpp"
#include "theory/steady_shear.hpp"

namespace {

namespace th = granule::theory;

TEST(PredictionGrids, LinspaceHitsBothEndsAndOnePointIsTheStart) {
  const auto x = th::linspace(1.0, 3.0, 5);
  ASSERT_EQ(x.size(), 5u);
  EXPECT_EQ(x.front(), 1.0);
  EXPECT_EQ(x.back(), 3.0);
  EXPECT_DOUBLE_EQ(x[1], 1.5);
  EXPECT_EQ(th::linspace(2.0, 7.0, 1), std::vector<double>{2.0});
  const auto k = th::logspace(1e-3, 1.0, 4);
  ASSERT_EQ(k.size(), 4u);
  EXPECT_NEAR(k[1], 1e-2, 1e-15);
  EXPECT_NEAR(k.back(), 1.0, 1e-15);
}

TEST(PredictionTables, HaffStartsAtTheInitialTemperature) {
  th::HaffInputs in;
  in.temperature = 2.5;
  const th::PredictionTable table = th::haff_table(in);
  ASSERT_EQ(table.rows.size(), static_cast<std::size_t>(in.points));
  for (const auto& row : table.rows) EXPECT_EQ(row.size(), table.columns.size());
  EXPECT_EQ(table.rows.front()[0], 0.0);  // c
  EXPECT_EQ(table.rows.front()[1], 0.0);  // t
  EXPECT_DOUBLE_EQ(table.rows.front()[2], 2.5);
  EXPECT_LT(table.rows.back()[2], 2.5);   // it cools
}

TEST(PredictionTables, FreeStabilityAddsTheAsymptoticColumns) {
  th::FreeStabilityInputs in;
  const std::size_t plain = th::free_stability_table(in).columns.size();
  in.asymptotic = true;
  const th::PredictionTable table = th::free_stability_table(in);
  EXPECT_EQ(table.columns.size(), plain + 6);
  for (const auto& row : table.rows) EXPECT_EQ(row.size(), table.columns.size());
}

TEST(PredictionTables, ShearStartAtTheSteadyTemperature) {
  th::ShearStartInputs in;
  in.temperature_over_steady = 1.0;
  const th::ShearStartPrediction p = th::shear_start_table(in);
  const double sigma = th::diameter_for_area_fraction(in.area_fraction, in.particles, in.box_x, in.box_y);
  EXPECT_DOUBLE_EQ(p.initial_temperature,
                   th::steady_shear_temperature_kinetic(in.restitution, in.shear_rate, sigma, in.area_fraction));
  EXPECT_EQ(p.table.derived_names.size(), p.table.derived.size());
  ASSERT_EQ(p.table.rows.size(), static_cast<std::size_t>(in.points));
  EXPECT_NEAR(p.table.rows.front()[4], p.initial_temperature, 1e-12 * p.initial_temperature);  // T_4.26 at t = 0
}

TEST(PredictionTables, ShearScalesIsASummaryWithItsDerivedValues) {
  const th::PredictionTable table = th::shear_scales_table(th::ShearScalesInputs{});
  EXPECT_TRUE(table.columns.empty());
  EXPECT_FALSE(table.summary.empty());
  EXPECT_EQ(table.derived_names.size(), table.derived.size());
  for (double v : table.derived) EXPECT_TRUE(std::isfinite(v));
}

}  // namespace
