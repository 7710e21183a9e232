// The options that say which balls a frame holds and how they look, as `billiard detect` and
// `billiard learn-balls` read them: --ball-set and --ball-model (estimator/ball_model.h).
#pragma once

#include <string>

#include "estimator/ball_class.h"
#include "estimator/ball_detector.h"
#include "sim/physics/parameters.h"

namespace billiard::cli {

// The ball set of a --ball-set option: the set it names, or --params' set when it is empty;
// UsageError for a name that is no set.
estimator::BallSet BallSetOption(const std::string& name, const physics::ModelParameters& params);

// The detector's ball set and identity from the model file of a --ball-model option (`path`):
// its set and its colours and shares. UsageError, with the reason, for a file that is not a
// model, or a --ball-set (`ball_set_option`, empty when not given) that names another set.
void UseBallModel(const std::string& path, const std::string& ball_set_option,
                  estimator::DetectorOptions* options);

}  // namespace billiard::cli
