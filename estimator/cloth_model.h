// The cloth's colour across the table, as the detector learns it from a frame (ball_detector.h):
// vignetting and mixed lights change it from place to place, so a ball is told from the cloth
// where it lies (local_cloth.h), not from one colour for the whole table.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "estimator/table_finder.h"

namespace billiard::estimator {

// The local colour of the cloth, learnt from a frame.
struct ClothModel {
  cv::Mat colour;    // CV_32FC3 (BGR) map of the cloth colour, one cell per `cell` full-res px
  double cell = 0;   // full-resolution pixels per cell of `colour`
  double noise = 0;  // robust spread of the cloth's colour across its own colour, relative
  // The rate of colour change [L*a*b* units per full-resolution px] of the cloth's own texture
  // and noise (circle_votes.h): the scale of what counts as an edge.
  double edge_noise = 0;
  bool empty() const { return colour.empty(); }
  // The cloth colour at a full-resolution pixel.
  cv::Vec3f ColourAt(const Eigen::Vector2d& pixel) const;
};

// The cloth's local colour, from the table's cloth pixels, and its spread across its own colour:
// the colour averaged over cells of about a 24th of the table (a cell less than a fifth cloth takes
// its neighbours' colour), its noise the median distance across the colour (scaled to a standard
// deviation), its edge noise circle_votes.h's EdgeNoise of the table.
ClothModel LearnClothModel(const cv::Mat& bgr, const TableRegion& table);

// The least rate of colour change [L*a*b* units per px] that is an edge on a cloth of
// `edge_noise` (ClothModel::edge_noise).
double EdgeThreshold(double edge_noise);

}  // namespace billiard::estimator
