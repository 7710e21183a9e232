// Where balls may be centred: every edge of the frame votes for the centres of the circles of a
// ball's radius it could lie on (a Hough transform for circles of known radius, after Kimme,
// Ballard and Sklansky 1975, with the radius given at each place by the table's perspective,
// ball_scale.h).
//
// An edge is where the colour (CIE L*a*b*) changes fastest across, at its strongest along its
// own direction (so each outline contributes one pixel in thickness). Its direction comes from
// the colour structure tensor (Di Zenzo 1986), which has no sign: a bright ball on dark cloth, a
// dark ball on bright cloth and the crease between two touching balls all have edges, each
// pointing one way or the other, so every edge votes at one radius on both sides. On a ball's
// outline the inward votes meet at its centre; the outward ones scatter on a circle twice as
// wide. Touching balls keep the edges of their crease, so a full rack gives a peak per ball,
// where a filter on the ball's colour sees one blob.
//
// Each vote weighs 1 / (2 pi r) (less for an edge weaker than a few times the cloth's noise), so
// that a ball's peak, summed over about a tenth of its radius, is the fraction of its outline
// that is there: 1 for an isolated ball, about 0.5 for one in a rack or half hidden. Lines (a cue,
// the cushion) and textures spread their votes. Voting runs on the table's region at a reduced
// resolution where a ball is about kVoteRadiusPx across, so that its cost does not grow with the
// camera's resolution.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "estimator/ball_scale.h"
#include "estimator/lab_image.h"
#include "estimator/table_finder.h"

namespace billiard::estimator {

// Voting runs where the table's smallest balls are about this many pixels in radius (or at full
// resolution when they are smaller).
inline constexpr double kVoteRadiusPx = 7.0;

struct CircleVote {
  Eigen::Vector2d pixel;  // [full-resolution px]
  double support = 0;     // the fraction of a circle's outline voting for it (about 0..1)
};

// The local maxima of the votes inside the table of a BGR frame with at least `min_support`,
// strongest first.
std::vector<CircleVote> VoteForCircles(const cv::Mat& bgr, const TableRegion& table,
                                       const BallScale& scale, double min_support);

// The support of a circle of `radius` [px] centred within a tenth of its radius of `centre`,
// voted as VoteForCircles does but at full resolution, in a window around it; `edge_noise` is
// EdgeNoise's. At the votes' reduced resolution the crease between a dark ball and a bright
// neighbour touching it is a pixel wide, and the thinning keeps the neighbour's edge only: the
// black in the middle of a rack keeps a quarter of its outline there, all of it here.
double FullResolutionSupport(const cv::Mat& bgr, const Eigen::Vector2d& centre, double radius,
                             double edge_noise);

// The median rate of colour change over the table [L*a*b* units per full-resolution px]: the
// cloth's own texture and noise, the scale of what counts as an edge.
double EdgeNoise(const LabImage& lab, const TableRegion& table);

}  // namespace billiard::estimator
