// What makes a fitted outline (ball_outline.h) a ball rather than a shadow, a pocket, a hand, a
// spot on the cloth or a second outline of a ball: a score from 0 to 1.
//
// Each term is a ramp from 0 to 1 over a range of a measure that has a meaning of its own:
//   - outline: the fraction of the rays with an edge on the circle (from 45 %, full at 80 %), and
//     no gap between them of more than 0.9 pi (half the ball hidden is still a ball);
//   - size: the fitted radius within 25 % of the ball's at that place (a parabola, 1 when equal);
//   - votes: the fraction of the circle's outline that voted for its centre (circle_votes.h, from
//     0.08, full at 0.33), which also rewards a sharp edge over a shadow's soft one;
//   - look: the larger of two signs of a ball. Its colour is far from the cloth's: the median CIE
//     L*a*b* distance (Delta E 1976) of its disc from the local cloth colour, from 8 (about where
//     two colours side by side look different) and full at 20. Or it shines: a ball is a glossy
//     sphere, so its brightest pixels (the 98th percentile of L*) stand out of its median L* (from
//     15, full at 35), which also tells a dark ball on dark cloth from a shadow, which is matte.
// The score is the square root of the terms' product: the default threshold, 0.5, asks for a
// product of a quarter.
#pragma once

#include <opencv2/core.hpp>

#include "estimator/ball_outline.h"
#include "estimator/lab_image.h"

namespace billiard::estimator {

struct BallEvidence {
  double outline = 0, size = 0, votes = 0, look = 0;
  double Score() const;
};

// The evidence for the outline being a ball of `expected_radius` [px] in a frame, on cloth of
// colour `cloth` (float L*a*b*), with `vote_support` of its circle voting for it
// (circle_votes.h; 1 when the outline came from elsewhere, a tracker's prediction).
BallEvidence EvidenceForBall(const LabImage& lab, const BallOutline& outline,
                             double expected_radius, const cv::Vec3f& cloth,
                             double vote_support);

}  // namespace billiard::estimator
