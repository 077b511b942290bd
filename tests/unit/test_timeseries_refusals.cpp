// timeseries.csv is read back as untrusted input (src/io/timeseries_csv.hpp): a damaged row is
// refused with an InputError naming the file, the line and the column.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "io/io_error.hpp"
#include "io/timeseries_csv.hpp"

namespace granule {
namespace {

namespace fs = std::filesystem;

class TimeseriesRefusals : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = (fs::path(::testing::TempDir()) /
             ("timeseries_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".csv"))
                .string();
  }
  void TearDown() override { fs::remove(path_); }

  // Two rows at t = 1, 2 (c = 0.5, 1), with `edit` applied to the second sample before writing.
  template <typename Edit>
  void write_rows(Edit edit) const {
    std::vector<DiagnosticsSample> samples(2);
    for (std::size_t k = 0; k < 2; ++k) {
      samples[k].t = static_cast<double>(k + 1);
      samples[k].c = 0.5 * static_cast<double>(k + 1);
      samples[k].kinetic_energy = 1.0;
    }
    edit(samples[1]);
    write_timeseries(path_, samples);
  }

  std::string refusal() const {
    try {
      read_timeseries(path_);
    } catch (const InputError& error) {
      return error.what();
    }
    return "";
  }

  std::string path_;
};

TEST_F(TimeseriesRefusals, WrittenRowsReadBack) {
  write_rows([](DiagnosticsSample&) {});
  const std::vector<DiagnosticsSample> rows = read_timeseries(path_);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].t, 2.0);
  EXPECT_EQ(rows[1].c, 1.0);
}

TEST_F(TimeseriesRefusals, ANaNTimeNamesTheLineAndColumn) {
  write_rows([](DiagnosticsSample& s) { s.t = std::numeric_limits<double>::quiet_NaN(); });
  EXPECT_EQ(refusal(), path_ + ", line 3, column t: nan is not a finite number");
}

TEST_F(TimeseriesRefusals, AnInfiniteEnergyIsRefused) {
  write_rows([](DiagnosticsSample& s) { s.kinetic_energy = INFINITY; });
  EXPECT_EQ(refusal(), path_ + ", line 3, column kinetic_energy: inf is not a finite number");
}

TEST_F(TimeseriesRefusals, TheFlowMeasuresOf3DRunsMayBeNaN) {
  write_rows([](DiagnosticsSample& s) { s.flow.density_contrast = std::numeric_limits<double>::quiet_NaN(); });
  EXPECT_TRUE(std::isnan(read_timeseries(path_)[1].flow.density_contrast));
}

TEST_F(TimeseriesRefusals, TimeGoingBackIsRefused) {
  write_rows([](DiagnosticsSample& s) { s.t = 0.5; });
  EXPECT_EQ(refusal(), path_ + ", line 3, column t: 0.5 is less than in the row before (1): rows go forward in time");
}

TEST_F(TimeseriesRefusals, ATextValueOrAShortRowIsRefused) {
  write_rows([](DiagnosticsSample&) {});
  std::ofstream(path_, std::ios::app) << "3,x\n";
  EXPECT_NE(refusal().find(", line 4: 2 values, expected "), std::string::npos);
  write_rows([](DiagnosticsSample&) {});
  std::string text;
  {
    std::ifstream in(path_);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  text.replace(text.rfind("\n2,") + 1, 1, "two");
  std::ofstream(path_) << text;
  EXPECT_EQ(refusal(), path_ + ", line 3, column t: \"two\" is not a number");
}

TEST_F(TimeseriesRefusals, AForeignHeaderIsRefused) {
  std::ofstream(path_) << "time,collisions\n1,2\n";
  EXPECT_NE(refusal().find(", line 1: the header is not the columns"), std::string::npos);
}

}  // namespace
}  // namespace granule
