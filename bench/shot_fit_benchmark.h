// Synthetic truth through the camera: shots simulated on a table of known (hidden) constants,
// rendered as the loop's table simulator renders them (sim/render/table_renderer.h, the overhead
// camera at 1280x720, sensor noise and motion blur) and tracked by the loop's estimator
// (estimator/ball_estimator.h), its tracks cut into shots as `billiard identify` cuts a log
// (sim/shot_fit/shot_recorder.h); then the constants fitted from them (shot_fit::FitShots), to
// be compared with the hidden ones. `billiard bench-shot-fit --camera` runs it; docs/
// benchmarks/shot_fit_camera_report.md has its figures.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "sim/batch/thread_pool.h"
#include "sim/physics/parameters.h"
#include "sim/shot_fit/shot_fit.h"
#include "sim/table/table_geometry.h"

namespace billiard::bench {

struct CameraShotOptions {
  double rate = 50.0;       // frames per second [Hz]: the real recordings'
  double settle = 0.3;      // the balls shown at rest before the strike, as the loop does [s]
  double duration = 5.0;    // from the strike to the last frame [s]
  int width = 1280, height = 720;  // the loop's camera
  // A ball's samples thinned where it moved less than this [m], as the real recordings are
  // (shot_fit::ShotRecorder): a ball at rest costs the fit two samples.
  double thinning = 0.002;
};

// Scene k of `scenes` simulated with `truth` (Han's cushions, as the fits), rendered frame by
// frame and tracked by a fresh estimator: the estimator's tracks of the balls as the shot's
// samples, the strike at the track nearest ball 0. Scene k's job on `pool` (its own renderer,
// seeded by k, and estimator), so the shots do not depend on the thread count. A shot the
// estimator does not see struck (no track of the cue ball before the strike) is nullopt; a job
// that throws, std::runtime_error with its reason.
std::vector<std::optional<shot_fit::TrackedShot>> CameraTrackedShots(
    const table::TableGeometry& table, const physics::ModelParameters& truth,
    const std::vector<shot_fit::SyntheticScene>& scenes, const CameraShotOptions& options,
    batch::ThreadPool& pool);

}  // namespace billiard::bench
