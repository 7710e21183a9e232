// The camera's pose over the table without markers: from the playing surface's four corners,
// found in the frame (table_finder.h) or given, and the table's known size.
//
// Each side of the playing surface is seen where the cushion meets the cloth when the camera sees
// the cushion's face (the camera over the table, or beyond the opposite side), and at the nose
// (table_fallback.h's NoseHeight) when it sees the cushion from behind (beyond the side's rail):
// the table finder's sides are those (measured on rendered overhead frames: the corners found lie
// where the faces meet the cloth, 8.5 px inside the noses' corners at 2.2 mm a pixel). So the
// pose is first cv::solvePnP's of the four corners on the cloth (table_calibration.h's
// PoseFromPoints, as the marker calibration's of its markers), then refined (Levenberg-Marquardt)
// so that each side's ends, at the height that pose says it is seen at, lie on the side's line
// through the corners. Which table corner each is:
//   - the long side is the one the table finder says (TableRegion::image_from_table), or, for
//     corners given, the first side (corner 1 to 2);
//   - the table's x axis along it points to the image's right (up it, for a side straight up the
//     image), as CameraModel::Overhead's;
//   - the y axis makes the camera look down on the cloth (a right-handed table frame, z up).
// A rectangle's 180-degree turn looks the same: which end of the table is x = 0 is the one the
// convention picks, not the rig's head or foot.
//
// Four points give the pose's six unknowns two equations to spare; unless a focal length is
// given, one of them fits it (Zhang 2000: a rectangle's homography fixes the focal length of an
// oblique view): the focal length whose pose reprojects the corners best, over a geometric grid
// of focal lengths, then refined with the pose. An overhead view (its corners' depths within
// kOverheadDepthRatio) fits every focal length about alike (its height changes, not its map of
// the cloth), and keeps the guess of the image width. The fit's error is the RMS distance of the sides' ends from their lines [px].
#pragma once

#include <Eigen/Core>
#include <array>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "estimator/lens_estimate.h"
#include "estimator/table_calibration.h"
#include "sim/camera/camera_model.h"
#include "sim/physics/parameters.h"

namespace billiard::estimator {

// The playing surface's corners [px] in order around the table, whether the first side (corner 0
// to 1) is a long one, and the lens they were seen through: the table finder's estimate from the
// sides' bend (lens_estimate.h), a pinhole for corners given.
struct TableCornerPixels {
  std::array<Eigen::Vector2d, 4> pixels;
  bool first_side_long = true;
  RadialLens lens;
};

// The table points [m] (at height `z`) of the corners, by the convention above.
std::array<Eigen::Vector3d, 4> TablePointsOf(const TableCornerPixels& corners,
                                             const physics::TableParameters& table, double z);

// The camera from the corners (see the top of the file) in frames of `size`; `intrinsics` as
// PoseFromPoints', its focal length fitted when zero. Where the corners were seen through a lens
// and `intrinsics` has no distortion, the camera has the lens's (LensIntrinsics). None when no
// pose is found.
std::optional<CalibrationResult> CalibrateFromCorners(const TableCornerPixels& corners,
                                                      const cv::Size& size,
                                                      const physics::TableParameters& table,
                                                      double nose_height,
                                                      const camera::CameraModel& intrinsics = {});

// A camera's intrinsics of focal length `focal_px` through `lens`: the principal point at the
// lens's centre (the frame's where it is a pinhole) and OpenCV's k1 the lens's at that focal
// length, k1 (focal_px / lens.focal_px)^2 (the lens's k1 is the distortion at its assumed focal
// length; the bend a plumb line shows is k1 / f^2 whatever f is).
camera::CameraModel LensIntrinsics(const RadialLens& lens, const cv::Size& size, double focal_px);

// The corners of the table found in a BGR frame (table_finder.h); none, with FindTable's reason
// in `why`, when it finds none.
std::optional<TableCornerPixels> FoundTableCorners(const cv::Mat& bgr, std::string* why);

}  // namespace billiard::estimator
