// Test data: the real overhead snooker photograph in the test-data directory's real-tables/
// (tests/support/test_data.h) and the centres of its 21 balls, read off the image by hand
// (about +-2 px).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace billiard::estimator::testing {

// Inside the test-data directory.
inline constexpr char kRealTablePhoto[] = "real-tables/snooker_overhead_1280x720.png";

struct HandBall {
  const char* name;  // its class (ball_class.h's name); the yellow looks orange in the warm light
  Eigen::Vector2d pixel;
};

inline std::vector<HandBall> RealTablePhotoBalls() {
  return {{"cue", {534, 575}},  {"black", {924, 373}}, {"pink", {643, 408}},
          {"blue", {746, 198}}, {"green", {255, 390}}, {"yellow", {1146, 395}},
          {"red", {237, 113}},  {"red", {395, 175}},   {"red", {539, 227}},
          {"red", {181, 268}},  {"red", {453, 361}},   {"red", {730, 275}},
          {"red", {1047, 99}},  {"red", {1049, 207}},  {"red", {1162, 193}},
          {"red", {915, 465}},  {"red", {1054, 528}},  {"red", {1072, 604}},
          {"red", {918, 576}},  {"red", {761, 596}},   {"red", {705, 535}}};
}

// The ball radius in the photo [px], measured across a few balls.
constexpr double kRealTablePhotoRadiusPx = 15.0;

}  // namespace billiard::estimator::testing
