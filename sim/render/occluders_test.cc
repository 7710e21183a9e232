// The occluders against geometry: a sphere's image the size the pinhole gives it, what is in
// front decided by depth (a ball over a capsule stays in view, a capsule over a ball hides it),
// and bad input refused.
#include "sim/render/occluders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "sim/params/parameter_sets.h"

namespace billiard::render {
namespace {

// Looking straight down from 2.5 m over the middle of a pool table.
camera::CameraModel Overhead() {
  return camera::CameraModel::Overhead(params::LoadParameters("pool").table, 1280, 720);
}

const cv::Vec3b kSkin{120, 160, 210};
const Eigen::Vector3d kUp = Eigen::Vector3d::UnitZ();

TEST(Occluders, ASphereCoversTheDiscThePinholeGivesIt) {
  const camera::CameraModel camera = Overhead();
  const Eigen::Vector3d centre = camera.Centre() - Eigen::Vector3d(0, 0, 1.5);
  const double radius = 0.1;
  cv::Mat frame(camera.height, camera.width, CV_8UC3, cv::Scalar(0, 0, 0));
  const cv::Mat mask = DrawOccluders(camera, {{centre, centre, radius, radius, kSkin}}, {}, kUp,
                                     0.35, &frame);
  // On the axis a sphere at distance D images as a disc of radius f R / sqrt(D^2 - R^2).
  const double disc = camera.fx * radius / std::sqrt(1.5 * 1.5 - radius * radius);
  EXPECT_NEAR(cv::sum(mask)[0] / 255.0, M_PI * disc * disc, 0.01 * M_PI * disc * disc);
  // Lit from above, its middle faces the light: its colour, unshaded.
  const cv::Vec3b middle = frame.at<cv::Vec3b>(static_cast<int>(camera.cy),
                                               static_cast<int>(camera.cx));
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(middle[k], kSkin[k], 2);
}

TEST(Occluders, WhatIsNearerTheCameraIsSeen) {
  const camera::CameraModel camera = Overhead();
  const double r = 0.028575;
  const Eigen::Vector3d ball(1.0, 0.6, r);
  const Eigen::Vector2d ball_px = camera.Project(ball);
  const double ball_radius_px = camera.fx * r / (camera.Centre().z() - r);
  const std::vector<OccludedBall> balls = {{ball, r}};
  // An arm 10 cm above the ball hides it; a cue lying on the cloth under it does not.
  const Capsule arm{{0.8, 0.6, 0.1 + r}, {1.2, 0.6, 0.1 + r}, 0.05, 0.04, kSkin};
  const Capsule cue{{0.8, 0.6, 0.005}, {1.2, 0.6, 0.005}, 0.005, 0.005, kSkin};
  cv::Mat frame(camera.height, camera.width, CV_8UC3, cv::Scalar(0, 0, 0));
  const cv::Mat over = DrawOccluders(camera, {arm}, balls, kUp, 0.35, &frame);
  EXPECT_LT(VisibleShare(camera, balls, 0, over), 0.01);
  const cv::Mat under = DrawOccluders(camera, {cue}, balls, kUp, 0.35, &frame);
  EXPECT_GT(VisibleShare(camera, balls, 0, under), 0.99);
  // Beside the ball the cue is seen.
  EXPECT_EQ(under.at<uchar>(static_cast<int>(std::lround(ball_px.y())),
                            static_cast<int>(std::lround(ball_px.x() + 2 * ball_radius_px))),
            255);
}

// Seen level with the cloth at the balls' height, a ball straight behind another of its size
// images inside the nearer one's disc: hidden whole, the nearer one seen whole.
TEST(Occluders, ABallStraightBehindAnotherIsHidden) {
  const double r = 0.028575;
  const camera::CameraModel camera = camera::CameraModel::LookingAt(
      {-1.0, 0.6, r}, {1.0, 0.6, r}, 640, 480, 0.8);
  const std::vector<OccludedBall> balls = {{{0.5, 0.6, r}, r}, {{0.7, 0.6, r}, r}};
  const cv::Mat nothing = cv::Mat::zeros(camera.height, camera.width, CV_8UC1);
  EXPECT_GT(VisibleShare(camera, balls, 0, nothing), 0.99);
  EXPECT_LT(VisibleShare(camera, balls, 1, nothing), 0.01);
}

TEST(Occluders, RefusesAFrameOfAnotherSizeAndANegativeRadius) {
  const camera::CameraModel camera = Overhead();
  cv::Mat small(10, 10, CV_8UC3);
  const Capsule c{{1, 0.5, 0.1}, {1.2, 0.5, 0.1}, 0.05, 0.05, kSkin};
  EXPECT_THROW(DrawOccluders(camera, {c}, {}, kUp, 0.35, &small), std::invalid_argument);
  cv::Mat frame(camera.height, camera.width, CV_8UC3);
  Capsule negative = c;
  negative.to_radius = -0.01;
  EXPECT_THROW(DrawOccluders(camera, {negative}, {}, kUp, 0.35, &frame), std::invalid_argument);
}

}  // namespace
}  // namespace billiard::render
