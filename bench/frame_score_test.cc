// A frame's detections scored against its labels: one to one, nearest pairs first, within
// max(8 px, 0.6 R), ignored balls counting neither way; the totals over the frame; and the
// table found against the labelled playing surface.
#include "bench/frame_score.h"

#include <gtest/gtest.h>

#include <cmath>

#include "bench/detection_report.h"

namespace billiard::bench {
namespace {

estimator::BallDetection At(double u, double v) { return {Eigen::Vector2d(u, v), 10.0, 0.9}; }

TEST(FrameScore, ScoresOneToOneNearestFirstWithinTheGate) {
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

// A found side's error is the distance of the labelled side's ends from its line, whatever corner
// the table finder starts at and whichever way it goes round; only what the frame shows counts.
// The found corner 1 is 4 px below the labelled one: side 0's line turns by atan(4 / 400), so
// the labelled corner 1 is 4 cos(that) px from it, and the frame's edge at x = 300 half that.
TEST(FrameScore, TableSideErrorAtTheLabelledEndsInTheFrame) {
  LabelledFrame frame;
  frame.corners = {{{100, 100}, {500, 100}, {500, 300}, {100, 300}}};
  estimator::TableRegion table;
  // Found from the labelled corner 2, the other way round.
  table.corners = {{{500, 300}, {500, 104}, {100, 100}, {100, 300}}};
  const double cosine = 400 / std::hypot(400.0, 4.0);
  EXPECT_NEAR(TableSideError(frame, table, {640, 480}), 4 * cosine, 1e-9);
  // A frame 301 px wide: side 1 is out of it, side 0 is seen up to x = 300.
  EXPECT_NEAR(TableSideError(frame, table, {301, 480}), 2 * cosine, 1e-9);
  frame.unseen_side = 0;
  EXPECT_NEAR(TableSideError(frame, table, {640, 480}), 0.0, 1e-9);
}

}  // namespace
}  // namespace billiard::bench
