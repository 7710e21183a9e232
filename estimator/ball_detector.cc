#include "estimator/ball_detector.h"

#include "estimator/ball_refinement.h"
#include "estimator/local_cloth.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace billiard::estimator {

using internal::Ballness;
using internal::Decompose;
using internal::LocalCloth;
using internal::MakeLocalCloth;
using internal::RefineBall;

namespace {

// The search runs where a ball is about this many pixels in radius: small enough to be cheap,
// large enough that the centre-surround filter still sees a disc.
constexpr double kSearchRadius = 4.5;
cv::Mat AsBgr(const cv::Mat& image) {
  if (image.type() == CV_8UC3) return image;
  if (image.type() == CV_8UC1) {
    cv::Mat bgr;
    cv::cvtColor(image, bgr, cv::COLOR_GRAY2BGR);
    return bgr;
  }
  throw std::invalid_argument("ball detector: the frame must be 8-bit BGR or grey");
}

// The dominant colour of the frame: the mode of the chromaticity histogram, averaged over its
// neighbourhood. The cloth is the largest uniformly coloured thing in a table camera's view.
cv::Vec3f DominantColour(const cv::Mat& bgr) {
  constexpr int kBins = 64;
  cv::Mat hist = cv::Mat::zeros(kBins, kBins, CV_32F);
  for (int y = 0; y < bgr.rows; y += 2) {
    const auto* row = bgr.ptr<cv::Vec3b>(y);
    for (int x = 0; x < bgr.cols; x += 2) {
      const int s = row[x][0] + row[x][1] + row[x][2];
      if (s < 45) continue;  // too dark for a chromaticity
      hist.at<float>(row[x][0] * (kBins - 1) / s, row[x][1] * (kBins - 1) / s) += 1.0f;
    }
  }
  cv::blur(hist, hist, {3, 3});
  cv::Point peak;
  cv::minMaxLoc(hist, nullptr, nullptr, nullptr, &peak);
  cv::Vec3d sum(0, 0, 0);
  double count = 0;
  for (int y = 0; y < bgr.rows; y += 2) {
    const auto* row = bgr.ptr<cv::Vec3b>(y);
    for (int x = 0; x < bgr.cols; x += 2) {
      const int s = row[x][0] + row[x][1] + row[x][2];
      if (s < 45) continue;
      const int bx = row[x][0] * (kBins - 1) / s, gx = row[x][1] * (kBins - 1) / s;
      if (std::abs(bx - peak.y) <= 1 && std::abs(gx - peak.x) <= 1) {
        sum += cv::Vec3d(row[x][0], row[x][1], row[x][2]);
        ++count;
      }
    }
  }
  if (count == 0) return {128, 128, 128};
  return cv::Vec3f(sum / count);
}

// Fills cells without an estimate from their neighbours (normalized convolution), widening until
// every cell has one.
void FillMissing(cv::Mat& colour, cv::Mat& weight) {
  for (int k = 3; k < 4 * std::max(colour.rows, colour.cols); k = 2 * k + 1) {
    double min_weight;
    cv::minMaxLoc(weight, &min_weight);
    if (min_weight > 0) break;
    cv::Mat weighted, blurred_weight, blurred;
    std::vector<cv::Mat> channels;
    cv::split(colour, channels);
    for (auto& c : channels) c = c.mul(weight);
    cv::merge(channels, weighted);
    cv::blur(weighted, blurred, {k, k}, {-1, -1}, cv::BORDER_REPLICATE);
    cv::blur(weight, blurred_weight, {k, k}, {-1, -1}, cv::BORDER_REPLICATE);
    for (int y = 0; y < colour.rows; ++y) {
      for (int x = 0; x < colour.cols; ++x) {
        const float w = blurred_weight.at<float>(y, x);
        if (weight.at<float>(y, x) == 0 && w > 0) {
          colour.at<cv::Vec3f>(y, x) = blurred.at<cv::Vec3f>(y, x) / w;
          weight.at<float>(y, x) = 1e-3f;
        }
      }
    }
  }
}

// Ballness of every pixel of `small` (a reduced frame at the model's search resolution).
cv::Mat BallnessMap(const cv::Mat& small, const ClothModel& model) {
  const float inv_across = MakeLocalCloth({1, 1, 1}, model.noise).inv_across;
  cv::Mat b(small.size(), CV_32F);
  for (int y = 0; y < small.rows; ++y) {
    const auto* in = small.ptr<cv::Vec3b>(y);
    const auto* unit = model.search_unit.ptr<cv::Vec3f>(y);
    const float* inv_norm = model.search_inv_norm.ptr<float>(y);
    auto* out = b.ptr<float>(y);
    for (int x = 0; x < small.cols; ++x) {
      out[x] = Ballness(cv::Vec3f(in[x][0], in[x][1], in[x][2]),
                        LocalCloth{unit[x], inv_norm[x], inv_across});
    }
  }
  return b;
}

// The cloth model of a reduced frame (scale: reduced px per full-res px) and its ballness map.
ClothModel LearnCloth(const cv::Mat& small, double scale, double radius_small, cv::Mat* ballness) {
  // First pass: cloth is what is close to the dominant colour, loosely (tint and brightness drift
  // across a real table).
  const LocalCloth global = MakeLocalCloth(DominantColour(small), 0.0);
  cv::Mat cloth_sum(small.size(), CV_32FC3, cv::Scalar::all(0));
  cv::Mat cloth_mask(small.size(), CV_32F, cv::Scalar(0));
  for (int y = 0; y < small.rows; ++y) {
    for (int x = 0; x < small.cols; ++x) {
      const cv::Vec3b p = small.at<cv::Vec3b>(y, x);
      const cv::Vec3f c(p[0], p[1], p[2]);
      float s, e;
      Decompose(c, global, &s, &e);
      if (e < 0.15f && s > 0.5f && s < 1.5f) {
        cloth_sum.at<cv::Vec3f>(y, x) = c;
        cloth_mask.at<float>(y, x) = 1.0f;
      }
    }
  }
  // Cells about three ball diameters across: fine enough for vignetting, coarse enough that
  // every cell holds mostly cloth.
  const int cell = std::max(4, static_cast<int>(std::lround(6 * radius_small)));
  const cv::Size cells((small.cols + cell - 1) / cell, (small.rows + cell - 1) / cell);
  cv::Mat sum, weight;
  cv::resize(cloth_sum, sum, cells, 0, 0, cv::INTER_AREA);
  cv::resize(cloth_mask, weight, cells, 0, 0, cv::INTER_AREA);
  cv::Mat colour(cells, CV_32FC3);
  for (int y = 0; y < cells.height; ++y) {
    for (int x = 0; x < cells.width; ++x) {
      float& w = weight.at<float>(y, x);
      if (w < 0.25f) {
        w = 0;
        colour.at<cv::Vec3f>(y, x) = cv::Vec3f(0, 0, 0);
      } else {
        colour.at<cv::Vec3f>(y, x) = sum.at<cv::Vec3f>(y, x) / w;
      }
    }
  }
  FillMissing(colour, weight);

  ClothModel model;
  model.colour = colour;
  model.cell = static_cast<double>(small.cols) / cells.width / scale;

  // The cloth's own spread across its colour, from the first-pass cloth pixels: the scale of the
  // across-hue term, so that noise and weave never look like a ball.
  cv::Mat local;
  cv::resize(colour, local, small.size(), 0, 0, cv::INTER_LINEAR);
  std::vector<float> across;
  for (int y = 0; y < small.rows; y += 2) {
    for (int x = 0; x < small.cols; x += 2) {
      if (cloth_mask.at<float>(y, x) == 0) continue;
      const cv::Vec3b p = small.at<cv::Vec3b>(y, x);
      float s, e;
      Decompose(cv::Vec3f(p[0], p[1], p[2]), MakeLocalCloth(local.at<cv::Vec3f>(y, x), 0.0), &s,
                &e);
      across.push_back(e);
    }
  }
  if (!across.empty()) {
    auto mid = across.begin() + across.size() / 2;
    std::nth_element(across.begin(), mid, across.end());
    model.noise = 1.4826 * *mid;
  }
  model.search_unit.create(small.size(), CV_32FC3);
  model.search_inv_norm.create(small.size(), CV_32F);
  for (int y = 0; y < small.rows; ++y) {
    for (int x = 0; x < small.cols; ++x) {
      const LocalCloth c = MakeLocalCloth(local.at<cv::Vec3f>(y, x), model.noise);
      model.search_unit.at<cv::Vec3f>(y, x) = c.unit;
      model.search_inv_norm.at<float>(y, x) = c.inv_norm;
    }
  }
  *ballness = BallnessMap(small, model);

  // Playing area: the largest connected cloth region, its ball-sized notches closed and its holes
  // filled.
  cv::Mat cloth = *ballness < 0.5f, labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(cloth, labels, stats, centroids, 4);
  int largest = 0;
  for (int i = 1; i < n; ++i) {
    if (largest == 0 ||
        stats.at<int>(i, cv::CC_STAT_AREA) > stats.at<int>(largest, cv::CC_STAT_AREA)) {
      largest = i;
    }
  }
  cv::Mat area = labels == largest;
  const int d = 2 * static_cast<int>(std::ceil(1.3 * radius_small)) + 1;
  cv::morphologyEx(area, area, cv::MORPH_CLOSE,
                   cv::getStructuringElement(cv::MORPH_ELLIPSE, {d, d}), {-1, -1}, 1,
                   cv::BORDER_CONSTANT, 0);
  cv::Mat outside(area.rows + 2, area.cols + 2, CV_8U, cv::Scalar(0));
  area.copyTo(outside(cv::Rect(1, 1, area.cols, area.rows)));
  cv::floodFill(outside, cv::Point(0, 0), 128);
  model.area = outside(cv::Rect(1, 1, area.cols, area.rows)) != 128;
  model.area_scale = scale;
  return model;
}

// Radius [small px] of the typical compact blob: what a ball is when nobody says.
double EstimateRadius(const cv::Mat& ballness) {
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(ballness >= 0.5f, labels, stats, centroids, 8);
  std::vector<double> radii;
  for (int i = 1; i < n; ++i) {
    const int w = stats.at<int>(i, cv::CC_STAT_WIDTH), h = stats.at<int>(i, cv::CC_STAT_HEIGHT);
    const int area = stats.at<int>(i, cv::CC_STAT_AREA);
    const int x = stats.at<int>(i, cv::CC_STAT_LEFT), y = stats.at<int>(i, cv::CC_STAT_TOP);
    const double fill = static_cast<double>(area) / (w * h), aspect = static_cast<double>(w) / h;
    const bool at_border = x == 0 || y == 0 || x + w == ballness.cols || y + h == ballness.rows;
    if (area >= 9 && fill > 0.55 && fill < 0.92 && aspect > 0.75 && aspect < 1.33 && !at_border) {
      radii.push_back(std::sqrt(area / M_PI));
    }
  }
  if (radii.empty()) return 0;
  std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
  return radii[radii.size() / 2];
}

// The frame at 1/factor of its resolution, one pixel of each factor x factor block: the search
// only needs to see ball-sized blobs, and reading a ninth of the frame is what keeps it cheap.
cv::Mat Reduce(const cv::Mat& bgr, int factor) {
  if (factor == 1) return bgr;
  cv::Mat small(bgr.rows / factor, bgr.cols / factor, CV_8UC3);
  const int offset = factor / 2;
  for (int y = 0; y < small.rows; ++y) {
    const auto* in = bgr.ptr<cv::Vec3b>(y * factor + offset) + offset;
    auto* out = small.ptr<cv::Vec3b>(y);
    for (int x = 0; x < small.cols; ++x) out[x] = in[x * factor];
  }
  return small;
}

}  // namespace

cv::Vec3f ClothModel::ColourAt(const Eigen::Vector2d& pixel) const {
  const double x = std::clamp(pixel.x() / cell - 0.5, 0.0, colour.cols - 1.0);
  const double y = std::clamp(pixel.y() / cell - 0.5, 0.0, colour.rows - 1.0);
  const int x0 = std::min(static_cast<int>(x), colour.cols - 2 < 0 ? 0 : colour.cols - 2);
  const int y0 = std::min(static_cast<int>(y), colour.rows - 2 < 0 ? 0 : colour.rows - 2);
  const int x1 = std::min(x0 + 1, colour.cols - 1), y1 = std::min(y0 + 1, colour.rows - 1);
  const float fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
  return (1 - fy) * ((1 - fx) * colour.at<cv::Vec3f>(y0, x0) + fx * colour.at<cv::Vec3f>(y0, x1)) +
         fy * ((1 - fx) * colour.at<cv::Vec3f>(y1, x0) + fx * colour.at<cv::Vec3f>(y1, x1));
}

bool ClothModel::InArea(const Eigen::Vector2d& pixel) const {
  const int x = static_cast<int>(std::floor((pixel.x() + 0.5) * area_scale));
  const int y = static_cast<int>(std::floor((pixel.y() + 0.5) * area_scale));
  return x >= 0 && y >= 0 && x < area.cols && y < area.rows && area.at<uint8_t>(y, x) != 0;
}

double ExpectedRadiusPx(const camera::CameraModel& camera, double ball_radius) {
  const Eigen::Vector3d centre =
      camera.Unproject({0.5 * (camera.width - 1), 0.5 * (camera.height - 1)}, ball_radius);
  return ball_radius / camera.MetresPerPixel(centre);
}

BallDetector::BallDetector(DetectorOptions options) : options_(options) {}

namespace {

// Peaks of the centre-surround filter on the ballness: mean ballness in the ball's core minus
// that in a ring just outside it (box sums from one integral image, evaluated only where the
// ballness is high: a ball's centre is inside the ball). Full-resolution pixels, strongest first.
std::vector<Eigen::Vector2d> Candidates(const cv::Mat& ballness, const cv::Mat& area, int factor,
                                        double r_small) {
  const int in = static_cast<int>(std::lround(0.7 * r_small));
  const int mid = static_cast<int>(std::lround(1.15 * r_small));
  const int out = static_cast<int>(std::lround(1.7 * r_small));
  cv::Mat sum;
  cv::integral(ballness, sum, CV_32F);
  const auto box = [&](int x, int y, int half) {
    const int x0 = std::max(0, x - half), y0 = std::max(0, y - half);
    const int x1 = std::min(ballness.cols, x + half + 1),
              y1 = std::min(ballness.rows, y + half + 1);
    return sum.at<float>(y1, x1) - sum.at<float>(y0, x1) - sum.at<float>(y1, x0) +
           sum.at<float>(y0, x0);
  };
  const float in_area = static_cast<float>((2 * in + 1) * (2 * in + 1));
  const float ring_area =
      static_cast<float>((2 * out + 1) * (2 * out + 1) - (2 * mid + 1) * (2 * mid + 1));
  cv::Mat response(ballness.size(), CV_32F, cv::Scalar(0));
  for (int y = 0; y < ballness.rows; ++y) {
    const float* b = ballness.ptr<float>(y);
    const uint8_t* inside = area.ptr<uint8_t>(y);
    float* r = response.ptr<float>(y);
    for (int x = 0; x < ballness.cols; ++x) {
      if (b[x] < 0.5f || !inside[x]) continue;
      r[x] = box(x, y, in) / in_area - (box(x, y, out) - box(x, y, mid)) / ring_area;
    }
  }
  std::vector<std::pair<float, Eigen::Vector2d>> found;
  for (int y = 1; y + 1 < response.rows; ++y) {
    for (int x = 1; x + 1 < response.cols; ++x) {
      const float r = response.at<float>(y, x);
      if (r < 0.4f) continue;
      bool peak = true;
      for (int dy = -1; dy <= 1 && peak; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) peak = peak && response.at<float>(y + dy, x + dx) <= r;
      }
      if (peak) {
        found.push_back({r, {x * factor + factor / 2, y * factor + factor / 2}});  // as Reduce
      }
    }
  }
  std::sort(found.begin(), found.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<Eigen::Vector2d> pixels;
  for (std::size_t i = 0; i < found.size() && i < 200; ++i) pixels.push_back(found[i].second);
  return pixels;
}

int SearchFactor(double radius_px) {
  return std::max(1, static_cast<int>(std::lround(radius_px / kSearchRadius)));
}

}  // namespace

void BallDetector::LearnCloth(const cv::Mat& image) {
  const cv::Mat bgr = AsBgr(image);
  radius_px_ = options_.ball_radius_px;
  cv::Mat ballness;
  if (radius_px_ <= 0) {
    // Without a radius: blobs at a resolution where balls of the usual sizes (8-30 px) are
    // blobs give a first guess (too large by the blur and the shadows' tint), and the median
    // radius of the edges fitted around the strongest of them the answer.
    const int factor = std::max(1, bgr.cols / 400);
    const cv::Mat small = Reduce(bgr, factor);
    cloth_ = billiard::estimator::LearnCloth(small, 1.0 / factor, 15.0 / factor, &ballness);
    const double guess = EstimateRadius(ballness) * factor;
    if (guess <= 0) {
      cloth_ = {};
      return;
    }
    std::vector<double> radii;
    for (const auto& pixel : Candidates(ballness, cloth_.area, factor, guess / factor)) {
      const auto fit =
          RefineBall(bgr, pixel, guess, MakeLocalCloth(cloth_.ColourAt(pixel), cloth_.noise), 0.0);
      if (fit) radii.push_back(fit->radius_px);
      if (radii.size() == 30) break;
    }
    if (radii.empty()) {
      cloth_ = {};
      return;
    }
    std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
    radius_px_ = radii[radii.size() / 2];
  }
  const int factor = SearchFactor(radius_px_);
  cloth_ = billiard::estimator::LearnCloth(Reduce(bgr, factor), 1.0 / factor, radius_px_ / factor,
                                           &ballness);
  cloth_.frame_size = bgr.size();
}

std::vector<BallDetection> BallDetector::Detect(const cv::Mat& image) {
  const cv::Mat bgr = AsBgr(image);
  if (cloth_.empty() || cloth_.frame_size != bgr.size()) {
    LearnCloth(bgr);
    if (cloth_.empty()) return {};
  }
  const int factor = SearchFactor(radius_px_);
  const cv::Mat ballness = BallnessMap(Reduce(bgr, factor), cloth_);
  std::vector<BallDetection> balls;
  for (const Eigen::Vector2d& candidate :
       Candidates(ballness, cloth_.area, factor, radius_px_ / factor)) {
    // A plateau or a neighbouring peak on a ball already found.
    const bool seen = std::any_of(balls.begin(), balls.end(), [&](const BallDetection& d) {
      return (d.pixel - candidate).norm() < 0.8 * radius_px_;
    });
    if (seen) continue;
    const auto ball = RefineAt(bgr, candidate, radius_px_);
    if (!ball || !cloth_.InArea(ball->pixel)) continue;
    const bool duplicate = std::any_of(balls.begin(), balls.end(), [&](const BallDetection& d) {
      return (d.pixel - ball->pixel).norm() < radius_px_;
    });
    if (!duplicate) balls.push_back(*ball);
  }
  std::sort(balls.begin(), balls.end(),
            [](const BallDetection& a, const BallDetection& b) { return a.score > b.score; });
  return balls;
}

std::optional<BallDetection> BallDetector::RefineAt(const cv::Mat& image,
                                                    const Eigen::Vector2d& predicted,
                                                    double radius_px) const {
  const cv::Mat bgr = AsBgr(image);
  if (!cloth_.empty()) {
    return RefineBall(bgr, predicted, radius_px,
                      MakeLocalCloth(cloth_.ColourAt(predicted), cloth_.noise), options_.min_score);
  }
  // No cloth learnt yet: the cloth around the window, the median of a ring well outside the ball.
  std::array<std::vector<uint8_t>, 3> ring;
  for (int k = 0; k < 64; ++k) {
    const double angle = 2 * M_PI * k / 64;
    const int x = static_cast<int>(std::lround(predicted.x() + 2.5 * radius_px * std::cos(angle)));
    const int y = static_cast<int>(std::lround(predicted.y() + 2.5 * radius_px * std::sin(angle)));
    if (x < 0 || y < 0 || x >= bgr.cols || y >= bgr.rows) continue;
    for (int c = 0; c < 3; ++c) ring[c].push_back(bgr.at<cv::Vec3b>(y, x)[c]);
  }
  if (ring[0].empty()) return std::nullopt;
  cv::Vec3f colour;
  for (int c = 0; c < 3; ++c) {
    std::nth_element(ring[c].begin(), ring[c].begin() + ring[c].size() / 2, ring[c].end());
    colour[c] = ring[c][ring[c].size() / 2];
  }
  return RefineBall(bgr, predicted, radius_px, MakeLocalCloth(colour, 0.0), options_.min_score);
}

}  // namespace billiard::estimator
