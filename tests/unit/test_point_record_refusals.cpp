// A sweep point's record and summary.json are read back as untrusted input
// (src/sweep/point_record.hpp): a damaged one is refused with an InputError naming the file, the
// key and what is allowed; a missing one leaves the point pending.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/io_error.hpp"
#include "sweep/point_record.hpp"
#include "sweep/results_table.hpp"

namespace granule::sweep {
namespace {

namespace fs = std::filesystem;

class PointRecordRefusals : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_.root = fs::path(::testing::TempDir()) /
                ("point_records_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_.root);
    fs::create_directories(dir_.root / "points");
    fs::create_directories(dir_.run(point_));
    spec_.points = {point_};
  }
  void TearDown() override { fs::remove_all(dir_.root); }

  void write_text(const fs::path& path, const std::string& text) const { std::ofstream(path) << text; }

  // A record as write_record writes it, with `value` in place of the value of `key`.
  void write_record_with(const std::string& key, const std::string& value) const {
    std::string fields[][2] = {{"point", "\"p\""}, {"status", "\"failed\""}, {"exit_code", "1"}, {"error", "\"boom\""},
                               {"seconds", "2.5"}};
    std::string text = "{";
    for (auto& [name, original] : fields) {
      text += (text.size() > 1 ? ", \"" : "\"") + name + "\": " + (name == key ? value : original);
    }
    write_text(dir_.record(point_), text + "}\n");
  }

  // The message of the InputError that reading the record throws ("" if none).
  std::string refusal() const {
    try {
      read_record(dir_, point_);
    } catch (const InputError& error) {
      return error.what();
    }
    return "";
  }

  SweepPoint point_{"p", {}};
  SweepDirectory dir_;
  SweepSpec spec_;
};

TEST_F(PointRecordRefusals, AWrittenRecordReadsBack) {
  write_record(dir_, point_, PointRecord{"collapsed", 3, "", 1.25});
  const std::optional<PointRecord> r = read_record(dir_, point_);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, "collapsed");
  EXPECT_EQ(r->exit_code, 3);
  EXPECT_EQ(r->seconds, 1.25);
}

TEST_F(PointRecordRefusals, AMissingRecordLeavesThePointPending) {
  EXPECT_FALSE(read_record(dir_, point_));
  EXPECT_EQ(current_record(dir_, point_).status, "pending");
}

// A value of a record, damaged, and what the refusal says of it.
struct Damage {
  const char* key;
  const char* value;
  const char* said;
};

const Damage kDamages[] = {
    {"status", "5", "\"status\" is 5, expected one of \"finished\", \"collapsed\", \"interrupted\", \"failed\""},
    {"status", "\"done\"", "\"status\" is \"done\""},
    {"exit_code", "\"x\"", "\"exit_code\" is \"x\", expected an integer in [0, 255]"},
    {"exit_code", "-1", "\"exit_code\" is -1"},
    {"exit_code", "1.5", "\"exit_code\" is 1.5"},
    {"exit_code", "18446744073709551615", "\"exit_code\" is 18446744073709551615"},
    {"seconds", "-1", "\"seconds\" is -1, expected a finite number >= 0"},
    {"seconds", "1e999", "not JSON"},  // JSON holds no infinity: an overflowing number is a syntax error
    {"point", "\"q\"", "\"point\" is \"q\", expected \"p\""},
    {"error", "{\"a\": 1}", "nested more than 1 deep"},
};

TEST_F(PointRecordRefusals, EachDamagedValueIsRefusedNamingTheRecordTheKeyAndTheRemedy) {
  for (const Damage& damage : kDamages) {
    write_record_with(damage.key, damage.value);
    const std::string message = refusal();
    EXPECT_EQ(message.rfind(dir_.record(point_).string() + ": ", 0), 0u) << damage.key << " = " << damage.value;
    EXPECT_NE(message.find(damage.said), std::string::npos) << message;
    EXPECT_NE(message.find("delete it to run point p again"), std::string::npos) << message;
  }
}

TEST_F(PointRecordRefusals, AMissingKeyIsRefused) {
  write_text(dir_.record(point_), R"({"point": "p", "status": "failed", "exit_code": 1, "seconds": 1})");
  EXPECT_NE(refusal().find("\"error\" missing, expected a string"), std::string::npos);
}

TEST_F(PointRecordRefusals, ARecordThatIsNotJsonIsRefusedNotTakenAsMissing) {
  write_text(dir_.record(point_), "{\"point\": \"p\", \"status\": \"fin");
  const std::string message = refusal();
  EXPECT_NE(message.find(dir_.record(point_).string() + ": not JSON"), std::string::npos) << message;
  EXPECT_THROW(current_record(dir_, point_), InputError);
}

TEST_F(PointRecordRefusals, ARecordThatIsNotAnObjectIsRefused) {
  write_text(dir_.record(point_), "[1, 2]");
  EXPECT_NE(refusal().find("not a JSON object"), std::string::npos);
}

TEST_F(PointRecordRefusals, ASummaryWithAnUnknownStopReasonIsRefused) {
  write_text(dir_.run(point_) / "summary.json", R"({"stop_reason": 5, "wall_seconds": 1.0})");
  try {
    current_record(dir_, point_);
    FAIL() << "accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("summary.json: \"stop_reason\" is 5, expected one of \"time reached\""), std::string::npos)
        << message;
    EXPECT_NE(message.find("to run the point again"), std::string::npos) << message;
  }
}

TEST_F(PointRecordRefusals, AFinishedSummaryStandsInForAMissingRecord) {
  write_text(dir_.run(point_) / "summary.json", R"({"stop_reason": "inelastic collapse", "wall_seconds": 2.0})");
  const PointRecord r = current_record(dir_, point_);
  EXPECT_EQ(r.status, "collapsed");
  EXPECT_EQ(r.seconds, 2.0);
}

TEST_F(PointRecordRefusals, CollectingWithADamagedRecordWritesNoResults) {
  write_record_with("status", "5");
  EXPECT_THROW(write_results(dir_, spec_), InputError);
  EXPECT_FALSE(fs::exists(dir_.results()));
}

}  // namespace
}  // namespace granule::sweep
