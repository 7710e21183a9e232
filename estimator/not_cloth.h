// What on the playing surface is not its cloth (local_cloth.h: another hue, or darker or brighter
// than the table's light makes the cloth), seen reduced by a whole factor. Its compact blobs are
// mostly single balls, whose outlines give the balls' scale (ball_detector.cc): seen with the
// table kNotClothTableSize pixels across or more (BlobFactor). Its large parts that come across
// the surface's edge are what leans over the table, which needs no detail: seen with the balls
// about kIntruderRadiusPx in radius (IntruderFactor), it costs 1-2 ms a frame.
//
// An arm, a sleeve, a body over a rail, a cue's butt: each reaches onto the playing surface from
// beyond its edge, and what lies on it (a gloved finger, a knuckle, a watch's face) can be outlined
// like a ball. A ball covers one ball's area; a rack, a cluster or a row of balls along a cushion
// a few. So a part of the not-cloth that touches the surface's edge and covers at least
// kIntruderBallAreas balls' areas is an intruder, once the not-cloth is opened by a disc of
// kIntruderOpeningRadii of a ball's radius: a cue's shaft, narrower than that, is cut from the
// ball it points at, and a ball frozen to a cushion from the cushion's shade. What is faintly not
// cloth (a contrast of kIntruderFaintContrast, local_cloth.h: between a shadow's and a ball's) and
// joined to an intruder is the intruder too, as Canny's (1986) hysteresis joins faint edges to
// strong ones: a dark glove at the end of an arm, a sleeve in the arm's shade.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "estimator/ball_scale.h"
#include "estimator/cloth_model.h"
#include "estimator/table_finder.h"

namespace billiard::estimator {

inline constexpr double kNotClothTableSize = 640.0;
inline constexpr double kIntruderRadiusPx = 4.0;
inline constexpr double kIntruderBallAreas = 8.0;
inline constexpr double kIntruderOpeningRadii = 0.5;
inline constexpr float kIntruderFaintContrast = 0.4f;

class NotClothMap {
 public:
  // The not-cloth of a BGR frame over `table`'s playing surface, on `cloth`, reduced by `factor`
  // (full-resolution pixels per map pixel, at least 1).
  NotClothMap(const cv::Mat& bgr, const TableRegion& table, const ClothModel& cloth, int factor);

  // The factors above: for the blobs of the balls' scale, and for the intruders.
  static int BlobFactor(const TableRegion& table);
  static int IntruderFactor(const BallScale& scale);

  // 255 where the surface is not cloth (the map's pixels), 0 elsewhere and off the surface.
  const cv::Mat& mask() const { return mask_; }
  // The frame's rectangle the map covers (the table's bounds in the frame), and the full-resolution
  // pixels per map pixel.
  const cv::Rect& region() const { return region_; }
  int factor() const { return factor_; }
  // A map pixel's full-resolution pixel, and back.
  Eigen::Vector2d ToFull(const Eigen::Vector2d& map_pixel) const;
  Eigen::Vector2d ToMap(const Eigen::Vector2d& full_pixel) const;

  // 255 on the intruders (above) for balls of `scale`.
  cv::Mat Intruders(const BallScale& scale) const;

 private:
  cv::Rect region_;  // of the frame, at full resolution
  int factor_ = 1;
  cv::Mat mask_, faint_, surface_;
};

}  // namespace billiard::estimator
