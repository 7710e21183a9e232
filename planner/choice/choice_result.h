// What a choice answers: its status, the candidates best first, the stroke to play, and the
// answers given before any choosing (a scene that cannot be played; nothing that plans).
//
// Module: billiard::choice.
#pragma once

#include <Eigen/Core>
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "planner/choice/candidates.h"
#include "sim/cue/robot.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/rules/rules.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::choice {

enum class ChoiceStatus {
  kOk,
  kInvalid,   // no cue ball, a scene the simulation refuses
  kNoTarget,  // no object ball to play
  kNoPlan,    // no candidate plans: nothing to play (ChoiceResult::fallback is a stroke)
};
const char* ChoiceStatusName(ChoiceStatus status);  // "ok", "invalid", "no_target", "no_plan"

// A defensive stroke (safety.h), played instead of the chosen pot: it calls nothing.
struct SafetyStroke {
  int target = -1;  // the legal ball it hits first
  physics::CueStroke stroke;
  double win = 0.0;              // its estimated chance of winning the rack
  double foul_rate = 0.0;        // of its full-model executions
  int samples = 0;               // its full-model executions
};

struct ChoiceResult {
  ChoiceStatus status = ChoiceStatus::kInvalid;
  std::string reason;            // why not, when not ok; when ok and !likely, that no shot is
  std::vector<Candidate> candidates;  // every one that planned, the best scored first
  bool likely = false;           // the choice's reported probability >= ChoiceOptions::likely
  std::optional<Eigen::Vector2d> cue_placement;  // ball in hand: where the cue ball goes
  // With kNoPlan: a stroke that at least hits the first legal target full in the face
  // (ghost-ball aim at the ball's centre, 2 m/s), so that a loop has something to play.
  std::optional<physics::CueStroke> fallback;
  // Set when a safety was weighed against the best attempt (safety.h) and won: the stroke played.
  std::optional<SafetyStroke> safety;
  double attempt_win = -1.0;  // the best attempt's chance of winning the rack; -1 when not weighed
  double safety_win = -1.0;   // the best safety's, played or not; -1 when none was weighed
  double decision_us = 0.0;
  int simulations = 0;  // table simulations, plans and executions

  const Candidate* chosen() const { return candidates.empty() ? nullptr : &candidates.front(); }
  // The stroke to play: the safety's when one was chosen, else the chosen pot's, else the
  // fallback; nullptr when there is none (an invalid scene, an empty table).
  const physics::CueStroke* stroke() const {
    if (safety) return &safety->stroke;
    if (chosen()) return &chosen()->plan.stroke;
    return fallback ? &*fallback : nullptr;
  }
};

// The microseconds from `start` to now: a choice's decision_us.
double MicrosecondsSince(std::chrono::steady_clock::time_point start);

// The checks every choice starts with: a cue ball (id 0), a scene the simulation accepts, every
// ball at rest (kInvalid), a legal target under `rules` (kNoTarget). std::nullopt when the
// scene can be played.
std::optional<ChoiceResult> Unplayable(const table::TableGeometry& table,
                                       const physics::ModelParameters& params,
                                       const std::vector<table::SceneBall>& balls,
                                       rules::Rules rules);

// `result` made a kNoPlan for `reason`: its fallback hits the first legal target of `balls`
// (under `rules`) full in the face from the cue ball, at the elevation `robot`'s cue needs
// (cue::ElevationFor); none, and the reason said, when its cue clears at no elevation. Without a
// robot, level.
void NoPlan(const table::TableGeometry& table, double ball_radius,
            const std::vector<table::SceneBall>& balls, rules::Rules rules,
            const std::optional<cue::Robot>& robot, std::string reason, ChoiceResult* result);

}  // namespace billiard::choice
