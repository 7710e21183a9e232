#include "estimator/ball_features.h"

#include <algorithm>
#include <cmath>

#include "estimator/ball_pixels.h"

namespace billiard::estimator {

namespace {

// Nearly the whole ball, inside the blur of its outline (ball_identity.cc's kLimbRadii).
constexpr double kFeatureRadii = 0.9;

struct Pixel {
  cv::Vec3f lab;
  double rho;  // distance from the centre over kFeatureRadii of the radius: 0..1
};

std::vector<Pixel> ReadPixels(const cv::Mat& bgr, const BallDetection& ball,
                              const cv::Vec3f& gain) {
  std::vector<cv::Vec3f> colours;
  std::vector<double> radii;
  ForEachPixelWithin(bgr, ball, kFeatureRadii, [&](const cv::Vec3f& p, double r) {
    colours.push_back(p);
    radii.push_back(r / (kFeatureRadii * ball.radius_px));
  });
  const std::vector<cv::Vec3f> lab = ToLab(colours, gain);
  std::vector<Pixel> pixels;
  for (std::size_t i = 0; i < lab.size(); ++i) pixels.push_back({lab[i], radii[i]});
  return pixels;
}

// Adds `weight` to the hue histogram at `hue` (radians), split between its two nearest bins.
void AddHue(double hue, float weight, float* bins) {
  const double at = (hue + M_PI) / (2 * M_PI) * kHueBins - 0.5;
  const double below = std::floor(at);
  const float upper = static_cast<float>(at - below);
  const int b = (static_cast<int>(below) + kHueBins) % kHueBins;
  bins[b] += weight * (1 - upper);
  bins[(b + 1) % kHueBins] += weight * upper;
}

float MedianOf(std::vector<float> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// The median colour's four features, from the coloured pixels (none: zeros).
void MedianColourFeatures(const std::vector<cv::Vec3f>& coloured, float* out) {
  if (coloured.empty()) return;
  std::vector<float> l, a, b, saturation;
  for (const cv::Vec3f& p : coloured) {
    const float lightness = std::max(p[0], 1.0f);
    l.push_back(p[0]);
    a.push_back(p[1] / lightness);
    b.push_back(p[2] / lightness);
    saturation.push_back(static_cast<float>(Chroma(p)) / lightness);
  }
  out[0] = MedianOf(l) / 100;
  out[1] = MedianOf(a);
  out[2] = MedianOf(b);
  out[3] = MedianOf(saturation);
}

}  // namespace

std::vector<float> BallFeatures(const cv::Mat& bgr, const BallDetection& ball,
                                const cv::Vec3f& gain) {
  std::vector<float> features(kBallFeatureCount, 0.0f);
  const std::vector<Pixel> pixels = ReadPixels(bgr, ball, gain);
  if (pixels.empty()) return features;
  float* hues = features.data();
  float* shares = hues + kHueBins;  // white, black, plain, coloured, dark
  float* rings = shares + 5;
  std::vector<float> ring_count(kRings, 0.0f);
  std::vector<cv::Vec3f> coloured;
  const float unit = 1.0f / static_cast<float>(pixels.size());
  for (const Pixel& p : pixels) {
    const bool grey = Chroma(p.lab) < kGreyChroma;
    const bool plain = Plain(p.lab);
    const int ring = std::min(kRings - 1, static_cast<int>(p.rho * kRings));
    shares[0] += unit * (grey && p.lab[0] >= kWhiteLightness);
    shares[1] += unit * (grey && p.lab[0] <= kBlackLightness);
    shares[2] += unit * plain;
    shares[4] += unit * (p.lab[0] < kBlackLightness);
    ring_count[ring] += 1;
    rings[ring] += plain;
    if (plain) continue;
    shares[3] += unit;
    coloured.push_back(p.lab);
    AddHue(std::atan2(p.lab[2], p.lab[1]), unit, hues);
  }
  for (int r = 0; r < kRings; ++r) rings[r] = ring_count[r] > 0 ? rings[r] / ring_count[r] : 0;
  MedianColourFeatures(coloured, rings + kRings);
  return features;
}

}  // namespace billiard::estimator
