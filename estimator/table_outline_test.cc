// The table's outline compared between frames, on a drawn table whose outline is known: the same
// view agrees fully, balls moved on the cloth (away from the outline) change nothing, and a
// camera moved by more than the outline's band no longer agrees.
#include "estimator/table_outline.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace billiard::estimator {
namespace {

constexpr int kWidth = 800, kHeight = 400;
// The cloth's outline, and the rail drawn around it.
const std::array<Eigen::Vector2d, 4> kCloth = {
    {{100, 80}, {700, 80}, {700, 320}, {100, 320}}};
constexpr int kRailPx = 30;

// A green cloth in a brown rail on a dark floor, shifted by `shift` [px] as a moved camera sees
// it, with a white ball at `ball`.
cv::Mat DrawTable(const cv::Point& shift, const cv::Point& ball) {
  cv::Mat frame(kHeight, kWidth, CV_8UC3, cv::Scalar(20, 25, 30));
  const cv::Point top_left(static_cast<int>(kCloth[0].x()), static_cast<int>(kCloth[0].y()));
  const cv::Point bottom_right(static_cast<int>(kCloth[2].x()), static_cast<int>(kCloth[2].y()));
  const cv::Point rail(kRailPx, kRailPx);
  cv::rectangle(frame, top_left - rail + shift, bottom_right + rail + shift, {40, 70, 120},
                cv::FILLED);
  cv::rectangle(frame, top_left + shift, bottom_right + shift, {50, 140, 40}, cv::FILLED);
  cv::circle(frame, ball + shift, 12, {235, 235, 235}, cv::FILLED, cv::LINE_AA);
  return frame;
}

TEST(TableOutline, NoneLearntAgreesWithEveryFrame) {
  EXPECT_EQ(TableOutline().Agreement(DrawTable({0, 0}, {400, 200})), 1.0);
}

TEST(TableOutline, TheSameViewAgreesWhereverTheBallsAre) {
  const TableOutline outline(DrawTable({0, 0}, {400, 200}), kCloth);
  EXPECT_NEAR(outline.Agreement(DrawTable({0, 0}, {400, 200})), 1.0, 1e-9);
  // The ball moved 150 px along the table: the band along the outline (3 px either side at about
  // 400 px across, 6 px here) sees the same pixels.
  EXPECT_NEAR(outline.Agreement(DrawTable({0, 0}, {550, 250})), 1.0, 1e-9);
}

TEST(TableOutline, ACameraMovedBeyondTheBandNoLongerAgrees) {
  const TableOutline outline(DrawTable({0, 0}, {400, 200}), kCloth);
  // 20 px both ways: every side's edge leaves the band (the corners' crossings aside).
  EXPECT_LT(outline.Agreement(DrawTable({20, 20}, {400, 200})), 0.3);
  // The nearer the view, the more it agrees: 2 px (1 px at the band's resolution) keeps every
  // edge in the band, only off its ridge.
  const double two = outline.Agreement(DrawTable({2, 2}, {400, 200}));
  const double eight = outline.Agreement(DrawTable({8, 8}, {400, 200}));
  EXPECT_GT(two, eight + 0.1);
  EXPECT_GT(two, 0.3);
}

}  // namespace
}  // namespace billiard::estimator
