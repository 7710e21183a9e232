// The detection benchmark: how detections are scored against labels (one to one, nearest pairs
// first, within max(8 px, 0.6 R), ignored balls counting neither way), how a malformed
// labels.json is refused, and the synthetic suite held to the bounds (rendered frames,
// whose truth is exact).
#include "bench/detection_benchmark.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "bench/detection_suite.h"
#include "sim/params/parameter_sets.h"

namespace billiard::bench {
namespace {

estimator::BallDetection At(double u, double v) { return {Eigen::Vector2d(u, v), 10.0, 0.9}; }

TEST(DetectionBenchmark, ScoresOneToOneNearestFirstWithinTheGate) {
  LabelledFrame frame;
  frame.balls = {{100, 100}, {130, 100}, {300, 300}};
  frame.ignored = {{500, 50}};
  frame.radius_px = 20;  // gate max(8, 12) = 12 px
  EXPECT_EQ(MatchDistancePx(20), 12.0);
  EXPECT_EQ(MatchDistancePx(5), 8.0);
  // One detection 1 px from the first label and a second 1.4 px from it (the nearer takes it, the
  // other is false), one exactly at the gate from the first label (not within: false), one 11 px
  // from the third label, one far from anything, one on the ignored ball (neither way).
  const FrameScore score = ScoreFrame(
      frame, {At(101, 100), At(112, 100), At(311, 300), At(600, 600), At(502, 51), At(99, 99)});
  EXPECT_EQ(score.labels, 3);
  EXPECT_EQ(score.found, 2);
  EXPECT_EQ(score.false_detections, 3);
  ASSERT_EQ(score.missed.size(), 1u);
  EXPECT_EQ(score.missed[0], Eigen::Vector2d(130, 100));
  ASSERT_EQ(score.centre_errors.size(), 2u);
  EXPECT_NEAR(score.centre_errors[0], 1.0, 1e-12);
  EXPECT_NEAR(score.centre_errors[1], 11.0, 1e-12);
  EXPECT_TRUE(score.detection_matched[4]) << "the ignored ball's detection counts neither way";

  const Totals totals = Total({&score});
  EXPECT_DOUBLE_EQ(totals.recall, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(totals.precision, 2.0 / 5.0);
  EXPECT_NEAR(totals.median_error_px, 11.0, 1e-12);
}

TEST(DetectionBenchmark, AMalformedLabelsFileIsRefusedNamingTheEntry) {
  const std::string dir = std::filesystem::temp_directory_path() / "billiard_labels_test";
  std::filesystem::create_directories(dir);
  const auto refusal = [&](const std::string& json) {
    std::ofstream(dir + "/labels.json") << json;
    try {
      LoadLabelledSet(dir);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(refusal("{").find("not JSON"), std::string::npos);
  EXPECT_NE(refusal("{\"a.png\": {\"balls\": [[1]], \"ball_radius_px\": 5}}").find("'a.png'"),
            std::string::npos);
  EXPECT_NE(refusal("{\"a.png\": {\"balls\": []}}").find("ball_radius_px"), std::string::npos);
  EXPECT_NE(refusal("{\"a.png\": {\"balls\": [], \"ball_radius_px\": 5, \"view\": \"side\"}}")
                .find("view"),
            std::string::npos);
  EXPECT_NE(refusal("{\"_note\": 1}").find("no frame"), std::string::npos);
  std::ofstream(dir + "/labels.json")
      << "{\"_note\": \"x\", \"b.png\": {\"balls\": [[1, 2]], \"in_pocket\": [[3, 4]], "
         "\"ignore\": [[5, 6]], \"ball_radius_px\": 7.5, \"view\": \"oblique\"}}";
  const auto frames = LoadLabelledSet(dir);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].file, "b.png");
  EXPECT_EQ(frames[0].ignored.size(), 2u);
  EXPECT_EQ(frames[0].view, "oblique");
  std::filesystem::remove_all(dir);
  EXPECT_THROW(LoadLabelledSet(dir), std::invalid_argument);
}

// The bounds on the synthetic suite: overhead views 98 % recall and precision, oblique
// 90 % recall and 95 % precision, median centre error 1.5 px (0.15 px here: the truth is exact).
TEST(DetectionBenchmark, TheSyntheticSuiteWithinTheBounds) {
  const auto frames = RenderDetectionSuite(params::LoadParameters("pool"));
  ASSERT_EQ(frames.size(), 30u);
  DetectionBenchmarkOptions options;
  const DetectionBenchmarkResult result = RunDetectionBenchmark("synthetic", frames, options);
  std::vector<const FrameScore*> overhead, oblique;
  for (const FrameScore& f : result.frames) (f.view == "overhead" ? overhead : oblique).push_back(&f);
  const Totals o = Total(overhead), q = Total(oblique);
  std::fprintf(stderr, "synthetic: overhead %d/%d, %d false; oblique %d/%d, %d false\n", o.found,
               o.labels, o.false_detections, q.found, q.labels, q.false_detections);
  EXPECT_GE(o.recall, 0.98);
  EXPECT_GE(o.precision, 0.98);
  EXPECT_GE(q.recall, 0.90);
  EXPECT_GE(q.precision, 0.95);
  EXPECT_LT(Total(overhead).median_error_px, 0.15);
  EXPECT_LT(Total(oblique).median_error_px, 0.15);
  // Frame by frame too: the burgundy overhead rack's scale, measured 12 % small before the larger
  // scales were tried (ball_detector.cc), put its outlines inside its balls, 3.7 px off.
  for (const FrameScore& f : result.frames) {
    ASSERT_FALSE(f.centre_errors.empty()) << f.file;
    EXPECT_LT(Total({&f}).median_error_px, 1.0) << f.file;
  }
}

}  // namespace
}  // namespace billiard::bench
