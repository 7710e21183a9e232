// The camera over the table: a pinhole with OpenCV's lens distortion (k1, k2, p1, p2, k3) and a
// pose relative to the table. Shared by the renderer (sim/render/) and the estimator
// (estimator/), so that both speak of the same pixels.
//
// Module: billiard::camera, below both. Includes the physics (sim/physics/, for the table's
// size) and nothing else of the project; the JSON format below is read with nlohmann-json.
//
// Table frame: origin at a corner of the playing surface, x along the long side, y along the short
// side, z up from the cloth [m]. Camera frame (OpenCV): x right, y down in the image, z along the
// optical axis. A ball's centre is one radius above the cloth, so a pixel is mapped back to the
// table at z = r, not on the cloth.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>

#include "sim/physics/parameters.h"

namespace billiard::camera {

struct CameraModel {
  int width = 0, height = 0;                               // image size [px]
  double fx = 0, fy = 0, cx = 0, cy = 0;                   // intrinsics [px]
  std::array<double, 5> distortion{};                      // k1, k2, p1, p2, k3 (OpenCV order)
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // table -> camera
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();   // p_cam = rotation p_table + translation

  // A camera `height` metres above the centre of the table looking straight down, x to the right
  // of the image and y up it, with the focal length chosen so that the playing surface spans
  // `fill` of the image's width or height, whichever binds first.
  static CameraModel Overhead(const physics::TableParameters& table, int width, int height,
                              double height_above_cloth = 2.5, double fill = 0.92,
                              const std::array<double, 5>& distortion = {});

  // A camera at `eye` looking at `target` (table coordinates [m]), with the image's up towards
  // the table's +z (its x axis level), a horizontal field of view of `horizontal_fov` [rad], no
  // distortion: the oblique views of a phone held over the table or a broadcast camera.
  static CameraModel LookingAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                               int width, int height, double horizontal_fov);

  // Pixel (u, v) of a point in table coordinates (in front of the camera).
  Eigen::Vector2d Project(const Eigen::Vector3d& table_point) const;
  // The point at height z above the cloth seen at `pixel`.
  Eigen::Vector3d Unproject(const Eigen::Vector2d& pixel, double z) const;
  // Unit direction, in table coordinates, of the ray through `pixel`.
  Eigen::Vector3d Ray(const Eigen::Vector2d& pixel) const;
  // The camera's centre in table coordinates.
  Eigen::Vector3d Centre() const;
  // Metres on the cloth per pixel near `table_point` (the mean of the two axes).
  double MetresPerPixel(const Eigen::Vector3d& table_point) const;

  // Normalized image coordinates (x/z, y/z) with and without the lens distortion.
  Eigen::Vector2d Distort(const Eigen::Vector2d& undistorted) const;
  Eigen::Vector2d Undistort(const Eigen::Vector2d& distorted) const;
};

// JSON: {"width":..,"height":..,"fx":..,"fy":..,"cx":..,"cy":..,"distortion":[k1,k2,p1,p2,k3],
//        "rotation":[9 numbers, row-major],"translation":[3 numbers]}.
// Throws std::invalid_argument with a one-line reason on a malformed or non-finite camera.
CameraModel ParseCameraModel(const std::string& json_text, const std::string& origin);
CameraModel LoadCameraModel(const std::string& path);
std::string CameraModelJson(const CameraModel& camera);

}  // namespace billiard::camera
