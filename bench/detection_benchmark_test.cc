// The detection benchmark: the synthetic suite held to the bounds (rendered frames, whose
// truth is exact). How a frame is scored is frame_score_test.cc's, how labels.json is read
// labelled_set_test.cc's.
#include "bench/detection_benchmark.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "bench/detection_report.h"
#include "bench/detection_suite.h"
#include "sim/params/parameter_sets.h"

namespace billiard::bench {
namespace {

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
