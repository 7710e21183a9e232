#include "sim/camera/camera_model.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace billiard::camera {

CameraModel CameraModel::Overhead(const physics::TableParameters& table, int width, int height,
                                  double height_above_cloth, double fill,
                                  const std::array<double, 5>& distortion) {
  CameraModel c;
  c.width = width;
  c.height = height;
  const double f = fill * std::min(width * height_above_cloth / table.length,
                                   height * height_above_cloth / table.width);
  c.fx = c.fy = f;
  c.cx = 0.5 * (width - 1);
  c.cy = 0.5 * (height - 1);
  c.distortion = distortion;
  // Looking down: camera x = table x, camera y = -table y, optical axis = -table z.
  c.rotation = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();
  const Eigen::Vector3d centre(0.5 * table.length, 0.5 * table.width, height_above_cloth);
  c.translation = -c.rotation * centre;
  return c;
}

CameraModel CameraModel::LookingAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                                   int width, int height, double horizontal_fov) {
  CameraModel c;
  c.width = width;
  c.height = height;
  c.fx = c.fy = 0.5 * width / std::tan(0.5 * horizontal_fov);
  c.cx = 0.5 * (width - 1);
  c.cy = 0.5 * (height - 1);
  // Camera axes in table coordinates: z along the view, x level and to the right, y down.
  const Eigen::Vector3d forward = (target - eye).normalized();
  Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ());
  if (right.norm() < 1e-9) right = Eigen::Vector3d::UnitX();  // straight down
  right.normalize();
  const Eigen::Vector3d down = forward.cross(right);
  c.rotation.row(0) = right.transpose();
  c.rotation.row(1) = down.transpose();
  c.rotation.row(2) = forward.transpose();
  c.translation = -c.rotation * eye;
  return c;
}

Eigen::Vector2d CameraModel::Distort(const Eigen::Vector2d& p) const {
  const auto& [k1, k2, p1, p2, k3] = distortion;
  const double x = p.x(), y = p.y(), r2 = x * x + y * y;
  const double radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3));
  return {x * radial + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x),
          y * radial + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y};
}

Eigen::Vector2d CameraModel::Undistort(const Eigen::Vector2d& distorted) const {
  // Fixed-point iteration, as OpenCV's undistortPoints, continued to convergence: the lenses of
  // overhead table cameras are mild enough for it to contract.
  Eigen::Vector2d p = distorted;
  for (int i = 0; i < 50; ++i) {
    const Eigen::Vector2d next = p + (distorted - Distort(p));
    if ((next - p).squaredNorm() < 1e-28) return next;
    p = next;
  }
  return p;
}

Eigen::Vector2d CameraModel::Project(const Eigen::Vector3d& table_point) const {
  const Eigen::Vector3d p = rotation * table_point + translation;
  const Eigen::Vector2d d = Distort(p.head<2>() / p.z());
  return {fx * d.x() + cx, fy * d.y() + cy};
}

Eigen::Vector3d CameraModel::Ray(const Eigen::Vector2d& pixel) const {
  const Eigen::Vector2d n = Undistort({(pixel.x() - cx) / fx, (pixel.y() - cy) / fy});
  return (rotation.transpose() * Eigen::Vector3d(n.x(), n.y(), 1.0)).normalized();
}

Eigen::Vector3d CameraModel::Centre() const { return -rotation.transpose() * translation; }

Eigen::Vector3d CameraModel::Unproject(const Eigen::Vector2d& pixel, double z) const {
  const Eigen::Vector3d c = Centre(), d = Ray(pixel);
  return c + (z - c.z()) / d.z() * d;
}

double CameraModel::MetresPerPixel(const Eigen::Vector3d& table_point) const {
  const Eigen::Vector2d pixel = Project(table_point);
  const double z = table_point.z();
  const double du = (Unproject(pixel + Eigen::Vector2d(1, 0), z) - table_point).norm();
  const double dv = (Unproject(pixel + Eigen::Vector2d(0, 1), z) - table_point).norm();
  return 0.5 * (du + dv);
}

CameraModel ParseCameraModel(const std::string& json_text, const std::string& origin) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(json_text);
  } catch (const nlohmann::json::exception& e) {
    // parse_error, and out_of_range for a number beyond double range (1e400).
    throw std::invalid_argument(origin + ": not valid JSON (" + e.what() + ")");
  }
  const auto numbers = [&](const char* key, std::size_t count) {
    if (!j.is_object() || !j.contains(key)) {
      throw std::invalid_argument(origin + ": missing \"" + key + "\"");
    }
    const nlohmann::json& v = count == 1 ? nlohmann::json::array({j.at(key)}) : j.at(key);
    if (!v.is_array() || v.size() != count) {
      throw std::invalid_argument(origin + ": \"" + key + "\" must hold " + std::to_string(count) +
                                  " numbers");
    }
    std::vector<double> out;
    for (const auto& x : v) {
      if (!x.is_number() || !std::isfinite(x.get<double>())) {
        throw std::invalid_argument(origin + ": \"" + key + "\" must hold finite numbers");
      }
      out.push_back(x.get<double>());
    }
    return out;
  };
  CameraModel c;
  c.width = static_cast<int>(numbers("width", 1)[0]);
  c.height = static_cast<int>(numbers("height", 1)[0]);
  c.fx = numbers("fx", 1)[0];
  c.fy = numbers("fy", 1)[0];
  c.cx = numbers("cx", 1)[0];
  c.cy = numbers("cy", 1)[0];
  const auto k = numbers("distortion", 5);
  std::copy(k.begin(), k.end(), c.distortion.begin());
  const auto r = numbers("rotation", 9), t = numbers("translation", 3);
  c.rotation = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(r.data());
  c.translation = Eigen::Map<const Eigen::Vector3d>(t.data());
  if (c.width <= 0 || c.height <= 0 || !(c.fx > 0) || !(c.fy > 0)) {
    throw std::invalid_argument(origin + ": image size and focal lengths must be positive");
  }
  if (!(c.rotation * c.rotation.transpose()).isIdentity(1e-6) || c.rotation.determinant() < 0) {
    throw std::invalid_argument(origin + ": \"rotation\" is not a rotation matrix");
  }
  return c;
}

CameraModel LoadCameraModel(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("cannot read camera file '" + path + "'");
  std::stringstream text;
  text << in.rdbuf();
  return ParseCameraModel(text.str(), path);
}

std::string CameraModelJson(const CameraModel& c) {
  nlohmann::json j;
  j["width"] = c.width;
  j["height"] = c.height;
  j["fx"] = c.fx;
  j["fy"] = c.fy;
  j["cx"] = c.cx;
  j["cy"] = c.cy;
  j["distortion"] = c.distortion;
  const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> r = c.rotation;
  j["rotation"] = std::vector<double>(r.data(), r.data() + 9);
  j["translation"] = {c.translation.x(), c.translation.y(), c.translation.z()};
  return j.dump(2);
}

}  // namespace billiard::camera
