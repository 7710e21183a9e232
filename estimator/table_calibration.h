// The camera's pose over the table, from one frame showing the four corner markers.
//
// The markers are square ArUco-style tags on the cushion frame, one near each corner of the table.
// Their centres are found with cv::aruco (the 4x4 dictionaries, normal or inverted, i.e. white
// border); a tag whose bits do not decode (small, blurred, or not of a standard dictionary) is
// still a square quad with a high-contrast border, so the quads ArUco rejects are kept when they
// look like a marker (square, bright border against a dark ring or the reverse, the size of the
// others). The marker nearest each image corner is that corner's marker.
//
// Correspondence with the table: the camera looks down with the table's x axis to the right of
// the image and y up it (as CameraModel::Overhead), so the marker at the image's top-left is the
// one at the table's (0, W) corner, and so on. With their table coordinates and an intrinsics
// guess, cv::solvePnP (IPPE for the planar markers, then Levenberg-Marquardt) gives the pose.
// Four points fix the pose but not the focal length: a wrong guess moves the camera up or down
// and changes the mapping of the pixels back to the table by a fraction of the ball radius over
// the camera's height, which a later calibration with a checkerboard removes.
#pragma once

#include <Eigen/Core>
#include <array>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "estimator/table_finder.h"
#include "sim/camera/camera_model.h"
#include "sim/physics/parameters.h"

namespace billiard::estimator {

// The largest RMS reprojection error of the marker centres [px] a calibration is accepted with
// (`billiard calibrate --max-reprojection-px`). Markers found to a fraction of a pixel and a
// layout that is the table's reproject within a pixel (0.34 px on the real photograph); a layout
// that is not (another table's margin, markers in the wrong order) misses by tens of pixels (41.5
// px there with the default margin), and its pose puts the frame's balls in the wrong places.
inline constexpr double kMaxReprojectionPx = 3.0;

// How far, as a fraction of the radius measured in a frame, the ball radius a calibration
// predicts (ExpectedRadiusPx) may be from it before `billiard detect --calib` says so. The
// detector looks for balls of the predicted size: on the real photograph it finds 19 to 21 of
// the 21 balls looking for 12 % less to 20 % more than their radius, 9 at 18 % less. A good
// calibration predicts within 7 % (the outline measured includes the blur of the ball's edge).
inline constexpr double kMaxBallRadiusMismatch = 0.15;

// Where the markers' centres are in table coordinates [m], in image order: top-left, top-right,
// bottom-right, bottom-left.
struct MarkerLayout {
  std::array<Eigen::Vector3d, 4> centres;
  // Markers `margin` [m] outside each corner of the playing surface, diagonally, at `height` [m]
  // above the cloth.
  static MarkerLayout AroundTable(const physics::TableParameters& table, double margin,
                                  double height);
};

// The centres [px] of the four markers in image order (top-left, top-right, bottom-right,
// bottom-left); empty unless all four are found.
std::optional<std::array<Eigen::Vector2d, 4>> FindCornerMarkers(const cv::Mat& image);

struct CalibrationResult {
  camera::CameraModel camera;
  // The points the pose is fitted to [px]: the markers' centres found, or the table's corners
  // (table_pose.h).
  std::array<Eigen::Vector2d, 4> points;
  double rms_reprojection_px = 0;  // of those points
};

// The camera whose pose puts `table_points` [m] at `pixels`: cv::solvePnP (IPPE for the planar
// points, then Levenberg-Marquardt) with `intrinsics` (their focal length, principal point and
// distortion), or where its focal length is zero a guess of the image width (a 53 degree
// horizontal field of view) and the image centre. None when OpenCV finds no pose.
std::optional<CalibrationResult> PoseFromPoints(const std::array<Eigen::Vector3d, 4>& table_points,
                                                const std::array<Eigen::Vector2d, 4>& pixels,
                                                const cv::Size& size,
                                                const camera::CameraModel& intrinsics = {});

// The camera over the table. `intrinsics` supplies the image size, focal lengths, principal
// point and distortion (its pose is ignored); when its focal length is zero, a guess of the
// image width (a 53 degree horizontal field of view) and the image centre are used. Empty when
// the markers are not all found.
std::optional<CalibrationResult> CalibrateTable(const cv::Mat& image, const MarkerLayout& layout,
                                                const camera::CameraModel& intrinsics = {});

// Where the markers at `pixels` (image order) lie on the table the frame shows, without markers
// (table_finder.h): through the homography of the playing surface found, its corners in image
// order taken for the table's (0, W), (L, W), (L, 0), (0, 0) (the long side across the image, as
// CameraModel::Overhead), at `height` [m]. The cloth's plane stands for the markers' (a few
// centimetres below them): about right for a camera over the table, which is what tells a user
// the layout of a rig's markers when the one given does not fit. None when no table is found.
std::optional<MarkerLayout> MarkersOnTableSeen(const cv::Mat& image,
                                               const std::array<Eigen::Vector2d, 4>& pixels,
                                               const physics::TableParameters& table,
                                               double height);

// How far [px] the playing surface found in a frame without markers (table_finder.h) is from where
// a calibrated camera puts the table's corners on the cloth: the largest distance of a projected
// corner from the nearest corner found. The two are found independently (markers, cloth), so they
// check each other: a few pixels apart when both are right (the found corners are the cushions'
// noses, a few centimetres above the cloth), tens when the calibration is of another table or the
// finder took something else for the cloth.
double CalibrationDisagreementPx(const TableRegion& found, const camera::CameraModel& camera,
                                 const physics::TableParameters& table);

}  // namespace billiard::estimator
