#include "estimator/detection_overlay.h"

#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

namespace billiard::estimator {

namespace {

constexpr double kConfidentScore = 0.5;
const cv::Scalar kConfident(60, 220, 60);  // BGR
const cv::Scalar kDoubtful(40, 40, 230);
const cv::Scalar kLabel(255, 255, 255);
const cv::Scalar kCloth(200, 160, 120);
const cv::Scalar kSurface(255, 120, 0);

int LineWidth(const cv::Mat& image) {
  // A pixel wide on a 720p frame, thicker on larger ones.
  return std::max(1, static_cast<int>(std::lround(image.cols / 1280.0)));
}

// A side through a lens is the image of a straight pinhole line, a curve: drawn as this many
// straight pieces (at most a few tenths of a pixel off the curve for a side bowed by 30 px).
constexpr int kLensSidePieces = 32;

// The four sides between `corners` (image px), each the image of its pinhole line through `lens`.
void DrawSides(const std::array<Eigen::Vector2d, 4>& corners, const RadialLens& lens,
               const cv::Scalar& colour, int thickness, cv::Mat* image) {
  const int pieces = lens.IsPinhole() ? 1 : kLensSidePieces;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector2d a = lens.ToPinhole(corners[i]), b = lens.ToPinhole(corners[(i + 1) % 4]);
    std::vector<cv::Point> side;
    for (int k = 0; k <= pieces; ++k) {
      const Eigen::Vector2d p = lens.ToImage(a + (b - a) * (static_cast<double>(k) / pieces));
      side.emplace_back(static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y())));
    }
    cv::polylines(*image, side, false, colour, thickness, cv::LINE_AA);
  }
}

}  // namespace

cv::Mat DetectionOverlay(const cv::Mat& image, const std::vector<BallDetection>& balls) {
  cv::Mat out;
  if (image.channels() == 1) {
    cv::cvtColor(image, out, cv::COLOR_GRAY2BGR);
  } else {
    out = image.clone();
  }
  const int thickness = LineWidth(out);
  for (std::size_t k = 0; k < balls.size(); ++k) {
    const BallDetection& b = balls[k];
    const cv::Point2d centre(b.pixel.x(), b.pixel.y());
    const cv::Scalar colour = b.score >= kConfidentScore ? kConfident : kDoubtful;
    cv::circle(out, centre, static_cast<int>(std::lround(b.radius_px)), colour, thickness,
               cv::LINE_AA);
    cv::drawMarker(out, centre, colour, cv::MARKER_CROSS, 5, thickness);
    char label[48];
    std::snprintf(label, sizeof label, "%zu %.2f %s", k, b.score,
                  BallClassName(b.ball_class).c_str());
    cv::putText(out, label, centre + cv::Point2d(b.radius_px + 2, -b.radius_px),
                cv::FONT_HERSHEY_SIMPLEX, 0.4 * thickness, kLabel, thickness, cv::LINE_AA);
  }
  return out;
}

void DrawTable(const TableRegion& table, cv::Mat* image) {
  const int thickness = LineWidth(*image);
  DrawSides(table.cloth_corners, table.lens, kCloth, thickness, image);
  DrawSides(table.corners, table.lens, kSurface, thickness, image);
}

}  // namespace billiard::estimator
