// `billiard render-break --out break.avi`: a break filmed as the table simulator's camera films
// it, written as a video (MJPG in an AVI, OpenCV's VideoWriter), with the camera model its frames
// were rendered with (`--camera-out`, billiard calibrate's JSON) and every ball's true place at
// the last frame on stdout: a video to try camera_node and `run_loop.sh --camera` on without a
// camera, whose tracks can be checked against that truth (docs/closed-loop.md, "A real camera").
// The frames are tools/camera_node/testing/break_video.h's, those camera_node's tests play.
#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

void AddRenderBreakCommand(CLI::App& app);

}  // namespace billiard::cli
