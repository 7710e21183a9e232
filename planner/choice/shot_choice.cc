#include "planner/choice/shot_choice.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "planner/pot/pot_geometry.h"
#include "sim/model_choice/model_choice.h"
#include "sim/table/rack.h"

namespace billiard::choice {

namespace {

using Motion = decltype(table::TableSimulationOptions::five_dof);

// The longest a stroke is simulated [s]: every pot rests well within it.
constexpr double kLongestStroke = 60.0;
// The fallback stroke's cue speed [m/s]: enough to reach a ball across the table and a rail.
constexpr double kFallbackSpeed = 2.0;
// A placed cue ball stays this far clear of the other balls [m].
constexpr double kPlacementClearance = 2e-3;
// The least heading tolerance used against a zero heading spread [rad].
constexpr double kTinySpread = 1e-9;
// The least share of a pocket's width a ball entering at a slant still sees.
constexpr double kLeastForeshortening = 0.2;
constexpr double kDegree = M_PI / 180.0;

double MicrosecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
      .count();
}

const table::SceneBall* FindBall(const std::vector<table::SceneBall>& balls, int id) {
  for (const table::SceneBall& b : balls) {
    if (b.id == id) return &b;
  }
  return nullptr;
}

Eigen::Vector2d Position(const table::SceneBall& b) { return b.state.segment<2>(physics::kX); }

// The binomial estimate of `successes` in `samples`.
PotProbability Binomial(int successes, int samples) {
  PotProbability p;
  p.samples = samples;
  p.successes = successes;
  if (samples > 0) {
    p.probability = static_cast<double>(successes) / samples;
    p.stderr_ = std::sqrt(p.probability * (1 - p.probability) / samples);
  }
  return p;
}

// One noisy execution of a stroke: whether it potted legally and, if it did, the value of the
// best next shot on the table it left.
struct Execution {
  bool potted = false;
  double next_value = 0.0;
};

Execution Execute(const table::TableGeometry& table, const physics::ModelParameters& params,
                  const std::vector<table::SceneBall>& balls, const pot::PotPlan& plan,
                  const ChoiceOptions& options, const Motion& motion, std::uint64_t sample,
                  bool value_next) {
  NormalStream normal(SampleSeed(options.seed, sample));
  const physics::CueStroke stroke = params::Perturbed(plan.stroke, options.noise,
                                                      params.ball.radius, [&] { return normal.Next(); });
  const StrokeResult result = PlayToRest(table, params, balls, stroke, motion);
  Execution e;
  e.potted = LegalPot(result, plan.ball, plan.pocket);
  if (e.potted && value_next) {
    e.next_value = BestNextShotValue(table, params.ball.radius, result.rest, options.rules,
                                     options.noise);
  }
  return e;
}

// Executions [0, samples) of each candidate in `which`, flattened into one batch, results in
// index order.
std::vector<Execution> ExecuteAll(const table::TableGeometry& table,
                                  const physics::ModelParameters& params,
                                  const std::vector<table::SceneBall>& balls,
                                  const std::vector<Candidate>& candidates,
                                  const std::vector<std::size_t>& which, int samples,
                                  const ChoiceOptions& options, const Motion& motion,
                                  bool value_next, batch::ThreadPool& pool) {
  const std::size_t n = which.size() * static_cast<std::size_t>(samples);
  auto results = pool.Map(n, [&](std::size_t job) {
    const Candidate& c = candidates[which[job / samples]];
    return Execute(table, params, balls, c.plan, options, motion, job % samples, value_next);
  });
  std::vector<Execution> executions(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (results[i].ok()) executions[i] = *results[i].value;  // a throw counts as a miss
  }
  return executions;
}

// The plans of every legal target, pocket and kind, in that order.
std::vector<pot::PotPlan> PlanCandidates(const table::TableGeometry& table,
                                         const physics::ModelParameters& params,
                                         const std::vector<table::SceneBall>& balls,
                                         const ChoiceOptions& options, batch::ThreadPool& pool) {
  std::vector<pot::PotRequest> requests;
  for (int ball : LegalTargets(options.rules, balls)) {
    for (const table::Pocket& pocket : table.pockets) {
      for (pot::ShotKind kind : options.kinds) {
        pot::PotRequest r;
        r.ball = ball;
        r.pocket = pocket.name;
        r.kind = kind;
        requests.push_back(r);
      }
    }
  }
  auto plans = pool.Map(requests.size(), [&](std::size_t i) {
    return pot::PlanPot(table, params, balls, requests[i], options.pot);
  });
  std::vector<pot::PotPlan> ok;
  for (auto& p : plans) {
    if (p.ok() && p.value->status == pot::PotStatus::kOk) ok.push_back(std::move(*p.value));
  }
  return ok;
}

// A stroke that hits `ball` full in the face from the cue ball.
physics::CueStroke FallbackStroke(const table::SceneBall& cue, const table::SceneBall& ball) {
  const Eigen::Vector2d d = Position(ball) - Position(cue);
  physics::CueStroke s;
  s.speed = kFallbackSpeed;
  s.heading = std::atan2(d.y(), d.x());
  return s;
}

ChoiceResult Refusal(ChoiceStatus status, std::string reason) {
  ChoiceResult r;
  r.status = status;
  r.reason = std::move(reason);
  return r;
}

// The checks every choice starts with; std::nullopt when the scene can be played.
std::optional<ChoiceResult> Unplayable(const table::TableGeometry& table,
                                       const physics::ModelParameters& params,
                                       const std::vector<table::SceneBall>& balls, Rules rules) {
  if (!FindBall(balls, 0)) return Refusal(ChoiceStatus::kInvalid, "no cue ball (id 0)");
  try {
    table::ValidateScene(table, params.ball.radius, balls);
  } catch (const std::invalid_argument& e) {
    return Refusal(ChoiceStatus::kInvalid, e.what());
  }
  for (const table::SceneBall& b : balls) {
    if (b.state.segment<5>(physics::kVx).norm() > 0) {
      return Refusal(ChoiceStatus::kInvalid,
                     "ball " + std::to_string(b.id) + " is moving: a choice starts at rest");
    }
  }
  if (LegalTargets(rules, balls).empty()) {
    return Refusal(ChoiceStatus::kNoTarget, "no object ball on the table");
  }
  return std::nullopt;
}

// A ball-in-hand place: where, for which pot, and how easy it looks.
struct Placement {
  Eigen::Vector2d place;
  double estimate = 0.0;
};

// The best-looking place behind each legal target for each pocket, best first.
std::vector<Placement> CandidatePlacements(const table::TableGeometry& table, double radius,
                                           const std::vector<table::SceneBall>& balls,
                                           const ChoiceOptions& options) {
  constexpr double kBackDistances[] = {0.15, 0.3, 0.5};       // [m] behind the ghost ball
  constexpr double kCutAngles[] = {0.0, 15.0, -15.0, 30.0, -30.0};  // [deg]
  std::vector<table::SceneBall> others;
  for (const table::SceneBall& b : balls) {
    if (b.id != 0) others.push_back(b);
  }
  std::vector<Placement> best;
  for (int ball : LegalTargets(options.rules, others)) {
    const Eigen::Vector2d object = Position(*FindBall(others, ball));
    for (const table::Pocket& pocket : table.pockets) {
      const Eigen::Vector2d to_pocket = (pocket.centre - object).normalized();
      std::optional<Placement> top;
      for (double back : kBackDistances) {
        for (double cut : kCutAngles) {
          const Eigen::Vector2d approach =
              Eigen::Rotation2Dd(cut * kDegree) * to_pocket;
          const Eigen::Vector2d place = object - 2 * radius * to_pocket - back * approach;
          if (!table.OnSurface(place, radius)) continue;
          const bool clear = std::all_of(others.begin(), others.end(), [&](const auto& b) {
            return (Position(b) - place).norm() >= 2 * radius + kPlacementClearance;
          });
          if (!clear) continue;
          const double estimate = EasyPotEstimate(radius, WithCueBallAt(others, place), ball,
                                                  pocket, options.noise);
          if (!top || estimate > top->estimate) top = Placement{place, estimate};
        }
      }
      if (top && top->estimate > 0) best.push_back(*top);
    }
  }
  std::stable_sort(best.begin(), best.end(),
                   [](const Placement& a, const Placement& b) { return a.estimate > b.estimate; });
  return best;
}

// The executions of one candidate (the k-th of a batch of `samples` each): its pot rate and the
// mean next-shot value of the executions that pot.
struct Tally {
  PotProbability pots;
  double next_shot_value = 0.0;
};

Tally TallyOf(const std::vector<Execution>& executions, std::size_t k, int samples) {
  int successes = 0;
  double value_sum = 0.0;
  for (int s = 0; s < samples; ++s) {
    const Execution& e = executions[k * samples + s];
    successes += e.potted;
    value_sum += e.next_value;
  }
  return {Binomial(successes, samples), successes > 0 ? value_sum / successes : 0.0};
}

// p (1 + v) with the lookahead, p alone without it.
double Score(const Tally& tally, bool lookahead) {
  return lookahead ? tally.pots.probability * (1 + tally.next_shot_value) : tally.pots.probability;
}

// Screens candidates `which`: screen_samples closed-form executions each, their legal pot rate
// and, with the lookahead, the mean next-shot value of those that pot; score p (1 + v). Returns
// the simulations run.
int Screen(const table::TableGeometry& table, const physics::ModelParameters& params,
           const std::vector<table::SceneBall>& balls, const std::vector<std::size_t>& which,
           const ChoiceOptions& options, batch::ThreadPool& pool, std::vector<Candidate>* candidates) {
  const std::vector<Execution> screened = ExecuteAll(table, params, balls, *candidates, which,
                                                     options.screen_samples, options, {},
                                                     options.lookahead, pool);
  for (std::size_t k = 0; k < which.size(); ++k) {
    Candidate& c = (*candidates)[which[k]];
    const Tally tally = TallyOf(screened, k, options.screen_samples);
    c.screen_probability = tally.pots.probability;
    c.score = Score(tally, options.lookahead);
  }
  return static_cast<int>(screened.size());
}

// The screening's order: the score, ties (often several pots screened at 1) to the wider
// heading window.
bool ScreenedBetter(const Candidate& a, const Candidate& b) {
  if (a.score != b.score) return a.score > b.score;
  return std::min(a.plan.margin_left_deg, a.plan.margin_right_deg) >
         std::min(b.plan.margin_left_deg, b.plan.margin_right_deg);
}

// The best `position_plans` screened candidates planned again with a cue-ball target: the place
// the next shot looks easiest from (CandidatePlacements on the table without the object ball).
std::vector<Candidate> PositionCandidates(const table::TableGeometry& table,
                                          const physics::ModelParameters& params,
                                          const std::vector<table::SceneBall>& balls,
                                          std::vector<Candidate> screened,
                                          const ChoiceOptions& options, batch::ThreadPool& pool) {
  std::stable_sort(screened.begin(), screened.end(), ScreenedBetter);
  std::vector<pot::PotRequest> requests;
  for (const Candidate& c : screened) {
    if (static_cast<int>(requests.size()) >= options.position_plans) break;
    if (c.screen_probability <= 0) break;
    std::vector<table::SceneBall> after;
    for (const table::SceneBall& b : balls) {
      if (b.id != c.plan.ball) after.push_back(b);
    }
    const std::vector<Placement> places =
        CandidatePlacements(table, params.ball.radius, after, options);
    if (places.empty()) continue;
    pot::PotRequest r;
    r.ball = c.plan.ball;
    r.pocket = c.plan.pocket;
    r.kind = c.plan.kind;
    r.cue_target = pot::CueTarget{places.front().place, options.position_radius};
    requests.push_back(r);
  }
  auto plans = pool.Map(requests.size(), [&](std::size_t i) {
    return pot::PlanPot(table, params, balls, requests[i], options.pot);
  });
  std::vector<Candidate> played;
  for (std::size_t i = 0; i < plans.size(); ++i) {
    if (!plans[i].ok() || plans[i].value->status != pot::PotStatus::kOk) continue;
    Candidate c;
    c.plan = std::move(*plans[i].value);
    c.position_target = requests[i].cue_target->point;
    played.push_back(std::move(c));
  }
  return played;
}

}  // namespace

const char* RulesName(Rules rules) { return rules == Rules::kNineBall ? "nine-ball" : "any"; }

std::optional<Rules> ParseRules(const std::string& name) {
  if (name == "any") return Rules::kAny;
  if (name == "nine-ball") return Rules::kNineBall;
  return std::nullopt;
}

std::vector<int> LegalTargets(Rules rules, const std::vector<table::SceneBall>& balls) {
  std::vector<int> ids;
  for (const table::SceneBall& b : balls) {
    if (b.id > 0) ids.push_back(b.id);
  }
  std::sort(ids.begin(), ids.end());
  if (rules == Rules::kNineBall && ids.size() > 1) ids.resize(1);
  return ids;
}

std::vector<table::SceneBall> WithCueBallAt(std::vector<table::SceneBall> balls,
                                            const Eigen::Vector2d& place) {
  return table::WithBallAt(std::move(balls), 0, place);
}

std::uint64_t SampleSeed(std::uint64_t seed, std::uint64_t index) {
  // SplitMix64 (Steele, Lea and Flood 2014) over the seed, then over the index.
  auto mix = [](std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  };
  return mix(mix(seed) ^ index);
}

double NormalStream::Next() {
  if (spare_) {
    const double z = *spare_;
    spare_.reset();
    return z;
  }
  auto uniform = [&] { return (static_cast<double>(engine_() >> 11) + 0.5) * 0x1.0p-53; };
  const double r = std::sqrt(-2.0 * std::log(uniform()));
  const double angle = 2.0 * M_PI * uniform();
  spare_ = r * std::sin(angle);
  return r * std::cos(angle);
}

StrokeResult PlayToRest(const table::TableGeometry& table, const physics::ModelParameters& params,
                        const std::vector<table::SceneBall>& balls,
                        const physics::CueStroke& stroke, const Motion& motion) {
  StrokeResult result;
  std::vector<table::SceneBall> start = balls;
  for (table::SceneBall& b : start) {
    if (b.id != 0) continue;
    try {
      b.state = physics::StrikeBall(stroke, Position(b), params);
    } catch (const std::invalid_argument&) {
      result.rest = balls;
      return result;
    }
  }
  result.struck = true;
  table::TableSimulationOptions sim_options;
  sim_options.five_dof = motion;
  table::TableSimulation sim(table, params, start, sim_options);
  sim.Run(kLongestStroke);
  result.first_contact = table::FirstBallMet(sim.events(), 0);
  for (std::size_t i = 0; i < sim.ball_count(); ++i) {
    if (sim.pocket(i)) {
      if (sim.id(i) == 0) {
        result.scratch = true;
      } else {
        result.pocketed.emplace_back(sim.id(i), *sim.pocket(i));
      }
      continue;
    }
    table::SceneBall b;
    b.id = sim.id(i);
    b.state.segment<2>(physics::kX) = sim.State(i).segment<2>(physics::kX);
    result.rest.push_back(b);
  }
  return result;
}

bool LegalPot(const StrokeResult& result, int ball, const std::string& pocket) {
  if (!result.struck || result.scratch || result.first_contact != ball) return false;
  return std::any_of(result.pocketed.begin(), result.pocketed.end(),
                     [&](const auto& p) { return p.first == ball && p.second == pocket; });
}

PotProbability EstimatePotProbability(const table::TableGeometry& table,
                                      const physics::ModelParameters& params,
                                      const std::vector<table::SceneBall>& balls,
                                      const pot::PotPlan& plan,
                                      const params::ExecutionNoise& noise, int samples,
                                      std::uint64_t seed, batch::ThreadPool& pool) {
  ChoiceOptions options;
  options.noise = noise;
  options.seed = seed;
  Candidate c;
  c.plan = plan;
  const std::vector<Execution> executions =
      ExecuteAll(table, params, balls, {c}, {0}, samples, options,
                 model_choice::TableMotion(params), false, pool);
  int successes = 0;
  for (const Execution& e : executions) successes += e.potted;
  return Binomial(successes, samples);
}

double EasyPotEstimate(double radius, const std::vector<table::SceneBall>& balls, int ball,
                       const table::Pocket& pocket, const params::ExecutionNoise& noise,
                       double max_cut_deg) {
  const table::SceneBall* cue = FindBall(balls, 0);
  const table::SceneBall* object = FindBall(balls, ball);
  if (!cue || !object) return 0.0;
  const Eigen::Vector2d c = Position(*cue), o = Position(*object);
  const Eigen::Vector2d to_pocket = pocket.centre - o;
  const double pocket_distance = to_pocket.norm();
  if (pocket_distance <= 0) return 1.0;
  const Eigen::Vector2d departure = to_pocket / pocket_distance;
  const Eigen::Vector2d ghost = pot::GhostBall(o, departure, radius);
  const double cue_distance = (ghost - c).norm();
  if (cue_distance <= 0) return 0.0;
  const Eigen::Vector2d approach = (ghost - c) / cue_distance;
  const double cut = pot::CutAngle(approach, departure);
  if (cut > max_cut_deg * kDegree) return 0.0;
  const double clearance = 2 * radius;
  if (!pot::BallsAcross(balls, c, ghost, clearance, {0, ball}).empty()) return 0.0;
  if (!pot::BallsAcross(balls, o, pocket.centre, clearance, {0, ball}).empty()) return 0.0;
  const double half_width = 0.5 * (pocket.capture_b - pocket.capture_a).norm() - radius;
  const double foreshortening =
      std::max(kLeastForeshortening, std::abs(departure.dot(pocket.inward)));
  const double object_tolerance = std::max(0.0, half_width * foreshortening) / pocket_distance;
  const double heading_tolerance =
      object_tolerance * 2 * radius * std::cos(cut) / cue_distance;
  const double spread = std::max(noise.heading, kTinySpread);
  return std::erf(heading_tolerance / (std::sqrt(2.0) * spread));
}

double BestNextShotValue(const table::TableGeometry& table, double radius,
                         const std::vector<table::SceneBall>& balls, Rules rules,
                         const params::ExecutionNoise& noise) {
  const std::vector<int> targets = LegalTargets(rules, balls);
  if (targets.empty()) return 1.0;
  if (rules == Rules::kNineBall && !FindBall(balls, 9)) return 1.0;
  if (!FindBall(balls, 0)) return 0.0;
  double best = 0.0;
  for (int ball : targets) {
    for (const table::Pocket& pocket : table.pockets) {
      best = std::max(best, EasyPotEstimate(radius, balls, ball, pocket, noise));
    }
  }
  return best;
}

const char* ChoiceStatusName(ChoiceStatus status) {
  switch (status) {
    case ChoiceStatus::kOk: return "ok";
    case ChoiceStatus::kInvalid: return "invalid";
    case ChoiceStatus::kNoTarget: return "no_target";
    case ChoiceStatus::kNoPlan: return "no_plan";
  }
  return "invalid";
}

namespace {

// The confirmation's seed stream, apart from the choice's own samples.
constexpr std::uint64_t kConfirmStream = 0x636f6e6669726d21ull;

// Steps 1-4 of the choice (shot_choice.h): the chosen's probability is still the finalists'.
ChoiceResult ChooseUnconfirmed(const table::TableGeometry& table,
                               const physics::ModelParameters& params,
                               const std::vector<table::SceneBall>& balls,
                               const ChoiceOptions& options, batch::ThreadPool& pool) {
  if (auto refusal = Unplayable(table, params, balls, options.rules)) return *refusal;
  ChoiceResult result;
  for (pot::PotPlan& plan : PlanCandidates(table, params, balls, options, pool)) {
    result.simulations += plan.simulations;
    Candidate c;
    c.plan = std::move(plan);
    result.candidates.push_back(std::move(c));
  }
  if (result.candidates.empty()) {
    result.status = ChoiceStatus::kNoPlan;
    result.reason = "no pot of a legal ball plans (every route blocked, too thin or out of reach)";
    const int target = LegalTargets(options.rules, balls).front();
    result.fallback = FallbackStroke(*FindBall(balls, 0), *FindBall(balls, target));
    return result;
  }
  std::vector<Candidate>& candidates = result.candidates;

  // Screening: every candidate on the closed form.
  std::vector<std::size_t> plain(candidates.size());
  for (std::size_t i = 0; i < plain.size(); ++i) plain[i] = i;
  result.simulations += Screen(table, params, balls, plain, options, pool, &candidates);
  // Position play for the best few: the same pot leaving the cue ball where the next shot looks
  // easiest.
  if (options.lookahead && options.position_plans > 0) {
    std::vector<Candidate> played =
        PositionCandidates(table, params, balls, candidates, options, pool);
    std::vector<std::size_t> added;
    for (Candidate& c : played) {
      result.simulations += c.plan.simulations;
      added.push_back(candidates.size());
      candidates.push_back(std::move(c));
    }
    result.simulations += Screen(table, params, balls, added, options, pool, &candidates);
  }
  std::stable_sort(candidates.begin(), candidates.end(), ScreenedBetter);

  // The finalists on the full model, with the lookahead.
  std::vector<std::size_t> finalists;
  for (std::size_t i = 0; i < candidates.size() && static_cast<int>(i) < options.finalists; ++i) {
    finalists.push_back(i);
  }
  const std::vector<Execution> full =
      ExecuteAll(table, params, balls, candidates, finalists, options.samples, options,
                 model_choice::TableMotion(params), options.lookahead, pool);
  result.simulations += static_cast<int>(full.size());
  for (std::size_t f = 0; f < finalists.size(); ++f) {
    Candidate& c = candidates[finalists[f]];
    c.finalist = true;
    const Tally tally = TallyOf(full, f, options.samples);
    c.full = tally.pots;
    c.next_shot_value = tally.next_shot_value;
    c.score = Score(tally, options.lookahead);
  }
  // Finalists first, by score; the others after them in screening order.
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    if (a.finalist != b.finalist) return a.finalist;
    return a.finalist && a.score > b.score;
  });
  result.status = ChoiceStatus::kOk;
  return result;
}

// Step 5: the chosen shot played confirm_samples more times on `balls` with fresh noise, its
// probability the one reported and judged likely or not.
void Confirm(const table::TableGeometry& table, const physics::ModelParameters& params,
             const std::vector<table::SceneBall>& balls, const ChoiceOptions& options,
             batch::ThreadPool& pool, ChoiceResult* result) {
  if (result->status != ChoiceStatus::kOk) return;
  Candidate& chosen = result->candidates.front();
  if (options.confirm_samples > 0) {
    ChoiceOptions fresh = options;
    fresh.seed = options.seed + kConfirmStream;
    const std::vector<Execution> executions =
        ExecuteAll(table, params, balls, result->candidates, {0}, options.confirm_samples, fresh,
                   model_choice::TableMotion(params), false, pool);
    int successes = 0;
    for (const Execution& e : executions) successes += e.potted;
    chosen.confirmed = Binomial(successes, options.confirm_samples);
    result->simulations += options.confirm_samples;
  }
  result->likely = chosen.reported().probability >= options.likely;
  if (!result->likely) {
    result->reason = "no shot is likely: the best pots with probability " +
                     std::to_string(chosen.reported().probability) +
                     "; playing the best expected one";
  }
}

}  // namespace

ChoiceResult ChooseShot(const table::TableGeometry& table, const physics::ModelParameters& params,
                        const std::vector<table::SceneBall>& balls, const ChoiceOptions& options,
                        batch::ThreadPool& pool) {
  const auto start = std::chrono::steady_clock::now();
  ChoiceResult result = ChooseUnconfirmed(table, params, balls, options, pool);
  Confirm(table, params, balls, options, pool, &result);
  result.decision_us = MicrosecondsSince(start);
  return result;
}

ChoiceResult ChooseWithBallInHand(const table::TableGeometry& table,
                                  const physics::ModelParameters& params,
                                  const std::vector<table::SceneBall>& balls,
                                  const ChoiceOptions& options, batch::ThreadPool& pool,
                                  int placements) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<Placement> places =
      CandidatePlacements(table, params.ball.radius, balls, options);
  if (places.empty()) {
    // Nothing looks pottable from anywhere tried: the cue ball where it is, or at the head
    // spot (x = 1/4 length) when it was lifted.
    const table::SceneBall* cue = FindBall(balls, 0);
    const Eigen::Vector2d place =
        cue ? Position(*cue) : Eigen::Vector2d(table.length / 4, table.width / 2);
    places.push_back({place, 0.0});
  }
  if (static_cast<int>(places.size()) > placements) places.resize(placements);
  std::optional<ChoiceResult> best;
  int simulations = 0;
  for (const Placement& p : places) {
    ChoiceResult r = ChooseUnconfirmed(table, params, WithCueBallAt(balls, p.place), options, pool);
    simulations += r.simulations;
    r.cue_placement = p.place;
    auto score = [](const ChoiceResult& c) {
      return c.chosen() ? c.chosen()->score : -1.0;
    };
    if (!best || score(r) > score(*best)) best = std::move(r);
  }
  best->simulations = simulations;
  // Only the placement played is confirmed: its probability, not the best of three, is reported.
  Confirm(table, params, WithCueBallAt(balls, *best->cue_placement), options, pool, &*best);
  best->decision_us = MicrosecondsSince(start);
  return *best;
}

ChoiceResult ChooseEasiestLooking(const table::TableGeometry& table,
                                  const physics::ModelParameters& params,
                                  const std::vector<table::SceneBall>& balls,
                                  const ChoiceOptions& options, bool ball_in_hand) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<table::SceneBall> scene = balls;
  std::optional<Eigen::Vector2d> placement;
  if (ball_in_hand) {
    const std::vector<Placement> places =
        CandidatePlacements(table, params.ball.radius, balls, options);
    if (!places.empty()) placement = places.front().place;
    else placement = Eigen::Vector2d(table.length / 4, table.width / 2);
    scene = WithCueBallAt(balls, *placement);
  }
  if (auto refusal = Unplayable(table, params, scene, options.rules)) return *refusal;
  struct Look {
    int ball;
    const table::Pocket* pocket;
    double estimate;
  };
  std::vector<Look> looks;
  for (int ball : LegalTargets(options.rules, scene)) {
    for (const table::Pocket& pocket : table.pockets) {
      looks.push_back({ball, &pocket,
                       EasyPotEstimate(params.ball.radius, scene, ball, pocket, options.noise)});
    }
  }
  std::stable_sort(looks.begin(), looks.end(),
                   [](const Look& a, const Look& b) { return a.estimate > b.estimate; });
  ChoiceResult result;
  result.cue_placement = placement;
  for (const Look& look : looks) {
    pot::PotRequest request;
    request.ball = look.ball;
    request.pocket = look.pocket->name;
    request.kind = pot::ShotKind::kDirect;
    pot::PotPlan plan = pot::PlanPot(table, params, scene, request, options.pot);
    result.simulations += plan.simulations;
    if (plan.status != pot::PotStatus::kOk) continue;
    if (const auto heading = pot::GhostBallHeading(table, params, scene, plan, options.pot)) {
      plan.stroke.heading = *heading;
    }
    Candidate c;
    c.plan = std::move(plan);
    c.screen_probability = look.estimate;
    c.score = look.estimate;
    result.candidates.push_back(std::move(c));
    break;
  }
  if (result.candidates.empty()) {
    result.status = ChoiceStatus::kNoPlan;
    result.reason = "no direct pot of a legal ball plans";
    const int target = LegalTargets(options.rules, scene).front();
    result.fallback = FallbackStroke(*FindBall(scene, 0), *FindBall(scene, target));
  } else {
    result.status = ChoiceStatus::kOk;
    result.likely = result.candidates.front().score >= options.likely;
  }
  result.decision_us = MicrosecondsSince(start);
  return result;
}

}  // namespace billiard::choice
