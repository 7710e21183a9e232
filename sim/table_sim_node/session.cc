#include "sim/table_sim_node/session.h"

#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "lcmtypes/node/node_loop.h"
#include "sim/params/execution_noise.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/robots.h"
#include "sim/params/table_specs.h"

namespace billiard::table_sim_node {

namespace {

// "K:P": a ball id and a pocket's name.
PotShot ParsePot(const std::string& text) {
  const std::size_t colon = text.find(':');
  PotShot pot;
  std::size_t used = 0;
  try {
    if (colon != std::string::npos) pot.ball = std::stoi(text.substr(0, colon), &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (colon == std::string::npos || used == 0 || used != colon || pot.ball < 0 ||
      colon + 1 == text.size()) {
    throw std::invalid_argument("--pot '" + text +
                                "' is not K:P (a ball id >= 0, a pocket's name)");
  }
  pot.pocket = text.substr(colon + 1);
  return pot;
}

// "A,B": a match's two players by name (the planner knows them, or refuses them).
std::vector<std::string> ParsePlayers(const std::string& text) {
  const std::size_t comma = text.find(',');
  if (comma == 0 || comma == std::string::npos || comma + 1 == text.size() ||
      text.find(',', comma + 1) != std::string::npos) {
    throw std::invalid_argument("--players '" + text + "' is not two names, A,B");
  }
  return {text.substr(0, comma), text.substr(comma + 1)};
}

// "S,T,...": the spin styles of the shots to random targets, in turn.
std::vector<std::int8_t> ParseSpins(const std::string& text) {
  const std::map<std::string, std::int8_t> styles = {{"natural", shot_request_t::SPIN_NATURAL},
                                                     {"stun", shot_request_t::SPIN_STUN},
                                                     {"follow", shot_request_t::SPIN_FOLLOW},
                                                     {"draw", shot_request_t::SPIN_DRAW}};
  std::vector<std::int8_t> spins;
  std::stringstream list(text);
  for (std::string name; std::getline(list, name, ',');) {
    const auto style = styles.find(name);
    if (style == styles.end()) {
      throw std::invalid_argument("--spins '" + text +
                                  "' is not a list of natural, stun, follow and draw");
    }
    spins.push_back(style->second);
  }
  if (spins.empty()) throw std::invalid_argument("--spins names no spin style");
  return spins;
}

// The table's own set of --plant-params: the same table and balls as the nodes', which the camera
// and the estimator are made for; only the physics may differ.
physics::ModelParameters PlantParameters(const std::string& name_or_path,
                                         const physics::ModelParameters& nodes) {
  physics::ModelParameters plant = params::LoadParameters(name_or_path);
  if (std::abs(plant.table.length - nodes.table.length) > 1e-9 ||
      std::abs(plant.table.width - nodes.table.width) > 1e-9 ||
      std::abs(plant.ball.radius - nodes.ball.radius) > 1e-9) {
    throw std::invalid_argument("--plant-params " + name_or_path +
                                ": not the table and balls of --params " + params::ParameterSetLabel(nodes));
  }
  return plant;
}

}  // namespace

ExecutionNoise RobotExecutionNoise() { return params::LoadNoise(params::kDefaultNoise); }

void AddSessionOptions(CLI::App& app, SessionCommandLine* line) {
  TableSimOptions& options = line->options;
  FaultInjection& faults = options.faults;
  app.add_option("--lcm-url", line->lcm_url,
                 "LCM URL (default: $LCM_DEFAULT_URL, else LCM's default)");
  app.add_option("--params", line->params, "paper | pool | path to a JSON parameter file")
      ->capture_default_str();
  app.add_option("--plant-params", line->plant_params,
                 "The table's own physics when it differs from the nodes' --params (a name or a "
                 "JSON file of the same table and balls): the nodes are checked against --params, "
                 "the balls roll with this set");
  app.add_option("--shots", options.shots, "Shots to random targets")->capture_default_str();
  app.add_option("--spins", line->spins,
                 "The spin styles of the shots to random targets in turn, from natural, stun, "
                 "follow and draw: varied, the strokes' tip heights vary, which a controller "
                 "learning its noise needs to tell the tip's error from the speed's")
      ->capture_default_str();
  app.add_option("--seed", options.seed, "Seed of the targets and the noise")
      ->capture_default_str();
  app.add_option("--noise", line->noise,
                 "Execution noise of the robot: on (sim/params/noise/robot.json) or off")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  app.add_option("--plant-noise", line->plant_noise,
                 "The robot executes with this noise (a name or a JSON file of "
                 "sim/params/noise/'s format) instead of --noise's, one the planner is not told "
                 "of: a controller can be seen measuring its own noise");
  app.add_option("--robot", line->robot,
                 "The robot that plays the strokes: gantry | player | FILE (sim/params/robots/); a "
                 "stroke its cue cannot make is refused, counted cue_blocked in NODE_STATUS")
      ->capture_default_str();
  app.add_option("--camera-rate", options.camera_rate, "Frames per second")->capture_default_str();
  app.add_flag("--realtime", line->realtime, "Real time instead of lockstep");
  app.add_option("--drop-frames", faults.drop_frames,
                 "Fault injection: probability a frame is lost")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--reorder-frames", faults.reorder_frames,
                 "Fault injection: probability a frame is sent after the next")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--duplicate", faults.duplicate,
                 "Fault injection: probability a frame or a request is sent twice")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--fault-seed", faults.seed, "Seed of the fault injection")->capture_default_str();
  app.add_option("--scene", options.scene,
                 std::string("A whole-table session instead of the shots: break (the eight-ball "
                             "rack of --seed on ") +
                     params::kDefaultTable +
                     ") or a scene file (every ball at rest); the cue ball is "
                     "struck once, rolling, at the ball nearest it");
  app.add_option("--pot", line->pots,
                 "--scene: pot ball K (the scene's id) in pocket P (lower_left, ..., upper_right) "
                 "instead of the strike at the nearest ball, planned by the planner from the "
                 "estimator's view; again for more pots in turn")
      ->type_name("K:P");
  app.add_option("--break-speed", options.break_speed,
                 "--scene: the cue ball's speed where it meets the first ball [m/s]")
      ->capture_default_str();
  app.add_option("--game", options.game,
                 "A game instead: nine-ball (the rack of --seed broken, then played), eight-ball "
                 "(a match, --players) or drill (a seeded nine-ball layout from ball in hand), the "
                 "planner choosing every shot")
      ->check(CLI::IsMember({"nine-ball", "eight-ball", "drill"}));
  app.add_option("--players", line->players,
                 "--game nine-ball or eight-ball: a match between two players, A,B (ours, "
                 "ours-no-safety, ours-one-level, no-lookahead, easiest-looking), the planner answering for "
                 "both; A breaks the first rack (eight-ball without it: ours,ours)")
      ->type_name("A,B");
  app.add_option("--racks", options.racks, "--game: racks played, seeds --seed, --seed + 1, ...")
      ->capture_default_str();
  app.add_option("--shot-limit", options.shot_limit, "--game: the most shots of a rack")
      ->capture_default_str();
  app.add_option("--reply-timeout", options.reply_timeout,
                 "Longest wait for the estimator or the planner [s]")
      ->capture_default_str();
}

TableSimOptions SessionOptions(const SessionCommandLine& line) {
  TableSimOptions options = line.options;
  if (options.shots < 1 || !(options.camera_rate > 0.0) || !(options.reply_timeout > 0.0) ||
      !(options.break_speed > 0.0) || options.racks < 1 || options.shot_limit < 1) {
    throw std::invalid_argument(
        "--shots, --camera-rate, --reply-timeout, --break-speed, --racks and --shot-limit must "
        "be positive");
  }
  if (!options.game.empty() && !options.scene.empty()) {
    throw std::invalid_argument("--game and --scene are two sessions: one at a time");
  }
  const FaultInjection& f = options.faults;
  if (f.drop_frames + f.reorder_frames + f.duplicate > 1.0) {
    throw std::invalid_argument("the fault probabilities add up to more than 1");
  }
  for (const std::string& pot : line.pots) options.pots.push_back(ParsePot(pot));
  if (!line.players.empty()) options.players = ParsePlayers(line.players);
  options.spins = ParseSpins(line.spins);
  if (options.game == "eight-ball" && options.players.empty()) options.players = {"ours", "ours"};
  if (!options.players.empty() && options.game != "nine-ball" && options.game != "eight-ball") {
    throw std::invalid_argument("--players plays a match: with --game nine-ball or eight-ball");
  }
  if (!options.pots.empty() && options.scene.empty()) {
    throw std::invalid_argument("--pot needs a --scene to pot in");
  }
  options.lockstep = !line.realtime;
  if (line.noise == "on") options.noise = RobotExecutionNoise();
  if (!line.plant_noise.empty()) {
    try {
      options.noise = params::LoadNoise(line.plant_noise);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("--plant-noise: ") + e.what());
    }
  }
  try {
    options.robot = params::LoadRobot(line.robot);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--robot: ") + e.what());
  }
  return options;
}

camera::CameraModel SessionCamera(const physics::TableParameters& table) {
  return camera::CameraModel::Overhead(table, kCameraWidth, kCameraHeight);
}

int RunSessionCommand(const std::string& name, const SessionCommandLine& line,
                      const InProcessNodes& in_process) {
  const auto fail = [&name](const std::string& reason, int status) {
    std::cerr << name << ": " << reason << std::endl;
    return status;
  };
  TableSimOptions options;
  physics::ModelParameters params;
  try {
    options = SessionOptions(line);
    params = params::LoadParameters(line.params);
    if (!line.plant_params.empty()) options.plant = PlantParameters(line.plant_params, params);
  } catch (const std::invalid_argument& e) {
    return fail(e.what(), 2);
  }
  nodes::StopOnSignals();
  nodes::WarnAboutTheReceiveBuffer(name, line.lcm_url);
  lcm::LCM lcm(line.lcm_url);
  if (!lcm.good()) return fail("cannot initialise LCM with " + nodes::DescribeUrl(line.lcm_url), 1);

  const auto start = std::chrono::steady_clock::now();
  const camera::CameraModel camera = SessionCamera(params.table);
  const std::function<bool()> alongside = in_process ? in_process(lcm, params, camera) : nullptr;
  TableSimNode node(lcm, params, camera, options);
  node.RunAlongside(alongside);
  std::vector<ShotResult> shots;
  std::optional<SceneResult> scene;
  std::optional<std::vector<GameResult>> games;
  try {
    if (!options.game.empty()) {
      games = node.RunGame();
    } else if (options.scene.empty()) {
      shots = node.Run();
    } else {
      scene = node.RunScene();
      shots = {scene->shot};
      if (!scene->pots.empty()) shots.clear();
      for (const PotResult& pot : scene->pots) shots.push_back(pot.shot);
    }
  } catch (const PeerMismatch& e) {
    return fail(e.what(), 3);
  } catch (const UnknownPlayer& e) {
    return fail("--players: the planner " + std::string(e.what()), 2);
  } catch (const std::invalid_argument& e) {  // a scene that does not load or fit
    return fail(e.what(), options.scene.empty() ? 1 : 2);
  } catch (const std::exception& e) {
    return fail(e.what(), nodes::StopRequested() ? 130 : 1);
  }
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  nlohmann::json summary = SessionSummary(shots, node.health().TakeStatus(), wall_s);
  if (scene) summary["scene"] = SceneSummary(*scene, options.scene);
  if (games) summary["game"] = GameSummary(*games, options.game, options.players);
  if (options.plant) summary["plant"] = params::ParameterSetLabel(*options.plant);
  if (!line.plant_noise.empty()) summary["plant_noise"] = options.noise.name;
  const bool noisy = line.noise == "on" || !line.plant_noise.empty();
  if (const DrawnNoise drawn = node.Drawn(); noisy && drawn.strokes > 0) {
    summary["drawn_noise"] = DrawnNoiseJson(drawn);
  }
  std::cout << summary.dump() << std::endl;
  return 0;
}

}  // namespace billiard::table_sim_node
