#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

// `billiard detect`: the balls in a camera frame (estimator/ball_detector.h), in pixels and, with
// a calibration, on the table.
void AddDetectCommand(CLI::App& app);

// `billiard calibrate`: the camera's pose over the table from the four corner markers
// (estimator/table_calibration.h), written as a camera JSON file for `detect --calib`.
void AddCalibrateCommand(CLI::App& app);

}  // namespace billiard::cli
