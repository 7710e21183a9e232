#include "estimator/table_calibration.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <opencv2/aruco.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace billiard::estimator {

namespace {

using Quad = std::vector<cv::Point2f>;

struct MarkerCandidate {
  Eigen::Vector2d centre;
  double side = 0;      // mean side length [px]
  double contrast = 0;  // border against its surroundings, 0..255
  bool decoded = false;
};

// The intersection of the diagonals: the centre of the square seen in perspective.
Eigen::Vector2d QuadCentre(const Quad& q) {
  const Eigen::Vector2d a(q[0].x, q[0].y), b(q[1].x, q[1].y), c(q[2].x, q[2].y), d(q[3].x, q[3].y);
  Eigen::Matrix2d m;
  m.col(0) = c - a;
  m.col(1) = b - d;
  const Eigen::Vector2d t = m.colPivHouseholderQr().solve(b - a);
  return a + t.x() * (c - a);
}

// How much a quad looks like a marker's outline: the mean grey of its outermost sixth (the
// marker's border cells) against the band just outside it and the band just inside it.
double BorderContrast(const cv::Mat& grey, const Quad& q) {
  constexpr int kSize = 48;  // the quad grown by a quarter on each side, warped to kSize^2
  const Eigen::Vector2d centre = QuadCentre(q);
  std::vector<cv::Point2f> grown;
  for (const auto& p : q) {
    const Eigen::Vector2d g = centre + 1.5 * (Eigen::Vector2d(p.x, p.y) - centre);
    grown.emplace_back(static_cast<float>(g.x()), static_cast<float>(g.y()));
  }
  const std::vector<cv::Point2f> square = {{0, 0}, {kSize, 0}, {kSize, kSize}, {0, kSize}};
  cv::Mat warped;
  cv::warpPerspective(grey, warped, cv::getPerspectiveTransform(grown, square), {kSize, kSize},
                      cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  // In the warp the quad spans [8, 40): border cells [8, 13), inside ring [13, 18), outside [3, 8).
  const auto band = [&](int from, int to) {
    double sum = 0;
    int n = 0;
    for (int y = from; y < kSize - from; ++y) {
      for (int x = from; x < kSize - from; ++x) {
        const int depth =
            std::min({x - from, y - from, kSize - from - 1 - x, kSize - from - 1 - y});
        if (depth < to - from) {
          sum += warped.at<uint8_t>(y, x);
          ++n;
        }
      }
    }
    return sum / n;
  };
  const double outside = band(3, 8), border = band(8, 13), inside = band(13, 18);
  return std::min(std::abs(border - outside), std::abs(border - inside));
}

MarkerCandidate Candidate(const cv::Mat& grey, const Quad& q, bool decoded) {
  MarkerCandidate c;
  c.centre = QuadCentre(q);
  c.decoded = decoded;
  std::array<double, 4> sides;
  for (int i = 0; i < 4; ++i) sides[i] = cv::norm(q[(i + 1) % 4] - q[i]);
  c.side = (sides[0] + sides[1] + sides[2] + sides[3]) / 4;
  const double squareness =
      *std::min_element(sides.begin(), sides.end()) / *std::max_element(sides.begin(), sides.end());
  c.contrast = squareness > 0.7 ? BorderContrast(grey, q) : 0.0;
  return c;
}

}  // namespace

MarkerLayout MarkerLayout::AroundTable(const physics::TableParameters& table, double margin,
                                       double height) {
  MarkerLayout layout;
  layout.centres = {Eigen::Vector3d(-margin, table.width + margin, height),
                    Eigen::Vector3d(table.length + margin, table.width + margin, height),
                    Eigen::Vector3d(table.length + margin, -margin, height),
                    Eigen::Vector3d(-margin, -margin, height)};
  return layout;
}

std::optional<std::array<Eigen::Vector2d, 4>> FindCornerMarkers(const cv::Mat& image) {
  cv::Mat grey = image;
  if (image.channels() == 3) cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  auto parameters = cv::aruco::DetectorParameters::create();
  parameters->detectInvertedMarker = true;
  parameters->cornerRefinementMethod = cv::aruco::CORNER_REFINE_SUBPIX;
  std::vector<MarkerCandidate> candidates;
  for (const auto dictionary : {cv::aruco::DICT_4X4_50, cv::aruco::DICT_4X4_1000}) {
    std::vector<int> ids;
    std::vector<Quad> found, rejected;
    cv::aruco::detectMarkers(grey, cv::aruco::getPredefinedDictionary(dictionary), found, ids,
                             parameters, rejected);
    for (const Quad& q : found) candidates.push_back(Candidate(grey, q, true));
    for (const Quad& q : rejected) candidates.push_back(Candidate(grey, q, false));
  }
  // A rejected quad counts when its border stands out and it is about the size of the markers.
  std::vector<double> sides;
  for (const auto& c : candidates) {
    if (c.decoded || c.contrast > 40) sides.push_back(c.side);
  }
  if (sides.size() < 4) return std::nullopt;
  std::nth_element(sides.begin(), sides.begin() + sides.size() / 2, sides.end());
  const double typical = sides[sides.size() / 2];
  const std::array<Eigen::Vector2d, 4> corners = {
      Eigen::Vector2d(0, 0), Eigen::Vector2d(image.cols, 0),
      Eigen::Vector2d(image.cols, image.rows), Eigen::Vector2d(0, image.rows)};
  std::array<Eigen::Vector2d, 4> markers;
  for (int k = 0; k < 4; ++k) {
    const MarkerCandidate* best = nullptr;
    for (const auto& c : candidates) {
      const bool marker_like =
          (c.decoded || c.contrast > 40) && c.side > 0.7 * typical && c.side < 1.4 * typical;
      // In this corner's quadrant of the image.
      const Eigen::Vector2d half(0.5 * image.cols, 0.5 * image.rows);
      const bool in_quadrant = ((c.centre - half).array() * (corners[k] - half).array() > 0).all();
      if (!marker_like || !in_quadrant) continue;
      if (best == nullptr || (c.centre - corners[k]).norm() < (best->centre - corners[k]).norm()) {
        best = &c;
      }
    }
    if (best == nullptr) return std::nullopt;
    markers[k] = best->centre;
  }
  return markers;
}

std::optional<CalibrationResult> PoseFromPoints(const std::array<Eigen::Vector3d, 4>& table_points,
                                                const std::array<Eigen::Vector2d, 4>& pixels,
                                                const cv::Size& size,
                                                const camera::CameraModel& intrinsics) {
  CalibrationResult result;
  result.points = pixels;
  camera::CameraModel& camera = result.camera;
  camera = intrinsics;
  camera.width = size.width;
  camera.height = size.height;
  if (!(intrinsics.fx > 0)) {
    camera.fx = camera.fy = size.width;
    camera.cx = 0.5 * (size.width - 1);
    camera.cy = 0.5 * (size.height - 1);
    camera.distortion = {};
  }
  const cv::Matx33d k(camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1);
  const std::vector<double> distortion(camera.distortion.begin(), camera.distortion.end());
  std::vector<cv::Point3d> object;
  std::vector<cv::Point2d> image;
  for (int i = 0; i < 4; ++i) {
    object.emplace_back(table_points[i].x(), table_points[i].y(), table_points[i].z());
    image.emplace_back(pixels[i].x(), pixels[i].y());
  }
  cv::Vec3d rvec, tvec;
  if (!cv::solvePnP(object, image, k, distortion, rvec, tvec, false, cv::SOLVEPNP_IPPE)) {
    return std::nullopt;
  }
  cv::solvePnPRefineLM(object, image, k, distortion, rvec, tvec);
  cv::Matx33d r;
  cv::Rodrigues(rvec, r);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) camera.rotation(i, j) = r(i, j);
    camera.translation(i) = tvec[i];
  }
  double sum = 0;
  for (int i = 0; i < 4; ++i) sum += (camera.Project(table_points[i]) - pixels[i]).squaredNorm();
  result.rms_reprojection_px = std::sqrt(sum / 4);
  return result;
}

std::optional<CalibrationResult> CalibrateTable(const cv::Mat& image, const MarkerLayout& layout,
                                                const camera::CameraModel& intrinsics) {
  const auto markers = FindCornerMarkers(image);
  if (!markers) return std::nullopt;
  return PoseFromPoints(layout.centres, *markers, image.size(), intrinsics);
}

std::optional<MarkerLayout> MarkersOnTableSeen(const cv::Mat& image,
                                               const std::array<Eigen::Vector2d, 4>& pixels,
                                               const physics::TableParameters& table,
                                               double height) {
  const TableSearch search = FindTable(image);
  if (!search.table) return std::nullopt;
  // The corners in image order: top-left, top-right, bottom-right, bottom-left (by the sums and
  // differences of their coordinates).
  std::array<Eigen::Vector2d, 4> corners = search.table->corners;
  const auto by = [&](auto key) {
    return *std::min_element(corners.begin(), corners.end(),
                             [&](const auto& a, const auto& b) { return key(a) < key(b); });
  };
  const std::array<Eigen::Vector2d, 4> ordered = {
      by([](const Eigen::Vector2d& p) { return p.x() + p.y(); }),
      by([](const Eigen::Vector2d& p) { return p.y() - p.x(); }),
      by([](const Eigen::Vector2d& p) { return -p.x() - p.y(); }),
      by([](const Eigen::Vector2d& p) { return p.x() - p.y(); })};
  const std::array<cv::Point2f, 4> image_points = {
      cv::Point2f(ordered[0].x(), ordered[0].y()), cv::Point2f(ordered[1].x(), ordered[1].y()),
      cv::Point2f(ordered[2].x(), ordered[2].y()), cv::Point2f(ordered[3].x(), ordered[3].y())};
  const float l = static_cast<float>(table.length), w = static_cast<float>(table.width);
  const std::array<cv::Point2f, 4> table_points = {cv::Point2f(0, w), cv::Point2f(l, w),
                                                   cv::Point2f(l, 0), cv::Point2f(0, 0)};
  const cv::Mat h = cv::getPerspectiveTransform(image_points.data(), table_points.data());
  MarkerLayout layout;
  for (int i = 0; i < 4; ++i) {
    const cv::Mat p = h * (cv::Mat_<double>(3, 1) << pixels[i].x(), pixels[i].y(), 1.0);
    layout.centres[i] = {p.at<double>(0) / p.at<double>(2), p.at<double>(1) / p.at<double>(2),
                         height};
  }
  return layout;
}

double CalibrationDisagreementPx(const TableRegion& found, const camera::CameraModel& camera,
                                 const physics::TableParameters& table) {
  double largest = 0;
  for (const Eigen::Vector3d& corner :
       {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(table.length, 0, 0),
        Eigen::Vector3d(table.length, table.width, 0), Eigen::Vector3d(0, table.width, 0)}) {
    const Eigen::Vector2d projected = camera.Project(corner);
    double nearest = HUGE_VAL;
    for (const Eigen::Vector2d& c : found.corners) nearest = std::min(nearest, (c - projected).norm());
    largest = std::max(largest, nearest);
  }
  return largest;
}

}  // namespace billiard::estimator
