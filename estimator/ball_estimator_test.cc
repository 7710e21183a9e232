// The estimator's refusals: frames it cannot take. Its accuracy on rendered shots is measured in
// bench/estimator_benchmark_test.cc.
#include "estimator/ball_estimator.h"

#include <gtest/gtest.h>

#include "sim/params/parameter_sets.h"
#include "sim/render/table_renderer.h"

namespace billiard::estimator {
namespace {

const physics::ModelParameters& Pool() {
  static const physics::ModelParameters p = params::LoadParameters("pool");
  return p;
}

TEST(BallEstimator, RefusesEmptyMisSizedAndBackwardFrames) {
  const camera::CameraModel camera = camera::CameraModel::Overhead(Pool().table, 640, 360);
  BallEstimator estimator(camera, Pool());
  const cv::Mat frame = render::TableRenderer(camera, Pool()).Render({}, 0.0);
  EXPECT_FALSE(estimator.Process(cv::Mat(), 0.0));
  EXPECT_FALSE(estimator.Process(cv::Mat(100, 100, CV_8UC3, cv::Scalar(0, 0, 0)), 0.0));
  EXPECT_TRUE(estimator.Process(frame, 1.0));
  EXPECT_FALSE(estimator.Process(frame, 0.5));
  EXPECT_TRUE(estimator.Balls().empty());
}

}  // namespace
}  // namespace billiard::estimator
