// The hard suite: its truth is the camera's geometry (a third of the table out of the frame by
// construction, the barrel lens bowing the sides as k1 says, a side's error a distance to a
// line), and the detector held to what it achieves on it (issue 45's acceptance where met).
#include "bench/hard_suite.h"

#include <gtest/gtest.h>

#include <map>

#include "bench/hard_suite_report.h"
#include "sim/params/parameter_sets.h"

namespace billiard::bench {
namespace {

const std::vector<HardFrame>& Suite() {
  static const std::vector<HardFrame> frames = RenderHardSuite(params::LoadParameters("pool"));
  return frames;
}

const HardFrame& First(const std::string& condition) {
  for (const HardFrame& f : Suite()) {
    if (f.condition == condition) return f;
  }
  throw std::logic_error("no case " + condition);
}

// The distance of `p` from the line through a and b.
double FromChord(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector3d line = a.homogeneous().cross(b.homogeneous());
  return std::abs(line.dot(p.homogeneous())) / line.head<2>().norm();
}

TEST(HardSuite, TheTruthIsTheCamerasGeometry) {
  EXPECT_EQ(Suite().size(), 54u) << "9 cases, 3 cloths, scattered and racked";
  // The end case's camera is moved so that a third of the table leaves the frame.
  EXPECT_NEAR(First("out-of-frame end").seen_share, 2.0 / 3.0, 0.02);
  EXPECT_LT(First("out-of-frame turned").seen_share, 0.75);
  for (const char* whole : {"arm", "player", "lens k1=-0.3", "elevation 15", "elevation 45"}) {
    EXPECT_EQ(First(whole).seen_share, 1.0) << whole;
    for (const auto& side : First(whole).sides) EXPECT_FALSE(side.empty()) << whole;
  }
  // Without a lens a side is straight; under k1 = -0.3 a long side (y = 0, 294 px below the
  // centre at its middle) bows towards the centre by about f y (k1 (x^2 + y^2) - k1 y^2) at its
  // ends: some 26 px.
  const auto bow = [](const std::vector<Eigen::Vector2d>& side) {
    return FromChord(side[side.size() / 2], side.front(), side.back());
  };
  EXPECT_LT(bow(First("arm").sides[0]), 0.01);
  EXPECT_GT(bow(First("lens k1=-0.3").sides[0]), 20.0);
  EXPECT_LT(bow(First("lens k1=-0.3").sides[0]), 32.0);
}

TEST(HardSuite, ASidesErrorIsItsLargestDistanceFromTheFoundLine) {
  const HardFrame& arm = First("arm");
  estimator::TableRegion table;
  // The found corners where the true sides meet: no error; one side moved out by 3 px: 3 px.
  for (int k = 0; k < 4; ++k) {
    table.corners[k] = arm.sides[(k + 3) % 4].back();
  }
  for (const double e : SideErrorsPx(arm, table)) EXPECT_LT(e, 0.05);
  table.corners[0].y() += 3.0;  // side 0 is the image's bottom edge (y up the table)
  table.corners[1].y() += 3.0;
  const std::array<double, 4> moved = SideErrorsPx(arm, table);
  EXPECT_NEAR(moved[0], 3.0, 0.05);
  EXPECT_LT(moved[2], 0.05);
}

// Issue 45's acceptance where it is met today (docs/benchmarks/detection/hard_suite_report.md):
// every side within 2 px with an arm or a player across the table, with a third of it out of
// frame at one end, and from 20 and 30 degrees; recall 98 % or more from 30 degrees. Not yet met,
// so not held: the turned camera (4 of 6), the barrel lens (25 px: the finder fits straight
// sides), 15 degrees (4 of 6) and recall from 15 and 20 degrees (86 and 92 %).
TEST(HardSuite, TheTableIsFoundWhereItIsNotWhole) {
  DetectionBenchmarkOptions options;
  options.read_image = [](const std::string&) -> cv::Mat { throw std::logic_error("rendered"); };
  const HardSuiteResult result = RunHardSuite(Suite(), options);
  std::map<std::string, std::vector<const FrameScore*>> by_case;
  for (std::size_t i = 0; i < result.conditions.size(); ++i) {
    const std::string& c = result.conditions[i];
    by_case[c].push_back(&result.detection.frames[i]);
    if (c == "arm" || c == "player" || c == "out-of-frame end" || c == "elevation 20" ||
        c == "elevation 30") {
      EXPECT_TRUE(SidesWithin(result, i)) << result.detection.frames[i].file;
    }
  }
  EXPECT_GE(Total(by_case["elevation 30"]).recall, 0.98);
  EXPECT_GE(Total(by_case["elevation 45"]).recall, 0.98);
}

}  // namespace
}  // namespace billiard::bench
