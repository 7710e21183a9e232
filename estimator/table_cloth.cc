#include "estimator/table_cloth.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <vector>

#include "estimator/lab_image.h"

namespace billiard::estimator {

namespace {

// The cloth colour's mode: a histogram of L* in bins of kLightnessBin and a*, b* in bins of
// kChromaBin, each pixel weighted by 1 - d^2 (d: its offset from the image centre over half the
// image's width and height), so that a cloth filling the middle wins over a floor filling the
// edges.
constexpr int kLightnessBins = 10;
constexpr double kLightnessBin = 10.0;
constexpr int kChromaBins = 64;
constexpr double kChromaBin = 4.0;
// A pixel is cloth when its chromaticity (b, g over b + g + r) is within kChromaSpreads robust
// spreads of the cloth's (but never less than kMinChromaTolerance: a clean synthetic cloth), its
// brightness within [kMinBrightness, kMaxBrightness] of the cloth's (shadows, vignetting, a
// light), and it is not on an edge stronger than kMaxRelativeGradient (Sobel magnitude over
// brightness): the barrier of the cushion's nose and the rail, which a floor of the cloth's
// colour beyond them would otherwise join.
constexpr double kChromaSpreads = 4.0;
constexpr double kMinChromaTolerance = 0.02;
constexpr double kMinBrightness = 0.4, kMaxBrightness = 1.7;
constexpr double kMaxRelativeGradient = 0.8;

// The histogram bin of an 8-bit L*a*b* colour (lab_image.h).
int HistogramBin(const cv::Vec3b& lab) {
  const int l = std::min(kLightnessBins - 1,
                         static_cast<int>(lab[0] * LabImage::kLightnessUnit / kLightnessBin));
  const int a = std::min(kChromaBins - 1, static_cast<int>(lab[1] / kChromaBin));
  const int b = std::min(kChromaBins - 1, static_cast<int>(lab[2] / kChromaBin));
  return (l * kChromaBins + a) * kChromaBins + b;
}

// The centre-weighted histogram of the frame's L*a*b* (`lab`, 8-bit).
std::vector<float> CentreWeightedHistogram(const cv::Mat& lab) {
  std::vector<float> histogram(kLightnessBins * kChromaBins * kChromaBins, 0.0f);
  const double half_w = 0.5 * lab.cols, half_h = 0.5 * lab.rows;
  for (int y = 0; y < lab.rows; ++y) {
    const auto* row = lab.ptr<cv::Vec3b>(y);
    const double dy = (y - half_h) / half_h;
    for (int x = 0; x < lab.cols; ++x) {
      const double dx = (x - half_w) / half_w;
      const double weight = 1.0 - (dx * dx + dy * dy);  // 0 from the middle of each edge out
      if (weight > 0) histogram[HistogramBin(row[x])] += static_cast<float>(weight);
    }
  }
  return histogram;
}

// A mode's bin (L*, a*, b* bin indices).
using Mode = std::array<int, 3>;

// Whether two bins are within one bin of each other on every axis: a mode's neighbourhood.
bool Neighbours(const Mode& p, const Mode& q, int reach) {
  return std::abs(p[0] - q[0]) <= reach && std::abs(p[1] - q[1]) <= reach &&
         std::abs(p[2] - q[2]) <= reach;
}

// The bin next to the fullest neighbourhood of bins (3 x 3 x 3) that overlaps none of the
// neighbourhoods of `taken`; nullopt when every bin's does.
std::optional<Mode> FullestNeighbourhood(const std::vector<float>& histogram,
                                         const std::vector<Mode>& taken) {
  std::optional<Mode> best_mode;
  float best = -1;
  for (int l = 0; l < kLightnessBins; ++l) {
    for (int a = 1; a + 1 < kChromaBins; ++a) {
      for (int b = 1; b + 1 < kChromaBins; ++b) {
        const Mode mode = {l, a, b};
        if (std::any_of(taken.begin(), taken.end(),
                        [&](const Mode& t) { return Neighbours(mode, t, 2); })) {
          continue;
        }
        float sum = 0;
        for (int dl = std::max(0, l - 1); dl <= std::min(kLightnessBins - 1, l + 1); ++dl) {
          for (int da = -1; da <= 1; ++da) {
            for (int db = -1; db <= 1; ++db) {
              sum += histogram[(dl * kChromaBins + a + da) * kChromaBins + b + db];
            }
          }
        }
        if (sum > best) {
          best = sum;
          best_mode = mode;
        }
      }
    }
  }
  return best_mode;
}

// The mean colour (BGR) of the pixels of `small` in the neighbourhood of `mode`.
cv::Vec3f MeanOfMode(const cv::Mat& small, const cv::Mat& lab, const Mode& mode) {
  cv::Vec3d sum(0, 0, 0);
  double count = 0;
  for (int y = 0; y < lab.rows; ++y) {
    const auto* row = lab.ptr<cv::Vec3b>(y);
    const auto* colour = small.ptr<cv::Vec3b>(y);
    for (int x = 0; x < lab.cols; ++x) {
      const int bin = HistogramBin(row[x]);
      const Mode of = {bin / (kChromaBins * kChromaBins), (bin / kChromaBins) % kChromaBins,
                       bin % kChromaBins};
      if (Neighbours(of, mode, 1)) {
        sum += cv::Vec3d(colour[x][0], colour[x][1], colour[x][2]);
        ++count;
      }
    }
  }
  return cv::Vec3f(sum / std::max(1.0, count));
}

}  // namespace

// The modes of the centre-weighted L*a*b* histogram, fullest first, whose neighbourhoods of bins
// do not overlap (so that the second is another colour, not the first's shade), each the mean of
// its pixels.
std::vector<cv::Vec3f> ClothColours(const cv::Mat& small, std::size_t count) {
  const cv::Mat lab = LabImage(small).pixels();
  const std::vector<float> histogram = CentreWeightedHistogram(lab);
  std::vector<Mode> modes;
  std::vector<cv::Vec3f> colours;
  while (colours.size() < count) {
    const std::optional<Mode> mode = FullestNeighbourhood(histogram, modes);
    if (!mode) break;
    modes.push_back(*mode);
    colours.push_back(MeanOfMode(small, lab, *mode));
  }
  return colours;
}

// The CIE L*a*b* of a BGR colour (0..255 a channel).
cv::Vec3f LabOfBgr(const cv::Vec3f& bgr) {
  const cv::Mat pixel(1, 1, CV_32FC3, cv::Scalar(bgr[0] / 255.0, bgr[1] / 255.0, bgr[2] / 255.0));
  cv::Mat lab;
  cv::cvtColor(pixel, lab, cv::COLOR_BGR2Lab);
  return lab.at<cv::Vec3f>(0, 0);
}

// Pixels of about the cloth's chromaticity and brightness, off strong edges.
cv::Mat ClothLike(const cv::Mat& small, const cv::Vec3f& cloth) {
  const double cloth_sum = cloth[0] + cloth[1] + cloth[2];
  const double cb = cloth[0] / cloth_sum, cg = cloth[1] / cloth_sum;
  cv::Mat distance(small.size(), CV_32F), brightness(small.size(), CV_32F);
  for (int y = 0; y < small.rows; ++y) {
    const auto* in = small.ptr<cv::Vec3b>(y);
    auto* d = distance.ptr<float>(y);
    auto* s = brightness.ptr<float>(y);
    for (int x = 0; x < small.cols; ++x) {
      const double sum = in[x][0] + in[x][1] + in[x][2] + 1e-3;
      d[x] = static_cast<float>(std::hypot(in[x][0] / sum - cb, in[x][1] / sum - cg));
      s[x] = static_cast<float>(sum / cloth_sum);
    }
  }
  // The spread of the chromaticity among the cloth-like pixels of the frame's middle.
  std::vector<float> near;
  for (int y = small.rows / 4; y < 3 * small.rows / 4; ++y) {
    for (int x = small.cols / 4; x < 3 * small.cols / 4; ++x) {
      const float d = distance.at<float>(y, x);
      if (d < 0.05f && std::abs(brightness.at<float>(y, x) - 1.0f) < 0.3f) near.push_back(d);
    }
  }
  double tolerance = kMinChromaTolerance;
  if (!near.empty()) {
    std::nth_element(near.begin(), near.begin() + near.size() / 2, near.end());
    tolerance = std::max(tolerance, kChromaSpreads * near[near.size() / 2]);
  }
  cv::Mat grey, gx, gy, magnitude, grey_f;
  cv::cvtColor(small, grey, cv::COLOR_BGR2GRAY);
  grey.convertTo(grey_f, CV_32F);
  cv::Sobel(grey_f, gx, CV_32F, 1, 0);
  cv::Sobel(grey_f, gy, CV_32F, 0, 1);
  cv::magnitude(gx, gy, magnitude);
  const cv::Mat relative = magnitude / (grey_f + 10.0f);
  cv::Mat cloth_like = (distance < tolerance) & (brightness > kMinBrightness) &
                       (brightness < kMaxBrightness) & (relative < kMaxRelativeGradient);
  cv::morphologyEx(cloth_like, cloth_like, cv::MORPH_OPEN,
                   cv::getStructuringElement(cv::MORPH_ELLIPSE, {3, 3}));
  return cloth_like;
}

// The cloth-like region that is largest once weighted by how central it is.
cv::Mat LargestCentralRegion(const cv::Mat& cloth_like) {
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(cloth_like, labels, stats, centroids, 4);
  int best = 0;
  double best_score = 0;
  for (int i = 1; i < n; ++i) {
    const double dx = centroids.at<double>(i, 0) / cloth_like.cols - 0.5;
    const double dy = centroids.at<double>(i, 1) / cloth_like.rows - 0.5;
    const double score =
        stats.at<int>(i, cv::CC_STAT_AREA) * std::max(0.1, 1.0 - 2.0 * (dx * dx + dy * dy));
    if (score > best_score) {
      best_score = score;
      best = i;
    }
  }
  if (best == 0) return cv::Mat::zeros(cloth_like.size(), CV_8U);
  return labels == best;
}

cv::Mat FillHoles(const cv::Mat& region) {
  cv::Mat padded(region.rows + 2, region.cols + 2, CV_8U, cv::Scalar(0));
  region.copyTo(padded(cv::Rect(1, 1, region.cols, region.rows)));
  cv::floodFill(padded, cv::Point(0, 0), 128);
  return padded(cv::Rect(1, 1, region.cols, region.rows)) != 128;
}

}  // namespace billiard::estimator
