#include "planner/node/planner_node_command.h"

#include <cmath>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "lcmtypes/names.h"
#include "lcmtypes/node/node_loop.h"
#include "planner/players/players.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/robots.h"
#include "sim/params/table_specs.h"

namespace billiard::planner_node {

void AddPlannerNodeOptions(CLI::App& app, PlannerNodeCommandLine* line) {
  PlannerNodeOptions& options = line->options;
  app.add_option("--lcm-url", line->lcm_url,
                 "LCM URL, e.g. udpm://239.255.76.67:7667?ttl=0 (default: $LCM_DEFAULT_URL, else "
                 "LCM's default)");
  app.add_option("--params", line->params, "paper | pool | path to a JSON parameter file")
      ->capture_default_str();
  app.add_option("--max-ball-speed", options.max_ball_speed,
                 "Refuse to plan for a ball faster than this [m/s]")
      ->capture_default_str();
  app.add_option("--rest-states", options.rest_states,
                 "Answer a request only when the table has been at rest (every ball under "
                 "--max-ball-speed) for this many table states in a row")
      ->capture_default_str();
  app.add_option("--max-rest-wait", options.max_rest_wait,
                 "Hold a request at most this long for the table to come to rest, then refuse it "
                 "not_at_rest [s]")
      ->capture_default_str();
  app.add_option("--max-state-age", options.max_state_age,
                 "Refuse to plan from a ball state further than this from the request in time [s]")
      ->capture_default_str();
  app.add_option("--queue-capacity", options.queue_capacity,
                 "Requests waiting to be planned; more are answered busy")
      ->capture_default_str();
  app.add_option("--table", line->table,
                 "The table pots are planned on: a built-in table (pool-9ft, snooker-12ft, ...) or "
                 "a table file")
      ->capture_default_str();
  app.add_option("--robot", line->robot,
                 "The robot whose cue plays the strokes: gantry | player | FILE (sim/params/robots/): "
                 "every pot is planned at the elevation its cue needs, refused cue_blocked where none clears")
      ->capture_default_str();
  app.add_flag("--no-refine", line->no_refine, "Plan with the closed-form inverse alone");
  app.add_option("--player", options.player,
                 "Who chooses a MODE_CHOOSE shot: " + players::KnownPlayerList())
      ->capture_default_str()
      ->check(CLI::IsMember(players::KnownPlayerNames()));
  app.add_option("--identify-every", options.identify_every,
                 "Identify the table online: every N shots, fit --identify to the node's own "
                 "tracked shots and plan with them (0: never)")
      ->capture_default_str();
  app.add_flag("--learn-noise", options.learn_noise,
               "Learn the robot's execution noise from the launches of its own strokes and "
               "choose shots for it (from 10 measured launches on)");
  app.add_option("--identify", line->identify,
                 "The constants the online fit identifies: mu,rolling,spin,cushion,"
                 "cushion_friction,ball_ball")
      ->capture_default_str();
}

PlannerNodeOptions NodeOptions(const PlannerNodeCommandLine& line,
                               const physics::ModelParameters& params) {
  PlannerNodeOptions options = line.options;
  if (!(std::isfinite(options.max_ball_speed) && options.max_ball_speed >= 0.0)) {
    throw std::invalid_argument("--max-ball-speed must be a finite speed >= 0");
  }
  if (options.rest_states < 1) throw std::invalid_argument("--rest-states must be at least 1");
  if (!(std::isfinite(options.max_rest_wait) && options.max_rest_wait >= 0.0)) {
    throw std::invalid_argument("--max-rest-wait must be a finite time >= 0");
  }
  if (!(std::isfinite(options.max_state_age) && options.max_state_age > 0.0)) {
    throw std::invalid_argument("--max-state-age must be a finite time > 0");
  }
  if (options.queue_capacity < 1)
    throw std::invalid_argument("--queue-capacity must be at least 1");
  options.planner.refine = !line.no_refine;
  if (options.identify_every < 0) throw std::invalid_argument("--identify-every must be >= 0");
  try {
    options.identify = shot_fit::ParseConstants(line.identify);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--identify: ") + e.what());
  }
  options.table = table::BuildTable(params::LoadTableSpec(line.table));
  try {
    options.pot.robot = params::LoadRobot(line.robot);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--robot: ") + e.what());
  }
  // The point planner's bounds are the parameter set's table: both must be the one table.
  if (std::abs(options.table->length - params.table.length) > 1e-9 ||
      std::abs(options.table->width - params.table.width) > 1e-9) {
    throw std::invalid_argument("--table " + line.table +
                                " is not the size of the parameter "
                                "set's table");
  }
  return options;
}

int RunPlannerNodeCommand(const PlannerNodeCommandLine& line) {
  PlannerNodeOptions options;
  physics::ModelParameters params;
  try {
    params = params::LoadParameters(line.params);
    options = NodeOptions(line, params);
  } catch (const std::invalid_argument& e) {
    std::cerr << "planner_node: " << e.what() << std::endl;
    return 2;
  }
  return nodes::RunNodeUntilStopped("planner_node", line.lcm_url, [&](lcm::LCM& lcm) {
    auto node = std::make_shared<PlannerNode>(lcm, params, options);
    std::cerr << "planner_node: " << params::ParameterSetLabel(params) << " parameters, LCM "
              << nodes::DescribeUrl(line.lcm_url) << ", answering " << messages::kShotRequestChannel
              << std::endl;
    return [node] { return node->Work(); };
  });
}

}  // namespace billiard::planner_node
