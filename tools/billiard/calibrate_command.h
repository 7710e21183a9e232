#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

// `billiard calibrate`: the camera's pose over the table, written as a camera JSON file for
// `detect --calib` and `estimator_node --camera`: from the four corner markers
// (estimator/table_calibration.h), or without markers from the table's corners, found in the
// frame or given with --corners (estimator/table_pose.h). Refused (exit 3, nothing written) when
// the frame shows neither the four markers nor the table, or the pose reprojects the points it
// was fitted to beyond --max-reprojection-px.
void AddCalibrateCommand(CLI::App& app);

}  // namespace billiard::cli
