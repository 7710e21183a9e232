// The detector's hard suite (issue 45): rendered frames of the cases that lose real tables, with
// the truth of the table's sides and of the balls.
//
// Each case is a pool table seen by the renderer's camera (sim/render), on three cloths (green,
// blue, burgundy), with 16 balls scattered and with the eight-ball rack:
//   - arm: an overhead camera (as CameraModel::Overhead, no lens distortion); a player's arm (a
//     skin-toned tapered capsule from the elbow, 35 cm up outside the long side, to the wrist,
//     10 cm over the cloth), the hand (a shorter, fatter capsule) and the cue (a wooden capsule
//     tapering from 15 mm at the butt to 6 mm at the tip) across the table;
//   - player: the same camera; a player leaning over the long side (a dark torso from the hips to
//     the shoulders, a capsule of 18 cm, the shoulders across it, the head over the cushion) and
//     one arm reaching in;
//   - out-of-frame end: the overhead camera moved along the table by a third of its length, so
//     that a third of the table is out of the frame at one end;
//   - out-of-frame turned: the camera moved across the table by 0.45 of its width and turned by
//     12 degrees about its axis, so that a long side and two corners leave the frame (a third of
//     the table);
//   - lens k1=-0.3: the overhead camera with barrel distortion k1 = -0.3 (OpenCV's model, the
//     renderer's lens), the table filling the frame: its sides bow by some 26 px;
//   - elevation 15, 20, 30, 45: a camera beside the long side looking at the table's middle from
//     that many degrees above the cloth, as far as it needs to be to have the table in its frame.
// Occlusion is geometric (render/occluders.h): a ball is hidden, and its label ignored as a real
// set's mostly hidden balls are, when less than half of its image is seen (past the occluders and
// the other balls) or its centre projects outside the frame.
//
// The truth of a side is the playing surface's edge as the camera sees it (table_pose.h's
// convention): where the cushion's face meets the cloth when the camera sees the face, the line of
// the cushion's nose when the camera is beyond that cushion; projected by the camera, lens
// included, and sampled along its length where it is in the frame. The share of the playing
// surface in the frame is the seen part.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "bench/detection_benchmark.h"
#include "estimator/table_finder.h"
#include "sim/physics/parameters.h"

namespace billiard::bench {

struct HardFrame {
  LabelledFrame frame;    // image and ball labels
  std::string condition;  // "arm", "player", "out-of-frame end", ..., "elevation 15"
  // Per side of the playing surface (table corners (0, 0), (L, 0), (L, W), (0, W), side k from
  // corner k to k + 1): its edge's points in the frame [px], empty when it is out of it.
  std::array<std::vector<Eigen::Vector2d>, 4> sides;
  double seen_share = 1.0;  // of the playing surface in the frame
  // The acceptance: every side within this [px] (2, 3 under the lens).
  double tolerance_px = 2.0;
};

// The suite's frames, rendered, with their truth; only the cases whose condition begins with
// `only_case` when it is given (the same frames as in the whole suite).
std::vector<HardFrame> RenderHardSuite(const physics::ModelParameters& params,
                                       std::uint32_t seed = 2026,
                                       const std::string& only_case = "");

// The error [px] of a found table's sides against the true ones: for each true side in the frame,
// the largest distance of its points from the nearest found side (the found side it matches: its
// line, or through the lens the finder found the curve that is its image,
// TableRegion::DistanceToSide); -1 for a side out of the frame.
std::array<double, 4> SideErrorsPx(const HardFrame& truth, const estimator::TableRegion& table);

}  // namespace billiard::bench
