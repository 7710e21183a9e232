#include "sim/render/occluders.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace billiard::render {

namespace {

// A capsule's projected box is widened by this many pixels: the lens bends the box's edges, so
// the projections of its corners do not quite bound it.
constexpr double kBoxMarginPx = 12.0;

struct Hit {
  double distance = std::numeric_limits<double>::infinity();  // along the ray [m]
  double coverage = 0;                                         // of the pixel, 0..1
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

// Where the ray from `origin` along unit `d` passes closest to the capsule's axis, and whether
// it meets the capsule there: the closest points of a ray and a segment (Eberly's), the capsule's
// radius at the segment's point, the pixel's share inside it from the ray's margin.
Hit RayCapsule(const Eigen::Vector3d& origin, const Eigen::Vector3d& d, const Capsule& c,
               double pixel_angle) {
  const Eigen::Vector3d axis = c.to - c.from, w = origin - c.from;
  const double aa = axis.squaredNorm(), ad = axis.dot(d), aw = axis.dot(w), dw = d.dot(w);
  const double denominator = aa - ad * ad;  // |d| = 1
  double s = aa > 0 && denominator > 1e-12 ? std::clamp((aw - ad * dw) / denominator, 0.0, 1.0)
                                           : 0.0;
  double t = std::max(0.0, ad * s - dw);
  if (aa > 0) s = std::clamp((t * ad + aw) / aa, 0.0, 1.0);  // the segment's point nearest t
  t = std::max(0.0, (c.from + s * axis - origin).dot(d));
  const Eigen::Vector3d on_axis = c.from + s * axis;
  const double miss = (origin + t * d - on_axis).norm();
  const double radius = c.from_radius + s * (c.to_radius - c.from_radius);
  const double pixel = std::max(1e-9, t * pixel_angle);
  Hit hit;
  hit.coverage = std::clamp((radius - miss) / pixel + 0.5, 0.0, 1.0);
  if (hit.coverage <= 0) return hit;
  const double inside = std::sqrt(std::max(0.0, radius * radius - miss * miss));
  hit.distance = t - inside;
  const Eigen::Vector3d surface = origin + hit.distance * d - on_axis;
  hit.normal = surface.norm() > 0 ? surface.normalized() : Eigen::Vector3d(-d);
  return hit;
}

// The nearest distance along the ray at which a ball is met (infinity where none is).
double NearestBall(const Eigen::Vector3d& origin, const Eigen::Vector3d& d,
                   const std::vector<OccludedBall>& balls) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const OccludedBall& ball : balls) {
    const Eigen::Vector3d oc = origin - ball.centre;
    const double b = oc.dot(d), q = oc.squaredNorm() - ball.radius * ball.radius;
    const double discriminant = b * b - q;
    if (discriminant >= 0) nearest = std::min(nearest, -b - std::sqrt(discriminant));
  }
  return nearest;
}

// The pixels a capsule may cover: the box of its bounding box's corners' projections, widened.
cv::Rect ProjectedBox(const camera::CameraModel& camera, const Capsule& c) {
  const double r = std::max(c.from_radius, c.to_radius);
  const Eigen::Vector3d low = c.from.cwiseMin(c.to).array() - r;
  const Eigen::Vector3d high = c.from.cwiseMax(c.to).array() + r;
  double u0 = HUGE_VAL, v0 = HUGE_VAL, u1 = -HUGE_VAL, v1 = -HUGE_VAL;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p((corner & 1) ? high.x() : low.x(), (corner & 2) ? high.y() : low.y(),
                            (corner & 4) ? high.z() : low.z());
    const Eigen::Vector2d pixel = camera.Project(p);
    u0 = std::min(u0, pixel.x());
    v0 = std::min(v0, pixel.y());
    u1 = std::max(u1, pixel.x());
    v1 = std::max(v1, pixel.y());
  }
  const cv::Rect box(cv::Point(static_cast<int>(std::floor(u0 - kBoxMarginPx)),
                               static_cast<int>(std::floor(v0 - kBoxMarginPx))),
                     cv::Point(static_cast<int>(std::ceil(u1 + kBoxMarginPx)),
                               static_cast<int>(std::ceil(v1 + kBoxMarginPx))));
  return box & cv::Rect(0, 0, camera.width, camera.height);
}

}  // namespace

cv::Mat DrawOccluders(const camera::CameraModel& camera, const std::vector<Capsule>& capsules,
                      const std::vector<OccludedBall>& balls,
                      const Eigen::Vector3d& light_direction, double ambient, cv::Mat* frame) {
  if (frame->type() != CV_8UC3 || frame->cols != camera.width || frame->rows != camera.height) {
    throw std::invalid_argument("occluders: the frame is not the camera's size in BGR");
  }
  const Eigen::Vector3d light = light_direction.normalized(), origin = camera.Centre();
  const double pixel_angle = 1.0 / camera.fx;
  cv::Mat depth(frame->size(), CV_64F, cv::Scalar(std::numeric_limits<double>::infinity()));
  cv::Mat mask = cv::Mat::zeros(frame->size(), CV_8UC1);
  for (const Capsule& c : capsules) {
    if (c.from_radius < 0 || c.to_radius < 0) {
      throw std::invalid_argument("occluders: a capsule's radius is negative");
    }
    const cv::Rect box = ProjectedBox(camera, c);
    for (int v = box.y; v < box.y + box.height; ++v) {
      for (int u = box.x; u < box.x + box.width; ++u) {
        const Eigen::Vector3d d = camera.Ray({u, v});
        const Hit hit = RayCapsule(origin, d, c, pixel_angle);
        if (hit.coverage <= 0 || hit.distance >= depth.at<double>(v, u) ||
            hit.distance >= NearestBall(origin, d, balls)) {
          continue;
        }
        depth.at<double>(v, u) = hit.distance;
        const double shade = ambient + (1.0 - ambient) * std::max(0.0, hit.normal.dot(light));
        cv::Vec3b& pixel = frame->at<cv::Vec3b>(v, u);
        for (int k = 0; k < 3; ++k) {
          const double lit = std::min(255.0, c.colour[k] * shade);
          pixel[k] = cv::saturate_cast<uchar>(hit.coverage * lit + (1 - hit.coverage) * pixel[k]);
        }
        mask.at<uchar>(v, u) =
            std::max(mask.at<uchar>(v, u), cv::saturate_cast<uchar>(255.0 * hit.coverage));
      }
    }
  }
  return mask;
}

double VisibleShare(const camera::CameraModel& camera, const std::vector<OccludedBall>& balls,
                    std::size_t index, const cv::Mat& mask) {
  const OccludedBall& ball = balls.at(index);
  const Eigen::Vector3d origin = camera.Centre();
  const Eigen::Vector2d centre = camera.Project(ball.centre);
  // The disc's radius on a pinhole, widened: a sphere off the axis images as a larger ellipse.
  const double reach = 1.5 * camera.fx * ball.radius / (ball.centre - origin).norm() + 2.0;
  double seen = 0, count = 0;
  for (int v = static_cast<int>(centre.y() - reach); v <= centre.y() + reach; ++v) {
    for (int u = static_cast<int>(centre.x() - reach); u <= centre.x() + reach; ++u) {
      const Eigen::Vector3d d = camera.Ray({u, v});
      const double own = NearestBall(origin, d, {ball});
      if (!std::isfinite(own)) continue;
      ++count;
      const bool in_frame = u >= 0 && v >= 0 && u < mask.cols && v < mask.rows;
      if (!in_frame || NearestBall(origin, d, balls) < own) continue;
      seen += 1.0 - mask.at<uchar>(v, u) / 255.0;
    }
  }
  return count > 0 ? seen / count : 0.0;
}

}  // namespace billiard::render
