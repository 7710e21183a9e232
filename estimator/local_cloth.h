// The cloth's colour at one place and how far a pixel is from it, ignoring what light does to the
// cloth: the "not cloth" whose compact blobs give the detector the balls' scale
// (ball_detector.cc). Internal to the estimator's detector.
#pragma once

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>

namespace billiard::estimator::internal {

// Ballness terms. Brightness s is relative to the local cloth (1 = cloth): shadows down to
// kDarkStart and light up to kBrightStart are still cloth; the across-hue term saturates at
// kAcrossNoise times the cloth's own spread (but never below kMinAcross, so a clean synthetic
// cloth does not make every pixel a ball).
inline constexpr float kDarkStart = 0.45f, kDarkRamp = 0.2f;
inline constexpr float kBrightStart = 1.25f, kBrightRamp = 0.2f;
inline constexpr float kAcrossNoise = 4.0f, kMinAcross = 0.2f;

// The cloth colour at one place, ready for Ballness().
struct LocalCloth {
  cv::Vec3f unit;    // cloth colour direction
  float inv_norm;    // 1 / |cloth colour|
  float inv_across;  // 1 / across-hue distance at which ballness saturates
};

inline LocalCloth MakeLocalCloth(const cv::Vec3f& colour, double noise) {
  const float norm = std::max(1e-3f, static_cast<float>(cv::norm(colour)));
  const float across = std::max(kMinAcross, static_cast<float>(kAcrossNoise * noise));
  return {colour / norm, 1.0f / norm, 1.0f / across};
}

// Relative brightness along the cloth colour and relative distance across it.
inline void Decompose(const cv::Vec3f& c, const LocalCloth& cloth, float* along, float* across) {
  const float a = c.dot(cloth.unit);
  const cv::Vec3f perpendicular = c - a * cloth.unit;
  *along = a * cloth.inv_norm;
  *across = std::sqrt(perpendicular.dot(perpendicular)) * cloth.inv_norm;
}

// How far from cloth, unclipped: 0 for anything the cloth and its light can look like, 1 at the
// threshold of a ball, more for strong colours.
inline float Contrast(float along, float across, const LocalCloth& cloth) {
  return std::max({0.0f, across * cloth.inv_across, (kDarkStart - along) * (1.0f / kDarkRamp),
                   (along - kBrightStart) * (1.0f / kBrightRamp)});
}

inline float Ballness(const cv::Vec3f& c, const LocalCloth& cloth) {
  float s, e;
  Decompose(c, cloth, &s, &e);
  return std::min(1.0f, Contrast(s, e, cloth));
}

}  // namespace billiard::estimator::internal
