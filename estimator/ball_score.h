// What makes a fitted outline (ball_outline.h) a ball rather than a shadow, projected light, a
// pocket, a hand, a spot on the cloth or a second outline of a ball: a score from 0 to 1.
//
// Each term is a ramp from 0 to 1 over a range of a measure that has a meaning of its own:
//   - outline: the fraction of the rays with an edge on the circle (from 45 %, full at 80 %), and
//     no gap between them of more than 0.9 pi (half the ball hidden is still a ball);
//   - size: the fitted radius within 25 % of the ball's at that place (a parabola, 1 when equal);
//   - votes: the fraction of the circle's outline that voted for its centre (circle_votes.h, from
//     0.08, full at 0.33), which also rewards a sharp edge over a shadow's soft one;
//   - look: the largest of three signs of a ball, over its disc:
//       - it is not the cloth, in a way light cannot make it: the median of the cloth contrast of
//         local_cloth.h without its bright part (another hue, or darker than any shadow), from
//         0.5 to 1;
//       - it shines: a ball is a glossy sphere, so its brightest pixels (the 98th percentile of
//         CIE L*) stand out of its median L* (from 15, full at 35), which also tells a dark ball
//         on dark cloth from a shadow, which is matte;
//       - brighter than the cloth, it darkens towards its rim as a sphere lit from above does
//         (the rim band's mean L* below 0.97 of the core's, full at 0.87): a white ball on a pale
//         cloth, where a disc of projected light is flat.
// The score is the square root of the terms' product: the default threshold, 0.5, asks for a
// product of a quarter. The look is measured only where the other three are not 0.
#pragma once

#include <opencv2/core.hpp>

#include "estimator/ball_outline.h"
#include "estimator/lab_image.h"

namespace billiard::estimator {

// A score from which an outline is surely a ball: the detector holds it to less than an unsure
// one (ball_placement.h), settles the balls' scale on such balls, and the tracker's RefineAt
// reports only such.
inline constexpr double kSureScore = 0.8;

struct BallEvidence {
  double outline = 0, size = 0, votes = 0, look = 0;
  double Score() const;
};

// The cloth around a ball: its colour (BGR) and the robust spread of its hue (ClothModel's).
struct ClothColour {
  cv::Vec3f bgr;
  double noise = 0;
};

// The evidence for the outline being a ball of `expected_radius` [px] in a BGR frame (`lab` its
// L*a*b*), on `cloth`, with `vote_support` of its circle voting for it (circle_votes.h; 1 when
// the outline came from elsewhere, a tracker's prediction).
BallEvidence EvidenceForBall(const cv::Mat& bgr, const LabImage& lab, const BallOutline& outline,
                             double expected_radius, const ClothColour& cloth,
                             double vote_support);

}  // namespace billiard::estimator
