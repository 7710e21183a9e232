// The hard suite's cases held to issue 45's acceptance on their rendered truth: with an arm, a
// hand and a cue, or a player leaning in across an overhead table, every side of the table within
// 2 px and every ball more than half seen found, nothing false; from 20 and 45 degrees above the
// cloth, the same; with a long side out of the frame, the table completed and the balls found.
#include "bench/hard_suite.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "bench/hard_suite_report.h"
#include "sim/params/parameter_sets.h"

namespace billiard::bench {
namespace {

// The case's six frames rendered and run through the detector.
HardSuiteResult RunCase(const std::string& condition) {
  const std::vector<HardFrame> frames =
      RenderHardSuite(params::LoadParameters("pool"), 2026, condition);
  EXPECT_EQ(frames.size(), 6u);
  return RunHardSuite(frames, {});
}

// Every side within tolerance, every ball more than half seen found, nothing false.
void ExpectWholeTableAndEveryBall(const HardSuiteResult& result) {
  for (std::size_t i = 0; i < result.detection.frames.size(); ++i) {
    const FrameScore& f = result.detection.frames[i];
    std::fprintf(stderr, "%s: %d of %d found, %d false\n", f.file.c_str(), f.found, f.labels,
                 f.false_detections);
    EXPECT_TRUE(SidesWithin(result, i)) << f.file;
    EXPECT_EQ(f.found, f.labels) << f.file;
    EXPECT_EQ(f.false_detections, 0) << f.file;
  }
}

TEST(HardSuite, AnArmAcrossTheTableHidesNoSideAndNoBall) {
  ExpectWholeTableAndEveryBall(RunCase("arm"));
}

// The blue cloth's rack: its blue balls and their shadows break the rack's not-cloth into pieces
// the size of a small ball, which outweighed the cue ball lying apart in the first scale (7.9 px
// for 13.4), and 10 of the 16 balls were lost. No 9-ft table is that large for its balls
// (ball_scale.h's LeastPlausibleScale).
TEST(HardSuite, APlayerLeaningInHidesNoSideAndNoBall) {
  ExpectWholeTableAndEveryBall(RunCase("player"));
}

// From 20 degrees above the cloth, over a rack, each short side's outline turned the corner onto
// the near side, and the lens estimate took the L for a barrel's bow (k1 about -0.7): the table
// found 25 to 35 px off, none of its balls. A lens now straightens every side or is none
// (lens_estimate.h). And every ball more than half seen is found: against the far cushion, its
// centre seen above the cushion's foot (ball_placement.h's GroundPoint), and half behind the
// near cushion (ball_outline.h: judged on the half in view).
TEST(HardSuite, FromTwentyDegreesEverySideWithinTwoPixelsAndEveryBallFound) {
  const HardSuiteResult result = RunCase("elevation 20");
  ExpectWholeTableAndEveryBall(result);
  for (const FrameScore& f : result.detection.frames) {
    ASSERT_TRUE(f.table) << f.file << ": " << f.failure;
    EXPECT_TRUE(f.table->lens.IsPinhole()) << f.file;
  }
}

// From 45 degrees, the near cushion is seen from behind: the cloth's outline runs along its back
// by the rail, and its nose is a faint line inside. Where a ball against it cut the outline, the
// outline's best supported line bridged the back and the nose (turned 0.027 rad); the back's own
// stretch was confirmed and dropped again for want of a nose met along the side (the faint line
// was not counted as one), and the near side was left 23.4 px off. A faint nose confirms it now
// (table_finder.cc's CushionNoses).
TEST(HardSuite, FromFortyFiveDegreesEverySideWithinTwoPixelsAndEveryBallFound) {
  ExpectWholeTableAndEveryBall(RunCase("elevation 45"));
}

// A third of the table out of the frame at one end: completed across it (table_partial.h), every
// side in the frame within 2 px. Over the blue rack, with no ball lying apart, every piece of
// not-cloth was smaller than the table allows (its blue balls break the rack up) and the balls
// were looked for at 7.9 px for 13.4: 12 of 15 found. The completed table's least scale now holds
// too (ball_detector.h's LeastPlausibleScale), and pieces that all fall short of it give no scale
// (the table's own is taken): 15 of 15. One ball at most a frame is missed (the dark green one
// the border cuts on the green cloth), nothing false.
TEST(HardSuite, ATableWithAnEndOutIsCompletedEverySideWithinTwoPixels) {
  constexpr int kMostMissed = 1;
  const HardSuiteResult result = RunCase("out-of-frame end");
  for (std::size_t i = 0; i < result.detection.frames.size(); ++i) {
    const FrameScore& f = result.detection.frames[i];
    ASSERT_TRUE(f.table) << f.file << ": " << f.failure;
    EXPECT_GE(f.table->side_out_of_frame, 0) << f.file;
    EXPECT_TRUE(SidesWithin(result, i)) << f.file;
    EXPECT_GE(f.found, f.labels - kMostMissed) << f.file;
    EXPECT_EQ(f.false_detections, 0) << f.file;
  }
}

// The camera turned 12 degrees with a third of the table out: the border crosses the table, and
// the seen cloth, a trapezoid, was read as an oblique view of a whole table; the balls' scale,
// wrong by half at the border, lost 7 to 9 of each rack's 12 balls that lie against it. Completed
// across its long side (table_partial.h), each frame finds all but at most one of them (the one
// the border cuts most), nothing false.
TEST(HardSuite, ATableTurnedWithALongSideOutIsCompletedAndItsBallsFound) {
  constexpr int kMostMissed = 1;
  const HardSuiteResult result = RunCase("out-of-frame turned");
  for (const FrameScore& f : result.detection.frames) {
    ASSERT_TRUE(f.table) << f.file << ": " << f.failure;
    EXPECT_GE(f.table->side_out_of_frame, 0) << f.file;
    EXPECT_EQ(f.table->view, estimator::TableView::kOverhead) << f.file;
    EXPECT_GE(f.found, f.labels - kMostMissed) << f.file;
    EXPECT_EQ(f.false_detections, 0) << f.file;
  }
}

}  // namespace
}  // namespace billiard::bench
