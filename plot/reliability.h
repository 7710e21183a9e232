// A reliability diagram: the measured rate of an event against its predicted probability, per
// bin of the prediction, the diagonal where a calibrated predictor lies, each bin's count and a
// binomial error bar. `billiard bench-game`'s calibration of the shot choice.
#pragma once

#include <string>
#include <vector>

namespace billiard::plot {

struct ReliabilityBin {
  double lo = 0.0, hi = 0.0;  // the bin of predicted probability
  double predicted = 0.0;     // the mean prediction in it
  double measured = 0.0;      // the share that happened
  int count = 0;
};

// Draws the bins with count > 0 into `path` (.png or .svg), 700 x 700 px; bins with fewer than
// `min_count` drawn hollow. Throws std::invalid_argument for another extension,
// std::runtime_error when it cannot be written.
void DrawReliability(const std::vector<ReliabilityBin>& bins, const std::string& title,
                     int min_count, const std::string& path);

}  // namespace billiard::plot
