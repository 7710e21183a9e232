#include "planner/choice/safety.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>
#include <variant>

#include "planner/choice/lookahead.h"
#include "planner/choice/placements.h"
#include "planner/choice/rack_value.h"
#include "planner/choice/scene_balls.h"
#include "planner/pot/pot_geometry.h"
#include "sim/cue/stroke_limits.h"
#include "sim/model_choice/model_choice.h"

namespace billiard::choice {

namespace {

// The safeties' seed stream, apart from the choice's and the confirmation's.
constexpr std::uint64_t kSafetyStream = 0x7361666574792121ull;
// Where the cue ball's line passes the object ball's centre, in ball widths (2 r) to the side:
// full, half-ball-ish and thin hits either way.
constexpr double kThicknesses[] = {0.0, 0.3, -0.3, 0.6, -0.6, 0.85, -0.85};
// The cue speeds [m/s]: a soft roll to the ball, a rail or two, a stroke round the table.
constexpr double kSpeeds[] = {0.7, 1.1, 1.7, 2.6};
constexpr int kEight = 8;
// A kick's headings are searched kKickStep apart within kKickReach of the mirror's [rad]: a
// cushion's rebound parts from a mirror's by a few degrees, and the 1 degree or so a ball's width
// subtends at a table's length is met by several steps.
constexpr double kKickStep = 0.25 * M_PI / 180.0;
constexpr double kKickReach = 8.0 * M_PI / 180.0;

bool Potted(const StrokeResult& result, int ball) {
  return std::any_of(result.pocketed.begin(), result.pocketed.end(),
                     [&](const auto& p) { return p.first == ball; });
}

// The opponent's best pot estimate with ball in hand on `rest` (the best place of
// placements.h); 1 when the rack is over for them (a foul that ends it hands them the win).
double HandChance(const table::TableGeometry& table, double radius,
                  const std::vector<table::SceneBall>& rest, rules::Rules opponent,
                  const params::ExecutionNoise& noise) {
  if (rules::RulesetOf(opponent).RackOver(rest)) return 1.0;
  ChoiceOptions o;
  o.rules = opponent;
  o.noise = noise;
  const std::vector<Placement> places = CandidatePlacements(table, radius, rest, o);
  return places.empty() ? 0.0 : places.front().estimate;
}

// One noisy execution judged: our chance of winning after it, whether it fouled.
struct Judged {
  double win = 0.0;
  bool foul = true;
};

// Executions [0, samples) of each of `strokes` (with `calls`, one each) on `motion`, flattened
// into one batch, stroke k's execution s at k samples + s. A throw counts as a foul that loses.
std::vector<Judged> JudgeAll(const table::TableGeometry& table,
                             const physics::ModelParameters& params,
                             const std::vector<table::SceneBall>& balls,
                             const std::vector<physics::CueStroke>& strokes,
                             const std::vector<std::optional<Call>>& calls, int samples,
                             const ChoiceOptions& options, const Motion& motion,
                             batch::ThreadPool& pool) {
  const std::size_t n = strokes.size() * static_cast<std::size_t>(samples);
  auto results = pool.Map(n, [&](std::size_t job) {
    NormalStream normal(SampleSeed(options.seed + kSafetyStream, job % samples));
    const physics::CueStroke played = params::Perturbed(
        strokes[job / samples], options.noise, params.ball.radius, [&] { return normal.Next(); });
    const StrokeResult r = PlayToRest(
        table,
        DrawnConstants(params, options.sample_constants, options.seed + kSafetyStream, job % samples),
        balls, played, motion);
    return Judged{WinChance(table, params.ball.radius, balls, r, calls[job / samples], options),
                  Fouls(balls, r, options.rules)};
  });
  std::vector<Judged> judged(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (results[i].ok()) judged[i] = *results[i].value;
  }
  return judged;
}

// The mean chance of winning of stroke k in `judged`.
double MeanWin(const std::vector<Judged>& judged, std::size_t k, int samples) {
  double sum = 0.0;
  for (int s = 0; s < samples; ++s) sum += judged[k * samples + s].win;
  return sum / samples;
}

// Stroke k of `judged` as a SafetyStroke: its chance, foul rate and the opponent's chance.
SafetyStroke Summary(const SafetyCandidate& c, const std::vector<Judged>& judged, std::size_t k,
                     int samples) {
  SafetyStroke s;
  s.target = c.target;
  s.stroke = c.stroke;
  s.samples = samples;
  s.win = MeanWin(judged, k, samples);
  int fouls = 0;
  for (int i = 0; i < samples; ++i) fouls += judged[k * samples + i].foul;
  s.foul_rate = static_cast<double>(fouls) / samples;
  return s;
}

// The candidates' indices, best screened first (ties in candidate order).
std::vector<std::size_t> ScreenSafeties(const table::TableGeometry& table,
                                        const physics::ModelParameters& params,
                                        const std::vector<table::SceneBall>& balls,
                                        const std::vector<SafetyCandidate>& candidates,
                                        const ChoiceOptions& options, batch::ThreadPool& pool) {
  std::vector<physics::CueStroke> strokes;
  for (const SafetyCandidate& c : candidates) strokes.push_back(c.stroke);
  const int samples = options.safety_screen_samples;
  const std::vector<Judged> judged =
      JudgeAll(table, params, balls, strokes, std::vector<std::optional<Call>>(strokes.size()),
               samples, options, {}, pool);
  std::vector<double> mean(candidates.size());
  for (std::size_t k = 0; k < mean.size(); ++k) mean[k] = MeanWin(judged, k, samples);
  std::vector<std::size_t> order(candidates.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return mean[a] > mean[b]; });
  return order;
}

// The attempt's chance of winning: its stroke (with its call; the fallback without) judged on
// the full model on the safeties' seeds.
double AttemptWin(const table::TableGeometry& table, const physics::ModelParameters& params,
                  const std::vector<table::SceneBall>& balls, const ChoiceResult& result,
                  const ChoiceOptions& options, batch::ThreadPool& pool) {
  std::optional<Call> call;
  if (const Candidate* c = result.chosen()) call = Call{c->plan.ball, c->plan.pocket};
  const std::vector<Judged> judged =
      JudgeAll(table, params, balls, {*result.stroke()}, {call}, options.safety_samples, options,
               model_choice::TableMotion(params), pool);
  return MeanWin(judged, 0, options.safety_samples);
}

std::string Why(const SafetyStroke& s, double attempt_win, const ChoiceResult& result) {
  char text[256];
  const double p = result.chosen() ? result.chosen()->reported().probability : 0.0;
  std::snprintf(text, sizeof text,
                "playing safe on ball %d: chance of winning the rack %.2f (fouls %.0f %%) against "
                "%.2f attempting (the best pot %.2f)",
                s.target, s.win, 100 * s.foul_rate, attempt_win, p);
  return text;
}

// Whether a ball other than `target` lies across the cue ball's straight line from `from` to
// `to` (pot_geometry.h's BallsAcross at two radii): the legal ball is hidden from the cue ball.
bool Hidden(const std::vector<table::SceneBall>& balls, int target, const Eigen::Vector2d& from,
            const Eigen::Vector2d& to, double radius) {
  return !pot::BallsAcross(balls, from, to, 2 * radius, {0, target}).empty();
}

// The cue ball's heading to meet `target` off one cushion as a mirror would return it: at the
// target mirrored in each line the cue ball's centre rebounds from (a radius inside the noses).
std::vector<double> MirrorHeadings(const table::TableGeometry& table, const Eigen::Vector2d& cue,
                                   const Eigen::Vector2d& target, double radius) {
  const double left = radius, right = table.length - radius;
  const double bottom = radius, top = table.width - radius;
  std::vector<double> headings;
  for (const Eigen::Vector2d& image : {Eigen::Vector2d(2 * left - target.x(), target.y()),
                                       Eigen::Vector2d(2 * right - target.x(), target.y()),
                                       Eigen::Vector2d(target.x(), 2 * bottom - target.y()),
                                       Eigen::Vector2d(target.x(), 2 * top - target.y())}) {
    headings.push_back(std::atan2(image.y() - cue.y(), image.x() - cue.x()));
  }
  return headings;
}

// Kicks at `target` off each cushion, one a speed: a cushion is no mirror (its rebound angle
// depends on the speed and the spin: Mathavan et al. 2010), so about each mirror heading the
// headings kKickStep apart within kKickReach are played once without noise on the closed form,
// and the middle of the longest run that meets `target` first is the kick (the heading the
// noise moves least off it). The Monte Carlo then judges them as the other candidates.
std::vector<SafetyCandidate> Kicks(const table::TableGeometry& table,
                                   const physics::ModelParameters& params,
                                   const std::vector<table::SceneBall>& balls, int target) {
  const Eigen::Vector2d cue = Position(*FindBall(balls, 0));
  const Eigen::Vector2d at = Position(*FindBall(balls, target));
  const int steps = static_cast<int>(std::round(kKickReach / kKickStep));
  std::vector<SafetyCandidate> kicks;
  for (const double mirror : MirrorHeadings(table, cue, at, params.ball.radius)) {
    for (const double speed : kSpeeds) {
      physics::CueStroke s;
      s.speed = speed;
      int run = 0, best_run = 0, best_end = 0;
      for (int k = -steps; k <= steps; ++k) {
        s.heading = mirror + k * kKickStep;
        run = FirstContact(table, params, balls, s) == target ? run + 1 : 0;
        if (run > best_run) {
          best_run = run;
          best_end = k;
        }
      }
      if (best_run == 0) continue;
      s.heading = mirror + (best_end - 0.5 * (best_run - 1)) * kKickStep;
      kicks.push_back({target, s});
    }
  }
  return kicks;
}

// The grid's strokes at `aim` (thicknesses about it, then speeds), appended to `candidates`.
void AddStrokesAt(int target, const Eigen::Vector2d& cue, const Eigen::Vector2d& aim, double radius,
                  std::vector<SafetyCandidate>* candidates) {
  const Eigen::Vector2d d = aim - cue;
  for (double thickness : kThicknesses) {
    const double heading = std::atan2(d.y(), d.x()) + std::asin(thickness * 2 * radius / d.norm());
    for (double speed : kSpeeds) {
      physics::CueStroke s;
      s.speed = speed;
      s.heading = heading;
      candidates->push_back({target, s});
    }
  }
}

}  // namespace

std::vector<SafetyCandidate> SafetyStrokes(const table::TableGeometry& table,
                                           const physics::ModelParameters& params,
                                           const std::vector<table::SceneBall>& balls,
                                           rules::Rules rules) {
  const double radius = params.ball.radius;
  const table::SceneBall* cue = FindBall(balls, 0);
  if (!cue) return {};
  std::vector<int> targets = rules::LegalTargets(rules, balls);
  auto distance = [&](int id) { return (Position(*FindBall(balls, id)) - Position(*cue)).norm(); };
  std::stable_sort(targets.begin(), targets.end(),
                   [&](int a, int b) { return distance(a) < distance(b); });
  if (static_cast<int>(targets.size()) > kSafetyTargets) targets.resize(kSafetyTargets);
  std::vector<SafetyCandidate> candidates;
  const Eigen::Vector2d from = Position(*cue);
  for (int target : targets) {
    const Eigen::Vector2d at = Position(*FindBall(balls, target));
    if ((at - from).norm() <= 2 * radius) continue;
    AddStrokesAt(target, from, at, radius, &candidates);
    if (!Hidden(balls, target, from, at, radius)) continue;
    const std::vector<SafetyCandidate> kicks = Kicks(table, params, balls, target);
    candidates.insert(candidates.end(), kicks.begin(), kicks.end());
  }
  return candidates;
}

std::vector<SafetyCandidate> MakeableByCue(const table::TableGeometry& table,
                                           const physics::ModelParameters& params,
                                           const std::vector<table::SceneBall>& balls,
                                           const std::optional<cue::Robot>& robot,
                                           std::vector<SafetyCandidate> candidates) {
  if (!robot) return candidates;
  const Eigen::Vector2d cue_ball = Position(*FindBall(balls, 0));
  std::vector<SafetyCandidate> makeable;
  for (SafetyCandidate& c : candidates) {
    const std::variant<double, std::string> elevation =
        cue::ElevationFor(table, params.ball.radius, balls, 0, c.stroke, *robot);
    if (!std::holds_alternative<double>(elevation)) continue;
    c.stroke.elevation = std::get<double>(elevation);
    // Slowed to the fastest pace whose hop the table's motion covers: the screening plays it so.
    c.stroke.speed = std::min(
        c.stroke.speed, cue::HopFreeSpeed(c.stroke, cue_ball, params, cue::TableMaxHop(params)));
    makeable.push_back(c);
  }
  return makeable;
}

rules::Rules OpponentRules(rules::Rules rules) {
  if (rules == rules::Rules::kEightBallSolids) return rules::Rules::kEightBallStripes;
  if (rules == rules::Rules::kEightBallStripes) return rules::Rules::kEightBallSolids;
  return rules;
}

bool Fouls(const std::vector<table::SceneBall>& before, const StrokeResult& result,
           rules::Rules rules) {
  if (!result.struck || result.scratch) return true;
  const std::vector<int> legal = rules::LegalTargets(rules, before);
  if (std::find(legal.begin(), legal.end(), result.first_contact) == legal.end()) return true;
  return result.pocketed.empty() && result.to_rail_after_contact.empty();
}

double WinChance(const table::TableGeometry& table, double radius,
                 const std::vector<table::SceneBall>& before, const StrokeResult& result,
                 const std::optional<Call>& call, const ChoiceOptions& options) {
  const bool eight_ball = rules::IsEightBall(options.rules);
  const bool called_pot = call && LegalPot(result, call->ball, call->pocket);
  if (eight_ball && Potted(result, kEight) && !(called_pot && call->ball == kEight)) return 0.0;
  const rules::Rules opponent = OpponentRules(options.rules);
  const Race theirs = RaceOf(result.rest, opponent, options.rules);
  const RunOutRates rates = MeasuredRunOutRates(options.rules);
  if (Fouls(before, result, options.rules)) {
    const double hand = HandChance(table, radius, result.rest, opponent, options.noise);
    return 1.0 - RackWinChance(hand, theirs, rates);
  }
  const bool kept = called_pot || (!eight_ball && !result.pocketed.empty());
  if (kept) {
    return RackWinChance(
        BestNextShotValue(table, radius, result.rest, options.rules, options.noise),
        RaceOf(result.rest, options.rules, opponent), rates);
  }
  const double next = BestNextShotValue(table, radius, result.rest, opponent, options.noise);
  return 1.0 - RackWinChance(next, theirs, rates);
}

std::optional<SafetyStroke> BestSafety(const table::TableGeometry& table,
                                       const physics::ModelParameters& params,
                                       const std::vector<table::SceneBall>& balls,
                                       const ChoiceOptions& options, batch::ThreadPool& pool,
                                       int* simulations) {
  const std::vector<SafetyCandidate> candidates = MakeableByCue(
      table, params, balls, options.pot.robot, SafetyStrokes(table, params, balls, options.rules));
  if (candidates.empty()) return std::nullopt;
  std::vector<std::size_t> order = ScreenSafeties(table, params, balls, candidates, options, pool);
  if (static_cast<int>(order.size()) > options.safety_finalists) {
    order.resize(options.safety_finalists);
  }
  std::vector<physics::CueStroke> strokes;
  for (std::size_t i : order) strokes.push_back(candidates[i].stroke);
  const std::vector<Judged> judged =
      JudgeAll(table, params, balls, strokes, std::vector<std::optional<Call>>(strokes.size()),
               options.safety_samples, options, model_choice::TableMotion(params), pool);
  if (simulations) {
    *simulations += static_cast<int>(candidates.size()) * options.safety_screen_samples +
                    static_cast<int>(judged.size());
  }
  std::optional<SafetyStroke> best;
  for (std::size_t k = 0; k < order.size(); ++k) {
    SafetyStroke s = Summary(candidates[order[k]], judged, k, options.safety_samples);
    if (!best || s.win > best->win) best = s;
  }
  return best;
}

void ConsiderSafety(const table::TableGeometry& table, const physics::ModelParameters& params,
                    const std::vector<table::SceneBall>& balls, const ChoiceOptions& options,
                    batch::ThreadPool& pool, ChoiceResult* result) {
  if (result->status != ChoiceStatus::kOk && result->status != ChoiceStatus::kNoPlan) return;
  const Candidate* chosen = result->chosen();
  if (chosen && chosen->reported().probability >= options.safety_below) return;
  const std::optional<SafetyStroke> best =
      BestSafety(table, params, balls, options, pool, &result->simulations);
  if (!best) return;
  result->attempt_win = AttemptWin(table, params, balls, *result, options, pool);
  result->simulations += options.safety_samples;
  result->safety_win = best->win;
  if (best->win <= result->attempt_win) return;
  result->reason = Why(*best, result->attempt_win, *result);
  result->safety = best;
}

}  // namespace billiard::choice
