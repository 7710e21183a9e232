// Shot choice: which pot to play when the robot's arm is not exact.
//
// A pot the planner (planner/pot/) finds is exact for the stroke it returns; the robot plays
// that stroke with an error (sim/params/execution_noise.h). The choice therefore asks of each
// pot how likely it is to drop as played, and how good the table it leaves is:
//  1. candidates: every legal object ball (all of them, or under nine-ball rules the
//     lowest-numbered) x every pocket x every kind (direct, bank, kick, curve) that plans;
//  2. screening: each candidate's probability from a few noisy executions with the closed-form
//     motion (Jaroukh 2019, exact for the level-cue paths most pots are, and cheap), and the
//     best few planned again with position play (the cue ball sent to where the next shot looks
//     easiest) and screened too;
//  3. the finalists (the few best screened) with many noisy executions on the full model the
//     table runs (model_choice::TableMotion): the probability of a legal pot (the object ball
//     in the called pocket, the cue ball's first contact that ball, no scratch) and its
//     standard error, and, over the executions that pot, the value of the best next shot on the
//     table each leaves (EasyPotEstimate, a closed-form estimate: no planning inside a sample);
//  4. the score: the expected number of balls over this shot and the next, p (1 + v), or p alone
//     without the lookahead. The best scored is the choice;
//  5. the chosen shot's probability estimated again from fresh executions (a seed stream of its
//     own, ChoiceOptions::confirm_samples of them): the finalists' estimates chose it, so the
//     best of them is biased up (the maximum of noisy estimates: a winner's curse), and the
//     reported probability must not come from the samples that selected. When that probability
//     is below ChoiceOptions::likely the choice says that no shot is likely and still plays it.
// This is the scheme of the computational-pool programs that won their tournaments (Smith
// 2007's PickPocket: Monte Carlo over the noise with a lookahead; Archibald, Altman and Shoham
// 2009's CueCard), here over the robot's own noise and a table model that includes throw,
// squirt and the cushions' impacts.
//
// Deterministic: execution s of every candidate draws its noise from a generator seeded by
// (seed, s) alone (common random numbers: candidates are compared on the same errors), each
// execution's result is stored at its index and the sums run in index order, so a seed gives the
// same choice on 1 thread or 64.
//
// Module: billiard::choice. Includes the pot planner, the table, the parameter sets (the noise),
// the table's motion rule and the thread pool.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "planner/pot/pot_planner.h"
#include "sim/batch/thread_pool.h"
#include "sim/params/execution_noise.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"
#include "sim/table/table_simulation.h"

namespace billiard::choice {

// kAny: any object ball may be hit first and potted. kNineBall (WPA Rules of Play): the cue
// ball's first contact must be the lowest-numbered ball on the table; a scratch, a wrong first
// contact or no contact is a foul and gives the next player (here: the next visit) ball in hand;
// the rack is won by potting the 9 legally. (The rule that a ball must reach a rail after the
// contact is not judged.)
enum class Rules { kAny, kNineBall };
const char* RulesName(Rules rules);  // "any", "nine-ball"
// std::nullopt for an unknown name.
std::optional<Rules> ParseRules(const std::string& name);

// The object balls that may be hit first (and potted by a called shot) under `rules`: ids > 0
// on the table, ascending; under nine-ball the lowest alone.
std::vector<int> LegalTargets(Rules rules, const std::vector<table::SceneBall>& balls);

// `balls` with the cue ball (id 0) lifted, if there, and placed at `place`, first.
std::vector<table::SceneBall> WithCueBallAt(std::vector<table::SceneBall> balls,
                                            const Eigen::Vector2d& place);

// ---------------------------------------------------------------------------------------------
// Noisy execution.

// A generator's seed for execution `index` of a run seeded `seed` (SplitMix64 of both): the
// executions are independent of one another and of the order they run in.
std::uint64_t SampleSeed(std::uint64_t seed, std::uint64_t index);

// Standard normal numbers from std::mt19937_64 by the Box-Muller transform, by hand so that a
// seed gives the same numbers on every standard library.
class NormalStream {
 public:
  explicit NormalStream(std::uint64_t seed) : engine_(seed) {}
  double Next();

 private:
  std::mt19937_64 engine_;
  std::optional<double> spare_;  // Box-Muller makes two at a time
};

// What a stroke did, played to rest.
struct StrokeResult {
  bool struck = false;     // false: no cue gives the stroke (the cue model refused it)
  int first_contact = -1;  // the first ball the cue ball touched, -1 none
  std::vector<std::pair<int, std::string>> pocketed;  // object balls and their pockets
  bool scratch = false;                               // the cue ball dropped
  std::vector<table::SceneBall> rest;                 // the balls left on the table, at rest
};

// Strikes the cue ball (id 0, at rest) of `balls` with `stroke` and simulates the table until
// every ball rests (closed form between events when `motion` is empty, else `motion`'s 5-DOF
// where it says).
StrokeResult PlayToRest(const table::TableGeometry& table, const physics::ModelParameters& params,
                        const std::vector<table::SceneBall>& balls,
                        const physics::CueStroke& stroke,
                        const decltype(table::TableSimulationOptions::five_dof)& motion);

// Whether `result` pots `ball` in `pocket` legally: the cue ball's first contact that ball, the
// ball in that pocket, no scratch.
bool LegalPot(const StrokeResult& result, int ball, const std::string& pocket);

// The probability of a legal pot and its standard error over noisy executions.
struct PotProbability {
  int samples = 0;
  int successes = 0;
  double probability = 0.0;  // successes / samples
  double stderr_ = 0.0;      // sqrt(p (1 - p) / samples), the binomial standard error
};

// `plan`'s stroke executed `samples` times with `noise` (execution s seeded SampleSeed(seed, s))
// on the full model the table runs, on `pool`'s threads.
PotProbability EstimatePotProbability(const table::TableGeometry& table,
                                      const physics::ModelParameters& params,
                                      const std::vector<table::SceneBall>& balls,
                                      const pot::PotPlan& plan,
                                      const params::ExecutionNoise& noise, int samples,
                                      std::uint64_t seed, batch::ThreadPool& pool);

// ---------------------------------------------------------------------------------------------
// A closed-form estimate, for the lookahead, the ball-in-hand screening and the baseline.

// The probability that a straight ghost-ball pot of `ball` in `pocket` from the cue ball drops
// under `noise`'s heading error: 0 when a ball lies across either line or the cut is past
// max_cut_deg; else erf(d / (sqrt 2 sigma)), d the heading tolerance. The object ball may leave
// its line by the pocket's half-width less a radius (foreshortened by the angle it enters at)
// over its distance to the pocket, and a heading error e of the cue ball, a distance D from
// the ghost ball, turns the object ball by e D / (2 r cos cut) (the line of centres moves
// sideways by e D on a ball of reach 2 r cos cut). It ignores throw, squirt and speed: a ranking,
// not the truth.
double EasyPotEstimate(double radius, const std::vector<table::SceneBall>& balls, int ball,
                       const table::Pocket& pocket, const params::ExecutionNoise& noise,
                       double max_cut_deg = 80.0);

// The best EasyPotEstimate over the legal targets and pockets of `balls` (1 when the rack is
// over: no object ball left, or under nine-ball the 9 gone).
double BestNextShotValue(const table::TableGeometry& table, double radius,
                         const std::vector<table::SceneBall>& balls, Rules rules,
                         const params::ExecutionNoise& noise);

// ---------------------------------------------------------------------------------------------
// The choice.

struct ChoiceOptions {
  Rules rules = Rules::kAny;
  params::ExecutionNoise noise = params::LoadNoise(params::kDefaultNoise);
  int samples = 64;         // full-model executions of each finalist
  int screen_samples = 16;  // closed-form executions of each candidate
  int finalists = 4;        // candidates that reach the full model
  // Fresh full-model executions of the chosen shot alone, on their own seed stream: the
  // probability reported (a binomial standard error of at most 0.5 / sqrt(n), 0.03 at 256).
  // 0: report the finalists' own (biased) estimate.
  int confirm_samples = 256;
  std::uint64_t seed = 1;
  bool lookahead = true;  // score p (1 + v); false: p alone
  // Below this probability the choice says that no shot is likely.
  double likely = 0.5;
  // With the lookahead, the best screened candidates planned again with position play: the cue
  // ball sent within position_radius of the place the next shot looks easiest from.
  int position_plans = 3;
  double position_radius = 0.15;  // [m]
  std::vector<pot::ShotKind> kinds = {pot::ShotKind::kDirect, pot::ShotKind::kBank,
                                      pot::ShotKind::kKick, pot::ShotKind::kCurve};
  pot::PotOptions pot;
};

struct Candidate {
  pot::PotPlan plan;
  std::optional<Eigen::Vector2d> position_target;  // position play: where the cue ball is sent
  double screen_probability = 0.0;
  bool finalist = false;
  PotProbability full;           // finalists only: the estimate that chose among them
  // The chosen alone (ChoiceOptions::confirm_samples > 0): the estimate from fresh executions,
  // independent of the choice, and the one reported.
  PotProbability confirmed;
  double next_shot_value = 0.0;  // mean over the potting executions; finalists only
  double score = 0.0;  // p (1 + v), or p without the lookahead: the full model's for finalists

  // The probability to report: the confirmed one when there is one, else the finalists'.
  const PotProbability& reported() const { return confirmed.samples > 0 ? confirmed : full; }
};

enum class ChoiceStatus {
  kOk,
  kInvalid,   // no cue ball, a scene the simulation refuses
  kNoTarget,  // no object ball to play
  kNoPlan,    // no candidate plans: nothing to play (ChoiceResult::fallback is a stroke)
};
const char* ChoiceStatusName(ChoiceStatus status);  // "ok", "invalid", "no_target", "no_plan"

struct ChoiceResult {
  ChoiceStatus status = ChoiceStatus::kInvalid;
  std::string reason;            // why not, when not ok; when ok and !likely, that no shot is
  std::vector<Candidate> candidates;  // every one that planned, the best scored first
  bool likely = false;           // the choice's reported probability >= ChoiceOptions::likely
  std::optional<Eigen::Vector2d> cue_placement;  // ball in hand: where the cue ball goes
  // With kNoPlan: a stroke that at least hits the first legal target full in the face
  // (ghost-ball aim at the ball's centre, 2 m/s), so that a loop has something to play.
  std::optional<physics::CueStroke> fallback;
  double decision_us = 0.0;
  int simulations = 0;  // table simulations, plans and executions

  const Candidate* chosen() const { return candidates.empty() ? nullptr : &candidates.front(); }
};

// The choice on `balls` (id 0 the cue ball, every ball at rest).
ChoiceResult ChooseShot(const table::TableGeometry& table, const physics::ModelParameters& params,
                        const std::vector<table::SceneBall>& balls, const ChoiceOptions& options,
                        batch::ThreadPool& pool);

// Ball in hand: the cue ball (if any in `balls`) lifted and placed where the choice scores best.
// Places are tried behind each legal target on the lines from each pocket (straight and cut 15
// and 30 degrees, 0.15 to 0.5 m back), screened by EasyPotEstimate, and the best of each
// target and pocket, up to `placements` of them, chosen among by ChooseShot's steps 1-4; only
// the placement chosen is confirmed (step 5), so its reported probability is no best of several.
ChoiceResult ChooseWithBallInHand(const table::TableGeometry& table,
                                  const physics::ModelParameters& params,
                                  const std::vector<table::SceneBall>& balls,
                                  const ChoiceOptions& options, batch::ThreadPool& pool,
                                  int placements = 3);

// The baseline that looks easiest: the legal target and pocket of the best EasyPotEstimate
// (the shortest, least cut clear line) planned as a direct pot and aimed through the ghost ball
// (pot::GhostBallHeading: throw not corrected), its probability not estimated. With ball in
// hand, the cue ball at the easiest-looking place.
ChoiceResult ChooseEasiestLooking(const table::TableGeometry& table,
                                  const physics::ModelParameters& params,
                                  const std::vector<table::SceneBall>& balls,
                                  const ChoiceOptions& options, bool ball_in_hand);

}  // namespace billiard::choice
