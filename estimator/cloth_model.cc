#include "estimator/cloth_model.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "estimator/circle_votes.h"
#include "estimator/lab_image.h"
#include "estimator/local_cloth.h"

namespace billiard::estimator {

using internal::Decompose;
using internal::MakeLocalCloth;

namespace {

// The cloth's colour map has kClothCells cells across the table's search mask; a cell with less
// than kMinCellCloth of its area cloth takes its neighbours' colour.
constexpr int kClothCells = 24;
constexpr double kMinCellCloth = 0.2;
// An edge is a colour change of at least kEdgeNoises times the cloth's own, and never less than
// kMinEdge L*a*b* units per pixel (a clean frame's cloth has almost no noise, and the least
// ball, black on navy, changes by several units per pixel).
constexpr double kEdgeNoises = 1.5, kMinEdge = 2.0;

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

double EdgeThreshold(double edge_noise) { return std::max(kMinEdge, kEdgeNoises * edge_noise); }

ClothModel LearnClothModel(const cv::Mat& bgr, const TableRegion& table) {
  cv::Mat small;
  cv::resize(bgr, small, table.cloth.size(), 0, 0, cv::INTER_AREA);
  const int cell = std::max(4, small.cols / kClothCells);
  const cv::Size cells((small.cols + cell - 1) / cell, (small.rows + cell - 1) / cell);
  cv::Mat sum(cells, CV_32FC3, cv::Scalar::all(0)), weight(cells, CV_32F, cv::Scalar(0));
  for (int y = 0; y < small.rows; ++y) {
    const auto* in = small.ptr<cv::Vec3b>(y);
    const auto* cloth = table.cloth.ptr<uint8_t>(y);
    for (int x = 0; x < small.cols; ++x) {
      if (!cloth[x]) continue;
      sum.at<cv::Vec3f>(y / cell, x / cell) += cv::Vec3f(in[x][0], in[x][1], in[x][2]);
      weight.at<float>(y / cell, x / cell) += 1.0f;
    }
  }
  cv::Mat colour(cells, CV_32FC3, cv::Scalar::all(0));
  for (int y = 0; y < cells.height; ++y) {
    for (int x = 0; x < cells.width; ++x) {
      float& w = weight.at<float>(y, x);
      if (w < kMinCellCloth * cell * cell) {
        w = 0;
      } else {
        colour.at<cv::Vec3f>(y, x) = sum.at<cv::Vec3f>(y, x) / w;
      }
    }
  }
  FillMissing(colour, weight);
  ClothModel model;
  model.colour = colour;
  model.cell = cell / table.mask_scale;
  std::vector<float> across;
  for (int y = 0; y < small.rows; y += 2) {
    for (int x = 0; x < small.cols; x += 2) {
      if (!table.cloth.at<uint8_t>(y, x)) continue;
      const cv::Vec3b p = small.at<cv::Vec3b>(y, x);
      float along, distance;
      Decompose(cv::Vec3f(p[0], p[1], p[2]),
                MakeLocalCloth(colour.at<cv::Vec3f>(y / cell, x / cell), 0.0), &along, &distance);
      across.push_back(distance);
    }
  }
  if (!across.empty()) {
    std::nth_element(across.begin(), across.begin() + across.size() / 2, across.end());
    model.noise = 1.4826 * across[across.size() / 2];
  }
  model.edge_noise = EdgeNoise(LabImage(bgr, table.Bounds()), table);
  return model;
}

}  // namespace billiard::estimator
