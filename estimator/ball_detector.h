// Balls in a camera frame of the table: where they are to a fraction of a pixel, and how sure.
//
// Nothing is tuned to one table or one light. Every frame teaches the detector its cloth:
//   - The cloth colour is the dominant chromaticity of the frame (the mode of a 2-D histogram),
//     refined into a coarse map of the local cloth colour, because vignetting and mixed lights
//     change both the brightness and the tint of a real cloth across the table.
//   - A pixel's "ballness" (0..1) measures how far its colour is from the local cloth colour, in a
//     way that ignores what light does to the cloth: the part of the colour along the cloth
//     colour is its brightness, so shadows (darker cloth) and cloth-tinted light (brighter cloth)
//     only count when far outside the cloth's range, while the part across the cloth colour (any
//     other hue) counts fully. Each term is linear in the colour, so an edge pixel that is part
//     ball and part cloth gets a ballness that depends on how much ball it covers, the same all
//     round the ball: what keeps the fitted centres unbiased.
//   - The playing area is the cloth's largest connected region with its holes (balls) and
//     ball-sized notches (balls on the cushion) filled: rails, pockets, diamonds and markers lie
//     outside it.
//
// Balls are found at a reduced resolution (the ball about 4.5 px in radius there) by a
// centre-surround filter on the ballness (full inside a ball-sized disc, empty around it), which
// peaks once per ball even when balls touch, and stays low along an arm or a cue (full around
// too) and on lines (never full inside). Each peak is then refined at full resolution by
// RefineAt: the ball's edge is found along rays from the centre, each where the contrast falls to
// half that of its own ray's rim (shading and highlights differ from ray to ray), and a circle is
// fitted to it with outliers (rays into a touching ball, an occluder or the cushion) dropped. The
// fit says what a ball is: enough of a round edge at the expected radius, ball-coloured inside,
// and, when brighter than the cloth, shaded like a sphere (a disc of projected light is flat).
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "sim/camera/camera_model.h"

namespace billiard::estimator {

struct BallDetection {
  Eigen::Vector2d pixel;  // centre (u, v) [px], sub-pixel, OpenCV convention (pixel centres at
                          // integers)
  double radius_px = 0;   // fitted radius of the ball's outline [px]
  double score = 0;       // 0..1: how ball-like (round edge, radius, contrast, sphere shading)
};

// The local colour of the cloth, learnt from a frame.
struct ClothModel {
  cv::Mat colour;    // CV_32FC3 (BGR) map of the cloth colour, one cell per `cell` full-res px
  double cell = 0;   // full-resolution pixels per cell of `colour`
  double noise = 0;  // robust spread of the cloth's colour across its own colour, relative
  cv::Mat area;      // CV_8UC1 playing area (255 inside) at `area_scale` of full resolution
  double area_scale = 0;
  // At the search resolution (area_scale): the cloth's colour direction and 1 / its norm, per
  // pixel, so that a frame's ballness costs a few multiplications per pixel.
  cv::Mat search_unit, search_inv_norm;
  cv::Size frame_size;  // of the frames this model was learnt from (approximately, when reduced)
  bool empty() const { return colour.empty(); }
  // The cloth colour at a full-resolution pixel.
  cv::Vec3f ColourAt(const Eigen::Vector2d& pixel) const;
  // Whether a full-resolution pixel lies in the playing area.
  bool InArea(const Eigen::Vector2d& pixel) const;
};

struct DetectorOptions {
  // Expected ball radius [px]; 0 = estimate it from the sizes of the blobs in each frame.
  double ball_radius_px = 0;
  // Detections scoring below this are not reported.
  double min_score = 0.5;
};

// The expected radius [px] of a ball of radius `ball_radius` [m] at the image centre.
double ExpectedRadiusPx(const camera::CameraModel& camera, double ball_radius);

class BallDetector {
 public:
  explicit BallDetector(DetectorOptions options = {});

  // Learns the cloth (and, without a radius option, the ball radius) from a BGR (CV_8UC3) or
  // grey (CV_8UC1) frame. A grey frame has no hue: there balls are what is much darker or
  // brighter than the cloth. About 10 ms at 1280x720; the table and its lights do not change
  // between frames, so this runs once, on Detect's first frame, and again when asked.
  void LearnCloth(const cv::Mat& image);

  // Every ball in a frame, best score first, against the cloth learnt (on the first frame, or
  // when the frame size changes).
  std::vector<BallDetection> Detect(const cv::Mat& image);

  // The ball near `predicted` (within about one radius), for a tracker: a search window of a few
  // radii, at full resolution, against the cloth learnt by the last Detect (or, before any, the
  // cloth around the window). Empty when nothing there scores min_score.
  std::optional<BallDetection> RefineAt(const cv::Mat& image, const Eigen::Vector2d& predicted,
                                        double radius_px) const;

  const ClothModel& cloth() const { return cloth_; }
  // The radius the last Detect used (the option, or the estimate).
  double radius_px() const { return radius_px_; }

 private:
  DetectorOptions options_;
  ClothModel cloth_;
  double radius_px_ = 0;
};

}  // namespace billiard::estimator
