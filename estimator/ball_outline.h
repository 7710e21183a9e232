// One ball's outline to a fraction of a pixel, from a guess of its centre and radius: what the
// detector does with each candidate (ball_detector.h), for isolated balls, balls touching in a
// rack, balls half hidden by a cushion or an arm.
//
// Along each of kOutlineRays rays from the guessed centre (out to half a radius either side of the
// outline), the ball's edge is where the colour
// (CIE L*a*b*, so that a change of hue counts as much as one of brightness) changes fastest: the
// outline of a ball against the cloth, against its own shadow, or against the dark crease where
// it touches another ball. A ray may cross several such places (a stripe, the number's disc, a
// highlight, the neighbour's far side): every local maximum of the colour's rate of change is
// kept as a candidate. The circle is then fitted by iteratively reweighted least squares (Tukey's
// biweight) to the candidate of each ray nearest the current circle, with the expected radius as
// a weak prior, so that internal edges and occluders (outliers) lose their say; the rays are cast
// again from the new centre (crossing the edge square on, sampled more finely over a narrower
// range) and the circle fitted once more.
//
// A ray supports the circle when one of its edges lies within a pixel (or 8 % of the radius) of
// it: the fraction of supporting rays and the largest gap between them say how much of a round
// outline is there. Where the detector knows that a straight edge hides part of the circle (an
// `Occluder`: the near cushion's nose in an oblique view, which hides the lower part of a ball
// against it), the edges beyond it are not candidates (the occluder's own edge would pull the
// circle onto it) and its rays are left out of both counts, so that a ball cut by the cushion is
// fitted and judged on the part of it the camera can see.
#pragma once

#include <Eigen/Core>
#include <bitset>
#include <opencv2/core.hpp>
#include <optional>

#include "estimator/lab_image.h"

namespace billiard::estimator {

inline constexpr int kOutlineRays = 32;
using OutlineRays = std::bitset<kOutlineRays>;  // ray k points at angle 2 pi k / kOutlineRays

struct BallOutline {
  Eigen::Vector2d centre;          // [px], OpenCV convention
  double radius = 0;               // [px]
  int supporting_rays = 0;         // of seen_rays
  int seen_rays = kOutlineRays;    // the rays whose place on the circle is in view
  double largest_gap = 0;          // [rad] between neighbouring supporting rays, hidden ones skipped
  double edge_strength = 0;        // mean rate of colour change across the outline [L*a*b* per px]
  OutlineRays supporting;          // which rays support the circle
  OutlineRays hidden;              // which rays' places on the circle an Occluder hides

  // The supporting share of the rays in view.
  double SupportedShare() const {
    return seen_rays > 0 ? static_cast<double>(supporting_rays) / seen_rays : 0.0;
  }
};

// A straight edge in the frame beyond which nothing of a ball is seen: pixel p is hidden when
// normal.dot(p) > offset - margin_px (the margin holds the occluder's own edge, found within a
// pixel or two of where the line was fitted). The default hides nothing.
struct Occluder {
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();
  double offset = 0;
  double margin_px = 0;

  bool Hides(const Eigen::Vector2d& pixel) const {
    return normal.squaredNorm() > 0 && normal.dot(pixel) > offset - margin_px;
  }
};

// The outline of the ball whose centre is about `start` [px] and radius about `radius` [px] in a
// frame (`lab` must hold 2.6 radii around `start`); `min_edge` [L*a*b* units per px] is the
// weakest change of colour that counts as an edge (a few times the cloth's noise). Empty when the
// rays find too few edges, or the circle they fit moves more than a radius away or changes its
// radius by more than 40 %. Beyond `occluder` no edge is taken and no ray is counted; with more than
// half the circle beyond it, the whole circle is counted (a ball mostly hidden is not asked for).
std::optional<BallOutline> FitBallOutline(const LabImage& lab, const Eigen::Vector2d& start,
                                          double radius, double min_edge,
                                          const Occluder& occluder = {});

// The centre of a found outline (`centre`, `radius` [px]) with each edge where the ball's side is
// white (the cue ball, a stripe's caps) placed where the chroma is half way between the colours
// either side of it, where the chroma steps there (within 2 px of the fastest change of colour);
// `centre` where too few do. Lit from above, a ball off the camera's axis shows the camera its
// shaded underside on the limb nearer the axis, about as dark as its own shadow beside it: the
// lightness hardly steps at the outline there, the fastest change of colour lies inside it (once a
// JPEG has blurred the chroma), and the centre moves away from the axis: a scale of the positions
// about it (+0.087 % through the loop's JPEG, ball_estimator_test), which an identification of the
// table takes for rolling resistance. The detector finds and scores a ball on the fastest changes,
// and places it with this.
Eigen::Vector2d CentreOnChroma(const LabImage& lab, const Eigen::Vector2d& centre, double radius,
                               double min_edge, const Occluder& occluder = {});

// The pixels FitBallOutline may read around `start`.
cv::Rect OutlineWindow(const Eigen::Vector2d& start, double radius);

}  // namespace billiard::estimator
