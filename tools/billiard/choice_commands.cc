#include "tools/billiard/choice_commands.h"

#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "bench/game_benchmark.h"
#include "planner/choice/monte_carlo.h"
#include "planner/choice/scene_balls.h"
#include "planner/game/game_json.h"
#include "planner/players/players.h"
#include "sim/batch/thread_pool.h"
#include "sim/model_choice/model_choice.h"
#include "sim/params/execution_noise.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/robots.h"
#include "sim/params/scene_file.h"
#include "sim/params/table_specs.h"
#include "sim/rules/rules.h"
#include "sim/table/rack.h"
#include "sim/table/table_simulation.h"
#include "tools/billiard/command_line.h"
#include "tools/billiard/noise_option.h"
#include "tools/billiard/pot_commands.h"
#include "tools/billiard/scene_commands.h"

namespace billiard::cli {

namespace {

nlohmann::json Point(const Eigen::Vector2d& p) { return {p.x(), p.y()}; }

// The options every choice command shares.
struct ChoiceArgs {
  std::string rules = "any";
  std::string noise = params::kDefaultNoise;
  int samples = 64;
  int confirm_samples = 256;
  std::uint64_t seed = 1;
  int threads = batch::DefaultThreadCount();
  bool one_level = false;
  bool exact_constants = false;
  std::string robot = params::kDefaultRobot;
  bool json = false;
};

void AddChoiceOptions(CLI::App* cmd, ChoiceArgs* args) {
  cmd->add_option("--rules", args->rules, "any | nine-ball | eight-ball (open; -solids, -stripes: a group taken)")->capture_default_str();
  cmd->add_option("--noise", args->noise,
                  "The execution noise: robot | computational-pool | a JSON file (sim/params/noise/)")
      ->capture_default_str();
  cmd->add_option("--samples", args->samples, "Full-model executions of each finalist")
      ->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_option("--confirm-samples", args->confirm_samples,
                  "Fresh full-model executions of the chosen shot: its reported probability")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  cmd->add_option("--seed", args->seed, "Seed of the sampled noise")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  cmd->add_option("--threads", args->threads, "Threads (the results do not depend on them)")
      ->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_flag("--one-level", args->one_level,
                "The lookahead's next shot valued in closed form, not planned (no second level)");
  cmd->add_flag("--exact-constants", args->exact_constants,
                "Take the parameter set's constants as exact: no draws within its \"uncertainty\"");
  cmd->add_option("--robot", args->robot, kRobotHelp)->capture_default_str();
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
}

choice::ChoiceOptions ChoiceOptionsOf(const ChoiceArgs& args) {
  choice::ChoiceOptions options;
  const std::optional<rules::Rules> parsed = rules::ParseRules(args.rules);
  if (!parsed) throw UsageError("--rules: unknown rules '" + args.rules +
                                "' (any, nine-ball, eight-ball, eight-ball-solids, eight-ball-stripes)");
  options.rules = *parsed;
  options.noise = LoadNoiseOption(args.noise, "--noise");
  options.samples = args.samples;
  options.confirm_samples = args.confirm_samples;
  options.seed = args.seed;
  options.second_level = !args.one_level;
  options.sample_constants = !args.exact_constants;
  options.pot.robot = LoadRobotOption(args.robot);
  return options;
}

struct LoadedScene {
  params::SceneFile file;  // as read: its table and parameter names
  physics::ModelParameters params;
  table::TableGeometry table;
  std::vector<table::SceneBall> balls;
};

LoadedScene LoadSceneOption(const std::string& path) {
  params::SceneFile scene;
  try {
    scene = params::LoadScene(path);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  LoadedScene s{scene, LoadParametersOption(scene.params), LoadTableOption(scene.table), {}};
  try {
    s.balls = params::LaunchedBalls(scene, s.params);
    table::ValidateScene(s.table, s.params.ball.radius, s.balls);  // bad input (2), as simulate's
  } catch (const std::invalid_argument& e) {
    throw UsageError(path + ": " + e.what());
  }
  return s;
}

nlohmann::json CandidateJson(const choice::Candidate& c) {
  nlohmann::json j = PotPlanJson(c.plan);
  j.erase("paths");
  j.erase("events");
  j["screen_probability"] = c.screen_probability;
  j["finalist"] = c.finalist;
  j["position_target"] = c.position_target ? Point(*c.position_target) : nlohmann::json(nullptr);
  if (c.finalist) {
    j["success_probability"] = c.reported().probability;
    j["probability_stderr"] = c.reported().stderr_;
    j["samples"] = c.reported().samples;
    j["selection_probability"] = c.full.probability;
    j["next_shot_value"] = c.next_shot_value;
  }
  j["score"] = c.score;
  return j;
}

nlohmann::json SafetyJson(const choice::SafetyStroke& s) {
  return {{"target", s.target}, {"stroke", CueStrokeJson(s.stroke)}, {"win", s.win},
          {"foul_rate", s.foul_rate}, {"samples", s.samples}};
}

// The choice as a player reads it: the call and the stroke to play (in degrees, mm and m/s), then
// the finalists it was chosen from. A refusal's reason is the line main() prints for exit 3.
void PrintChoice(const choice::ChoiceResult& r) {
  const choice::Candidate* chosen = r.chosen();
  if (r.safety) {
    std::cerr << "choose-shot: safety on ball " << r.safety->target
              << ", chance of winning the rack " << Fixed(r.safety->win, 2) << " against "
              << Fixed(r.attempt_win, 2) << " attempting (" << r.reason << ")\n"
              << "  cue     " << StrokeInWords(r.safety->stroke) << "\n";
  } else if (chosen) {
    std::cerr << "choose-shot: ball " << chosen->plan.ball << " in " << chosen->plan.pocket
              << " (" << pot::ShotKindName(chosen->plan.kind) << "), p "
              << Fixed(chosen->reported().probability, 2)
              << (r.likely ? "" : " (" + r.reason + ")") << "\n";
    if (r.cue_placement) {
      std::cerr << "  cue ball in hand at " << Fixed(r.cue_placement->x(), 3) << ", "
                << Fixed(r.cue_placement->y(), 3) << " m\n";
    }
    std::cerr << "  cue     " << StrokeInWords(chosen->plan.stroke) << "\n";
  } else {
    if (r.fallback) {
      std::cerr << "choose-shot: no pot plans; the fallback, the first legal ball hit full: "
                << StrokeInWords(*r.fallback) << "\n";
    }
    return;
  }
  std::cerr << "  finalists\n";
  for (const choice::Candidate& c : r.candidates) {
    if (!c.finalist) continue;
    std::cerr << "    ball " << c.plan.ball << " in " << c.plan.pocket << " ("
              << pot::ShotKindName(c.plan.kind) << "): p " << Fixed(c.reported().probability, 2)
              << " +- " << Fixed(c.reported().stderr_, 2) << ", next shot "
              << Fixed(c.next_shot_value, 2) << ", score " << Fixed(c.score, 3) << "\n";
  }
  std::cerr << "  " << r.candidates.size() << " candidates, " << r.simulations << " simulations, "
            << Fixed(r.decision_us / 1000, 0) << " ms\n";
}

// The table after `r`'s stroke is played once as planned (no noise; the cue ball placed first
// with ball in hand), to rest, written as a scene at `path`: the next shot's --scene.
void WriteSceneAfter(const LoadedScene& s, const choice::ChoiceResult& r, const std::string& path) {
  const std::vector<table::SceneBall> balls =
      r.cue_placement ? choice::WithCueBallAt(s.balls, *r.cue_placement) : s.balls;
  const choice::StrokeResult played = choice::PlayToRest(s.table, s.params, balls, *r.stroke(),
                                                         model_choice::TableMotion(s.params));
  std::cerr << "  played as planned: potted ";
  if (played.pocketed.empty()) std::cerr << "none";
  for (std::size_t i = 0; i < played.pocketed.size(); ++i) {
    std::cerr << (i ? ", " : "") << played.pocketed[i].first << " in " << played.pocketed[i].second;
  }
  std::cerr << (played.scratch ? "; the cue ball dropped (ball in hand next)" : "") << "; wrote "
            << path << "\n";
  params::SceneFile after = s.file;
  after.cues.clear();
  after.balls = played.rest;
  WriteScene(after, path, "--scene-out");
}

}  // namespace

nlohmann::json ChoiceJson(const choice::ChoiceResult& r) {
  nlohmann::json j;
  j["status"] = choice::ChoiceStatusName(r.status);
  j["reason"] = r.reason;
  j["likely"] = r.likely;
  const choice::Candidate* chosen = r.chosen();
  if (chosen) {
    nlohmann::json c = PotPlanJson(chosen->plan);
    c["success_probability"] = chosen->reported().probability;
    c["probability_stderr"] = chosen->reported().stderr_;
    c["samples"] = chosen->reported().samples;
    c["selection_probability"] = chosen->full.probability;
    c["next_shot_value"] = chosen->next_shot_value;
    c["score"] = chosen->score;
    c["position_target"] =
        chosen->position_target ? Point(*chosen->position_target) : nlohmann::json(nullptr);
    j["choice"] = c;
  } else {
    j["choice"] = nullptr;
  }
  j["candidates"] = nlohmann::json::array();
  for (const choice::Candidate& c : r.candidates) j["candidates"].push_back(CandidateJson(c));
  j["cue_placement"] = r.cue_placement ? Point(*r.cue_placement) : nlohmann::json(nullptr);
  if (r.fallback) j["fallback"] = CueStrokeJson(*r.fallback);
  j["plays_safe"] = r.safety.has_value();
  j["safety"] = r.safety ? SafetyJson(*r.safety) : nlohmann::json(nullptr);
  j["attempt_win"] = r.attempt_win >= 0 ? nlohmann::json(r.attempt_win) : nlohmann::json(nullptr);
  j["safety_win"] = r.safety_win >= 0 ? nlohmann::json(r.safety_win) : nlohmann::json(nullptr);
  j["simulations"] = r.simulations;
  j["decision_us"] = r.decision_us;
  return j;
}

namespace {

// A shot as a player reads it: the call (the break; a safety and why; or why nothing was
// called, and that the fallback was played), then the balls that dropped by number, "none" when
// none did (a count of 0 reads as the cue ball).
void PrintShot(const game::ShotRecord& r) {
  std::cerr << "shot " << r.number << " (visit " << r.visit << "): ";
  if (r.break_shot) {
    std::cerr << "break";
  } else if (r.ball >= 0) {
    std::cerr << "ball " << r.ball << " in " << r.pocket << " (" << r.kind << ", p " << r.predicted << ")";
  } else if (r.safety) {
    // No pot planned (no_plan) or one judged worse: the reason weighs the safety against it.
    std::cerr << "safety" << (r.status == "ok" ? "" : " (" + r.status + ")") << ": " << r.reason;
  } else {
    std::cerr << r.status << (r.reason.empty() ? "" : " (" + r.reason + ")")
              << ": the fallback, the first legal ball hit full";
  }
  std::cerr << " -> potted ";
  if (r.potted.empty()) std::cerr << "none";
  for (std::size_t i = 0; i < r.potted.size(); ++i) std::cerr << (i ? ", " : "") << r.potted[i];
  std::cerr << (r.foul ? ", foul: " + r.foul_reason : "") << "\n";
}

// How the rack ended, in words.
std::string EndOf(const game::GameSummary& m, int shot_limit) {
  switch (m.end) {
    case game::GameEnd::kCleared: return "cleared";
    case game::GameEnd::kShotLimit:
      return "not cleared: the shot limit (" + std::to_string(shot_limit) + ") reached";
    case game::GameEnd::kVisitOver: return "not cleared: the visit is over";
    case game::GameEnd::kNoStroke: return "stopped: no stroke to play (" + m.end_reason + ")";
  }
  return "";
}

// Every shot, then the summary with why the rack ended, on stderr.
void PrintGame(const game::GameRecord& game, int shot_limit) {
  for (const game::ShotRecord& r : game.shots) PrintShot(r);
  const game::GameSummary& m = game.summary;
  std::cerr << "play: " << EndOf(m, shot_limit) << " in " << m.shots << " shots, " << m.visits
            << " visits, " << m.pots << " of " << m.attempts << " attempts potted, " << m.fouls
            << " fouls" << (m.run_out ? ", a run-out" : "") << "\n";
}

}  // namespace

void AddChooseShotCommand(CLI::App& app) {
  struct Args : ChoiceArgs {
    std::string scene_path;
    bool ball_in_hand = false;
    std::string scene_out;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "choose-shot",
      "Choose the pot most likely to drop under the robot's execution noise, with a one-shot "
      "lookahead (exit 3 if there is none to play)");
  cmd->add_option("--scene", args->scene_path, "The scene JSON (as simulate --scene), every ball at rest")
      ->required();
  cmd->add_flag("--ball-in-hand", args->ball_in_hand,
                "Place the cue ball first (where the choice scores best); the scene's cue ball, if any, is lifted");
  cmd->add_option("--scene-out", args->scene_out,
                  "Write the table after the chosen stroke is played as planned (no noise), to rest: "
                  "the next shot's --scene");
  AddChoiceOptions(cmd, args.get());
  cmd->callback([args] {
    const LoadedScene s = LoadSceneOption(args->scene_path);
    const choice::ChoiceOptions options = ChoiceOptionsOf(*args);
    batch::ThreadPool pool(args->threads);
    const players::Turn turn{s.table, s.params, s.balls,
                             {args->ball_in_hand, rules::LegalTargets(options.rules, s.balls)}};
    const choice::ChoiceResult r = players::MakePlayer("ours")->Decide(turn, options, pool);
    if (args->json) {
      nlohmann::json j = ChoiceJson(r);
      j["rules"] = rules::RulesName(options.rules);
      j["noise"] = options.noise.name;
      j["constants_drawn"] = options.sample_constants && !s.params.uncertainty.sd.empty();
      j["table"] = s.table.name;
      DescribeParameters(s.params, &j);
      std::cout << j.dump() << std::endl;
    } else {
      PrintChoice(r);
    }
    if (!args->scene_out.empty() && (r.status == choice::ChoiceStatus::kOk || r.safety)) {
      WriteSceneAfter(s, r, args->scene_out);
    }
    if (r.status != choice::ChoiceStatus::kOk && !r.safety) {
      throw Refused(std::string(choice::ChoiceStatusName(r.status)) + ": " + r.reason);
    }
  });
}

void AddPlayCommand(CLI::App& app) {
  struct Args : ChoiceArgs {
    std::string scene_path;
    std::string rack;
    std::string policy = "ours";
    int shot_limit = 40;
    bool ball_in_hand = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "play",
      "Play a whole rack in simulation: shot by shot choice, execution with the noise, the "
      "rules' judgement, and a summary (pots per attempt, run-out, fouls)");
  CLI::Option* scene = cmd->add_option("--scene", args->scene_path, "The scene JSON, every ball at rest");
  CLI::Option* rack = cmd->add_option("--rack", args->rack, "nine-ball: the seeded rack, broken first");
  scene->excludes(rack);
  cmd->add_option("--policy", args->policy, "The player: ours | no-lookahead | easiest-looking")
      ->capture_default_str();
  cmd->add_option("--shot-limit", args->shot_limit, "Shots at most")->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_flag("--ball-in-hand", args->ball_in_hand, "Start with the cue ball in hand (a drill)");
  AddChoiceOptions(cmd, args.get());
  cmd->callback([args, scene, rack] {
    if (!scene->count() && !rack->count()) throw UsageError("play: give --scene S.json or --rack nine-ball");
    LoadedScene s;
    game::GameOptions options;
    options.choice = ChoiceOptionsOf(*args);
    if (rack->count()) {
      if (args->rack != "nine-ball") throw UsageError("--rack: only nine-ball is played");
      s.params = LoadParametersOption(params::kDefaultParameterSet);
      s.table = LoadTableOption(params::kDefaultTable);
      s.balls = table::Rack(table::RackKind::kNineBall, s.table, s.params.ball.radius, args->seed);
      options.break_shot = !args->ball_in_hand;
      if (args->rules == "any") options.choice.rules = rules::Rules::kNineBall;
    } else {
      s = LoadSceneOption(args->scene_path);
    }
    try {
      options.player = players::MakePlayer(args->policy);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--policy: ") + e.what());
    }
    options.execution = options.choice.noise;
    options.seed = args->seed;
    options.shot_limit = args->shot_limit;
    options.ball_in_hand = args->ball_in_hand;
    batch::ThreadPool pool(args->threads);
    const game::GameRecord game = game::PlayGame(s.table, s.params, s.balls, options, pool);
    PrintGame(game, options.shot_limit);
    if (args->json) {
      nlohmann::json j = game::GameJson(game);
      j["rules"] = rules::RulesName(options.choice.rules);
      j["noise"] = options.choice.noise.name;
      j["policy"] = options.player->Name();
      j["seed"] = args->seed;
      std::cout << j.dump() << std::endl;
    }
  });
}

void AddBenchGameCommand(CLI::App& app) {
  struct Args {
    bench::GameBenchmarkOptions options;
    std::string robot = params::kDefaultRobot;
    std::string out;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "bench-game",
      "The shot choice on seeded nine-ball layouts: calibration (a reliability diagram), ours "
      "against the baselines under both noises, decision time (JSON summary on stdout)");
  bench::GameBenchmarkOptions& o = args->options;
  cmd->add_option("--layouts", o.layouts, "Drills from ball in hand per noise and policy")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  cmd->add_option("--calibration-layouts", o.calibration_layouts, "Choices whose chosen shot is replayed")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  cmd->add_option("--executions", o.executions, "Replays of each chosen shot")
      ->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_option("--samples", o.samples, "The choice's full-model executions per finalist")
      ->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_option("--confirm-samples", o.confirm_samples,
                  "Fresh full-model executions of the chosen shot: its reported probability")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  cmd->add_option("--seed", o.seed, "The first layout's seed")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  cmd->add_option("--threads", o.threads, "Threads")->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_option("--chunk", o.chunk, "Layouts between the report's rewrites")
      ->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_option("--robot", args->robot, std::string(kRobotHelp) + "; none: the level cue, unchecked")
      ->capture_default_str();
  cmd->add_option("--noise", o.noise,
                  "The noise the calibration's choices plan for: robot | computational-pool | a "
                  "JSON file (sim/params/noise/)")
      ->capture_default_str();
  cmd->add_option("--plant-noise", o.plant_noise,
                  "The noise the chosen shots are replayed with, which the choice is not told of "
                  "(a name or a file; default: --noise's)");
  cmd->add_option("--out", args->out, "Write game_report.md, game_reliability.png and game_results.json here");
  cmd->callback([args] {
    if (!args->out.empty()) RequireWritableDirectory(args->out, "--out");
    bench::GameBenchmarkOptions options = args->options;
    options.robot = LoadRobotOrNone(args->robot);
    LoadNoiseOption(options.noise, "--noise");  // refused before the first choice, not after
    if (!options.plant_noise.empty()) LoadNoiseOption(options.plant_noise, "--plant-noise");
    options.progress = [](const std::string& line) { std::cerr << line << std::endl; };
    // The report rewritten after each chunk: a run stopped early leaves its largest whole part.
    const std::string out = args->out;
    const bench::GameBenchmarkResult result =
        bench::RunGameBenchmark(options, [out](const bench::GameBenchmarkResult& so_far) {
          if (!out.empty()) bench::WriteGameReport(so_far, out);
        });
    if (!out.empty()) std::cerr << "bench-game: wrote " << out << "/game_report.md\n";
    std::cout << bench::GameSummaryJson(result).dump() << std::endl;
  });
}

}  // namespace billiard::cli
