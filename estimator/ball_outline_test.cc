// A ball's outline on synthetic frames whose centres are known exactly: isolated balls of every
// colour to a tenth of a pixel (RMS) from a guess a third of a radius off, a ball in a touching
// row, one half hidden by a cushion, one blurred; nothing where there is no ball.
#include "estimator/ball_outline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <random>

#include "estimator/testing/synthetic_table.h"

namespace billiard::estimator {
namespace {

using testing::DrawTable;
using testing::SyntheticBall;

constexpr double kRadius = 13.1;
constexpr double kMinEdge = 3.0;  // L*a*b* units per pixel: a few times the frames' noise
const cv::Size kSize(400, 300);
const cv::Rect kCloth(20, 20, 360, 260);

const std::vector<cv::Vec3d> kColours = {{30, 30, 200},  {235, 235, 235}, {20, 20, 25},
                                         {200, 120, 20}, {20, 180, 230},  {150, 120, 230}};

TEST(BallOutline, FindsAnIsolatedBallOfEveryColourFromAGuessOff) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> fraction(0.0, 1.0);
  double squares = 0;
  int count = 0;
  for (const cv::Vec3d& colour : kColours) {
    const Eigen::Vector2d centre(150 + 10 * fraction(rng), 140 + 10 * fraction(rng));
    const cv::Mat frame = DrawTable({{centre, colour}}, kRadius, kSize, kCloth, 4.0, 7);
    const double angle = 2 * M_PI * fraction(rng);
    const Eigen::Vector2d guess = centre + kRadius / 3 * Eigen::Vector2d(std::cos(angle),
                                                                         std::sin(angle));
    const auto outline = FitBallOutline(LabImage(frame), guess, 1.1 * kRadius, kMinEdge);
    ASSERT_TRUE(outline) << "colour " << colour;
    EXPECT_LT((outline->centre - centre).norm(), 0.15) << "colour " << colour;
    EXPECT_NEAR(outline->radius, kRadius, 0.6) << "colour " << colour;
    EXPECT_GE(outline->supporting_rays, kOutlineRays * 9 / 10) << "colour " << colour;
    EXPECT_LT(outline->largest_gap, 0.5) << "colour " << colour;
    squares += (outline->centre - centre).squaredNorm();
    ++count;
  }
  EXPECT_LT(std::sqrt(squares / count), 0.1);
}

TEST(BallOutline, FindsABallInATouchingRow) {
  // Five balls touching in a row; the middle one has neighbours on two sides.
  std::vector<SyntheticBall> row;
  for (int i = 0; i < 5; ++i) {
    row.push_back({{100.3 + 2 * kRadius * i, 150.6}, kColours[i % kColours.size()]});
  }
  const cv::Mat frame = DrawTable(row, kRadius, kSize, kCloth, 3.0, 8);
  for (const SyntheticBall& ball : row) {
    const auto outline = FitBallOutline(LabImage(frame), ball.centre + Eigen::Vector2d(2, -1),
                                        kRadius, kMinEdge);
    ASSERT_TRUE(outline) << ball.centre.transpose();
    EXPECT_LT((outline->centre - ball.centre).norm(), 0.3) << ball.centre.transpose();
  }
}

TEST(BallOutline, FindsABallHalfHiddenAndABlurredOne) {
  const Eigen::Vector2d centre(200.4, 150.2);
  cv::Mat frame = DrawTable({{centre, kColours[3]}}, kRadius, kSize, kCloth, 3.0, 9);
  // A cushion over its lower half (everything below the centre's row, the rail's colour).
  cv::Mat hidden = frame.clone();
  cv::rectangle(hidden, cv::Rect(0, 151, kSize.width, kSize.height), cv::Scalar(70, 40, 30),
                cv::FILLED);
  const auto half = FitBallOutline(LabImage(hidden), centre, kRadius, kMinEdge);
  ASSERT_TRUE(half);
  EXPECT_LT((half->centre - centre).norm(), 1.0);
  EXPECT_LT(half->supporting_rays, kOutlineRays * 3 / 4);  // the hidden half has no outline
  // A horizontal smear over 5 px.
  cv::Mat blurred;
  cv::filter2D(frame, blurred, -1, cv::Mat::ones(1, 5, CV_32F) / 5.0);
  const auto smeared = FitBallOutline(LabImage(blurred), centre, kRadius, kMinEdge);
  ASSERT_TRUE(smeared);
  EXPECT_LT((smeared->centre - centre).norm(), 0.3);
}

TEST(BallOutline, NoOutlineWhereThereIsNoBall) {
  const cv::Mat cloth = DrawTable({}, kRadius, kSize, kCloth, 3.0, 10);
  const auto nothing = FitBallOutline(LabImage(cloth), {200, 150}, kRadius, kMinEdge);
  EXPECT_TRUE(!nothing || nothing->supporting_rays < kOutlineRays / 4);
  EXPECT_FALSE(FitBallOutline(LabImage(cloth), {200, 150}, 0.0, kMinEdge));
  // At the frame's edge, rays leave the image: no outline, no crash.
  EXPECT_FALSE(FitBallOutline(LabImage(cloth), {-50, -50}, kRadius, kMinEdge));
}

}  // namespace
}  // namespace billiard::estimator
