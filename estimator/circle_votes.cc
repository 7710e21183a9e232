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
// The L*a*b* noise (EdgeNoise) is never taken below kMinNoise units per pixel.
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

// The larger eigenvalue of a 2x2 structure tensor [[xx, xy], [xy, yy]]: the squared strength of
// the change of colour (Di Zenzo 1986).
float LargestEigenvalue(float xx, float yy, float xy) {
  return 0.5f * (xx + yy + std::sqrt((xx - yy) * (xx - yy) + 4 * xy * xy));
}

// The unit direction of fastest change (the larger eigenvector), without trigonometry.
void Direction(float xx, float yy, float xy, float largest, float* dx, float* dy) {
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

// The colour gradient of an 8-bit L*a*b* image: the channels' derivatives (16-bit, all three at
// once: OpenCV's fastest path), the structure tensor's squared strength at every pixel
// [(L*a*b* units per px)^2], and its direction where asked.
class ColourGradient {
 public:
  explicit ColourGradient(const cv::Mat& image) {
    cv::Sobel(image, gx_, CV_16S, 1, 0, 3);
    cv::Sobel(image, gy_, CV_16S, 0, 1, 3);
    strength2_.create(image.size(), CV_32F);
    for (int y = 0; y < image.rows; ++y) {
      float* m = strength2_.ptr<float>(y);
      for (int x = 0; x < image.cols; ++x) {
        float xx, yy, xy;
        Tensor(x, y, &xx, &yy, &xy);
        m[x] = LargestEigenvalue(xx, yy, xy);
      }
    }
  }
  const cv::Mat& strength2() const { return strength2_; }
  // The unit direction of fastest change at (x, y).
  void DirectionAt(int x, int y, float* dx, float* dy) const {
    float xx, yy, xy;
    Tensor(x, y, &xx, &yy, &xy);
    Direction(xx, yy, xy, strength2_.at<float>(y, x), dx, dy);
  }

 private:
  void Tensor(int x, int y, float* xx, float* yy, float* xy) const {
    // 8-bit L*a*b* stores L* times 255 / 100.
    static constexpr float kUnit[3] = {kSobelGain * LabImage::kLightnessUnit, kSobelGain,
                                       kSobelGain};
    const cv::Vec3s& ax = gx_.at<cv::Vec3s>(y, x);
    const cv::Vec3s& ay = gy_.at<cv::Vec3s>(y, x);
    *xx = *yy = *xy = 0;
    for (int c = 0; c < 3; ++c) {
      const float u = kUnit[c] * ax[c], v = kUnit[c] * ay[c];
      *xx += u * u;
      *yy += v * v;
      *xy += u * v;
    }
  }

  cv::Mat gx_, gy_, strength2_;
};

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

// Every edge's votes [share of a circle's outline per pixel] for the centres of the circles of
// radius `radius_at(x, y)` [px] through it, from the colour gradient of an image whose noise
// (median rate of change) is `noise`.
template <typename RadiusAt>
cv::Mat Votes(const ColourGradient& gradient, double noise, RadiusAt radius_at) {
  const cv::Mat& strength2 = gradient.strength2();
  const float min_edge2 = static_cast<float>(std::pow(kMinEdgeNoises * noise, 2));
  const float full_edge = static_cast<float>(std::max(kMinFullEdge, kFullEdgeNoises * noise));
  cv::Mat votes = cv::Mat::zeros(strength2.size(), CV_32F);
  for (int y = 1; y + 1 < strength2.rows; ++y) {
    const float* m = strength2.ptr<float>(y);
    for (int x = 1; x + 1 < strength2.cols; ++x) {
      if (m[x] < min_edge2) continue;
      float c, s;
      gradient.DirectionAt(x, y, &c, &s);
      // Thin: only the strongest pixel across the edge votes.
      const int dx = static_cast<int>(std::lround(c)), dy = static_cast<int>(std::lround(s));
      if (m[x] < strength2.at<float>(y + dy, x + dx) ||
          m[x] < strength2.at<float>(y - dy, x - dx)) {
        continue;
      }
      const double r = radius_at(x, y);
      if (!(r > 1)) continue;
      const float weight =
          std::min(1.0f, std::sqrt(m[x]) / full_edge) / static_cast<float>(2 * M_PI * r);
      Splat(votes, x + r * c, y + r * s, weight);
      Splat(votes, x - r * c, y - r * s, weight);
    }
  }
  return votes;
}

// The votes summed over a Gaussian of `sigma` [px] around every pixel.
void SumOverPeaks(double sigma, cv::Mat* votes) {
  cv::GaussianBlur(*votes, *votes, {0, 0}, sigma);
  *votes *= 2 * M_PI * sigma * sigma;  // the sum over the Gaussian's area, not its mean
}

}  // namespace

double EdgeNoise(const LabImage& lab, const TableRegion& table) {
  // From kNoisePatches x kNoisePatches patches spread over the table: a rate of change at every
  // pixel of a frame costs more than the rest of the search.
  const cv::Rect region = lab.region();
  const cv::Rect box =
      table.Bounds() & cv::Rect(region.x + 1, region.y + 1, region.width - 2, region.height - 2);
  std::vector<float> rates;
  for (int j = 0; j < kNoisePatches && !box.empty(); ++j) {
    for (int i = 0; i < kNoisePatches; ++i) {
      const int cx = box.x + (2 * i + 1) * box.width / (2 * kNoisePatches);
      const int cy = box.y + (2 * j + 1) * box.height / (2 * kNoisePatches);
      if (!table.Contains({cx, cy})) continue;
      const cv::Rect patch =
          cv::Rect(cx - kNoisePatchPx / 2, cy - kNoisePatchPx / 2, kNoisePatchPx, kNoisePatchPx) &
          box;
      for (int y = patch.y; y < patch.y + patch.height; ++y) {
        for (int x = patch.x; x < patch.x + patch.width; ++x) {
          const cv::Vec3f gx = 0.5f * (lab.Pixel(x + 1, y) - lab.Pixel(x - 1, y));
          const cv::Vec3f gy = 0.5f * (lab.Pixel(x, y + 1) - lab.Pixel(x, y - 1));
          rates.push_back(std::sqrt(LargestEigenvalue(gx.dot(gx), gy.dot(gy), gx.dot(gy))));
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
  const double factor = std::max(1.0, smallest / kVoteRadiusPx);
  cv::Mat small;
  cv::resize(bgr(region), small, {}, 1.0 / factor, 1.0 / factor, cv::INTER_AREA);
  cv::cvtColor(small, small, cv::COLOR_BGR2Lab);
  const auto to_small = [&](const Eigen::Vector2d& p) {
    return Eigen::Vector2d((p.x() - region.x + 0.5) / factor - 0.5,
                           (p.y() - region.y + 0.5) / factor - 0.5);
  };
  const auto to_full = [&](double x, double y) {
    return Eigen::Vector2d((x + 0.5) * factor - 0.5 + region.x,
                           (y + 0.5) * factor - 0.5 + region.y);
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
  // A radius beyond it too: the outline found may be a little inside the cloth's edge.
  const int reach = 2 * static_cast<int>(std::ceil(largest / factor)) + 1;
  cv::dilate(inside, inside, cv::getStructuringElement(cv::MORPH_RECT, {reach, reach}));

  const ColourGradient gradient(small);
  const cv::Mat& strength2 = gradient.strength2();
  std::vector<float> rates;
  for (int y = 0; y < small.rows; y += 2) {
    for (int x = 0; x < small.cols; x += 2) {
      if (inside.at<uint8_t>(y, x)) rates.push_back(strength2.at<float>(y, x));
    }
  }
  double noise = kMinNoise;
  if (!rates.empty()) {
    std::nth_element(rates.begin(), rates.begin() + rates.size() / 2, rates.end());
    noise = std::max(noise, std::sqrt(static_cast<double>(rates[rates.size() / 2])));
  }
  cv::Mat votes = Votes(gradient, noise, [&](int x, int y) {
    return scale.RadiusAt(to_full(x, y)) / factor;
  });
  SumOverPeaks(std::max(1.0, kPeakRadii * smallest / factor), &votes);
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

double FullResolutionSupport(const cv::Mat& bgr, const Eigen::Vector2d& centre, double radius,
                             double edge_noise) {
  if (!(radius > 1)) return 0.0;
  // The circle, the edges it is thinned against, and the window's own border.
  const int reach = static_cast<int>(std::ceil(radius)) + 3;
  const cv::Point middle(static_cast<int>(std::lround(centre.x())),
                         static_cast<int>(std::lround(centre.y())));
  const cv::Rect window =
      cv::Rect(middle.x - reach, middle.y - reach, 2 * reach + 1, 2 * reach + 1) &
      cv::Rect(0, 0, bgr.cols, bgr.rows);
  if (window.width < 3 || window.height < 3) return 0.0;
  cv::Mat lab;
  cv::cvtColor(bgr(window), lab, cv::COLOR_BGR2Lab);
  cv::Mat votes = Votes(ColourGradient(lab), std::max(kMinNoise, edge_noise),
                        [radius](int, int) { return radius; });
  SumOverPeaks(std::max(1.0, kPeakRadii * radius), &votes);
  // The peak nearest the centre given, as VoteForCircles would have found it.
  const int near = std::max(1, static_cast<int>(std::lround(kPeakRadii * radius)));
  const cv::Rect around =
      cv::Rect(middle.x - window.x - near, middle.y - window.y - near, 2 * near + 1,
               2 * near + 1) &
      cv::Rect(0, 0, votes.cols, votes.rows);
  if (around.empty()) return 0.0;
  double peak = 0;
  cv::minMaxLoc(votes(around), nullptr, &peak);
  return peak;
}

}  // namespace billiard::estimator
