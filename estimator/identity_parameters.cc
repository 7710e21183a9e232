#include "estimator/identity_parameters.h"

#include <opencv2/imgproc.hpp>

namespace billiard::estimator {

namespace {

struct SrgbColour {
  BallSet table;
  BallClass ball_class;
  cv::Vec3b srgb;  // R, G, B under white light
};

// Approximate colours of the balls (their sRGB under white light, read from manufacturers'
// product pictures: Aramith pool and snooker sets, carom balls, whose red and yellow English
// pool's are too); the classifier compares hues more than lightness, so a few per cent either way
// changes little. Pool's 4 is purple, or pink in TV sets (Aramith's TV balls, so that it is not
// taken for the 2 on camera), its 7 maroon or brown.
const SrgbColour kHandSetColours[] = {
    {BallSet::kPool, PoolBall(1), {250, 195, 10}},
    {BallSet::kPool, PoolBall(2), {20, 50, 160}},
    {BallSet::kPool, PoolBall(3), {215, 30, 30}},
    {BallSet::kPool, PoolBall(4), {85, 35, 125}},   // purple
    {BallSet::kPool, PoolBall(4), {230, 80, 140}},  // pink (TV sets)
    {BallSet::kPool, PoolBall(5), {250, 110, 10}},
    {BallSet::kPool, PoolBall(6), {10, 110, 60}},
    {BallSet::kPool, PoolBall(7), {125, 25, 35}},  // maroon
    {BallSet::kPool, PoolBall(7), {138, 54, 15}},  // brown
    {BallSet::kSnooker, BallClass::kRed, {200, 20, 20}},
    {BallSet::kSnooker, BallClass::kYellow, {250, 210, 10}},
    {BallSet::kSnooker, BallClass::kGreen, {10, 100, 50}},
    {BallSet::kSnooker, BallClass::kBrown, {110, 60, 30}},
    {BallSet::kSnooker, BallClass::kBlue, {10, 70, 180}},
    {BallSet::kSnooker, BallClass::kPink, {245, 150, 170}},
    {BallSet::kCarom, BallClass::kRed, {210, 30, 30}},
    {BallSet::kCarom, BallClass::kYellow, {250, 210, 20}}};

}  // namespace

BallSet ColourTableOf(BallSet set) { return set == BallSet::kBlackball ? BallSet::kCarom : set; }

BallClass ColourClassOf(BallClass ball_class, BallSet set) {
  const int number = static_cast<int>(ball_class);
  const bool stripe = set == BallSet::kPool && number > 8 && number <= 15;
  return stripe ? PoolBall(number - 8) : ball_class;
}

cv::Vec3f LabOfSrgb(const cv::Vec3b& srgb) {
  const cv::Mat pixel(1, 1, CV_32FC3,
                      cv::Scalar(srgb[2] / 255.0, srgb[1] / 255.0, srgb[0] / 255.0));  // BGR
  cv::Mat lab;
  cv::cvtColor(pixel, lab, cv::COLOR_BGR2Lab);
  return lab.at<cv::Vec3f>(0, 0);
}

const IdentityParameters& HandSetIdentity() {
  static const IdentityParameters parameters = [] {
    IdentityParameters p;
    for (const SrgbColour& c : kHandSetColours) {
      p.colours.push_back({c.table, c.ball_class, LabOfSrgb(c.srgb)});
    }
    return p;
  }();
  return parameters;
}

}  // namespace billiard::estimator
