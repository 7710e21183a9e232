#include "estimator/circle_votes.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace billiard::estimator {

namespace {

// An edge votes when its rate of colour change is at least kMinEdgeNoises times the table's
// median, and with full weight from kFullEdgeNoises times it (but never below kMinFullEdge
// L*a*b* units per pixel: a clean synthetic cloth has no noise to speak of).
constexpr double kMinEdgeNoises = 2.0, kFullEdgeNoises = 6.0, kMinFullEdge = 4.0;
constexpr double kMinNoise = 0.1;
// The votes are summed over a Gaussian of kPeakRadii of the smallest radius (at least a pixel);
// a peak is the largest within kPeakSeparationRadii of it.
constexpr double kPeakRadii = 0.1;
constexpr double kPeakSeparationRadii = 0.5;
// The noise at full resolution is the median over a grid of kNoiseGrid x kNoiseGrid points.
constexpr int kNoiseGrid = 32;
// 8-bit L*a*b* stores L* times 255 / 100; Sobel's 3x3 derivative is 8 times the slope.
constexpr float kLightnessUnit = 100.0f / 255.0f;
constexpr float kSobelGain = 1.0f / 8.0f;

// The colour structure tensor's strength (square root of its larger eigenvalue) and direction
// [rad] at every pixel of an 8-bit BGR image.
void ColourGradient(const cv::Mat& bgr, cv::Mat* magnitude, cv::Mat* angle) {
  cv::Mat lab;
  cv::cvtColor(bgr, lab, cv::COLOR_BGR2Lab);
  cv::Mat channels[3];
  cv::split(lab, channels);
  cv::Mat jxx = cv::Mat::zeros(bgr.size(), CV_32F), jyy = jxx.clone(), jxy = jxx.clone();
  for (int c = 0; c < 3; ++c) {
    cv::Mat gx, gy;
    const double unit = kSobelGain * (c == 0 ? kLightnessUnit : 1.0f);
    cv::Sobel(channels[c], gx, CV_32F, 1, 0, 3, unit);
    cv::Sobel(channels[c], gy, CV_32F, 0, 1, 3, unit);
    cv::accumulateSquare(gx, jxx);
    cv::accumulateSquare(gy, jyy);
    cv::accumulateProduct(gx, gy, jxy);
  }
  magnitude->create(bgr.size(), CV_32F);
  angle->create(bgr.size(), CV_32F);
  for (int y = 0; y < bgr.rows; ++y) {
    const float* a = jxx.ptr<float>(y);
    const float* b = jyy.ptr<float>(y);
    const float* c = jxy.ptr<float>(y);
    float* m = magnitude->ptr<float>(y);
    float* t = angle->ptr<float>(y);
    for (int x = 0; x < bgr.cols; ++x) {
      const float trace = a[x] + b[x];
      const float root = std::sqrt((a[x] - b[x]) * (a[x] - b[x]) + 4 * c[x] * c[x]);
      m[x] = std::sqrt(0.5f * (trace + root));
      t[x] = 0.5f * std::atan2(2 * c[x], a[x] - b[x]);
    }
  }
}

void Splat(cv::Mat& votes, double x, double y, float weight) {
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  if (x0 < 0 || y0 < 0 || x0 + 1 >= votes.cols || y0 + 1 >= votes.rows) return;
  const float fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
  float* r0 = votes.ptr<float>(y0);
  float* r1 = votes.ptr<float>(y0 + 1);
  r0[x0] += weight * (1 - fx) * (1 - fy);
  r0[x0 + 1] += weight * fx * (1 - fy);
  r1[x0] += weight * (1 - fx) * fy;
  r1[x0 + 1] += weight * fx * fy;
}

}  // namespace

double EdgeNoise(const cv::Mat& bgr, const TableRegion& table) {
  // From a grid of 3x3 patches: a rate of change at every pixel of a frame costs more than the
  // rest of the search.
  const cv::Rect box = table.Bounds() & cv::Rect(1, 1, bgr.cols - 2, bgr.rows - 2);
  std::vector<float> rates;
  for (int j = 0; j < kNoiseGrid; ++j) {
    for (int i = 0; i < kNoiseGrid; ++i) {
      const cv::Point p(box.x + (i + 0.5) * box.width / kNoiseGrid,
                        box.y + (j + 0.5) * box.height / kNoiseGrid);
      if (!table.Contains({p.x, p.y})) continue;
      cv::Mat magnitude, angle;
      ColourGradient(bgr(cv::Rect(p.x - 1, p.y - 1, 3, 3)), &magnitude, &angle);
      rates.push_back(magnitude.at<float>(1, 1));
    }
  }
  if (rates.empty()) return kMinNoise;
  std::nth_element(rates.begin(), rates.begin() + rates.size() / 2, rates.end());
  return std::max(kMinNoise, static_cast<double>(rates[rates.size() / 2]));
}

std::vector<CircleVote> VoteForCircles(const cv::Mat& bgr, const TableRegion& table, const BallScale& scale,
                           double min_support) {
  double smallest = HUGE_VAL, largest = 0;
  for (const auto& c : table.corners) {
    smallest = std::min(smallest, scale.RadiusAt(c));
    largest = std::max(largest, scale.RadiusAt(c));
  }
  std::vector<CircleVote> peaks;
  if (!(smallest > 0)) return peaks;
  const int margin = static_cast<int>(std::ceil(1.5 * largest));
  const cv::Rect region =
      (table.Bounds() + cv::Size(2 * margin, 2 * margin) - cv::Point(margin, margin)) &
      cv::Rect(0, 0, bgr.cols, bgr.rows);
  if (region.width < 8 || region.height < 8) return peaks;
  const int factor = std::max(1, static_cast<int>(smallest / kVoteRadiusPx));
  cv::Mat small;
  cv::resize(bgr(region), small, {}, 1.0 / factor, 1.0 / factor, cv::INTER_AREA);
  const auto to_small = [&](const Eigen::Vector2d& p) {
    return Eigen::Vector2d((p.x() - region.x + 0.5) / factor - 0.5,
                           (p.y() - region.y + 0.5) / factor - 0.5);
  };
  const auto to_full = [&](double x, double y) {
    return Eigen::Vector2d((x + 0.5) * factor - 0.5 + region.x, (y + 0.5) * factor - 0.5 + region.y);
  };
  // Where votes are cast from: the table, and a ball's width around it (balls on the cushion).
  cv::Mat voting = cv::Mat::zeros(small.size(), CV_8U), inside = voting.clone();
  std::vector<cv::Point> quad;
  for (const auto& c : table.corners) {
    const Eigen::Vector2d s = to_small(c);
    quad.emplace_back(static_cast<int>(std::lround(s.x())), static_cast<int>(std::lround(s.y())));
  }
  cv::fillConvexPoly(inside, quad, 255);
  const int reach = 2 * static_cast<int>(std::ceil(largest / factor)) + 1;
  cv::dilate(inside, voting, cv::getStructuringElement(cv::MORPH_ELLIPSE, {reach, reach}));

  cv::Mat magnitude, angle;
  ColourGradient(small, &magnitude, &angle);
  std::vector<float> rates;
  for (int y = 0; y < small.rows; y += 2) {
    for (int x = 0; x < small.cols; x += 2) {
      if (inside.at<uint8_t>(y, x)) rates.push_back(magnitude.at<float>(y, x));
    }
  }
  double noise = kMinNoise;
  if (!rates.empty()) {
    std::nth_element(rates.begin(), rates.begin() + rates.size() / 2, rates.end());
    noise = std::max(noise, static_cast<double>(rates[rates.size() / 2]));
  }
  const float min_edge = static_cast<float>(kMinEdgeNoises * noise);
  const float full_edge = static_cast<float>(std::max(kMinFullEdge, kFullEdgeNoises * noise));

  cv::Mat votes = cv::Mat::zeros(small.size(), CV_32F);
  for (int y = 1; y + 1 < small.rows; ++y) {
    const float* m = magnitude.ptr<float>(y);
    const float* t = angle.ptr<float>(y);
    const uint8_t* cast = voting.ptr<uint8_t>(y);
    for (int x = 1; x + 1 < small.cols; ++x) {
      if (!cast[x] || m[x] < min_edge) continue;
      const float c = std::cos(t[x]), s = std::sin(t[x]);
      // Thin: only the strongest pixel across the edge votes.
      const int dx = static_cast<int>(std::lround(c)), dy = static_cast<int>(std::lround(s));
      if (m[x] < magnitude.at<float>(y + dy, x + dx) || m[x] < magnitude.at<float>(y - dy, x - dx)) {
        continue;
      }
      const double r = scale.RadiusAt(to_full(x, y)) / factor;
      if (!(r > 1)) continue;
      const float weight = std::min(1.0f, m[x] / full_edge) / static_cast<float>(2 * M_PI * r);
      Splat(votes, x + r * c, y + r * s, weight);
      Splat(votes, x - r * c, y - r * s, weight);
    }
  }
  const double sigma = std::max(1.0, kPeakRadii * smallest / factor);
  cv::GaussianBlur(votes, votes, {0, 0}, sigma);
  votes *= 2 * M_PI * sigma * sigma;  // the sum over the Gaussian's area, not its mean
  const int separation = std::max(1, static_cast<int>(kPeakSeparationRadii * smallest / factor));
  cv::Mat neighbourhood_max;
  cv::dilate(votes, neighbourhood_max,
             cv::getStructuringElement(cv::MORPH_RECT, {2 * separation + 1, 2 * separation + 1}));
  for (int y = 0; y < votes.rows; ++y) {
    const float* v = votes.ptr<float>(y);
    const float* peak = neighbourhood_max.ptr<float>(y);
    const uint8_t* in = inside.ptr<uint8_t>(y);
    for (int x = 0; x < votes.cols; ++x) {
      if (in[x] && v[x] >= min_support && v[x] >= peak[x]) {
        peaks.push_back({to_full(x, y), v[x]});
      }
    }
  }
  std::sort(peaks.begin(), peaks.end(),
            [](const CircleVote& a, const CircleVote& b) { return a.support > b.support; });
  return peaks;
}

}  // namespace billiard::estimator
