// The numbers beside the balls against geometry: a lone ball's number sits at its upper right,
// clear of it; in a racked triangle of fifteen balls frozen together no number covers another
// or a ball, and each stays beside its own ball.
#include "plot/labels.h"

#include <gtest/gtest.h>

#include <cmath>

namespace billiard::plot {
namespace {

using Eigen::Vector2d;

constexpr double kRadius = 11.43;              // a pool ball at 400 px a metre
const Vector2d kDigits(13.0, 11.0);            // two digits at 11 px

bool MeetsDisc(const LabelBox& box, const Vector2d& c, double r) {
  const Vector2d nearest = c.cwiseMax(box.min).cwiseMin(box.max);
  return (nearest - c).norm() < r;
}

TEST(Labels, ALoneBallsNumberSitsAtItsUpperRight) {
  const Vector2d c(300, 200);
  const std::vector<LabelBox> boxes = PlaceLabels({{c, kDigits}}, kRadius);
  ASSERT_EQ(boxes.size(), 1u);
  EXPECT_GT(boxes[0].min.x(), c.x());
  EXPECT_LT(boxes[0].max.y(), c.y());
  EXPECT_FALSE(MeetsDisc(boxes[0], c, kRadius));
}

TEST(Labels, ARacksNumbersCoverNoNumberAndNoBall) {
  // Fifteen balls frozen together in the triangle, apex left (picture pixels, y down).
  std::vector<LabelRequest> rack;
  for (int row = 0; row < 5; ++row) {
    for (int k = 0; k <= row; ++k) {
      const Vector2d c(700 + row * 2 * kRadius * std::sqrt(3.0) / 2, 300 + (2 * k - row) * kRadius);
      rack.push_back({c, kDigits});
    }
  }
  const std::vector<LabelBox> boxes = PlaceLabels(rack, kRadius);
  ASSERT_EQ(boxes.size(), rack.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::size_t j = i + 1; j < boxes.size(); ++j) EXPECT_FALSE(boxes[i].Overlaps(boxes[j])) << i << ", " << j;
    for (const LabelRequest& ball : rack) EXPECT_FALSE(MeetsDisc(boxes[i], ball.centre, kRadius)) << i;
    // Beside its own ball: the box's nearest point within the rings' reach of its centre.
    const Vector2d c = rack[i].centre;
    const Vector2d nearest = c.cwiseMax(boxes[i].min).cwiseMin(boxes[i].max);
    EXPECT_LT((nearest - c).norm(), kRadius + 2.0 + 3 * 8.0 + 1e-9) << i;
  }
}

TEST(Labels, TheSameBallsGiveTheSamePlaces) {
  const std::vector<LabelRequest> two = {{{100, 100}, kDigits}, {{100 + 2 * kRadius, 100}, kDigits}};
  const std::vector<LabelBox> a = PlaceLabels(two, kRadius), b = PlaceLabels(two, kRadius);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].min, b[i].min);
    EXPECT_EQ(a[i].max, b[i].max);
  }
  EXPECT_FALSE(a[0].Overlaps(a[1]));
}

}  // namespace
}  // namespace billiard::plot
