// What a planner node is started with (planner_node.h): the planners' options, its limits on the
// table states it plans from, its queue, its table, online identification and the choice's
// sampling. planner_node_command.h fills them from build/bin/planner_node's command line.
#pragma once

#include <optional>
#include <vector>

#include "planner/choice/shot_choice.h"
#include "planner/pot/pot_planner.h"
#include "planner/shot_planner.h"
#include "sim/batch/thread_pool.h"
#include "sim/params/table_specs.h"
#include "sim/shot_fit/shot_fit.h"
#include "sim/table/table_geometry.h"

namespace billiard::planner_node {

struct PlannerNodeOptions {
  planner::PlannerOptions planner;
  // A ball faster than this [m/s] is still moving: a plan from where it is now would start from
  // the wrong place. The default is at least ten times the estimator's velocity error on balls
  // at rest (0.55 mm/s on rendered frames, 4-5 mm/s on simulated detections with 0.4 mm noise;
  // estimator/README.md) and below any ball that will roll on for more than a few millimetres (a
  // ball rolling at 0.05 m/s stops within v^2 / (2 g mu_roll), about 13 mm at mu_roll 0.01).
  double max_ball_speed = 0.05;
  // A request is answered only when the table is at rest: every ball of this many table states in
  // a row under max_ball_speed, so that a speed passing through zero (a ball stopping against a
  // cushion, a filter's estimate at a collision) is not taken for rest; a table never seen moving
  // is at rest. Three states are 25-50 ms at the camera's 60-120 Hz.
  int rest_states = 3;
  // The longest a request waits for the table to come to rest [s], in the table states' time past
  // the request's utime or on the node's clock since it arrived (when the states stop coming);
  // then it is refused STATUS_NOT_AT_REST with the ball still moving. Longer than a busy
  // estimator's lag behind the frames, shorter than the table simulator's reply timeout (10 s),
  // so that its retry, which shows the table at rest again, comes first.
  double max_rest_wait = 2.0;
  // The most a ball's state and a request may be apart in time [s] (their utimes).
  double max_state_age = 1.0;
  // Requests waiting to be planned; more are answered STATUS_BUSY.
  int queue_capacity = 32;
  // The table pots are planned on (its cushions and pockets); params::kDefaultTable when not given.
  std::optional<table::TableGeometry> table;
  pot::PotOptions pot = CameraPotOptions();
  // Online identification of the table (0: off): after every `identify_every` shots the node
  // commanded and saw tracked, the constants `identify` are fitted jointly to its latest
  // kIdentifyWindow shots (planner_node.h; sim/shot_fit/shot_fit.h, from the constants it plans
  // with) and its plans use them from then on; what the shots do not excite is kept.
  int identify_every = 0;
  std::vector<shot_fit::Constant> identify = {shot_fit::Constant::kMu,
                                              shot_fit::Constant::kRolling};
  // Learn the robot's execution noise from its own strokes (noise_learning.h): every shot's
  // launch measured from the tracks before the next plan, and from kMinNoiseShots of them on,
  // MODE_CHOOSE plans for the noise learned instead of choice.noise (the prior).
  bool learn_noise = false;
  // MODE_CHOOSE: the choice's samples, noise (the robot's, the table simulator's own) and seed;
  // its rules and pot options are the request's and `pot`.
  choice::ChoiceOptions choice;
  int choice_threads = batch::DefaultThreadCount();
  // MODE_CHOOSE: who decides, one of players::KnownPlayerNames (planner/players/players.h).
  std::string player = "ours";

  // Pots are planned on what the camera saw: touching balls measured a fraction of a millimetre
  // into each other (or into a cushion) are settled apart first (pot::PotOptions::settle_overlap),
  // by up to 2 mm, some four times the estimator's position error.
  static pot::PotOptions CameraPotOptions() {
    pot::PotOptions o;
    o.settle_overlap = 2e-3;
    return o;
  }
};

// The table pots and choices are planned on: `options.table`, else params::kDefaultTable.
table::TableGeometry TableOf(const PlannerNodeOptions& options);

}  // namespace billiard::planner_node
