#include "estimator/table_pose.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include "estimator/table_finder.h"

namespace billiard::estimator {

namespace {

// The focal lengths tried [image widths]: kFocalSteps per doubling from kMinFocal to kMaxFocal
// (table cameras: a wide lens over a home table to a broadcast camera's zoom). A fit is taken
// over the image width's only when it reprojects better by kFocalTiePx (an overhead view fits
// them all within noise).
constexpr double kMinFocal = 0.3, kMaxFocal = 3.2;
constexpr int kFocalSteps = 8;
constexpr double kFocalTiePx = 0.1;

// Twice the signed area of a quadrilateral in the image (v down): negative when its corners
// run as the table's (0, 0), (L, 0), (L, W), (0, W) do under a camera looking down.
double SignedArea(const std::array<Eigen::Vector2d, 4>& p) {
  double sum = 0;
  for (int i = 0; i < 4; ++i) {
    sum += p[i].x() * p[(i + 1) % 4].y() - p[(i + 1) % 4].x() * p[i].y();
  }
  return sum;
}

// Each side's image line (unit normal, so that a point's product is its distance [px]) and its
// two ends on the table [m].
struct SideLines {
  std::array<Eigen::Vector3d, 4> image;
  std::array<std::array<Eigen::Vector3d, 2>, 4> ends;
};

// The pose's parameters: the rotation vector, the translation, and the focal length's logarithm.
using PoseParameters = Eigen::Matrix<double, 7, 1>;
using SideResiduals = Eigen::Matrix<double, 8, 1>;

PoseParameters ParametersOf(const camera::CameraModel& camera) {
  const Eigen::AngleAxisd turn(camera.rotation);
  PoseParameters x;
  x << turn.angle() * turn.axis(), camera.translation, std::log(camera.fx);
  return x;
}

camera::CameraModel CameraOf(const PoseParameters& x, camera::CameraModel camera) {
  const Eigen::Vector3d r = x.head<3>();
  camera.rotation = r.norm() > 0 ? Eigen::AngleAxisd(r.norm(), r.normalized()).toRotationMatrix()
                                 : Eigen::Matrix3d::Identity();
  camera.translation = x.segment<3>(3);
  camera.fx = camera.fy = std::exp(x(6));
  return camera;
}

// The distances [px] of the sides' projected ends from the lines found.
SideResiduals Residuals(const SideLines& sides, const camera::CameraModel& camera) {
  SideResiduals r;
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < 2; ++k) {
      r(2 * i + k) = sides.image[i].dot(camera.Project(sides.ends[i][k]).homogeneous());
    }
  }
  return r;
}

// Levenberg-Marquardt (Marquardt 1963) on the sides' distances, from `camera`'s pose, the focal
// length too when `fit_focal`; the derivatives by central differences. Returns the distances' RMS.
double RefinePose(const SideLines& sides, bool fit_focal, camera::CameraModel* camera) {
  constexpr int kIterations = 60;
  constexpr double kStep = 1e-6;
  const int n = fit_focal ? 7 : 6;
  PoseParameters x = ParametersOf(*camera);
  double cost = Residuals(sides, *camera).squaredNorm();
  double lambda = 1e-3;
  for (int iteration = 0; iteration < kIterations; ++iteration) {
    Eigen::Matrix<double, 8, 7> jacobian = Eigen::Matrix<double, 8, 7>::Zero();
    for (int j = 0; j < n; ++j) {
      PoseParameters up = x, down = x;
      const double h = kStep * std::max(1.0, std::abs(x(j)));
      up(j) += h;
      down(j) -= h;
      jacobian.col(j) = (Residuals(sides, CameraOf(up, *camera)) -
                         Residuals(sides, CameraOf(down, *camera))) / (2 * h);
    }
    const SideResiduals r = Residuals(sides, CameraOf(x, *camera));
    const Eigen::MatrixXd jtj = (jacobian.transpose() * jacobian).topLeftCorner(n, n);
    const Eigen::VectorXd jtr = (jacobian.transpose() * r).head(n);
    Eigen::MatrixXd damped = jtj;
    damped.diagonal() += lambda * jtj.diagonal();
    PoseParameters next = x;
    next.head(n) -= damped.ldlt().solve(jtr);
    const double next_cost = Residuals(sides, CameraOf(next, *camera)).squaredNorm();
    if (next_cost < cost) {
      x = next;
      lambda = std::max(1e-12, lambda / 10);
      if (cost - next_cost < 1e-14 * (1 + cost)) {
        cost = next_cost;
        break;
      }
      cost = next_cost;
    } else {
      lambda *= 10;
    }
  }
  *camera = CameraOf(x, *camera);
  return std::sqrt(cost / 8);
}

// The sides of the table as found (image lines through the corners) and where they are on the
// table (their ends, at the height the camera sees each at).
SideLines SidesSeen(const std::array<Eigen::Vector2d, 4>& pixels,
                    const std::array<Eigen::Vector3d, 4>& on_cloth,
                    const camera::CameraModel& camera, double nose_height) {
  SideLines sides;
  const Eigen::Vector3d eye = camera.Centre();
  const Eigen::Vector3d middle = 0.25 * (on_cloth[0] + on_cloth[1] + on_cloth[2] + on_cloth[3]);
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d a = on_cloth[i], b = on_cloth[(i + 1) % 4];
    sides.image[i] = pixels[i].homogeneous().cross(pixels[(i + 1) % 4].homogeneous());
    sides.image[i] /= sides.image[i].head<2>().norm();
    // The camera beyond the side's line, on the far side from the table's middle, sees the
    // cushion from behind: its nose. Otherwise the cushion's face, down to the cloth.
    const Eigen::Vector2d along = (b - a).head<2>().normalized();
    const Eigen::Vector2d normal(-along.y(), along.x());
    const bool behind =
        normal.dot((eye - a).head<2>()) * normal.dot((middle - a).head<2>()) < 0;
    const double z = behind ? nose_height : 0.0;
    sides.ends[i] = {Eigen::Vector3d(a.x(), a.y(), z), Eigen::Vector3d(b.x(), b.y(), z)};
  }
  return sides;
}

// The largest over the smallest depth of the table's corners from the camera.
double DepthRatio(const std::array<Eigen::Vector3d, 4>& corners, const camera::CameraModel& camera) {
  double nearest = HUGE_VAL, farthest = 0;
  for (const auto& c : corners) {
    const double depth = (camera.rotation * c + camera.translation).z();
    nearest = std::min(nearest, depth);
    farthest = std::max(farthest, depth);
  }
  return farthest / nearest;
}

bool HasDistortion(const camera::CameraModel& c) {
  return std::any_of(c.distortion.begin(), c.distortion.end(), [](double d) { return d != 0.0; });
}

}  // namespace

camera::CameraModel LensIntrinsics(const RadialLens& lens, const cv::Size& size, double focal_px) {
  camera::CameraModel c;
  c.fx = c.fy = focal_px;
  c.cx = 0.5 * (size.width - 1);
  c.cy = 0.5 * (size.height - 1);
  if (!lens.IsPinhole()) {
    c.cx = lens.centre.x();
    c.cy = lens.centre.y();
    c.distortion[0] = lens.k1 * std::pow(focal_px / lens.focal_px, 2);
  }
  return c;
}

std::array<Eigen::Vector3d, 4> TablePointsOf(const TableCornerPixels& corners,
                                             const physics::TableParameters& table, double z) {
  // Unit coordinates (along the long side, along the short side) of each corner, the first one
  // at (0, 0) and the long side first or second.
  std::array<Eigen::Vector2d, 4> unit = {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0),
                                         Eigen::Vector2d(1, 1), Eigen::Vector2d(0, 1)};
  if (!corners.first_side_long) {
    for (auto& u : unit) u = Eigen::Vector2d(u.y(), u.x());
  }
  const auto pixel_of = [&](const Eigen::Vector2d& u) {
    for (int i = 0; i < 4; ++i) {
      if ((unit[i] - u).norm() < 0.5) return corners.pixels[i];
    }
    return corners.pixels[0];
  };
  // The x axis to the image's right (or up it); then y so that the camera looks down.
  const Eigen::Vector2d x_axis = pixel_of({1, 0}) + pixel_of({1, 1}) - pixel_of({0, 0}) -
                                 pixel_of({0, 1});
  if (x_axis.x() < 0 || (x_axis.x() == 0 && x_axis.y() > 0)) {
    for (auto& u : unit) u = Eigen::Vector2d(1, 1) - u;
  }
  const std::array<Eigen::Vector2d, 4> in_table_order = {pixel_of({0, 0}), pixel_of({1, 0}),
                                                         pixel_of({1, 1}), pixel_of({0, 1})};
  if (SignedArea(in_table_order) > 0) {
    for (auto& u : unit) u.y() = 1 - u.y();
  }
  std::array<Eigen::Vector3d, 4> points;
  for (int i = 0; i < 4; ++i) {
    points[i] = {unit[i].x() * table.length, unit[i].y() * table.width, z};
  }
  return points;
}

std::optional<CalibrationResult> CalibrateFromCorners(const TableCornerPixels& corners,
                                                      const cv::Size& size,
                                                      const physics::TableParameters& table,
                                                      double nose_height,
                                                      const camera::CameraModel& intrinsics) {
  // A first pose with every corner on the cloth, its focal length the guess's unless given; in an
  // oblique view, the grid's that fits best.
  const auto on_cloth = TablePointsOf(corners, table, 0.0);
  const bool focal_given = intrinsics.fx > 0;
  // The lens seen in the sides' bend, unless the intrinsics say theirs.
  const camera::CameraModel lens_intrinsics =
      corners.lens.IsPinhole() || HasDistortion(intrinsics)
          ? intrinsics
          : LensIntrinsics(corners.lens, size, focal_given ? intrinsics.fx : size.width);
  std::optional<CalibrationResult> first =
      PoseFromPoints(on_cloth, corners.pixels, size, lens_intrinsics);
  const bool fit_focal =
      !focal_given && first && DepthRatio(on_cloth, first->camera) > kOverheadDepthRatio;
  if (fit_focal) {
    const double guess_rms = first->rms_reprojection_px;
    for (double f = kMinFocal; f <= kMaxFocal; f *= std::pow(2.0, 1.0 / kFocalSteps)) {
      const auto fit = PoseFromPoints(on_cloth, corners.pixels, size,
                                      LensIntrinsics(corners.lens, size, f * size.width));
      if (fit && fit->rms_reprojection_px < guess_rms - kFocalTiePx &&
          fit->rms_reprojection_px < first->rms_reprojection_px) {
        first = fit;
      }
    }
  }
  if (!first) return std::nullopt;
  // Then each side at the height the camera sees it at, the pose (and focal length) refined.
  const SideLines sides = SidesSeen(corners.pixels, on_cloth, first->camera, nose_height);
  CalibrationResult result = *first;
  result.rms_reprojection_px = RefinePose(sides, fit_focal, &result.camera);
  return result;
}

std::optional<TableCornerPixels> FoundTableCorners(const cv::Mat& bgr, std::string* why) {
  const TableSearch search = FindTable(bgr);
  if (!search.table) {
    *why = search.reason;
    return std::nullopt;
  }
  const TableRegion& t = *search.table;
  const Eigen::Vector2d first = t.TableAt(t.corners[1]) - t.TableAt(t.corners[0]);
  return TableCornerPixels{t.corners, std::abs(first.x()) > std::abs(first.y()), t.lens};
}

}  // namespace billiard::estimator
