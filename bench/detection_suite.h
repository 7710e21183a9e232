// The detector's synthetic suite: frames of the simulator's renderer (sim/render) whose ball
// centres are known exactly, in the conditions the real frames show: overhead and oblique
// cameras, full racks of touching balls, balls against the cushions, cloths of other colours.
// Labelled as the real sets are (detection_benchmark.h), so that `billiard bench-detect` scores
// both the same way.
//
// Every scene is a pool table (the parameter set's) with balls at rest, seeded:
//   - scattered: 16 balls, two touching pairs and two against a cushion among them;
//   - rack: the eight-ball rack (fifteen balls touching) and the cue ball at the head string;
// seen by three cameras: overhead (CameraModel::Overhead, 1280x720, a mild barrel lens), from the
// side (2 m from the table's middle, 35 degrees up) and from the foot end (a broadcast's view);
// on the renderer's green cloth and on blue, navy, burgundy and grey ones. A ball's label is the
// projection of its centre (the silhouette's centre is within 0.1 px of it, table_renderer.h); a
// ball whose centre projects outside the frame (the end view's nearest) is ignored, as a real
// set's hidden balls are. The side and end views see the near cushion hide the lower part of the
// balls against it.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "bench/detection_benchmark.h"
#include "sim/camera/camera_model.h"
#include "sim/physics/parameters.h"
#include "sim/render/table_renderer.h"

namespace billiard::bench {

// The suite's frames, rendered, with their labels (LabelledFrame::image set; `file` a name for
// the frame).
std::vector<LabelledFrame> RenderDetectionSuite(const physics::ModelParameters& params,
                                                std::uint32_t seed = 2026);

// The suite's cloths: the bed's and the cushion's colours (BGR).
struct SuiteCloth {
  const char* name;
  cv::Vec3b bed, cushion;
};
const std::vector<SuiteCloth>& SuiteCloths();

// A scene's balls on the table [m]: scattered (16, as above, drawn from `rng`) or the eight-ball
// rack (drawn from `rack_seed`) with the cue ball at the head string.
std::vector<Eigen::Vector2d> SceneBalls(const physics::ModelParameters& params, bool rack,
                                        std::uint32_t rack_seed, std::mt19937* rng);

// The pool set at rest at `balls` (ball i numbered i mod 16).
std::vector<render::RenderBall> PoolBalls(const std::vector<Eigen::Vector2d>& balls);

// The suite's renderer options on `cloth`: an instant, sensor noise of 2 gray levels from `seed`.
render::RenderOptions SuiteRenderOptions(const SuiteCloth& cloth, std::uint64_t seed);

// The label of a frame `name`.png: each ball's projected centre, ignored where it projects
// outside the frame or `hidden` says so; the median of the balls' radii [px].
LabelledFrame LabelBalls(const std::string& name, const camera::CameraModel& camera,
                         bool overhead, const std::vector<Eigen::Vector2d>& balls, double r,
                         const std::vector<bool>& hidden = {});

// Writes the frames as PNG files and their labels.json into `directory` (created if missing):
// a set `billiard bench-detect --set` reads like a real one.
void WriteLabelledSet(const std::vector<LabelledFrame>& frames, const std::string& directory);

}  // namespace billiard::bench
