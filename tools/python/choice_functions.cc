#include "tools/python/choice_functions.h"

#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "planner/choice/choice_result.h"
#include "planner/game/game.h"
#include "planner/game/game_json.h"
#include "planner/players/players.h"
#include "sim/batch/thread_pool.h"
#include "sim/params/execution_noise.h"
#include "sim/params/robots.h"
#include "sim/params/table_specs.h"
#include "sim/rules/rules.h"
#include "sim/table/rack.h"
#include "tools/python/conversions.h"

namespace billiard::python {

namespace {

// The options choose_shot and play share, as the CLI's choice options.
struct ChoiceArgs {
  std::string rules, noise, robot;
  int samples = 0, confirm_samples = 0;
  std::uint64_t seed = 0;
  int threads = 0;  // 0: batch::DefaultThreadCount(); the answer does not depend on it
};

choice::ChoiceOptions ChoiceOptionsOf(const ChoiceArgs& args) {
  choice::ChoiceOptions options;
  const std::optional<rules::Rules> parsed = rules::ParseRules(args.rules);
  if (!parsed) throw py::value_error("unknown rules '" + args.rules + "' (any, nine-ball)");
  options.rules = *parsed;
  try {
    options.noise = params::LoadNoise(args.noise);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(std::string("noise: ") + e.what());
  }
  if (args.samples < 1 || args.confirm_samples < 0 || args.threads < 0) {
    throw py::value_error("samples must be >= 1, confirm_samples and threads >= 0");
  }
  options.samples = args.samples;
  options.confirm_samples = args.confirm_samples;
  options.seed = args.seed;
  options.pot.robot = Robot(args.robot);
  return options;
}

py::object Point(const std::optional<Eigen::Vector2d>& p) {
  if (!p) return py::none();
  return Array(2, p->data());
}

// The chosen pot as choose-shot --json's "choice" has it (the plan's stroke and windows, the
// probability reported and its standard error, the lookahead's value).
py::dict ChosenDict(const choice::Candidate& c) {
  py::dict d;
  d["ball"] = c.plan.ball;
  d["pocket"] = c.plan.pocket;
  d["kind"] = pot::ShotKindName(c.plan.kind);
  d["cue"] = CueJson(c.plan.stroke, c.plan.clearance);
  d["v0"] = Array(2, c.plan.v0.data());
  d["w0"] = Array(3, c.plan.w0.data());
  d["cut_deg"] = c.plan.cut_deg;
  d["margin_deg"] = std::vector<double>{c.plan.margin_left_deg, c.plan.margin_right_deg};
  d["success_probability"] = c.reported().probability;
  d["probability_stderr"] = c.reported().stderr_;
  d["samples"] = c.reported().samples;
  d["selection_probability"] = c.full.probability;
  d["next_shot_value"] = c.next_shot_value;
  d["score"] = c.score;
  d["position_target"] = Point(c.position_target);
  return d;
}

py::dict ChooseShot(const Array& states, const std::optional<std::vector<int>>& ids,
                    bool ball_in_hand, const ChoiceArgs& args, const std::string& table_name,
                    const std::string& params_name) {
  const table::TableGeometry table = Table(table_name);
  const physics::ModelParameters params = Params(params_name);
  const std::vector<table::SceneBall> balls = SceneBalls(states, ids);
  const choice::ChoiceOptions options = ChoiceOptionsOf(args);
  batch::ThreadPool pool(args.threads > 0 ? args.threads : batch::DefaultThreadCount());
  const players::Turn turn{table, params, balls,
                           {ball_in_hand, rules::LegalTargets(options.rules, balls)}};
  choice::ChoiceResult r;
  {
    py::gil_scoped_release release;  // minutes of simulation: other Python threads run
    r = players::MakePlayer("ours")->Decide(turn, options, pool);
  }
  if (r.status != choice::ChoiceStatus::kOk) {
    Refuse(std::string(choice::ChoiceStatusName(r.status)) + ": " + r.reason);
  }
  py::dict out;
  out["status"] = choice::ChoiceStatusName(r.status);
  out["reason"] = r.reason;
  out["likely"] = r.likely;
  out["choice"] = ChosenDict(*r.chosen());
  out["candidates"] = r.candidates.size();
  out["cue_placement"] = Point(r.cue_placement);
  out["simulations"] = r.simulations;
  out["decision_us"] = r.decision_us;
  return out;
}

// play: the scene's balls, or with rack="nine-ball" the seeded rack broken first, as the CLI;
// the game as `play --json` writes it.
py::object Play(const std::optional<Array>& states, const std::optional<std::vector<int>>& ids,
                const std::optional<std::string>& rack, const std::string& policy, int shot_limit,
                bool ball_in_hand, const ChoiceArgs& args, const std::string& table_name,
                const std::string& params_name) {
  if (states.has_value() == rack.has_value()) throw py::value_error("give states or rack, not both");
  if (shot_limit < 1) throw py::value_error("shot_limit must be >= 1");
  const table::TableGeometry table = Table(table_name);
  const physics::ModelParameters params = Params(params_name);
  game::GameOptions options;
  options.choice = ChoiceOptionsOf(args);
  std::vector<table::SceneBall> balls;
  if (rack) {
    if (*rack != "nine-ball") throw py::value_error("rack: only nine-ball is played");
    balls = table::Rack(table::RackKind::kNineBall, table, params.ball.radius, args.seed);
    options.break_shot = !ball_in_hand;
    if (args.rules == "any") options.choice.rules = rules::Rules::kNineBall;
  } else {
    balls = SceneBalls(*states, ids);
  }
  try {
    options.player = players::MakePlayer(policy);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(std::string("policy: ") + e.what());
  }
  options.execution = options.choice.noise;
  options.seed = args.seed;
  options.shot_limit = shot_limit;
  options.ball_in_hand = ball_in_hand;
  batch::ThreadPool pool(args.threads > 0 ? args.threads : batch::DefaultThreadCount());
  game::GameRecord game;
  {
    py::gil_scoped_release release;
    game = game::PlayGame(table, params, balls, options, pool);
  }
  return ToPython(game::GameJson(game));
}

}  // namespace

void AddChoiceFunctions(py::module_& m) {
  using py::arg;
  m.def(
      "choose_shot",
      [](const Array& states, std::optional<std::vector<int>> ids, const std::string& rules,
         bool ball_in_hand, const std::string& noise, int samples, int confirm_samples,
         std::uint64_t seed, int threads, const std::string& table, const std::string& params,
         const std::string& robot) {
        return ChooseShot(states, ids, ball_in_hand, {rules, noise, robot, samples, confirm_samples, seed, threads},
                          table, params);
      },
      arg("states"), arg("ids") = py::none(), arg("rules") = "any", arg("ball_in_hand") = false,
      arg("noise") = params::kDefaultNoise, arg("samples") = 64, arg("confirm_samples") = 256,
      arg("seed") = 1, arg("threads") = 0, arg("table") = params::kDefaultTable,
      arg("params") = "pool", arg("robot") = params::kDefaultRobot,
      "billiard choose-shot: the pot most likely to drop under the execution noise, with a "
      "one-shot lookahead, from a scene of balls at rest (N x 7 states, id 0 the cue ball): "
      "'choice' (ball, pocket, kind, cue, success_probability, probability_stderr, "
      "next_shot_value, ...), 'cue_placement' with ball_in_hand, 'likely'; raises Refused when "
      "there is none to play");
  m.def(
      "play",
      [](std::optional<Array> states, std::optional<std::vector<int>> ids,
         std::optional<std::string> rack, const std::string& rules, const std::string& policy,
         int shot_limit, bool ball_in_hand, const std::string& noise, int samples,
         int confirm_samples, std::uint64_t seed, int threads, const std::string& table,
         const std::string& params, const std::string& robot) {
        return Play(states, ids, rack, policy, shot_limit, ball_in_hand,
                    {rules, noise, robot, samples, confirm_samples, seed, threads}, table, params);
      },
      arg("states") = py::none(), arg("ids") = py::none(), arg("rack") = py::none(),
      arg("rules") = "any", arg("policy") = "ours", arg("shot_limit") = 40,
      arg("ball_in_hand") = false, arg("noise") = params::kDefaultNoise, arg("samples") = 64,
      arg("confirm_samples") = 256, arg("seed") = 1, arg("threads") = 0,
      arg("table") = params::kDefaultTable, arg("params") = "pool",
      arg("robot") = params::kDefaultRobot,
      "billiard play: a rack played in simulation shot by shot (states, or rack='nine-ball' "
      "racked from the seed and broken): 'shots' (each call, prediction, what dropped, any "
      "foul), 'summary' (pots per attempt, visits, fouls, cleared, run_out, end), 'balls_left'");
}

}  // namespace billiard::python
