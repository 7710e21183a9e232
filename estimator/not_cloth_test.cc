// What leans over the table, on a synthetic frame whose every part is known: an arm reaching in
// across the near rail with a dark glove at its end (no darker than a ball's shadow) and a cue
// from the glove to a ball, among a rack, a row of balls along a cushion, a ball frozen to another
// cushion and a glove-dark patch of shade on open cloth. The arm and the glove are intruders;
// nothing else is, the ball the cue touches included.
#include "estimator/not_cloth.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "estimator/ball_detector.h"
#include "estimator/testing/synthetic_table.h"

namespace billiard::estimator {
namespace {

using testing::DrawTable;
using testing::SyntheticBall;

constexpr double kRadius = 13.0;
const cv::Size kSize(800, 480);
const cv::Rect kCloth(40, 40, 720, 400);
const cv::Vec3d kClothBgr(60, 140, 40);  // DrawTable's
const cv::Scalar kSkin(125, 160, 215), kCue(55, 120, 185);
// A dark glove and a patch of shade: the cloth at 0.3 of its brightness, which the ball's
// contrast (local_cloth.h) puts between a shadow's and a ball's.
const cv::Scalar kDark(0.3 * kClothBgr[0], 0.3 * kClothBgr[1], 0.3 * kClothBgr[2]);

struct Scene {
  cv::Mat frame;
  std::vector<std::pair<std::string, Eigen::Vector2d>> not_intruders;
  std::vector<std::pair<std::string, Eigen::Vector2d>> intruders;
};

Scene ArmOverTheTable() {
  Scene scene;
  std::vector<SyntheticBall> balls;
  const cv::Vec3d red(30, 30, 200), white(235, 235, 235), orange(20, 120, 230);
  const double d = 2 * kRadius, row_height = std::sqrt(3.0) * kRadius;
  // A rack of six, touching.
  for (int row = 0; row < 3; ++row) {
    for (int k = 0; k <= row; ++k) {
      const Eigen::Vector2d centre(200 + row * row_height, 220 + (k - 0.5 * row) * d);
      balls.push_back({centre, red});
      scene.not_intruders.push_back({"a ball of the rack", centre});
    }
  }
  // Four balls in a row along the left cushion, touching each other and reaching the surface's
  // edge (as a ball against a cushion does where the cushion's nose is found a pixel or two out).
  const double against = kRadius - 1.5;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector2d centre(kCloth.x + against, 150 + k * d);
    balls.push_back({centre, orange});
    scene.not_intruders.push_back({"a ball of the row along the cushion", centre});
  }
  const Eigen::Vector2d frozen(400, kCloth.y + against);
  balls.push_back({frozen, red});
  scene.not_intruders.push_back({"the ball frozen to the far cushion", frozen});
  const Eigen::Vector2d aimed(470, 240);
  balls.push_back({aimed, white});
  scene.not_intruders.push_back({"the ball the cue touches", aimed});
  scene.frame = DrawTable(balls, kRadius, kSize, kCloth, 3.0, 5);

  // The forearm from beyond the near rail, the glove at its end, the cue from the glove to the
  // ball, and a patch of shade alone on the cloth.
  const std::vector<cv::Point> arm = {{550, 480}, {630, 480}, {620, 330}, {560, 330}};
  const std::vector<cv::Point> glove = {{560, 332}, {620, 332}, {630, 290}, {550, 290}};
  cv::fillPoly(scene.frame, std::vector<std::vector<cv::Point>>{arm}, kSkin, cv::LINE_AA);
  cv::fillPoly(scene.frame, std::vector<std::vector<cv::Point>>{glove}, kDark, cv::LINE_AA);
  const Eigen::Vector2d toward = (Eigen::Vector2d(585, 300) - aimed).normalized();
  const Eigen::Vector2d tip = aimed + kRadius * toward;
  cv::line(scene.frame, {585, 300}, {static_cast<int>(tip.x()), static_cast<int>(tip.y())}, kCue,
           5, cv::LINE_AA);
  const Eigen::Vector2d shade(330, 360);
  cv::circle(scene.frame, {330, 360}, static_cast<int>(2 * kRadius), kDark, cv::FILLED,
             cv::LINE_AA);
  scene.not_intruders.push_back({"the patch of shade", shade});
  scene.intruders = {{"the forearm", {590, 400}},
                     {"the forearm at the rail", {590, 435}},
                     {"the glove", {590, 305}}};
  return scene;
}

bool At(const NotClothMap& map, const cv::Mat& image, const Eigen::Vector2d& pixel) {
  const Eigen::Vector2d p = map.ToMap(pixel);
  return image.at<uint8_t>(static_cast<int>(std::lround(p.y())),
                           static_cast<int>(std::lround(p.x()))) != 0;
}

TEST(NotCloth, TheArmAndItsGloveIntrudeAndNothingElseOnTheTableDoes) {
  const Scene scene = ArmOverTheTable();
  DetectorOptions options;
  options.ball_radius_px = kRadius;
  BallDetector detector(options);
  ASSERT_TRUE(detector.LearnTable(scene.frame)) << detector.failure();
  const NotClothMap map(scene.frame, *detector.table(), detector.cloth(),
                        NotClothMap::IntruderFactor(*detector.scale()));
  const cv::Mat intruders = map.Intruders(*detector.scale());
  for (const auto& [what, pixel] : scene.intruders) {
    EXPECT_TRUE(At(map, intruders, pixel)) << what << " at " << pixel.transpose();
  }
  for (const auto& [what, pixel] : scene.not_intruders) {
    EXPECT_FALSE(At(map, intruders, pixel)) << what << " at " << pixel.transpose();
  }
  // The not-cloth itself: the balls are in it, the open cloth and the glove (as dark as a shadow)
  // are not.
  EXPECT_TRUE(At(map, map.mask(), scene.not_intruders.front().second));
  EXPECT_FALSE(At(map, map.mask(), {700, 400}));
  EXPECT_FALSE(At(map, map.mask(), {590, 305}));
}

TEST(NotCloth, MapPixelsAndFullResolutionPixelsAreInverse) {
  cv::Mat large;
  cv::resize(ArmOverTheTable().frame, large, {}, 3, 3, cv::INTER_LINEAR);
  BallDetector detector;
  ASSERT_TRUE(detector.LearnTable(large)) << detector.failure();
  const NotClothMap map(large, *detector.table(), detector.cloth(),
                        NotClothMap::BlobFactor(*detector.table()));
  EXPECT_GT(map.factor(), 1);
  const Eigen::Vector2d full(1234.5, 678.25);
  EXPECT_LT((map.ToFull(map.ToMap(full)) - full).norm(), 1e-9);
  const int across = std::max(map.mask().cols, map.mask().rows);
  EXPECT_GE(across, kNotClothTableSize);
  EXPECT_LT(across, 2 * kNotClothTableSize);
}

}  // namespace
}  // namespace billiard::estimator
