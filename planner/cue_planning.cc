#include "planner/cue_planning.h"

#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

#include "planner/reachability.h"
#include "sim/cue/clearance.h"
#include "sim/cue/stroke_limits.h"
#include "sim/physics/closed_form.h"

namespace billiard::planner {

namespace {

constexpr int kStruck = 0;  // the request's ball, among the cue's obstacles

std::string Fixed(double value, int digits) {
  std::ostringstream s;
  s.precision(digits);
  s << std::fixed << value;
  return s.str();
}

// The request's ball at its start, and the others.
std::vector<table::SceneBall> BallsOf(const ShotRequest& q, const CueSetting& setting) {
  std::vector<table::SceneBall> balls = {table::AtRest(kStruck, q.from.x(), q.from.y())};
  for (const table::SceneBall& b : setting.others) {
    if (b.id != kStruck) balls.push_back(b);
  }
  return balls;
}

// The closed form's launch as a level stroke: the heading and tip offsets the elevation is first
// found for. None where the closed form or the table refuses the request (PlanShot then says why).
std::optional<physics::CueStroke> FirstStroke(const ShotRequest& q, const physics::ModelParameters& params) {
  if (!OnTable(q.from, params) || !OnTable(q.to, params)) return std::nullopt;
  const LaunchSolution guess = InvertClosedForm(q, physics::ClosedFormParameters::From(params));
  if (!guess.ok) return std::nullopt;
  const physics::StrokeSolution solved = physics::StrokeFor(guess.v0, guess.w0, params);
  if (solved.ok) return solved.stroke;
  // Beyond the cue's limits level: its line is still the launch's.
  return physics::CueStroke{1.0, std::atan2(guess.v0.y(), guess.v0.x()), 0.0, 0.0, 0.0};
}

ShotPlan Refused(ShotPlan plan, PlanStatus status, std::string reason) {
  plan.status = status;
  plan.reason = std::move(reason);
  return plan;
}

// The planned stroke judged against the robot: it clears, stays within its ranges and keeps the
// ball on the cloth.
ShotPlan Judged(ShotPlan plan, const cue::CueClearance& clearance, const ShotRequest& q,
                const physics::ModelParameters& params, const cue::Robot& robot) {
  plan.clearance = clearance;
  if (!clearance.clears) {
    return Refused(std::move(plan), PlanStatus::kCueBlocked,
                   "at " + Fixed(plan.stroke.elevation * 180.0 / M_PI, 1) + " deg the " + robot.name + "'s cue meets " +
                       clearance.what + " (" + Fixed(-clearance.distance * 1e3, 2) + " mm into it)");
  }
  const std::string outside = cue::OutsideRanges(robot, plan.stroke, params.ball.radius);
  if (!outside.empty()) return Refused(std::move(plan), PlanStatus::kUnreachable, "the " + robot.name + " cannot: " + outside);
  const std::string hop = cue::HopReason(plan.stroke, q.from, params, cue::kMaxHopOnTheCloth);
  if (!hop.empty()) return Refused(std::move(plan), PlanStatus::kUnreachable, hop);
  return plan;
}

ShotPlan PlanAtTheCue(const ShotRequest& q, const physics::ModelParameters& params, PlannerOptions options,
                      const CueSetting& setting) {
  const std::optional<physics::CueStroke> first = FirstStroke(q, params);
  if (!first) return PlanShot(q, params, options);
  const double r = params.ball.radius;
  const std::vector<table::SceneBall> balls = BallsOf(q, setting);
  const std::variant<double, std::string> needed =
      cue::ElevationFor(setting.table, r, balls, kStruck, *first, setting.robot);
  if (const std::string* why = std::get_if<std::string>(&needed)) {
    return Refused(ShotPlan{}, PlanStatus::kCueBlocked, *why);
  }
  options.elevation = std::get<double>(needed);
  ShotPlan plan = PlanShot(q, params, options);
  if (plan.status != PlanStatus::kOk) return plan;
  cue::CueClearance clearance = cue::Clearance(setting.table, r, balls, kStruck, plan.stroke, setting.robot);
  // The refined heading turned into the cue's way: planned once more at what it needs there.
  if (!clearance.clears) {
    const std::variant<double, std::string> again =
        cue::ElevationFor(setting.table, r, balls, kStruck, plan.stroke, setting.robot);
    const double* higher = std::get_if<double>(&again);
    if (higher && *higher > options.elevation) {
      options.elevation = *higher;
      const double solve_us = plan.solve_us;
      plan = PlanShot(q, params, options);
      plan.solve_us += solve_us;
      if (plan.status != PlanStatus::kOk) return plan;
      clearance = cue::Clearance(setting.table, r, balls, kStruck, plan.stroke, setting.robot);
    }
  }
  return Judged(std::move(plan), clearance, q, params, setting.robot);
}

}  // namespace

ShotPlan PlanShotForRobot(const ShotRequest& request, const physics::ModelParameters& params,
                          const PlannerOptions& options, const CueSetting& setting) {
  try {
    return PlanAtTheCue(request, params, options, setting);
  } catch (const std::invalid_argument& e) {
    // The cue's geometry refuses what the strike cannot place (a non-finite number, say).
    return Refused(ShotPlan{}, PlanStatus::kInvalid, e.what());
  }
}

}  // namespace billiard::planner
