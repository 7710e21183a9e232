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

#include <opencv2/core.hpp>

#include "estimator/ball_class.h"
#include "estimator/ball_outline.h"
#include "estimator/cloth_model.h"
#include "estimator/table_finder.h"

namespace billiard::estimator {

// Outlines whose radius is within this factor of the scale's agree with it.
inline constexpr double kScaleAgreement = 1.12;

struct BallScale {
  Eigen::Vector3d inverse_depth = Eigen::Vector3d::UnitZ();  // relative, as TableRegion's
  double radius_at_centre = 0;                               // [px]
  // Measured: the outlines' rays that agree with it (ScaleFromOutlines); 0 where it is given.
  double support = 0;

  double RadiusAt(const Eigen::Vector2d& pixel) const {
    return radius_at_centre * inverse_depth.dot(pixel.homogeneous());
  }
};

// The least radius at the table's centre [px] that a found table allows its balls: no table is
// larger, for its balls, than its game's largest regulation table (LargestTableRatio), and the
// found sides give the width in pixels. There is no such bound above: toy and home tables come
// in any size (dev2's fou frames: a toy table, balls twice as large for its width as on a 9-ft).
double LeastPlausibleScale(const TableRegion& table, BallSet set);

// A ball's radius over the playing surface's width on the largest table its set is played on
// (regulation sizes; ball_scale.cc cites them).
double LargestTableRatio(BallSet set);

// The scale most of the outlines agree with (within kScaleAgreement), each weighed by the rays
// that found its edge: the weighted median of the heaviest agreeing group, so that a pocket, a
// shadow, a half-hidden ball or a piece of a rack among them changes nothing. Where some
// outlines are at least `least_plausible` [px at the table's centre] (LeastPlausibleScale), the
// heaviest group of those: the pieces of a rack that the cloth's colour breaks up (blue balls on
// a blue cloth) can outweigh the one ball lying apart, never the table's size. Empty without
// outlines, and where none is at least `least_plausible` (a rack's pieces alone, no ball lying
// apart: the table's own scale, ScaleFromTable, or the scale already settled, is the better one).
std::optional<BallScale> ScaleFromOutlines(const TableRegion& table,
                                           const std::vector<BallOutline>& outlines,
                                           double least_plausible = 0);

// The scale the compact blobs of not-cloth on the table say (not_cloth.h): blobs about as wide as
// high and filling their bounding ellipse, mostly single balls, outlined (ball_outline.h) and
// given to ScaleFromOutlines (with `least_plausible`) where enough of their rays found an edge.
// Empty without such blobs (an empty table, a rack).
std::optional<BallScale> ScaleFromBlobs(const cv::Mat& bgr, const TableRegion& table,
                                        const ClothModel& cloth, double least_plausible = 0);

// The scale the table's size says, for balls of `ball_to_table_width` (radius over the width of
// the playing surface, 0.0225 for pool balls on a 9-ft table): for an empty table, or one whose
// balls all touch (a rack). As good as the table is known: a 7-ft table's balls look 29 % larger.
BallScale ScaleFromTable(const TableRegion& table, double ball_to_table_width);

}  // namespace billiard::estimator
