#include "planner/pot/search_context.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <stdexcept>

#include "planner/pot/pot_geometry.h"
#include "sim/model_choice/model_choice.h"

namespace billiard::pot {

using physics::BallState;
using physics::CueStroke;
using table::EventType;
using table::SceneBall;
using table::TableEvent;
using table::TableSimulation;

namespace {

// Planning scenes that need more events are refused; a pot takes tens.
constexpr std::int64_t kMaxPlanEvents = 20000;
// Where no rail is on a route, the search meets the jaws with Han 2005's single impulse, 20 times
// cheaper than Mathavan et al. 2010's integrated impact: the truth, which finds the margin, has
// the set's own.
constexpr table::CushionModel kSearchCushion = table::CushionModel::kHan2005;
// Where the search meets rails with Mathavan et al. 2010's impact (a bank's, a kick's, position
// play's), it integrates each with this many steps per approach momentum, not the truth's
// table::kMathavanSteps: 5 times cheaper, the rebound angle within 0.07 degrees of the converged
// one (cushion_impact_test), which the truth's aim and window, found from the search's, take up.
constexpr double kSearchMathavanSteps = 50.0;

}  // namespace

BallState Rotated(BallState s, double angle) {
  const Eigen::Rotation2Dd turn(angle);
  s.segment<2>(physics::kVx) = turn * Eigen::Vector2d(s.segment<2>(physics::kVx));
  s.segment<2>(physics::kWx) = turn * Eigen::Vector2d(s.segment<2>(physics::kWx));
  return s;
}

BallState StateBefore(const TableSimulation& sim, std::size_t i, double t) {
  const std::vector<table::MotionSegment>& segments = sim.segments(i);
  for (auto it = segments.rbegin(); it != segments.rend(); ++it) {
    if (it->start_time() < t) return it->At(t);
  }
  return segments.front().At(t);
}

std::size_t IndexOf(const TableSimulation& sim, int id) {
  for (std::size_t i = 0; i < sim.ball_count(); ++i) {
    if (sim.id(i) == id) return i;
  }
  throw std::logic_error("no ball " + std::to_string(id));
}

namespace {

// A number to three significant digits, and its unit: "1.23 deg".
std::string InWords(double value, const char* unit) {
  std::ostringstream s;
  s.precision(3);
  s << value << " " << unit;
  return s.str();
}

}  // namespace

std::string Degrees(double radians) { return InWords(radians / kDegree, "deg"); }

std::string MetresPerSecond(double speed) { return InWords(speed, "m/s"); }

SearchContext::SearchContext(const table::TableGeometry& table, const physics::ModelParameters& params,
                             const std::vector<SceneBall>& balls, int object, const table::Pocket& pocket,
                             const PotOptions& options, std::optional<CueTarget> target)
    : table_(table), params_(params), balls_(balls), object_id_(object), pocket_(pocket),
      options_(options), target_(std::move(target)), r_(params.ball.radius) {
  truth_motion_ = options.truth_motion ? options.truth_motion : model_choice::TableMotion(params);
  for (std::size_t i = 0; i < balls_.size(); ++i) {
    if (balls_[i].id == 0) cue_ = i;
    if (balls_[i].id == object) object_ = i;
  }
  cue_position_ = balls_[cue_].state.head<2>();
  balls_[cue_].state = physics::MakeBallState(cue_position_.x(), cue_position_.y(), 0, 0, 0, 0, 0);
}

void SearchContext::SearchAmong(std::vector<SceneBall> near, bool rails_matter) {
  near_ = std::move(near);
  rails_matter_ = rails_matter;
}

std::unique_ptr<TableSimulation> SearchContext::Simulation(const std::vector<SceneBall>& balls, bool truth) {
  table::TableSimulationOptions o;
  o.cushion_model = truth || rails_matter_ ? options_.cushion_model : kSearchCushion;
  if (!truth) o.mathavan_steps = kSearchMathavanSteps;
  if (truth) o.five_dof = truth_motion_;
  o.max_events = kMaxPlanEvents;
  ++simulations_;
  return std::make_unique<TableSimulation>(table_, params_, balls, o);
}

std::unique_ptr<TableSimulation> SearchContext::Launch(const CueStroke& stroke, bool truth, bool whole) {
  std::vector<SceneBall> balls = whole || near_.empty() ? balls_ : near_;
  for (SceneBall& b : balls) {
    if (b.id == 0) b = table::Struck(0, stroke, cue_position_, params_);
  }
  return Simulation(balls, truth);
}

Contact SearchContext::FirstContact(const CueStroke& stroke, bool truth) {
  Contact c;
  std::unique_ptr<TableSimulation> sim = Launch(stroke, truth);
  const auto cue_event = [](const TableEvent& e) { return table::SettlesFirstBallMet(e, 0); };
  if (!sim->RunUntil(cue_event)) return c;
  const auto it = std::find_if(sim->events().rbegin(), sim->events().rend(), cue_event);
  if (it->type == EventType::kBallPocket) return c;
  c.ball = it->ball == 0 ? it->other : it->ball;
  c.time = it->time;
  const std::size_t k = IndexOf(*sim, c.ball);
  const std::size_t cue = IndexOf(*sim, 0);
  c.cue_before = StateBefore(*sim, cue, c.time);
  c.object_before = StateBefore(*sim, k, c.time);
  c.object_after = sim->StateAt(k, c.time);
  c.cue_at = c.cue_before.head<2>();
  c.object_at = c.object_after.head<2>();
  c.departure = Angle(c.object_after.segment<2>(physics::kVx));
  c.normal = Angle(c.object_at - c.cue_at);
  for (std::size_t i = 0; i < sim->ball_count(); ++i) {
    if (i != cue && i != k && !sim->pocket(i)) c.others.push_back({sim->id(i), sim->StateAt(i, c.time)});
  }
  return c;
}

Played SearchContext::Play(const CueStroke& stroke, bool truth, bool to_rest) {
  Played played;
  played.sim = Launch(stroke, truth, to_rest);
  const std::size_t object = IndexOf(*played.sim, object_id_), cue = IndexOf(*played.sim, 0);
  if (to_rest) {
    played.sim->Run();
  } else {
    played.sim->RunUntil(KsFate(*played.sim));
  }
  PotOutcome& o = played.outcome;
  o.first_contact = table::FirstBallMet(played.sim->events(), 0);
  for (const TableEvent& e : played.sim->events()) {
    if (e.type == EventType::kBallPocket && e.ball == object_id_) {
      played.arrival_speed = StateBefore(*played.sim, object, e.time).segment<2>(physics::kVx).norm();
    }
  }
  if (!to_rest && !played.arrival_speed && !played.sim->events().empty() &&
      played.sim->events().back().ball == object_id_ &&
      played.sim->events().back().type == EventType::kBallCushion) {
    // Stopped where a rail turned K away: its speed there, as near the pocket as it got.
    played.arrival_speed =
        StateBefore(*played.sim, object, played.sim->events().back().time).segment<2>(physics::kVx).norm();
  }
  o.potted = played.sim->pocket(object) && *played.sim->pocket(object) == pocket_.name;
  o.cue_pocket = played.sim->pocket(cue);
  o.legal = o.potted && o.first_contact == object_id_ && !o.cue_pocket;
  o.cue_rest = played.sim->State(cue).head<2>();
  return played;
}

std::function<bool(const TableEvent&)> SearchContext::KsFate(const TableSimulation& sim) const {
  const int k = object_id_, rails = RailCount(table_);
  const std::size_t index = IndexOf(sim, k);
  const Eigen::Vector2d mouth = pocket_.centre;
  return [&sim, k, rails, index, mouth](const TableEvent& e) {
    if (e.ball != k) return false;
    if (e.type == EventType::kBallPocket) return true;
    if (e.type != EventType::kBallCushion || e.cushion >= rails) return false;
    const BallState after = sim.StateAt(index, e.time);
    return after.segment<2>(physics::kVx).dot(mouth - after.head<2>()) <= 0.0;
  };
}

}  // namespace billiard::pot
