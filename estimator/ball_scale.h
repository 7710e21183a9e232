// How large a ball looks at each place in the frame.
//
// A ball of radius R whose centre is at depth z from a pinhole of focal length f looks about
// f R / z pixels in radius (to within the cosine of its angle off the optical axis), and the
// inverse depth of the table's points is an affine function of the pixel (table_finder.h). So
// the apparent radius is one number, the radius at the table's centre, times the table's
// relative inverse depth: measured from a few balls anywhere, known everywhere, for an overhead
// camera (where it is the same everywhere) and for an oblique one (where the near balls look
// twice the far ones) alike.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "estimator/ball_outline.h"
#include "estimator/table_finder.h"

namespace billiard::estimator {

// Outlines whose radius is within this factor of the scale's agree with it.
inline constexpr double kScaleAgreement = 1.12;

struct BallScale {
  Eigen::Vector3d inverse_depth = Eigen::Vector3d::UnitZ();  // relative, as TableRegion's
  double radius_at_centre = 0;                               // [px]

  double RadiusAt(const Eigen::Vector2d& pixel) const {
    return radius_at_centre * inverse_depth.dot(pixel.homogeneous());
  }
};

// The scale most of the outlines agree with (within kScaleAgreement): the median of the largest
// agreeing group, so that a pocket, a shadow or a half-hidden ball among them changes nothing.
// Empty without outlines.
std::optional<BallScale> ScaleFromOutlines(const TableRegion& table,
                                           const std::vector<BallOutline>& outlines);

}  // namespace billiard::estimator
