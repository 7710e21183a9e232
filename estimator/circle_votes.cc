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
// The noise at full resolution is the median over kNoisePatches x kNoisePatches patches of
// kNoisePatchPx x kNoisePatchPx pixels (a ball in one changes the median little).
constexpr int kNoisePatches = 5;
constexpr int kNoisePatchPx = 16;
// Sobel's 3x3 derivative is 8 times the slope.
constexpr float kSobelGain = 1.0f / 8.0f;

// The colour structure tensor (Di Zenzo 1986) of the three channels' derivatives at one pixel:
// its strength (the square root of the larger eigenvalue) and the unit direction of fastest
// change (the larger eigenvector, without trigonometry).
void StructureTensor(float xx, float yy, float xy, float* strength, float* dx, float* dy) {
  const float root = std::sqrt((xx - yy) * (xx - yy) + 4 * xy * xy);
  const float largest = 0.5f * (xx + yy + root);
  *strength = std::sqrt(largest);
  // (largest - yy, xy) and (xy, largest - xx) are both eigenvectors; the longer is exact.
  float ex = largest - yy, ey = xy;
  if (ex * ex + ey * ey < xy * xy + (largest - xx) * (largest - xx)) {
    ex = xy;
    ey = largest - xx;
  }
  const float norm = std::sqrt(ex * ex + ey * ey);
  *dx = norm > 0 ? ex / norm : 1.0f;
  *dy = norm > 0 ? ey / norm : 0.0f;
}

// The colour gradient's strength [L*a*b* units per px] and direction at every pixel of an 8-bit
// L*a*b* image.
void ColourGradient(const cv::Mat& lab, cv::Mat* magnitude, cv::Mat* dx, cv::Mat* dy) {
  cv::Mat channels[3];
  cv::split(lab, channels);
  cv::Mat jxx = cv::Mat::zeros(lab.size(), CV_32F), jyy = jxx.clone(), jxy = jxx.clone();
  for (int c = 0; c < 3; ++c) {
    cv::Mat gx, gy;
    const double unit = kSobelGain * (c == 0 ? LabImage::kLightnessUnit : 1.0f);
    cv::Sobel(channels[c], gx, CV_32F, 1, 0, 3, unit);
    cv::Sobel(channels[c], gy, CV_32F, 0, 1, 3, unit);
    cv::accumulateSquare(gx, jxx);
    cv::accumulateSquare(gy, jyy);
    cv::accumulateProduct(gx, gy, jxy);
  }
  magnitude->create(lab.size(), CV_32F);
  dx->create(lab.size(), CV_32F);
  dy->create(lab.size(), CV_32F);
  for (int y = 0; y < lab.rows; ++y) {
    const float* a = jxx.ptr<float>(y);
    const float* b = jyy.ptr<float>(y);
    const float* c = jxy.ptr<float>(y);
    float* m = magnitude->ptr<float>(y);
    float* u = dx->ptr<float>(y);
    float* v = dy->ptr<float>(y);
    for (int x = 0; x < lab.cols; ++x) StructureTensor(a[x], b[x], c[x], &m[x], &u[x], &v[x]);
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

double EdgeNoise(const LabImage& lab, const TableRegion& table) {
  // From kNoisePatches x kNoisePatches patches spread over the table: a rate of change at every
  // pixel of a frame costs more than the rest of the search.
  const cv::Rect region = lab.region();
  const cv::Rect box = table.Bounds() & cv::Rect(region.x + 1, region.y + 1, region.width - 2,
                                                 region.height - 2);
  std::vector<float> rates;
  for (int j = 0; j < kNoisePatches && !box.empty(); ++j) {
    for (int i = 0; i < kNoisePatches; ++i) {
      const int cx = box.x + (2 * i + 1) * box.width / (2 * kNoisePatches);
      const int cy = box.y + (2 * j + 1) * box.height / (2 * kNoisePatches);
      if (!table.Contains({cx, cy})) continue;
      const cv::Rect patch = cv::Rect(cx - kNoisePatchPx / 2, cy - kNoisePatchPx / 2,
                                      kNoisePatchPx, kNoisePatchPx) & box;
      for (int y = patch.y; y < patch.y + patch.height; ++y) {
        for (int x = patch.x; x < patch.x + patch.width; ++x) {
          const cv::Vec3f gx = 0.5f * (lab.Pixel(x + 1, y) - lab.Pixel(x - 1, y));
          const cv::Vec3f gy = 0.5f * (lab.Pixel(x, y + 1) - lab.Pixel(x, y - 1));
          float strength, dx, dy;
          StructureTensor(gx.dot(gx), gy.dot(gy), gx.dot(gy), &strength, &dx, &dy);
          rates.push_back(strength);
        }
      }
    }
  }
  if (rates.empty()) return kMinNoise;
  std::nth_element(rates.begin(), rates.begin() + rates.size() / 2, rates.end());
  return std::max(kMinNoise, static_cast<double>(rates[rates.size() / 2]));
}

std::vector<CircleVote> VoteForCircles(const cv::Mat& bgr, const TableRegion& table,
                                       const BallScale& scale, double min_support) {
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
  cv::Mat reduced;
  cv::resize(bgr(region), reduced, {}, 1.0 / factor, 1.0 / factor, cv::INTER_AREA);
  const cv::Mat small = LabImage(reduced).pixels();
  const auto to_small = [&](const Eigen::Vector2d& p) {
    return Eigen::Vector2d((p.x() - region.x + 0.5) / factor - 0.5,
                           (p.y() - region.y + 0.5) / factor - 0.5);
  };
  const auto to_full = [&](double x, double y) {
    return Eigen::Vector2d((x + 0.5) * factor - 0.5 + region.x, (y + 0.5) * factor - 0.5 + region.y);
  };
  // Peaks count inside the cloth's outline (the detector decides which are on the playing
  // surface); votes come from the region, the rails included (a ball against the cushion has its
  // outline there).
  cv::Mat inside = cv::Mat::zeros(small.size(), CV_8U);
  std::vector<cv::Point> quad;
  for (const auto& c : table.cloth_corners) {
    const Eigen::Vector2d s = to_small(c);
    quad.emplace_back(static_cast<int>(std::lround(s.x())), static_cast<int>(std::lround(s.y())));
  }
  cv::fillConvexPoly(inside, quad, 255);

  cv::Mat magnitude, along_x, along_y;
  ColourGradient(small, &magnitude, &along_x, &along_y);
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
    const float* cs = along_x.ptr<float>(y);
    const float* sn = along_y.ptr<float>(y);
    for (int x = 1; x + 1 < small.cols; ++x) {
      if (m[x] < min_edge) continue;
      const float c = cs[x], s = sn[x];
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
