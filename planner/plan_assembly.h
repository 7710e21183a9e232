// Steps 4 and 5 of PlanShot (shot_planner.h): the plan made of the refined launch. Its
// prediction is the launch's run read again (each launch is simulated once, shot.h): the launch
// state, where and when it arrives, the path there and the miss; its verdict says whether that
// is a plan the robot can play.
#pragma once

#include "planner/shot.h"
#include "planner/shot_planner.h"

namespace billiard::planner {

// Step 4: the arrival of `launch` (speed, heading) into `plan`: v0, w0, predicted_final,
// arrival_time, refined_miss_m, and predicted_path sampled every path_sample_dt (and at its
// ends). Whether it arrived (within the time limit).
bool Predict(Shot& shot, const double launch[2], ShotPlan* plan);

// Step 5: the verdict on the prediction, `plan`'s status and reason: converged (else unreachable
// when a speed bound decides it, BeyondReach, or not converged), on the table all the way, and a
// stroke the robot can give (then `plan`'s stroke).
void Conclude(Shot& shot, const double launch[2], bool arrived, ShotPlan* plan);

}  // namespace billiard::planner
