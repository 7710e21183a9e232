// What comes between the camera and the table in a real frame: a player's arm and hand, the cue,
// the player's torso and head leaning over the cushion. Each is a tapered capsule (the points
// within a radius of a segment, the radius going linearly from one end's to the other's; a
// sphere where both ends are one point), ray-traced through the camera's pixels (its lens
// included) after the table and the balls are rendered (table_renderer.h), so that what it hides
// is decided by geometry: a pixel shows the capsule where the pixel's ray meets it before any
// ball, and the balls in front of it stay in view.
//
// Shading is Lambertian under the renderer's light, the normal taken from the nearest point of
// the axis (exact for a cylinder, close for a gently tapered one); the capsule's outline is
// anti-aliased by the ray's margin to the surface, as the renderer's balls are.
#pragma once

#include <Eigen/Core>
#include <vector>

#include <opencv2/core.hpp>

#include "sim/camera/camera_model.h"

namespace billiard::render {

struct Capsule {
  Eigen::Vector3d from, to;  // the axis' ends, table frame [m]
  double from_radius = 0, to_radius = 0;  // [m]
  cv::Vec3b colour;  // BGR, lit straight on
};

// A ball the occluders may pass behind or in front of: its centre, table frame [m].
struct OccludedBall {
  Eigen::Vector3d centre;
  double radius = 0;
};

// Draws `capsules` into `frame` (8UC3 BGR, the camera's size) as `camera` sees them lit from
// `light_direction` (towards the light, table frame) with `ambient` of the light everywhere, and
// returns the mask of what they cover (8UC1: 255 fully, the anti-aliased share at the outline).
// Balls nearer the camera than a capsule along a ray hide it there. Throws std::invalid_argument
// on a frame of another size or type, or a negative radius.
cv::Mat DrawOccluders(const camera::CameraModel& camera, const std::vector<Capsule>& capsules,
                      const std::vector<OccludedBall>& balls,
                      const Eigen::Vector3d& light_direction, double ambient, cv::Mat* frame);

// The share of ball `index`'s image that the camera sees: of the pixels whose ray meets it, those
// where it is the nearest of `balls` and `mask` (DrawOccluders') does not cover it, from 0 to 1.
// The cushions are not counted (a ball behind the near cushion is seen).
double VisibleShare(const camera::CameraModel& camera, const std::vector<OccludedBall>& balls,
                    std::size_t index, const cv::Mat& mask);

}  // namespace billiard::render
