#include "planner/choice/choice_result.h"

#include <cmath>
#include <stdexcept>
#include <utility>
#include <variant>

#include "planner/choice/scene_balls.h"
#include "sim/cue/stroke_limits.h"
#include "sim/table/table_simulation.h"

namespace billiard::choice {

namespace {

// The fallback stroke's cue speed [m/s]: enough to reach a ball across the table and a rail.
constexpr double kFallbackSpeed = 2.0;

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

}  // namespace

const char* ChoiceStatusName(ChoiceStatus status) {
  switch (status) {
    case ChoiceStatus::kOk: return "ok";
    case ChoiceStatus::kInvalid: return "invalid";
    case ChoiceStatus::kNoTarget: return "no_target";
    case ChoiceStatus::kNoPlan: return "no_plan";
  }
  return "invalid";
}

double MicrosecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
      .count();
}

std::optional<ChoiceResult> Unplayable(const table::TableGeometry& table,
                                       const physics::ModelParameters& params,
                                       const std::vector<table::SceneBall>& balls,
                                       rules::Rules rules) {
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
  if (rules::LegalTargets(rules, balls).empty()) {
    return Refusal(ChoiceStatus::kNoTarget, "no object ball on the table");
  }
  return std::nullopt;
}

void NoPlan(const table::TableGeometry& table, double ball_radius,
            const std::vector<table::SceneBall>& balls, rules::Rules rules,
            const std::optional<cue::Robot>& robot, std::string reason, ChoiceResult* result) {
  result->status = ChoiceStatus::kNoPlan;
  result->reason = std::move(reason);
  const int target = rules::LegalTargets(rules, balls).front();
  physics::CueStroke fallback = FallbackStroke(*FindBall(balls, 0), *FindBall(balls, target));
  if (robot) {
    const std::variant<double, std::string> e = cue::ElevationFor(table, ball_radius, balls, 0, fallback, *robot);
    if (const std::string* why = std::get_if<std::string>(&e)) {
      result->reason += "; the fallback toward ball " + std::to_string(target) + " is cue_blocked: " + *why;
      return;
    }
    fallback.elevation = std::get<double>(e);
  }
  result->fallback = fallback;
}

}  // namespace billiard::choice
