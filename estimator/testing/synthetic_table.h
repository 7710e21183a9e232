// Test data: synthetic frames of a table whose balls' centres are known exactly, for the
// detector's tests: a noisy cloth inside a dark rail, balls drawn as Lambert-shaded spheres lit
// from above with exact anti-aliasing (8x8 samples per edge pixel).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <random>
#include <vector>

namespace billiard::estimator::testing {

struct SyntheticBall {
  Eigen::Vector2d centre;
  cv::Vec3d colour;
};

inline cv::Mat DrawTable(const std::vector<SyntheticBall>& balls, double radius, cv::Size size,
                  cv::Rect cloth_rect, double noise_sigma, unsigned seed) {
  const cv::Vec3d cloth(60, 140, 40), rail(30, 40, 70);
  cv::Mat f(size, CV_64FC3);
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      f.at<cv::Vec3d>(y, x) = cloth_rect.contains({x, y}) ? cloth : rail;
    }
  }
  const auto shade = [&](const SyntheticBall& b, double x, double y) {
    const double rho2 = ((Eigen::Vector2d(x, y) - b.centre) / radius).squaredNorm();
    return b.colour * (0.35 + 0.65 * std::sqrt(std::max(0.0, 1.0 - rho2)));
  };
  for (const SyntheticBall& b : balls) {
    for (int y = static_cast<int>(b.centre.y() - radius) - 2; y <= b.centre.y() + radius + 2; ++y) {
      for (int x = static_cast<int>(b.centre.x() - radius) - 2; x <= b.centre.x() + radius + 2;
           ++x) {
        const double d = (Eigen::Vector2d(x, y) - b.centre).norm();
        if (d > radius + 1) continue;
        cv::Vec3d& p = f.at<cv::Vec3d>(y, x);
        if (d < radius - 1) {
          p = shade(b, x, y);
          continue;
        }
        cv::Vec3d sum(0, 0, 0);
        int inside = 0;
        for (int sy = 0; sy < 8; ++sy) {
          for (int sx = 0; sx < 8; ++sx) {
            const double px = x - 0.4375 + sx / 8.0, py = y - 0.4375 + sy / 8.0;
            if ((Eigen::Vector2d(px, py) - b.centre).norm() <= radius) {
              sum += shade(b, px, py);
              ++inside;
            }
          }
        }
        p = (sum + (64 - inside) * p) / 64.0;
      }
    }
  }
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, noise_sigma);
  cv::Mat out(size, CV_8UC3);
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        out.at<cv::Vec3b>(y, x)[c] =
            cv::saturate_cast<uint8_t>(f.at<cv::Vec3d>(y, x)[c] + noise(rng));
      }
    }
  }
  return out;
}

}  // namespace billiard::estimator::testing
