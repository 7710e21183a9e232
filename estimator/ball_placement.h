// Where a ball may lie, which the detector holds its outlines to (ball_detector.h):
//   - on the table: its centre a little inside the cushions' noses near a pocket, where pocket
//     liners and holes look like balls, elsewhere a little inside the cloth's outline (the noses
//     are found less surely than the outline: an old cloth's worn track, a cushion's face hidden);
//   - not in a pocket's mouth: an unsure outline near a pocket beyond the noses is the mouth's
//     dark rim between its jaws;
//   - on the cloth: not mostly surrounded by what is neither cloth nor another ball (a hand, an
//     arm, a sleeve, a cue's butt) and not on what leans over the table (not_cloth.h's
//     intruders);
// and, in an oblique view, hidden in part behind the near cushion's nose, which the outline is
// fitted and scored around (ball_outline.h's Occluder).
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "estimator/ball_detector.h"
#include "estimator/ball_outline.h"
#include "estimator/ball_scale.h"
#include "estimator/cloth_model.h"
#include "estimator/table_finder.h"

namespace billiard::estimator {

// Where a ball of `radius` [px] centred at `centre` [px] touches the cloth, as the camera sees
// it. The centre is a radius above the cloth, and a height there is seen shifted away from the
// camera by its length times the cosine of the line of sight's elevation e over the cloth (in the
// ball's own pixels: `radius` per ball radius). The table's homography gives e where the ball is:
// a small circle on the cloth looks like an ellipse whose minor over major axis is sin e, its
// minor axis along the view, pointing to the camera where the inverse depth grows. From overhead
// (e = 90 degrees) the centre itself; from 15 degrees 0.97 of a radius nearer the camera.
Eigen::Vector2d GroundPoint(const TableRegion& table, const Eigen::Vector2d& centre, double radius);

// Whether a ball of `radius` [px] may be centred at `centre`: where it touches the cloth
// (GroundPoint) within half a radius outside the cloth's outline, and near a pocket (within 3
// radii of a corner or the middle of a side) within half a radius outside the cushions' noses. A
// ball against the far cushion in a low view has its centre beyond the cushion's foot: from 15
// degrees some 0.7 of a radius.
bool OnTable(const TableRegion& table, const Eigen::Vector2d& centre, double radius);

// Whether an outline scoring `score` is a pocket's mouth rather than a ball: unsure (below
// kSureScore), near a pocket and beyond the cushions' noses.
bool InPocketMouth(const TableRegion& table, const Eigen::Vector2d& centre, double radius,
                   double score);

// The near cushion's nose in an oblique view, as an occluder of the balls against it: the cushion
// stands between the camera and such a ball and hides its lower part, which is not missing from
// its outline but out of view. The near side is the one nearest the camera (the largest inverse
// depth at its middle); an overhead camera sees every ball whole (no occluder).
Occluder NearCushion(const TableRegion& table, double radius);

// The balls of `balls` that lie on the cloth: an unsure one is not when it is mostly surrounded
// by something else or lies on what leans over the table (an intruder of not_cloth.h); a sure one
// only when both (a logo on a player's cap, a knuckle in the middle of a hand), for a ball is
// never under an arm and a sure ball in a rack is surrounded by balls that were not all found.
// The intruders are looked for only when a ball needs them.
std::vector<BallDetection> OnCloth(const cv::Mat& bgr, const TableRegion& table,
                                   const ClothModel& cloth, const BallScale& scale,
                                   const std::vector<BallDetection>& balls);

}  // namespace billiard::estimator
