// The Monte Carlo estimate: a stroke played many times with the robot's execution noise
// (sim/params/execution_noise.h) on the table's own motion, and how often it pots legally.
// When the parameter set carries an uncertainty (sim/params/constants_uncertainty.h) and
// ChoiceOptions::sample_constants is on, each execution also plays on the table's constants
// drawn within it: a bank that pots only on the cushion's exact restitution is then as likely
// as the spread of cushions it may meet lets it be (issue 47).
//
// Deterministic: execution s of every stroke draws its noise, and its constants, from
// generators seeded by (seed, s) alone (common random numbers: candidates are compared on the same errors), each
// execution's result is stored at its index and the sums run in index order, so a seed gives the
// same estimate on 1 thread or 64.
//
// Module: billiard::choice.
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "planner/choice/choice_options.h"
#include "planner/pot/pot_planner.h"
#include "sim/batch/thread_pool.h"
#include "sim/params/execution_noise.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"
#include "sim/table/table_simulation.h"

namespace billiard::choice {

// The table's motion between events: empty for the closed form (Jaroukh 2019) throughout, else
// the 5-DOF model where it says (model_choice::TableMotion).
using Motion = decltype(table::TableSimulationOptions::five_dof);

// A generator's seed for execution `index` of a run seeded `seed` (SplitMix64 of both): the
// executions are independent of one another and of the order they run in.
std::uint64_t SampleSeed(std::uint64_t seed, std::uint64_t index);

// The table's constants for execution `index` of a run seeded `seed`: `params` drawn within its
// uncertainty (params::SampledConstants) from a stream of their own, apart from the noise's, or
// `params` itself when `draw` is false or the set has no uncertainty.
physics::ModelParameters DrawnConstants(const physics::ModelParameters& params, bool draw,
                                        std::uint64_t seed, std::uint64_t index);

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
  // The balls that met a rail after the cue ball's first contact (what a referee asks).
  std::vector<int> to_rail_after_contact;
};

// Strikes the cue ball (id 0, at rest) of `balls` with `stroke` and simulates the table until
// every ball rests (closed form between events when `motion` is empty, else `motion`'s 5-DOF
// where it says), the balls resting past a pocket's mouth dropped (DropHangingBalls). The
// simulation's events are copied to `events` when it is given (what a study of a stroke's path
// asks; nothing else keeps them).
//
// The drop is here, not only where a rack is played, so that a choice predicts what the table
// (planner/game/, the table simulator node) does: a soft pot whose ball stops in the jaws counts
// as the pot it is on a real table. Without it the choice's chances ran low against the matches'
// outcomes (400 nine-ball racks: 0.76 predicted, 0.89 potted for shots called 0.7 to 0.8).
StrokeResult PlayToRest(const table::TableGeometry& table, const physics::ModelParameters& params,
                        const std::vector<table::SceneBall>& balls,
                        const physics::CueStroke& stroke, const Motion& motion,
                        std::vector<table::TableEvent>* events = nullptr);

// Every ball of `result.rest` resting with its centre past a pocket's mouth line (the line
// TableGeometry::OnSurface does not let a placed ball cross) moved into that pocket: an object
// ball into `pocketed` (after the simulation's own), the cue ball a scratch.
void DropHangingBalls(const table::TableGeometry& table, StrokeResult* result);

// The first ball the cue ball of `balls` meets when struck by `stroke` on the closed form, -1
// none (or no cue gives the stroke): PlayToRest's first_contact, the table run only until that
// contact or the cue ball's drop (what a search over headings asks of each).
int FirstContact(const table::TableGeometry& table, const physics::ModelParameters& params,
                 const std::vector<table::SceneBall>& balls, const physics::CueStroke& stroke);

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

// The binomial estimate of `successes` in `samples`.
PotProbability Binomial(int successes, int samples);

// One noisy execution of a stroke: whether it potted legally and, if it did and the lookahead
// was asked, the value of the best next shot on the table it left (BestNextShotValue) and that
// table (second_level.h plans the next shot on it).
struct Execution {
  bool potted = false;
  double next_value = 0.0;
  std::vector<table::SceneBall> rest;  // the table a pot left, for the second level
};

// The legal-pot rate of `executions`, all of one stroke.
PotProbability PotRateOf(const std::vector<Execution>& executions);

// Executions [0, samples) of each of `plans`, flattened into one batch on `pool`'s threads,
// results in index order (plan k's execution s at k samples + s). Execution s of every plan is
// its stroke perturbed by options.noise from SampleSeed(options.seed, s), played on `motion`;
// with `value_next` a pot's next shot is valued under options.rules. A throw counts as a miss.
std::vector<Execution> ExecuteAll(const table::TableGeometry& table,
                                  const physics::ModelParameters& params,
                                  const std::vector<table::SceneBall>& balls,
                                  const std::vector<const pot::PotPlan*>& plans, int samples,
                                  const ChoiceOptions& options, const Motion& motion,
                                  bool value_next, batch::ThreadPool& pool);

// Executions [first, first + count) of each of `plans`, as ExecuteAll's (plan k's execution
// first + s at k count + s): a sequential estimate adds samples in rounds, each sample the same
// whichever round plays it.
std::vector<Execution> ExecuteRange(const table::TableGeometry& table,
                                    const physics::ModelParameters& params,
                                    const std::vector<table::SceneBall>& balls,
                                    const std::vector<const pot::PotPlan*>& plans, int first,
                                    int count, const ChoiceOptions& options, const Motion& motion,
                                    bool value_next, batch::ThreadPool& pool);

// `plan`'s stroke executed `samples` times with `noise` (execution s seeded SampleSeed(seed, s))
// on the full model the table runs, on `pool`'s threads.
PotProbability EstimatePotProbability(const table::TableGeometry& table,
                                      const physics::ModelParameters& params,
                                      const std::vector<table::SceneBall>& balls,
                                      const pot::PotPlan& plan,
                                      const params::ExecutionNoise& noise, int samples,
                                      std::uint64_t seed, batch::ThreadPool& pool);

}  // namespace billiard::choice
