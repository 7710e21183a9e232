#include "sim/table_sim_node/session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <optional>
#include <stdexcept>

#include "lcmtypes/node/node_loop.h"
#include "sim/params/parameter_sets.h"

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
  app.add_option("--seed", options.seed, "Seed of the targets and the noise")
      ->capture_default_str();
  app.add_option("--noise", line->noise,
                 "Execution noise of the robot: on (sim/params/noise/robot.json) or off")
      ->check(CLI::IsMember({"on", "off"}))
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
                 "A whole-table session instead of the shots: break (the eight-ball rack of "
                 "--seed on pool-9ft) or a scene file (every ball at rest); the cue ball is "
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
                 "A game instead: nine-ball (the rack of --seed broken, then played) or drill "
                 "(a seeded nine-ball layout from ball in hand), under nine-ball rules, the "
                 "planner choosing every shot")
      ->check(CLI::IsMember({"nine-ball", "drill"}));
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
  if (!options.pots.empty() && options.scene.empty()) {
    throw std::invalid_argument("--pot needs a --scene to pot in");
  }
  options.lockstep = !line.realtime;
  if (line.noise == "on") options.noise = RobotExecutionNoise();
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
  } catch (const std::invalid_argument& e) {  // a scene that does not load or fit
    return fail(e.what(), options.scene.empty() ? 1 : 2);
  } catch (const std::exception& e) {
    return fail(e.what(), nodes::StopRequested() ? 130 : 1);
  }
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  nlohmann::json summary = SessionSummary(shots, node.health().TakeStatus(), wall_s);
  if (scene) summary["scene"] = SceneSummary(*scene, options.scene);
  if (games) summary["game"] = GameSummary(*games, options.game);
  if (options.plant) summary["plant"] = params::ParameterSetLabel(*options.plant);
  std::cout << summary.dump() << std::endl;
  return 0;
}

nlohmann::json SessionSummary(const std::vector<ShotResult>& shots, const node_status_t& health,
                              double wall_s) {
  nlohmann::json j;
  std::vector<double> misses;
  for (const ShotResult& s : shots) {
    nlohmann::json shot = {{"target", {s.target.x(), s.target.y()}},
                           {"final", {s.final_point.x(), s.final_point.y()}},
                           {"miss_m", s.miss_m},
                           {"plan_ms", s.plan_ms},
                           {"status", s.status},
                           {"retries", s.retries}};
    if (!s.reason.empty()) shot["reason"] = s.reason;
    j["shots"].push_back(shot);
    misses.push_back(s.miss_m);
  }
  if (!misses.empty()) {
    std::sort(misses.begin(), misses.end());
    const std::size_t n = misses.size();
    j["median_miss_m"] = n % 2 ? misses[n / 2] : 0.5 * (misses[n / 2 - 1] + misses[n / 2]);
    j["max_miss_m"] = misses.back();
    double mean = 0.0, spread = 0.0;
    for (double m : misses) mean += m / n;
    for (double m : misses) spread += (m - mean) * (m - mean) / n;
    j["mean_miss_m"] = mean;
    j["stddev_miss_m"] = std::sqrt(spread);
  }
  for (int i = 0; i < health.num_counters; ++i) {
    j["counters"][health.counter_names[i]] = health.counter_values[i];
  }
  j["received"] = health.received;
  j["dropped"] = health.dropped;
  j["wall_s"] = wall_s;
  return j;
}

nlohmann::json GameSummary(const std::vector<GameResult>& games, const std::string& kind) {
  nlohmann::json j = {{"kind", kind}};
  int cleared = 0, run_outs = 0, shots = 0, attempts = 0, pots = 0, fouls = 0, visits = 0,
      balls = 0, misidentified = 0, untracked = 0, decided = 0;
  std::vector<double> decisions, rms;
  double worst = 0.0;
  for (const GameResult& game : games) {
    nlohmann::json rack = {{"seed", game.seed},
                           {"cleared", game.cleared},
                           {"visits", game.visits},
                           {"run_out", game.cleared && game.visits == 1}};
    int rack_attempts = 0, rack_pots = 0, rack_fouls = 0, rack_balls = 0;
    for (const GameShot& s : game.shots) {
      nlohmann::json shot = {{"number", s.number},
                             {"visit", s.visit},
                             {"break", s.break_shot},
                             {"ball_in_hand", s.ball_in_hand},
                             {"status", s.status},
                             {"potted", s.potted},
                             {"called_potted", s.called_potted},
                             {"foul", s.foul},
                             {"decision_ms", s.decision_ms},
                             {"estimator",
                              {{"position_rms_mm", s.position_rms_mm},
                               {"position_max_mm", s.position_max_mm},
                               {"untracked", s.untracked},
                               {"misidentified", s.misidentified}}}};
      shot["first_contact"] =
          s.first_contact < 0 ? nlohmann::json() : nlohmann::json(s.first_contact);
      if (!s.reason.empty()) shot["reason"] = s.reason;
      if (s.foul) shot["foul_reason"] = s.foul_reason;
      if (s.cue_placement) shot["cue_placement"] = {s.cue_placement->x(), s.cue_placement->y()};
      if (s.called >= 0) {
        shot["called"] = {
            {"ball", s.called}, {"pocket", s.pocket}, {"kind", s.kind}, {"predicted", s.predicted}};
        ++rack_attempts;
        rack_pots += s.called_potted;
      }
      rack_fouls += s.foul;
      if (!s.foul) rack_balls += static_cast<int>(s.potted.size());
      if (!s.break_shot && s.status == "ok") {
        ++decided;
        decisions.push_back(s.decision_ms);
        rms.push_back(s.position_rms_mm);
        worst = std::max(worst, s.position_max_mm);
        misidentified += s.misidentified;
        untracked += s.untracked;
      }
      rack["shots"].push_back(shot);
    }
    rack["attempts"] = rack_attempts;
    rack["pots"] = rack_pots;
    rack["fouls"] = rack_fouls;
    rack["balls_potted"] = rack_balls;
    j["racks"].push_back(rack);
    cleared += game.cleared;
    run_outs += game.cleared && game.visits == 1;
    shots += static_cast<int>(game.shots.size());
    attempts += rack_attempts;
    pots += rack_pots;
    fouls += rack_fouls;
    visits += game.visits;
    balls += rack_balls;
  }
  const auto median = [](std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  j["summary"] = {{"racks", games.size()},
                  {"cleared", cleared},
                  {"run_outs", run_outs},
                  {"shots", shots},
                  {"attempts", attempts},
                  {"pots", pots},
                  {"pots_per_attempt", attempts ? static_cast<double>(pots) / attempts : 0.0},
                  {"fouls", fouls},
                  {"visits", visits},
                  {"balls_per_visit", visits ? static_cast<double>(balls) / visits : 0.0},
                  {"median_decision_ms", median(decisions)},
                  {"max_decision_ms",
                   decisions.empty() ? 0.0 : *std::max_element(decisions.begin(), decisions.end())},
                  {"decisions", decided},
                  {"median_position_rms_mm", median(rms)},
                  {"max_position_error_mm", worst},
                  {"misidentified_ball_decisions", misidentified},
                  {"untracked_ball_decisions", untracked}};
  return j;
}

nlohmann::json SceneSummary(const SceneResult& scene, const std::string& name) {
  nlohmann::json j = {{"name", name}, {"events", scene.events}};
  for (std::size_t k = 0; k < scene.final_balls.size(); ++k) {
    const table::SceneBall& b = scene.final_balls[k];
    nlohmann::json ball = {{"id", b.id}, {"final", {b.state[physics::kX], b.state[physics::kY]}}};
    ball["pocketed"] =
        scene.pockets[k].empty() ? nlohmann::json() : nlohmann::json(scene.pockets[k]);
    j["balls"].push_back(ball);
  }
  for (const PotResult& pot : scene.pots) {
    const ShotResult& shot = pot.shot;
    nlohmann::json p = {{"ball", pot.asked.ball}, {"pocket", pot.asked.pocket},
                        {"status", shot.status},  {"potted", pot.potted},
                        {"scratch", pot.scratch}, {"plan_ms", shot.plan_ms},
                        {"retries", shot.retries}};
    p["dropped"] = pot.dropped.empty() ? nlohmann::json() : nlohmann::json(pot.dropped);
    p["first_contact"] =
        pot.first_contact < 0 ? nlohmann::json() : nlohmann::json(pot.first_contact);
    if (!shot.reason.empty()) p["reason"] = shot.reason;
    if (shot.status == "ok") {
      p["kind"] = pot.kind;
      p["margin_deg"] = {pot.margin_left_deg, pot.margin_right_deg};
      p["speed_window"] = {pot.speed_lo, pot.speed_hi};
      p["planned_cue_rest"] = {shot.target.x(), shot.target.y()};
      p["cue_rest_error_m"] = shot.miss_m;
    }
    p["cue_rest"] = {shot.final_point.x(), shot.final_point.y()};
    j["pots"].push_back(p);
  }
  const TrackingReport& t = scene.tracking;
  double sum = 0.0, worst = 0.0;
  int frames = 0, lost = 0, misnamed = 0, unnamed = 0, named_at_end = 0;
  for (const BallTracking& b : t.balls) {
    nlohmann::json ball = {{"id", b.id},           {"frames", b.frames},
                           {"lost", b.lost},       {"misnamed", b.misnamed},
                           {"unnamed", b.unnamed}, {"named_at_end", b.named_at_end}};
    if (b.frames > 0) {
      ball["rms_error_mm"] = 1e3 * std::sqrt(b.sum_squared_error / b.frames);
      ball["max_error_mm"] = 1e3 * b.max_error;
    }
    j["tracking"]["balls"].push_back(ball);
    sum += b.sum_squared_error;
    frames += b.frames;
    lost += b.lost;
    misnamed += b.misnamed;
    unnamed += b.unnamed;
    named_at_end += b.named_at_end;
    worst = std::max(worst, b.max_error);
  }
  j["tracking"]["rms_error_mm"] = frames > 0 ? 1e3 * std::sqrt(sum / frames) : 0.0;
  j["tracking"]["max_error_mm"] = 1e3 * worst;
  j["tracking"]["lost_ball_frames"] = lost;
  j["tracking"]["misnamed_ball_frames"] = misnamed;
  j["tracking"]["unnamed_ball_frames"] = unnamed;
  j["tracking"]["named_at_end"] = named_at_end;
  j["tracking"]["swaps"] = t.swaps;
  j["tracking"]["reacquired"] = t.reacquired;
  return j;
}

}  // namespace billiard::table_sim_node
