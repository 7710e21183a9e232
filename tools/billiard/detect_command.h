#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

// `billiard detect`: the balls in a camera frame (estimator/ball_detector.h), in pixels and, with
// a calibration, on the table the calibration gives (never looked for), and with --scene-out as a
// scene (detected_scene.h). Where no table is found, the balls on the cloth in pixels, "table":
// null and the reason; only a frame without a cloth is refused (exit 3). A calibration of another
// image size is a usage error; one whose ball radius is not the frame's, and a frame without
// balls, are said so on stderr.
void AddDetectCommand(CLI::App& app);

}  // namespace billiard::cli
