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
#include <vector>

#include "bench/detection_benchmark.h"
#include "sim/physics/parameters.h"

namespace billiard::bench {

// The suite's frames, rendered, with their labels (LabelledFrame::image set; `file` a name for
// the frame).
std::vector<LabelledFrame> RenderDetectionSuite(const physics::ModelParameters& params,
                                                std::uint32_t seed = 2026);

// Writes the frames as PNG files and their labels.json into `directory` (created if missing):
// a set `billiard bench-detect --set` reads like a real one.
void WriteLabelledSet(const std::vector<LabelledFrame>& frames, const std::string& directory);

}  // namespace billiard::bench
