// A ball's outline on synthetic frames whose centres are known exactly: isolated balls of every
// colour to a tenth of a pixel (RMS) from a guess a third of a radius off, a ball in a touching
// row, one half hidden by a cushion, one cut by the near cushion's nose, one blurred; a white
// ball with a limb as dark as the cloth, through a JPEG, centred on its chroma; nothing where
// there is no ball.
#include "estimator/ball_outline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
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

// A ball whose lower part a cushion's nose hides (a band of the cushion's colour from half a
// radius below its centre down, as a camera beyond the near rail sees it). Given the nose as an
// occluder, the hidden rays do not count: its outline is whole where it is seen (all of them
// support it), where without the occluder a third of the circle is missing (0.66 support, which
// the score's ramp from 0.45 to 0.8 reads as a doubtful ball). The fit is as good either way
// here (0.2 px: Tukey's weights drop the band's straight edge); on the rendered side view the
// vote's peak lies on the nose, and the fit needs the occluder too (ball_detector_test).
TEST(BallOutline, ABallCutByTheNearCushionIsFittedOnItsVisiblePart) {
  const Eigen::Vector2d centre(200.4, 150.2);
  cv::Mat frame = DrawTable({{centre, kColours[3]}}, kRadius, kSize, kCloth, 3.0, 10);
  const double nose = centre.y() + 0.5 * kRadius;
  cv::rectangle(frame, cv::Point(0, static_cast<int>(std::ceil(nose))),
                cv::Point(kSize.width, kSize.height), cv::Scalar(30, 80, 20), cv::FILLED);
  const Occluder near_cushion{Eigen::Vector2d::UnitY(), std::ceil(nose) - 0.5, 1.5};
  const Eigen::Vector2d guess = centre + Eigen::Vector2d(1.5, 4.0);  // a vote pulled to the nose
  const auto cut = FitBallOutline(LabImage(frame), guess, kRadius, kMinEdge, near_cushion);
  ASSERT_TRUE(cut);
  EXPECT_LT((cut->centre - centre).norm(), 0.3);
  EXPECT_LT(cut->seen_rays, kOutlineRays * 7 / 8);
  EXPECT_GE(cut->SupportedShare(), 0.9);
  const auto unaware = FitBallOutline(LabImage(frame), guess, kRadius, kMinEdge);
  ASSERT_TRUE(unaware);
  std::fprintf(stderr,
               "cut ball: %.2f px off with the nose as occluder (%.2f of its rays in view "
               "support it), %.2f px without (%.2f of all)\n",
               (cut->centre - centre).norm(), cut->SupportedShare(),
               (unaware->centre - centre).norm(), unaware->SupportedShare());
  EXPECT_LT(unaware->SupportedShare(), 0.8);
}

// A ball centred on the near cushion's nose, its upper half seen (a set's labels count it): the
// occluder's margin, which keeps the nose's own edge out of the fit, hides no part of the ball,
// so the outline is judged on the half in view, not on the whole circle as a ball mostly hidden
// is (before: 17 of 32 rays counted hidden with the margin, the whole circle asked for, a gap of
// half of it, no ball).
TEST(BallOutline, ABallHalfBehindTheNearCushionIsJudgedOnItsHalfInView) {
  const Eigen::Vector2d centre(200.4, 150.2);
  cv::Mat frame = DrawTable({{centre, kColours[3]}}, kRadius, kSize, kCloth, 3.0, 10);
  const int nose = static_cast<int>(std::ceil(centre.y()));
  cv::rectangle(frame, cv::Point(0, nose), cv::Point(kSize.width, kSize.height),
                cv::Scalar(30, 80, 20), cv::FILLED);
  const Occluder near_cushion{Eigen::Vector2d::UnitY(), nose - 0.5, 1.5};
  const auto half = FitBallOutline(LabImage(frame), centre, kRadius, kMinEdge, near_cushion);
  ASSERT_TRUE(half);
  EXPECT_LT((half->centre - centre).norm(), 0.5);
  EXPECT_LE(half->seen_rays, kOutlineRays / 2);
  EXPECT_LT(half->largest_gap, 0.5 * M_PI);
}

// A white ball shaded from its lit right to its left limb, there as dark as the cloth beside it
// (as the camera sees a ball off its axis, lit from above), drawn at 4x and averaged down (its
// outline antialiased), then through a JPEG at quality 90 (its chroma halved and blurred): the
// fastest change of colour on the dark limb lies inside the ball and moves the centre right
// (0.22 px); placed on the chroma, the centre keeps less than two thirds of that and is within
// 0.15 px of the drawn one (0.14: on the dark limb a JPEG's chroma, blurred in Cb and Cr, is less
// in L*a*b* than on the lit one, and its half-way crossing lies a little inside).
TEST(BallOutline, AWhiteBallsCentreOnItsChromaWhereItsShadedLimbMeetsTheCloth) {
  constexpr int kSupersample = 4;
  constexpr double kDarkLimb = 0.3;  // the left limb's share of white: the cloth's lightness
  const cv::Vec3b cloth(40, 110, 40);  // BGR
  const Eigen::Vector2d centre(200.3, 150.6);
  cv::Mat fine(kSize.height * kSupersample, kSize.width * kSupersample, CV_8UC3,
               cv::Scalar(cloth[0], cloth[1], cloth[2]));
  for (int y = 0; y < fine.rows; ++y) {
    for (int x = 0; x < fine.cols; ++x) {
      const Eigen::Vector2d p((x + 0.5) / kSupersample - 0.5, (y + 0.5) / kSupersample - 0.5);
      const Eigen::Vector2d d = p - centre;
      if (d.norm() > kRadius) continue;
      const double lit = kDarkLimb + (1 - kDarkLimb) * (d.x() + kRadius) / (2 * kRadius);
      const auto grey = static_cast<uchar>(std::lround(240 * lit));
      fine.at<cv::Vec3b>(y, x) = {grey, grey, grey};
    }
  }
  cv::Mat frame;
  cv::resize(fine, frame, kSize, 0, 0, cv::INTER_AREA);
  std::vector<uchar> jpeg;
  cv::imencode(".jpg", frame, jpeg, {cv::IMWRITE_JPEG_QUALITY, 90});
  const LabImage lab(cv::imdecode(jpeg, cv::IMREAD_COLOR));
  const auto outline = FitBallOutline(lab, centre + Eigen::Vector2d(1.5, -1.0), kRadius, kMinEdge);
  ASSERT_TRUE(outline);
  EXPECT_GT(outline->centre.x() - centre.x(), 0.2);  // the dark limb's edge found inside
  const Eigen::Vector2d placed = CentreOnChroma(lab, outline->centre, outline->radius, kMinEdge);
  EXPECT_LT((placed - centre).norm(), 0.15);
  EXPECT_LT((placed - centre).norm(), 2.0 / 3.0 * (outline->centre - centre).norm());
  RecordProperty("fastest_change_error_px", std::to_string((outline->centre - centre).norm()));
  RecordProperty("chroma_error_px", std::to_string((placed - centre).norm()));
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
