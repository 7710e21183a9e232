#include "sim/params/table_specs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace billiard::params {
namespace {

constexpr double kInch = 0.0254;

TEST(TableSpecsTest, BuiltInTablesLoadAndBuild) {
  const std::vector<std::string> expected = {"carom-10ft", "pool-7ft", "pool-8ft", "pool-9ft",
                                             "snooker-12ft"};
  std::vector<std::string> names = TableNames();
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, expected);
  for (const std::string& name : names) {
    const table::TableSpec spec = LoadTableSpec(name);
    EXPECT_EQ(spec.name, name);
    EXPECT_FALSE(spec.source.empty()) << name << " must say where its numbers come from";
    EXPECT_TRUE(spec.rail.has_value()) << name << " must give its rail";
    EXPECT_NO_THROW(table::BuildTable(spec)) << name;
  }
}

// The sizes against the governing bodies' figures: WPA Equipment Specifications (playing surface
// 100 x 50 in and 92 x 46 in, +-1/8 in; nose height 62.5-64.5 % of the 2.25 in ball; mouths
// 4.5-4.625 in corner, 5-5.125 in side; cut angles 142 and 104 +-1 deg), WPBSA Official Rules
// 1(a) (3569 x 1778 mm, +-13 mm), UMB World Rules of Carom art. 2.1 (2.84 x 1.42 m, +-5 mm;
// cushion 37 +-1 mm; no pockets).
TEST(TableSpecsTest, SizesWithinTheRules) {
  struct Size {
    const char* name;
    double length, width, tolerance;
  };
  for (const Size& s :
       {Size{"pool-9ft", 100 * kInch, 50 * kInch, kInch / 8},
        Size{"pool-8ft", 92 * kInch, 46 * kInch, kInch / 8},
        Size{"snooker-12ft", 3.569, 1.778, 0.013}, Size{"carom-10ft", 2.84, 1.42, 0.005}}) {
    const table::TableSpec spec = LoadTableSpec(s.name);
    EXPECT_NEAR(spec.length, s.length, s.tolerance) << s.name;
    EXPECT_NEAR(spec.width, s.width, s.tolerance) << s.name;
  }
  for (const char* name : {"pool-7ft", "pool-8ft", "pool-9ft"}) {
    SCOPED_TRACE(name);
    const table::TableSpec spec = LoadTableSpec(name);
    EXPECT_GE(spec.cushion_height, 0.625 * 2.25 * kInch);
    EXPECT_LE(spec.cushion_height, 0.645 * 2.25 * kInch);
    ASSERT_TRUE(spec.corner && spec.side);
    EXPECT_GE(spec.corner->mouth, 4.5 * kInch);
    EXPECT_LE(spec.corner->mouth, 4.625 * kInch);
    EXPECT_GE(spec.side->mouth, 5.0 * kInch);
    EXPECT_LE(spec.side->mouth, 5.125 * kInch);
    EXPECT_NEAR(spec.corner->jaw_angle, 142, 1);
    EXPECT_NEAR(spec.side->jaw_angle, 104, 1);
  }
  // The rail: WPA's width (4-7.5 in, the cushion included) on every table, none lower than its
  // nose, the pool rail FastFiz's 0.040005 m.
  for (const std::string& name : TableNames()) {
    SCOPED_TRACE(name);
    const table::TableSpec spec = LoadTableSpec(name);
    ASSERT_TRUE(spec.rail.has_value());
    EXPECT_GE(spec.rail->width, 4.0 * kInch);
    EXPECT_LE(spec.rail->width, 7.5 * kInch);
    EXPECT_GT(spec.rail->height, spec.cushion_height);
  }
  EXPECT_EQ(LoadTableSpec("pool-9ft").rail->height, 0.040005);
  const table::TableSpec carom = LoadTableSpec("carom-10ft");
  EXPECT_NEAR(carom.cushion_height, 0.037, 0.001);
  EXPECT_FALSE(carom.corner || carom.side);
}

const char kMinimal[] = R"({"length": 2.0, "width": 1.0, "cushion_height": 0.036,
  "corner": {"mouth": 0.116, "jaw_angle": 142, "jaw_radius": 0.003, "capture_depth": 0.044}})";

TEST(TableSpecsTest, ParsesAMinimalTableNamedByItsOrigin) {
  const table::TableSpec spec = ParseTableSpec(kMinimal, "mine.json");
  EXPECT_EQ(spec.name, "mine.json");
  EXPECT_EQ(spec.source, "");
  EXPECT_EQ(spec.length, 2.0);
  ASSERT_TRUE(spec.corner.has_value());
  EXPECT_EQ(spec.corner->capture_depth, 0.044);
  EXPECT_FALSE(spec.side.has_value());
  EXPECT_FALSE(spec.rail.has_value()) << "a table written before rails were data still loads";
}

TEST(TableSpecsTest, ReadsTheRail) {
  const table::TableSpec spec = ParseTableSpec(
      R"({"length": 2, "width": 1, "cushion_height": 0.036, "rail": {"height": 0.04, "width": 0.15}})",
      "t.json");
  ASSERT_TRUE(spec.rail.has_value());
  EXPECT_EQ(spec.rail->height, 0.04);
  EXPECT_EQ(spec.rail->width, 0.15);
}

void ExpectRefused(const std::string& json, const std::string& message) {
  try {
    ParseTableSpec(json, "t.json");
    ADD_FAILURE() << "accepted; expected: " << message;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).find(message), 0u) << e.what();
  }
}

TEST(TableSpecsTest, RefusesNamingTheKey) {
  ExpectRefused(R"({"length": 2, "width": 1, "cushion_height": 0.03, "colour": "green"})",
                "t.json: unknown key colour");
  ExpectRefused(R"({"length": 2, "width": 1, "cushion_height": 0.03,
    "corner": {"mouth": 0.1, "jaw_angle": 142, "jaw_radius": 0, "capture_depth": 0, "mouthh": 1}})",
                "t.json: unknown key corner.mouthh");
  ExpectRefused(R"({"length": "2", "width": 1, "cushion_height": 0.03})",
                "t.json: length must be a number, not string");
  ExpectRefused(R"({"length": 2, "cushion_height": 0.03})", "t.json: missing number width");
  ExpectRefused(R"({"length": 2, "width": 1, "cushion_height": 0.03,
    "corner": {"mouth": 0.1, "jaw_angle": 142, "capture_depth": 0}})",
                "t.json: missing number corner.jaw_radius");
  ExpectRefused(R"({"length": 2, "width": 1, "cushion_height": 0.03, "side": [1]})",
                "t.json: \"side\" must be an object, not array");
  ExpectRefused(R"({"name": 7, "length": 2, "width": 1, "cushion_height": 0.03})",
                "t.json: name must be a string, not number");
  ExpectRefused(R"({"length": 2,)", "t.json: not valid JSON");
  ExpectRefused(R"([1, 2])", "t.json: a table specification is a JSON object");
  ExpectRefused(R"({"length": 2, "width": 1, "cushion_height": 0.03, "rail": {"height": 0.04}})",
                "t.json: missing number rail.width");
  ExpectRefused(R"({"length": 2, "width": 1, "cushion_height": 0.03,
    "rail": {"height": 0.04, "width": 0.15, "colour": 1}})",
                "t.json: unknown key rail.colour");
  ExpectRefused(R"({"length": 2, "width": 1, "cushion_height": 0.03, "rail": 0.04})",
                "t.json: \"rail\" must be an object, not number");
  ExpectRefused(R"({"length": 2, "width": 1, "cushion_height": 0.03,
    "rail": {"height": 0.02, "width": 0.15}})",
                "t.json: table 't.json': rail.height must be at least cushion_height");
  ExpectRefused(R"({"length": 2, "width": 1, "cushion_height": -0.03})",
                "t.json: table 't.json': cushion_height must be positive");
}

TEST(TableSpecsTest, LoadsAFileByPathAndRefusesAnUnknownName) {
  const std::string path = ::testing::TempDir() + "table_specs_test.json";
  {
    std::ofstream file(path);
    file << kMinimal;
  }
  EXPECT_EQ(LoadTableSpec(path).name, path);
  std::remove(path.c_str());
  try {
    LoadTableSpec("pool-10ft");
    ADD_FAILURE() << "accepted an unknown table";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "unknown table 'pool-10ft' (not a built-in table: carom-10ft, pool-7ft, pool-8ft, "
              "pool-9ft, snooker-12ft; not a readable file)");
  }
}

}  // namespace
}  // namespace billiard::params
