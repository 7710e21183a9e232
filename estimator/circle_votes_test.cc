// The circle votes on synthetic frames: a peak at every ball's centre, isolated or in a touching
// triangle (a rack), whose support is the share of its outline there; the balls' scale from their
// outlines, a pocket and half a ball among them, and from the table's size.
#include "estimator/circle_votes.h"

#include <gtest/gtest.h>

#include <cmath>

#include "estimator/ball_outline.h"
#include "estimator/ball_scale.h"
#include "estimator/lab_image.h"
#include "estimator/table_finder.h"
#include "estimator/testing/synthetic_table.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"

namespace billiard::estimator {
namespace {

using testing::DrawTable;
using testing::SyntheticBall;

constexpr double kRadius = 12.0;
const cv::Size kSize(640, 360);
const cv::Rect kCloth(20, 20, 600, 320);  // not 2:1, and the scale does not mind

// A triangle of touching balls (a rack of `rows` rows) and isolated balls.
std::vector<SyntheticBall> RackAndStrays(int rows) {
  std::vector<SyntheticBall> balls;
  const cv::Vec3d colours[] = {{30, 30, 200}, {20, 180, 230}, {20, 20, 25}, {150, 120, 230}};
  int k = 0;
  for (int row = 0; row < rows; ++row) {
    for (int i = 0; i <= row; ++i) {
      const Eigen::Vector2d centre(420 + row * std::sqrt(3.0) * kRadius,
                                   180 + (2 * i - row) * kRadius);
      balls.push_back({centre, colours[k++ % 4]});
    }
  }
  balls.push_back({{120.4, 100.7}, {235, 235, 235}});
  balls.push_back({{200.2, 260.1}, {200, 120, 20}});
  return balls;
}

TEST(CircleVotes, APeakAtEveryBallIsolatedOrInARack) {
  const std::vector<SyntheticBall> balls = RackAndStrays(4);
  const cv::Mat frame = DrawTable(balls, kRadius, kSize, kCloth, 3.0, 1);
  const TableSearch search = FindTable(frame);
  ASSERT_TRUE(search.table) << search.reason;
  const BallScale scale{search.table->inverse_depth, kRadius};
  const std::vector<CircleVote> peaks = VoteForCircles(frame, *search.table, scale, 0.08);
  for (const SyntheticBall& ball : balls) {
    const CircleVote* nearest = nullptr;
    for (const CircleVote& peak : peaks) {
      if (!nearest || (peak.pixel - ball.centre).norm() < (nearest->pixel - ball.centre).norm()) {
        nearest = &peak;
      }
    }
    ASSERT_NE(nearest, nullptr);
    EXPECT_LT((nearest->pixel - ball.centre).norm(), 2.0) << ball.centre.transpose();
    EXPECT_GT(nearest->support, 0.25) << ball.centre.transpose();
  }
  // The isolated balls' outlines are whole: nearly all of it votes.
  for (const CircleVote& peak : peaks) {
    if ((peak.pixel - balls[balls.size() - 1].centre).norm() < 2.0) {
      EXPECT_GT(peak.support, 0.6);
    }
  }
  // Strongest first.
  for (std::size_t i = 1; i < peaks.size(); ++i) {
    EXPECT_GE(peaks[i - 1].support, peaks[i].support);
  }
}

TEST(CircleVotes, AtFullResolutionTheShareOfTheOutlineThereWhereverTheBall) {
  // Its share of the outline: all of an isolated ball's, half of a ball cut by the frame's edge,
  // none on bare cloth, and in a rack as much as the reduced resolution's votes give it (about
  // half: touching balls of like lightness have faint creases) or more. The black in the middle
  // of a rendered rack, with contact shadows, is BallDetector's test.
  std::vector<SyntheticBall> balls = RackAndStrays(4);
  const cv::Mat frame = DrawTable(balls, kRadius, kSize, kCloth, 3.0, 1);
  const TableSearch search = FindTable(frame);
  ASSERT_TRUE(search.table) << search.reason;
  const double noise = EdgeNoise(LabImage(frame, search.table->Bounds()), *search.table);
  const Eigen::Vector2d isolated = balls.back().centre;
  EXPECT_NEAR(FullResolutionSupport(frame, isolated, kRadius, noise), 1.0, 0.15);
  EXPECT_LT(FullResolutionSupport(frame, {300.0, 300.0}, kRadius, noise), 0.08);
  const cv::Mat cut = frame(cv::Rect(cvRound(isolated.x()), 0, 300, kSize.height)).clone();
  EXPECT_NEAR(FullResolutionSupport(cut, isolated - Eigen::Vector2d(cvRound(isolated.x()), 0),
                                    kRadius, noise),
              0.5, 0.12);
  const BallScale scale{search.table->inverse_depth, kRadius};
  const std::vector<CircleVote> peaks = VoteForCircles(frame, *search.table, scale, 0.0);
  for (int i = 0; i < 10; ++i) {  // the rack
    const Eigen::Vector2d centre = balls[i].centre;
    double coarse = 0;
    for (const CircleVote& peak : peaks) {
      if ((peak.pixel - centre).norm() < 2.0) coarse = std::max(coarse, peak.support);
    }
    const double fine = FullResolutionSupport(frame, centre, kRadius, noise);
    EXPECT_GT(fine, 0.45) << centre.transpose();
    EXPECT_GT(fine, coarse - 0.02) << centre.transpose();
  }
}

TEST(BallScale, MostOutlinesAgreeOnTheScaleWhateverTheOddOnes) {
  const cv::Mat frame = DrawTable({}, kRadius, kSize, kCloth, 3.0, 2);
  const TableSearch search = FindTable(frame);
  ASSERT_TRUE(search.table) << search.reason;
  const TableRegion& table = *search.table;
  // Flat view: the inverse depth is 1 everywhere, so the scale is the radius.
  std::vector<BallOutline> outlines;
  for (const double r : {12.1, 11.9, 12.0, 12.3}) outlines.push_back({{300, 180}, r, 32});
  outlines.push_back({{200, 180}, 25.0, 32});  // a pocket
  outlines.push_back({{250, 180}, 6.0, 32});   // a highlight
  outlines.push_back({{350, 180}, 9.0, 12});   // half a ball, poorly seen
  const auto scale = ScaleFromOutlines(table, outlines);
  ASSERT_TRUE(scale);
  EXPECT_NEAR(scale->radius_at_centre, 12.0, 0.15);
  EXPECT_NEAR(scale->RadiusAt({100, 100}), 12.0, 0.3);
  // One well-seen ball outweighs a poorly seen piece of a rack.
  const auto weighed = ScaleFromOutlines(table, {{{300, 180}, 12.0, 32}, {{200, 180}, 7.0, 16}});
  ASSERT_TRUE(weighed);
  EXPECT_NEAR(weighed->radius_at_centre, 12.0, 0.3);
  EXPECT_FALSE(ScaleFromOutlines(table, {}));
  // From the table's size: its width times the ball's share of it.
  const double width_px = table.PixelsPerWidthAt(table.Centre());
  EXPECT_NEAR(ScaleFromTable(table, 0.0225).radius_at_centre, 0.0225 * width_px, 1e-9);
}

TEST(BallScale, NoTableIsLargerForItsBallsThanItsGamesLargest) {
  const cv::Mat frame = DrawTable({}, kRadius, kSize, kCloth, 3.0, 2);
  const TableSearch search = FindTable(frame);
  ASSERT_TRUE(search.table) << search.reason;
  const TableRegion& table = *search.table;
  const double width_px = table.PixelsPerWidthAt(table.Centre());
  // The ratios against the shipped parameter sets and tables: a pool ball on the 9-ft table, a
  // snooker ball on the 12-ft one.
  const auto ratio = [](const std::string& set, const std::string& table_name) {
    return params::LoadParameters(set).ball.radius / params::LoadTableSpec(table_name).width;
  };
  EXPECT_NEAR(LargestTableRatio(BallSet::kPool), ratio("pool", "pool-9ft"), 1e-4);
  EXPECT_NEAR(LargestTableRatio(BallSet::kSnooker), ratio("snooker", "snooker-12ft"), 1e-4);
  const double least = LeastPlausibleScale(table, BallSet::kPool);
  EXPECT_LT(least, LargestTableRatio(BallSet::kPool) * width_px);
  EXPECT_GT(least, 0.85 * LargestTableRatio(BallSet::kPool) * width_px);
  // Two pieces of a rack, well seen, outweigh the one ball lying apart ...
  const auto outline = [](double u, double radius, int rays) {
    BallOutline o;
    o.centre = {u, 180};
    o.radius = radius;
    o.supporting_rays = rays;
    return o;
  };
  const std::vector<BallOutline> outlines = {outline(300, 1.2 * least, 20),
                                             outline(200, 0.70 * least, 18),
                                             outline(210, 0.74 * least, 16)};
  EXPECT_NEAR(ScaleFromOutlines(table, outlines)->radius_at_centre, 0.70 * least, 0.05 * least);
  // ... but not the table's size: the ball apart is the scale.
  EXPECT_NEAR(ScaleFromOutlines(table, outlines, least)->radius_at_centre, 1.2 * least,
              1e-4 * least);
  // Where nothing is that large (the pieces of a rack with no ball apart), no scale: the table's
  // own is the better one.
  EXPECT_FALSE(ScaleFromOutlines(table, {outlines[1], outlines[2]}, least));
  EXPECT_TRUE(ScaleFromOutlines(table, {outlines[1], outlines[2]}));
}

}  // namespace
}  // namespace billiard::estimator
