#include "planner/pot/pot_planner.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <variant>

#include "planner/pot/pot_geometry.h"
#include "sim/model_choice/model_choice.h"
#include "sim/table/ball_collision.h"

namespace billiard::pot {

namespace {

using physics::BallState;
using physics::CueStroke;
using table::EventType;
using table::SceneBall;
using table::TableEvent;
using table::TableSimulation;

constexpr double kDegree = M_PI / 180.0;
// The aim is refined until K leaves along the window's middle to this [rad]: 10 um at a metre, a
// thousandth of a pocket's window seen from a metre (its edges are known to 1e-3 rad). An aim left
// further off than kAimAccepted is none.
constexpr double kAimTolerance = 1e-5;
constexpr double kAimAccepted = 1e-4;
constexpr int kMaxAimIterations = 12;
// The first difference of the aim's residual is taken over this heading step [rad].
constexpr double kAimProbe = 1e-4;
// Where the first guess misses K, headings this far apart are tried out to kContactScan [rad].
constexpr double kContactStep = 0.1 * kDegree;
constexpr double kContactScan = 1.5 * kDegree;
// The drop window: searched this far either side of the route's line (a bank's rebound is off
// the mirror line by a few degrees), in steps of kWindowStep, its edges found to
// kWindowResolution [rad].
constexpr double kDirectScan = 3.0 * kDegree;
constexpr double kRailScan = 8.0 * kDegree;
constexpr double kWindowStep = 0.2 * kDegree;
constexpr double kWindowResolution = 1e-3;
constexpr double kCoarseWindowResolution = 1e-3;
constexpr double kWidestWindow = 20.0 * kDegree;
// The heading margin is what the truth says to kMarginTolerance: 1 - kMarginTolerance of it pots
// and 1 + kMarginTolerance misses. Each edge is bracketed between a heading that pots and one
// that misses, kHeadingEdge.bracket either side of the edge predicted, and where the prediction is off
// by bisection until the outside is within kHeadingEdge.resolution of the inside (beyond the inside by
// less than (1 + 0.1) / (1 - 0.1) = 1.22: a margin lies between them, 0.9 of it inside, 1.1 of
// it outside). The bracket about the prediction is as wide as the tolerance, so that where the
// edge lies in it the margin's 1 - and 1 + kMarginTolerance are the two headings played. The
// speed window more coarsely (it is what the robot's speed may be off by, not what it aims with).
constexpr double kMarginTolerance = 0.1;
// Headings closer than this are the same heading played [rad].
constexpr double kSameHeading = 1e-12;
// An edge's search: the bracket about its prediction, the resolution the bisection goes to and
// how often at most it halves (an edge at the aim itself). A speed edge at the plan's own speed
// (a fragile pot) is told to 1/64 of its bracket, a heading edge, which the margin is, to 1/4096.
struct EdgeSearch {
  double bracket, resolution;
  int halvings;
};
constexpr EdgeSearch kHeadingEdge{kMarginTolerance, 0.2, 12};
constexpr EdgeSearch kSpeedEdge{0.1, 0.1, 6};
// An edge's first guess is at least this fraction of the way to its limit.
constexpr double kSmallestEdge = 1e-4;
// Planning scenes that need more events are refused; a pot takes tens.
constexpr std::int64_t kMaxPlanEvents = 20000;
// The longest a cue ball's path is followed to find where it passes its ghost ball [s].
constexpr double kLongestTime = 10.0;
// Where no rail is on a route, the search meets the jaws with Han 2005's single impulse, 20 times
// cheaper than Mathavan et al. 2010's integrated impact: the truth, which finds the margin, has
// the set's own.
constexpr table::CushionModel kSearchCushion = table::CushionModel::kHan2005;
// Where the search meets rails with Mathavan et al. 2010's impact (a bank's, a kick's, position
// play's), it integrates each with this many steps per approach momentum, not the truth's
// table::kMathavanSteps: 5 times cheaper, the rebound angle within 0.07 degrees of the converged
// one (cushion_impact_test), which the truth's aim and window, found from the search's, take up.
constexpr double kSearchMathavanSteps = 50.0;
// A pot's search simulates the balls within this distance of its routes' lines, beyond contact
// [m]: the drop window is a few degrees wide, 5 cm at a metre.
constexpr double kNearRoute = 0.15;
// The object ball's least speed in the first search of its drop window [m/s]: enough to reach
// any pocket.
constexpr double kReachSpeed = 3.0;
// The slowest cue stroke tried [m/s].
constexpr double kSlowestCue = 0.05;
// The first cue speed tried on a plain pot [m/s], and the arrival speed it is matched to within.
constexpr double kFirstCueSpeed = 1.5;
constexpr double kArrivalTolerance = 0.05;
// Position play: the grid of cue speeds (times the slowest that pots) and tip heights (times the
// largest offset) the Newton iteration starts from the best of.
constexpr double kGridSpeeds[] = {1.15, 1.5, 2.0, 2.8, 4.0};
constexpr double kGridTips[] = {-0.8, -0.4, 0.0, 0.4, 0.8};
constexpr int kMaxPositionIterations = 10;
// The Levenberg-Marquardt damping of position play's steps, relative to the normal matrix's trace.
constexpr double kPositionDamping = 1e-6;
// Position play's side spins, as fractions of the largest tip offset: none first.
constexpr double kPositionSides[] = {0.0, 0.5, -0.5};
// Newton's method starts from this many of the grid's nearest rest points, in turn.
constexpr std::size_t kPositionStarts = 3;
// Of the banks and the kicks, the shortest this many routes with clear lines are searched.
constexpr int kRoutesSearched = 3;
// Position play is tried on this many of a kind's pots, the widest first.
constexpr std::size_t kPositionRoutes = 2;
constexpr int kMaxTruthCorrections = 4;
// Curves: the cue elevations [rad] and side offsets (fraction of the largest) tried.
constexpr double kCurveElevations[] = {25.0 * kDegree, 45.0 * kDegree, 60.0 * kDegree};
constexpr double kCurveSides[] = {0.7, -0.7};
// How far a curve's cut on its path alone may lie beyond the cue's limit and its aim still be
// searched: the aim moves the contact around the object ball, which turns the cut [rad].
constexpr double kCurveCutSlack = 10.0 * kDegree;

double Wrap(double a) { return std::remainder(a, 2.0 * M_PI); }
Eigen::Vector2d Unit(double angle) { return {std::cos(angle), std::sin(angle)}; }
double Angle(const Eigen::Vector2d& v) { return std::atan2(v.y(), v.x()); }

// The state turned by `angle` about the vertical: velocity and horizontal spin.
BallState Rotated(BallState s, double angle) {
  const Eigen::Rotation2Dd turn(angle);
  s.segment<2>(physics::kVx) = turn * Eigen::Vector2d(s.segment<2>(physics::kVx));
  s.segment<2>(physics::kWx) = turn * Eigen::Vector2d(s.segment<2>(physics::kWx));
  return s;
}

// The state of ball i just before time t (the segment in force before an event at t).
BallState StateBefore(const TableSimulation& sim, std::size_t i, double t) {
  const std::vector<table::MotionSegment>& segments = sim.segments(i);
  for (auto it = segments.rbegin(); it != segments.rend(); ++it) {
    if (it->start_time() < t) return it->At(t);
  }
  return segments.front().At(t);
}

std::string Degrees(double radians) {
  std::ostringstream s;
  s.precision(3);
  s << radians / kDegree << " deg";
  return s.str();
}

// Where the cue ball first touched a ball, and the two balls there.
struct Contact {
  int ball = -1;  // the id it touched first; -1: none (it stopped or dropped first)
  double time = 0.0;
  Eigen::Vector2d cue_at = Eigen::Vector2d::Zero(), object_at = Eigen::Vector2d::Zero();
  BallState cue_before = BallState::Zero(), object_before = BallState::Zero();
  BallState object_after = BallState::Zero();
  double departure = 0.0;  // direction of K's velocity after the impact [rad]
  double normal = 0.0;     // direction of the line of centres, cue ball to K [rad]
  std::vector<SceneBall> others;  // every other ball then (neither the cue ball nor K)
};

// A full run: what became of K and of the cue ball.
struct Played {
  PotOutcome outcome;
  std::unique_ptr<TableSimulation> sim;
  // K's speed as it crossed a capture line or, stopped early, met the rail that turned it away.
  std::optional<double> arrival_speed;
};

struct Drop {
  double lo = 0.0, hi = 0.0;  // directions of K's departure that drop [rad]
  double Middle() const { return 0.5 * (lo + hi); }
};

// A stroke's free parts, the heading left to the aim.
struct StrokeShape {
  double speed = 0.0, tip_side = 0.0, tip_height = 0.0, elevation = 0.0;
  CueStroke At(double heading) const { return {speed, heading, tip_side, tip_height, elevation}; }
};

struct Route {
  ShotKind kind = ShotKind::kDirect;
  int rail = -1;
  Eigen::Vector2d object_aim = Eigen::Vector2d::Zero();  // where K is sent first
  Eigen::Vector2d cue_aim = Eigen::Vector2d::Zero();     // where the cue ball is sent first
  double elevation = 0.0, tip_side = 0.0;                // curve
};

struct Aimed {
  double heading = 0.0;
  Contact contact;
  double slope = 0.0;  // d departure / d heading
};

// A refusal on the way, the most telling kept.
struct Refusal {
  PotStatus status;
  std::string reason;
  // K does not drop along its own route, whatever the cue ball does: a curve, which changes only
  // the cue ball's path, cannot mend it.
  bool object_route_closed = false;
};

class PotSearch {
 public:
  PotSearch(const table::TableGeometry& table, const physics::ModelParameters& params,
            const std::vector<SceneBall>& balls, int object, const table::Pocket& pocket,
            const PotOptions& options, std::optional<CueTarget> target = std::nullopt)
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

  int simulations() const { return simulations_; }
  const std::vector<SceneBall>& balls() const { return balls_; }

  // The pot along `route`: the plan, or why not.
  // With `place_cue` the speed and follow/draw are chosen for the cue-ball target.
  std::variant<PotPlan, Refusal> Plan(const Route& route, bool place_cue = false) {
    // A bank's and a kick's route is the rail's rebound: the search meets it as the truth does.
    // So is position play's: where the cue ball stops turns on every rail it meets.
    rails_matter_ = route.kind == ShotKind::kBank || route.kind == ShotKind::kKick || (place_cue && target_);
    // A curve bends away from its lines: its search has every ball.
    near_ = route.kind == ShotKind::kCurve ? std::vector<SceneBall>{} : NearRoute(route);
    const Eigen::Vector2d object = balls_[object_].state.head<2>();
    const Eigen::Vector2d departure = (route.object_aim - object).normalized();
    const Eigen::Vector2d ghost = GhostBall(object, departure, r_);
    const Eigen::Vector2d approach = (ghost - (route.kind == ShotKind::kKick ? route.cue_aim : cue_position_)).normalized();
    if (route.kind != ShotKind::kCurve && CutAngle(approach, departure) > options_.max_cut_deg * kDegree) {
      return Refusal{PotStatus::kTooThin, "the cut is " + Degrees(CutAngle(approach, departure)) +
                                              ", beyond " + Degrees(options_.max_cut_deg * kDegree)};
    }
    StrokeShape shape{kFirstCueSpeed, route.tip_side, 0.0, route.elevation};
    const double first_heading = FirstHeading(route, shape, ghost);
    if (route.kind == ShotKind::kCurve) {
      if (std::optional<Refusal> thin = CurveTooThin(shape, first_heading, ghost, departure)) return *thin;
    }
    std::optional<Aimed> aimed = AimAt(shape, first_heading, Angle(departure), false, 0.0);
    if (!aimed) return Refusal{PotStatus::kBlocked, BlockedReason(shape, first_heading)};
    const double cut_angle = CutAngle(Unit(Angle(aimed->contact.cue_before.segment<2>(physics::kVx))),
                                      Unit(aimed->contact.departure));
    if (cut_angle > options_.max_cut_deg * kDegree) {
      return Refusal{PotStatus::kTooThin, "the cut is " + Degrees(cut_angle) + ", beyond " +
                                              Degrees(options_.max_cut_deg * kDegree)};
    }
    // The pace first, along the route's own line where K drops along it; else along the middle of
    // the window of a ball that gets there. Then the window at that pace, and the aim at its
    // middle.
    std::optional<Drop> drop;
    double line = Angle(departure);
    // A bank's rebound is the cushion model's, not a mirror's: K's line is found on its own path
    // off the rail, the secant method on the side of the pocket it passes.
    if (route.kind == ShotKind::kBank) line = BankLine(aimed->contact, line);
    if (!Drops(aimed->contact, line, ReachScale(aimed->contact))) {
      const double scan = route.kind == ShotKind::kBank ? kRailScan : kDirectScan;
      drop = DropWindow(aimed->contact, line, scan, kReachSpeed, kCoarseWindowResolution);
      if (!drop) {
        return Refusal{PotStatus::kBlocked,
                       "ball " + std::to_string(object_id_) + " does not drop in " + pocket_.name +
                           " along its route (a ball or a jaw is in the way)",
                       true};
      }
      aimed = AimAt(shape, aimed->heading, drop->Middle(), false, aimed->slope);
      if (!aimed) return Refusal{PotStatus::kBlocked, BlockedReason(shape, first_heading)};
    }
    std::optional<Refusal> paced = Pace(route, ghost, &shape, &*aimed, drop ? drop->Middle() : line);
    if (paced) return *paced;
    drop = DropWindow(aimed->contact, drop ? drop->Middle() : line,
                      route.kind == ShotKind::kBank ? kRailScan : kDirectScan, 0.0,
                      kWindowResolution, drop);
    if (!drop) {
      return Refusal{PotStatus::kNoStroke, "ball " + std::to_string(object_id_) +
                                               " does not drop at the pace it needs"};
    }
    aimed = AimAt(shape, aimed->heading, drop->Middle(), false, aimed->slope);
    if (!aimed) return Refusal{PotStatus::kBlocked, "the aim at the drop window's middle is blocked"};
    std::optional<Aimed> placed_aim;  // position play's truth aim, whose rest met the target
    if (place_cue && target_) {
      std::optional<Refusal> placed = Position(*target_, &shape, &*aimed, *drop, &placed_aim);
      if (placed) return *placed;
    }
    return Finish(route, shape, *aimed, *drop, placed_aim);
  }

  // The heading through the ghost ball alone for `plan` (GhostBallHeading).
  std::optional<double> GhostHeading(const PotPlan& plan) {
    const StrokeShape shape{plan.stroke.speed, plan.stroke.tip_side, plan.stroke.tip_height, plan.stroke.elevation};
    const std::optional<Aimed> ghost = AimAt(shape, plan.stroke.heading, plan.departure, true, 0.0, false);
    if (!ghost) return std::nullopt;
    return ghost->heading;
  }

  // Plays a stroke to rest, or with `to_rest` false until K drops (what the pace and the margin
  // ask: the cue ball's later travel, its cushions above all, is most of a shot's cost): K's fate
  // and the cue ball's.
  Played Play(const CueStroke& stroke, bool truth, bool to_rest = true) {
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

 private:
  // The event that decides K in `sim`: its drop, or a rail after which it heads away from P's
  // mouth (it cannot drop in P on its route then; what follows would only cost cushion impacts).
  // A rail that turns K toward P (a bank's, or one K runs along into the jaws) decides nothing.
  std::function<bool(const TableEvent&)> KsFate(const TableSimulation& sim) const {
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

  // The balls a pot's search can meet before K drops: the cue ball, K, and those within
  // kNearRoute of the cue ball's route to the ghost ball or of K's route to the pocket (the drop
  // window and the margin turn these lines by a few degrees at most). The rest cannot change
  // which ball the cue ball meets first or whether K drops; the truth has them all.
  std::vector<SceneBall> NearRoute(const Route& route) const {
    const Eigen::Vector2d k = balls_[object_].state.head<2>();
    const Eigen::Vector2d ghost = GhostBall(k, (route.object_aim - k).normalized(), r_);
    std::vector<Eigen::Vector2d> cue_legs = {cue_position_, route.cue_aim};
    if (route.kind == ShotKind::kKick) cue_legs.push_back(ghost);
    std::vector<Eigen::Vector2d> object_legs = {k, route.object_aim};
    if (route.kind == ShotKind::kBank) object_legs.push_back(pocket_.centre);
    std::vector<SceneBall> near = {balls_[cue_], balls_[object_]};
    const double reach = 2.0 * r_ + kNearRoute;
    const std::vector<int> ignore = {0, object_id_};
    std::vector<int> ids;
    for (const std::vector<Eigen::Vector2d>* legs : {&cue_legs, &object_legs}) {
      for (std::size_t i = 0; i + 1 < legs->size(); ++i) {
        for (int id : BallsAcross(balls_, (*legs)[i], (*legs)[i + 1], reach, ignore)) ids.push_back(id);
      }
    }
    for (const SceneBall& b : balls_) {
      if (std::find(ids.begin(), ids.end(), b.id) != ids.end()) near.push_back(b);
    }
    return near;
  }

  // The scene with the cue ball struck: the balls near the routes, or the whole scene in its own
  // order (so that its ties break as `simulate --scene`'s do) for a shot played to rest.
  std::unique_ptr<TableSimulation> Launch(const CueStroke& stroke, bool truth, bool whole = false) {
    std::vector<SceneBall> balls = whole || near_.empty() ? balls_ : near_;
    for (SceneBall& b : balls) {
      if (b.id == 0) b.state = physics::StrikeBall(stroke, cue_position_, params_);
    }
    return Simulation(balls, truth);
  }

  std::unique_ptr<TableSimulation> Simulation(const std::vector<SceneBall>& balls, bool truth) {
    table::TableSimulationOptions o;
    o.cushion_model = truth || rails_matter_ ? options_.cushion_model : kSearchCushion;
    if (!truth) o.mathavan_steps = kSearchMathavanSteps;
    if (truth) o.five_dof = truth_motion_;
    o.max_events = kMaxPlanEvents;
    ++simulations_;
    return std::make_unique<TableSimulation>(table_, params_, balls, o);
  }

  std::size_t IndexOf(const TableSimulation& sim, int id) const {
    for (std::size_t i = 0; i < sim.ball_count(); ++i) {
      if (sim.id(i) == id) return i;
    }
    throw std::logic_error("no ball " + std::to_string(id));
  }

  // The cue ball's first contact with a ball for `stroke`.
  Contact FirstContact(const CueStroke& stroke, bool truth) {
    Contact c;
    std::unique_ptr<TableSimulation> sim = Launch(stroke, truth);
    const auto cue_event = [](const TableEvent& e) {
      return (e.type == EventType::kBallBall && (e.ball == 0 || e.other == 0)) ||
             (e.type == EventType::kBallPocket && e.ball == 0);
    };
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

  // The launch heading that sends the cue ball along its route to the ghost ball, squirt
  // included (the launch leaves the cue's heading by the squirt angle).
  // A kick's and a curve's heading is found on the cue ball's own path, alone on the table (the
  // rail's rebound, the slide's bend): the secant method on the side of the ghost ball its path
  // passes, after the rail for a kick.
  double FirstHeading(const Route& route, const StrokeShape& shape, const Eigen::Vector2d& ghost) {
    const Eigen::Vector2d to = route.kind == ShotKind::kKick ? route.cue_aim : ghost;
    double heading = Angle(to - cue_position_);
    if (route.kind == ShotKind::kDirect || route.kind == ShotKind::kBank) {
      if (route.tip_side != 0.0) heading -= physics::SquirtAngle(route.tip_side, params_);
      return heading;
    }
    const bool kick = route.kind == ShotKind::kKick;
    double h0 = heading, f0 = PassingSide(shape.At(h0), ghost, kick);
    double h1 = h0 + kAimProbe, f1 = PassingSide(shape.At(h1), ghost, kick);
    if (!std::isfinite(f0) || !std::isfinite(f1)) return heading;
    for (int i = 0; i < kMaxAimIterations && std::abs(f1) > 1e-5 && f1 != f0; ++i) {
      const double h2 = h1 - f1 * (h1 - h0) / (f1 - f0);
      h0 = h1;
      f0 = f1;
      h1 = h2;
      f1 = PassingSide(shape.At(h1), ghost, kick);
      if (!std::isfinite(f1)) return heading;
    }
    return h1;
  }

  // A curve's cut read off the cue ball's path alone where it passes its ghost ball: one that
  // leaves the cut beyond the cue's limit by more than the aim can change it is refused before
  // the aim is searched (every heading tried there is a simulation). Where the path does not
  // pass the ghost ball, the aim's own scan decides.
  std::optional<Refusal> CurveTooThin(const StrokeShape& shape, double heading,
                                      const Eigen::Vector2d& ghost, const Eigen::Vector2d& departure) {
    const Passing pass = Pass(physics::StrikeBall(shape.At(heading), cue_position_, params_), ghost, false);
    if (!(std::abs(pass.side) < r_) || pass.velocity.norm() <= 0.0) return std::nullopt;
    const double cut = CutAngle(pass.velocity.normalized(), departure);
    const double limit = options_.max_cut_deg * kDegree;
    if (cut <= limit + kCurveCutSlack) return std::nullopt;
    return Refusal{PotStatus::kTooThin, "the curve's cut is " + Degrees(cut) + ", beyond " + Degrees(limit)};
  }

  // The signed distance [m] by which the cue ball's path alone on the table passes `point`
  // (left of its travel > 0), at its closest approach.
  double PassingSide(const CueStroke& stroke, const Eigen::Vector2d& point, bool after_rail) {
    return PassingSide(physics::StrikeBall(stroke, cue_position_, params_), point, after_rail);
  }

  // The same for a ball that starts in `state`, alone on the table.
  double PassingSide(const BallState& state, const Eigen::Vector2d& point, bool after_rail) {
    return Pass(state, point, after_rail).side;
  }

  // How a ball's path alone on the table passes a point: the signed distance of PassingSide
  // (infinite where it never does, after its rail if asked) and the ball's velocity there.
  struct Passing {
    double side = std::numeric_limits<double>::infinity();
    Eigen::Vector2d velocity = Eigen::Vector2d::Zero();
  };
  Passing Pass(const BallState& state, const Eigen::Vector2d& point, bool after_rail) {
    std::vector<SceneBall> alone = {{0, state}};
    std::unique_ptr<TableSimulation> sim = Simulation(alone, false);
    // Run a stretch at a time until the path has passed the point (it draws away again) or
    // the ball rests: a kick's cue ball would go on from cushion to cushion.
    constexpr double kStretch = 0.1, kSample = 2e-3;  // [s]
    constexpr double kPassed = 0.2;                    // [m] beyond the closest approach
    double best = std::numeric_limits<double>::infinity(), t = 0.0;
    Passing passing;
    bool railed = !after_rail;
    std::size_t seen = 0;
    while (!sim->AtRest() && t < kLongestTime) {
      sim->Run(t + kStretch);
      for (; seen < sim->events().size(); ++seen) {
        if (sim->events()[seen].type == EventType::kBallCushion && !railed) {
          railed = true;
          t = sim->events()[seen].time;
        }
      }
      if (!railed) {
        t = sim->time();
        continue;
      }
      double d = best;
      for (; t <= sim->time(); t += kSample) {
        const BallState s = sim->StateAt(0, t);
        const Eigen::Vector2d to = point - s.head<2>();
        d = to.norm();
        if (d < best) {
          best = d;
          const Eigen::Vector2d v = s.segment<2>(physics::kVx);
          passing = {(v.x() * to.y() - v.y() * to.x()) > 0.0 ? best : -best, v};
        }
      }
      if (d > best + kPassed) break;
    }
    return railed ? passing : Passing{};
  }

  // The direction near `mirror` in which K, leaving the contact at the reach speed alone on the
  // table, passes the pocket's mouth after its rail (or `mirror` where that is not found).
  double BankLine(const Contact& c, double mirror) {
    const double scale = ReachScale(c);
    const auto side = [&](double direction) {
      BallState k = Rotated(c.object_after, Wrap(direction - c.departure));
      k.tail<5>() *= scale;
      return PassingSide(k, pocket_.centre, true);
    };
    double h0 = mirror, f0 = side(h0), h1 = h0 + kAimProbe, f1 = side(h1);
    for (int i = 0; i < kMaxAimIterations && std::isfinite(f0) && std::isfinite(f1) &&
                    std::abs(f1) > 1e-4 && f1 != f0; ++i) {
      const double h2 = h1 - f1 * (h1 - h0) / (f1 - f0);
      h0 = h1;
      f0 = f1;
      h1 = h2;
      f1 = side(h1);
    }
    return std::isfinite(f1) && std::abs(Wrap(h1 - mirror)) < kRailScan ? h1 : mirror;
  }

  // The contact normal [rad] that sends K along `target` when the cue ball arrives as in `c`:
  // the ball-ball impact model the simulation resolves (Alciatore TP A.14), so that the cut- and
  // spin-induced throw is aimed for.
  double ThrowCorrectedNormal(const Contact& c, double target) const {
    const auto departure = [&](double normal) {
      BallState cue = c.cue_before;
      cue.head<2>() = c.object_at - 2.0 * r_ * Unit(normal);
      const table::BallBallImpulse hit =
          table::ResolveBallBallImpact(cue, c.object_before, params_.ball, params_.collision);
      return Angle(hit.b.segment<2>(physics::kVx));
    };
    double normal = target;
    for (int i = 0; i < 6; ++i) {
      const double f = Wrap(departure(normal) - target);
      if (std::abs(f) < 1e-12) break;
      const double h = 1e-7;
      const double slope = Wrap(departure(normal + h) - departure(normal - h)) / (2.0 * h);
      if (!(std::abs(slope) > 1e-6)) break;
      normal -= f / slope;
    }
    return normal;
  }

  // The heading at which the cue ball's first contact is K and K leaves along `target` (the
  // throw corrected) or, with options.correct_throw false, the line of centres points along it
  // (the ghost ball alone). `slope` is d departure / d heading if known (0: measured).
  std::optional<Aimed> AimAt(const StrokeShape& shape, double heading, double target, bool truth,
                             double slope, bool throw_corrected = true) {
    Contact c = FirstContact(shape.At(heading), truth);
    if (c.ball != object_id_) {
      bool found = false;
      for (double d = kContactStep; d <= kContactScan && !found; d += kContactStep) {
        for (double sign : {1.0, -1.0}) {
          c = FirstContact(shape.At(heading + sign * d), truth);
          if (c.ball == object_id_) {
            heading += sign * d;
            found = true;
            break;
          }
        }
      }
      if (!found) return std::nullopt;
    }
    const auto residual = [&](const Contact& x) {
      return Wrap((throw_corrected ? x.departure : x.normal) - target);
    };
    double f = residual(c);
    if (slope == 0.0) {
      const Contact probe = FirstContact(shape.At(heading + kAimProbe), truth);
      if (probe.ball != object_id_) return std::nullopt;
      slope = Wrap(residual(probe) - f) / kAimProbe;
    }
    if (!std::isfinite(f) || !std::isfinite(slope)) return std::nullopt;
    // The impact model's step first: the normal that throws K onto the target, reached by
    // moving the contact along the cue ball's approach (the normal turns with the heading as
    // the departure does, less the throw's change).
    if (throw_corrected && std::abs(slope) > 0.0) {
      const double normal = ThrowCorrectedNormal(c, target);
      const double normal_slope = slope;  // the throw changes slowly with the normal
      const double step = Wrap(normal - c.normal) / normal_slope;
      Contact next = FirstContact(shape.At(heading + step), truth);
      if (next.ball == object_id_) {
        const double g = residual(next);
        if (std::abs(g) < std::abs(f)) {
          if (std::abs(g - f) > 0.0 && std::abs(step) > 0.0) slope = (g - f) / step;
          heading += step;
          c = next;
          f = g;
        }
      }
    }
    for (int i = 0; i < kMaxAimIterations && std::abs(f) > kAimTolerance; ++i) {
      if (!(std::abs(slope) > 1e-9) || !std::isfinite(slope)) return std::nullopt;
      double step = -f / slope;
      Contact next;
      double g = 0.0;
      for (int halving = 0; halving < 8; ++halving) {
        next = FirstContact(shape.At(heading + step), truth);
        if (next.ball == object_id_) {
          g = residual(next);
          if (std::abs(g) < std::abs(f)) break;
        }
        step *= 0.5;
      }
      if (next.ball != object_id_) return std::nullopt;
      if (std::abs(g - f) > 0.0) slope = (g - f) / step;
      heading += step;
      c = next;
      f = g;
    }
    if (!(std::abs(f) <= kAimAccepted) || !std::isfinite(heading)) return std::nullopt;
    return Aimed{heading, c, slope};
  }

  // Whether K, leaving the contact along `direction` with its post-impact speed and spin,
  // drops in P among the balls still on the table.
  bool Drops(const Contact& c, double direction, double scale, bool truth = false) {
    std::vector<SceneBall> balls = c.others;
    BallState object = Rotated(c.object_after, Wrap(direction - c.departure));
    object.tail<5>() *= scale;
    balls.push_back({object_id_, object});
    std::unique_ptr<TableSimulation> sim = Simulation(balls, truth);
    sim->RunUntil(KsFate(*sim));
    const std::optional<std::string>& dropped = sim->pocket(balls.size() - 1);
    return dropped && *dropped == pocket_.name;
  }

  // The factor that brings K's post-impact speed (and spin) up to `min_speed`.
  static double ReachScale(const Contact& c, double min_speed = kReachSpeed) {
    const double speed = c.object_after.segment<2>(physics::kVx).norm();
    return speed > 0.0 ? std::max(1.0, min_speed / speed) : 1.0;
  }

  // The directions about `route_direction` in which K drops in P: the window containing the
  // first direction found to drop, scanned out to `scan` either side, its edges to `resolution`.
  // K leaves at least at `min_speed` (its speed and spin scaled up): before the pace is chosen,
  // the window is that of a ball that gets there. A `hint` (the window found before, coarser)
  // brackets each edge from the start.
  std::optional<Drop> DropWindow(const Contact& c, double route_direction, double scan,
                                 double min_speed, double resolution,
                                 const std::optional<Drop>& hint = std::nullopt,
                                 bool truth = false) {
    const double scale = ReachScale(c, min_speed);
    const auto drops = [&](double direction) { return Drops(c, direction, scale, truth); };
    // The half-width of the window a straight path would have: the capture line's half-length
    // less a ball's radius, seen from where K leaves.
    const double capture = 0.5 * (pocket_.capture_b - pocket_.capture_a).norm();
    const double guess = std::max(kWindowStep, (capture - r_) / (pocket_.centre - c.object_at).norm());
    std::optional<double> inside;
    for (double d = 0.0; d <= scan && !inside; d += kWindowStep) {
      for (double sign : {1.0, -1.0}) {
        if (drops(route_direction + sign * d)) {
          inside = route_direction + sign * d;
          break;
        }
        if (d == 0.0) break;
      }
    }
    if (!inside) return std::nullopt;
    const auto edge = [&](double sign) {
      double in = *inside, out = in;
      if (hint) {
        // The hint's edge, a coarse step either side of it.
        const double near = (sign > 0.0 ? hint->hi : hint->lo);
        const double a = near - sign * kCoarseWindowResolution, b = near + sign * kCoarseWindowResolution;
        if ((a - in) * sign > 0.0 && drops(a)) in = a;
        out = drops(b) ? in : b;
      }
      if (out == in) {
        // Out from the inside, first by the half-width the pocket's opening would give seen
        // from K, then growing.
        double step = 0.8 * guess;
        out = in + sign * step;
        while (drops(out)) {
          in = out;
          step = std::max(0.5 * guess, 0.5 * std::abs(out - *inside));
          out = in + sign * step;
          if (std::abs(out - *inside) > kWidestWindow) return in;
        }
      }
      while (std::abs(out - in) > resolution) {
        const double mid = 0.5 * (in + out);
        (drops(mid) ? in : out) = mid;
      }
      return in;
    };
    Drop drop;
    drop.lo = edge(-1.0);
    drop.hi = edge(1.0);
    return drop;
  }

  // The plain pot's pace: the cue speed at which K crosses the capture line at the arrival
  // speed (its square nearly linear in the cue speed's square: friction takes energy by the
  // metre), re-aimed at each speed (the throw changes with it, a kick's rebound and a curve's
  // bend too).
  std::optional<Refusal> Pace(const Route& route, const Eigen::Vector2d& ghost, StrokeShape* shape,
                              Aimed* aimed, double direction) {
    const double top = params_.cue.max_speed;
    double v_prev = 0.0, a2_prev = 0.0;
    bool have_prev = false;
    for (int i = 0; i < 8; ++i) {
      Played played = Play(shape->At(aimed->heading), false, false);
      const double a = played.arrival_speed.value_or(0.0);
      if (played.arrival_speed) arrival_ = a;
      if (played.arrival_speed && std::abs(a - options_.arrival_speed) < kArrivalTolerance) break;
      double next;
      if (!played.arrival_speed && !have_prev) {
        next = std::min(top, shape->speed * 1.6);
        if (shape->speed >= top) {
          return Refusal{PotStatus::kNoStroke, "ball " + std::to_string(object_id_) +
                                                   " does not reach " + pocket_.name +
                                                   " at the cue's top speed"};
        }
      } else if (!have_prev || !played.arrival_speed) {
        next = std::min(top, shape->speed * (played.arrival_speed ? 0.8 : 1.3));
      } else {
        const double v2 = shape->speed * shape->speed, a2 = a * a;
        const double slope = (a2 - a2_prev) / (v2 - v_prev * v_prev);
        if (slope > 0.0) pace_slope_ = slope;
        const double target = options_.arrival_speed * options_.arrival_speed;
        next = slope > 0.0 ? std::sqrt(std::max(kSlowestCue * kSlowestCue, v2 + (target - a2) / slope))
                           : shape->speed * 1.2;
        next = std::min(top, next);
      }
      if (played.arrival_speed) {
        v_prev = shape->speed;
        a2_prev = a * a;
        have_prev = true;
      }
      if (next == shape->speed) break;
      shape->speed = next;
      if (!Reaim(route, ghost, *shape, direction, aimed)) {
        return Refusal{PotStatus::kBlocked, "at " + std::to_string(next) +
                                                " m/s the cue ball no longer reaches ball " +
                                                std::to_string(object_id_) + " first"};
      }
    }
    return std::nullopt;
  }

  // The aim for `shape` from the last one (a curve's path found again first, its bend changes
  // with the shape).
  bool Reaim(const Route& route, const Eigen::Vector2d& ghost, const StrokeShape& shape,
             double direction, Aimed* aimed) {
    const double from = route.kind == ShotKind::kCurve ? FirstHeading(route, shape, ghost) : aimed->heading;
    std::optional<Aimed> again = AimAt(shape, from, direction, false, aimed->slope);
    if (!again) return false;
    *aimed = *again;
    return true;
  }

  // Where the truth or the search leaves the cue ball for a shape: the pot aimed at `middle`.
  struct Landing {
    bool legal = false;
    Eigen::Vector2d rest = Eigen::Vector2d::Zero();
    Aimed aimed;
  };
  std::optional<Landing> LandWith(const StrokeShape& shape, const Aimed& from, double middle,
                                  bool truth) {
    std::optional<Aimed> aimed = AimAt(shape, from.heading, middle, truth, from.slope);
    if (!aimed) return std::nullopt;
    const PotOutcome o = Play(shape.At(aimed->heading), truth).outcome;
    if (!o.legal) return std::nullopt;
    return Landing{true, o.cue_rest, *aimed};
  }

  // Position play: the cue speed and tip height (follow > 0, draw < 0) that pot K and leave the
  // cue ball at the target, by Newton's method on the search's rest point from the nearest of a
  // coarse grid, then corrected on the truth with the search's Jacobian.
  std::optional<Refusal> Position(const CueTarget& target, StrokeShape* shape, Aimed* aimed,
                                  const Drop& drop, std::optional<Aimed>* truth_aim) {
    // Without side spin first; then with it either way (it turns the cue ball off the rails and
    // throws K, so it reaches rest points that speed and follow or draw alone do not).
    std::optional<Refusal> first;
    for (double side : kPositionSides) {
      StrokeShape s = *shape;
      s.tip_side = side * params_.cue.max_tip_offset * r_;
      Aimed a = *aimed;
      if (side != 0.0) {
        std::optional<Aimed> again = AimAt(s, aimed->heading - physics::SquirtAngle(s.tip_side, params_),
                                           drop.Middle(), false, aimed->slope);
        if (!again) continue;
        a = *again;
      }
      std::optional<Refusal> refused = PositionWithSide(target, &s, &a, drop, truth_aim);
      if (!refused) {
        *shape = s;
        *aimed = a;
        return std::nullopt;
      }
      if (!first) first = refused;
    }
    first->reason += " (with side spin too)";
    return first;
  }

  // Position play at the shape's side spin: speed and tip height.
  std::optional<Refusal> PositionWithSide(const CueTarget& target, StrokeShape* shape, Aimed* aimed,
                                          const Drop& drop, std::optional<Aimed>* truth_aim) {
    const double max_tip = params_.cue.max_tip_offset * r_;
    const double side = shape->tip_side;
    const double tip_room = std::sqrt(std::max(0.0, max_tip * max_tip - side * side)) * 0.999;
    const double top = params_.cue.max_speed;
    const double base = shape->speed;
    const double tolerance = std::max(target.radius, options_.position_tolerance);
    const auto bounded = [&](Eigen::Vector2d x) {
      x.x() = std::clamp(x.x(), kSlowestCue, top);
      x.y() = std::clamp(x.y(), -tip_room, tip_room);
      return x;
    };
    const auto shaped = [&](const Eigen::Vector2d& x) {
      StrokeShape s = *shape;
      s.speed = x.x();
      s.tip_height = x.y();
      return s;
    };
    std::vector<std::pair<Eigen::Vector2d, Landing>> grid;
    for (double speed : kGridSpeeds) {
      for (double tip : kGridTips) {
        const Eigen::Vector2d xi = bounded({base * speed / kGridSpeeds[1], tip * tip_room});
        std::optional<Landing> l = LandWith(shaped(xi), *aimed, drop.Middle(), false);
        if (l) grid.emplace_back(xi, *l);
      }
    }
    if (grid.empty()) return Refusal{PotStatus::kTargetUnreachable, "no stroke of the grid pots and leaves the cue ball on the table"};
    const auto miss_of = [&](const Landing& l) { return (l.rest - target.point).norm(); };
    std::sort(grid.begin(), grid.end(), [&](const auto& a, const auto& b) { return miss_of(a.second) < miss_of(b.second); });
    // d rest / d (speed, tip height) by forward differences on the search.
    const auto jacobian = [&](const Eigen::Vector2d& at, const Landing& l, Eigen::Matrix2d* j) {
      const Eigen::Vector2d steps(0.02 * at.x(), 0.05 * tip_room);
      for (int c = 0; c < 2; ++c) {
        Eigen::Vector2d probe = at;
        probe[c] += (at[c] + steps[c] > (c == 0 ? top : tip_room)) ? -steps[c] : steps[c];
        std::optional<Landing> p = LandWith(shaped(probe), l.aimed, drop.Middle(), false);
        if (!p) return false;
        j->col(c) = (p->rest - l.rest) / (probe[c] - at[c]);
      }
      return j->allFinite();
    };
    // A Levenberg-Marquardt step in units of the grid's spans: where speed and tip move the rest
    // point along one line (a cue ball already rolling at contact, whatever the tip), the step to
    // the nearest point of that line.
    const Eigen::Vector2d span(base, tip_room > 0.0 ? tip_room : 1.0);
    const auto step_to = [&](const Eigen::Matrix2d& jacobian, const Eigen::Vector2d& miss) {
      const Eigen::Matrix2d js = jacobian * span.asDiagonal();
      const Eigen::Matrix2d normal = js.transpose() * js;
      const Eigen::Matrix2d damped = normal + kPositionDamping * normal.trace() * Eigen::Matrix2d::Identity();
      return Eigen::Vector2d(span.asDiagonal() * (damped.inverse() * (js.transpose() * miss)));
    };
    // Gauss-Newton (a step that does not come closer is halved) from the nearest grid points in
    // turn: the rest point jumps where the cue ball's path meets a cushion or a ball.
    Eigen::Vector2d x = grid.front().first;
    Landing here = grid.front().second;
    Eigen::Matrix2d j;
    for (std::size_t start = 0; start < grid.size() && start < kPositionStarts; ++start) {
      Eigen::Vector2d xs = grid[start].first;
      Landing at = grid[start].second;
      for (int i = 0; i < kMaxPositionIterations; ++i) {
        const Eigen::Vector2d miss = target.point - at.rest;
        if (miss.norm() < 0.25 * tolerance || !jacobian(xs, at, &j)) break;
        Eigen::Vector2d step = step_to(j, miss);
        bool better = false;
        for (int halving = 0; halving < 5 && !better; ++halving, step *= 0.5) {
          const Eigen::Vector2d xn = bounded(xs + step);
          std::optional<Landing> l = LandWith(shaped(xn), at.aimed, drop.Middle(), false);
          if (l && miss_of(*l) < miss.norm()) {
            xs = xn;
            at = *l;
            better = true;
          }
        }
        if (!better) break;
      }
      if (miss_of(at) < miss_of(here)) {
        x = xs;
        here = at;
      }
      if (miss_of(here) < 0.25 * tolerance) break;
    }
    // The truth's rest point, corrected with the search's Jacobian there.
    std::optional<Landing> truth = LandWith(shaped(x), here.aimed, drop.Middle(), true);
    const bool have_jacobian = jacobian(x, here, &j);
    for (int i = 0; truth && have_jacobian && i < kMaxTruthCorrections; ++i) {
      const Eigen::Vector2d miss = target.point - truth->rest;
      if (miss.norm() < 0.5 * tolerance) break;
      const Eigen::Vector2d xn = bounded(x + step_to(j, miss));
      std::optional<Landing> l = LandWith(shaped(xn), truth->aimed, drop.Middle(), true);
      if (!l || (l->rest - target.point).norm() >= miss.norm()) break;
      x = xn;
      truth = l;
    }
    if (!truth || (truth->rest - target.point).norm() > tolerance) {
      const Eigen::Vector2d nearest = truth ? truth->rest : here.rest;
      std::ostringstream reason;
      reason.precision(3);
      reason << "the cue ball stops at best " << (nearest - target.point).norm()
             << " m from the target, at (" << nearest.x() << ", " << nearest.y() << ")";
      return Refusal{PotStatus::kTargetUnreachable, reason.str()};
    }
    *shape = shaped(x);
    std::optional<Aimed> again = AimAt(*shape, here.aimed.heading, drop.Middle(), false, here.aimed.slope);
    if (!again) return Refusal{PotStatus::kTargetUnreachable, "the stroke for the target loses ball " + std::to_string(object_id_)};
    *aimed = *again;
    *truth_aim = truth->aimed;
    return std::nullopt;
  }

  // The last x from x0 toward `guess` (a predicted edge), at most `limit`, for which `pots` holds
  // and the first beyond it that misses (both `limit` where it still pots there): the guess's own
  // bracket (`search.bracket` of it either side) where the edge lies in it, else found by
  // bisection until the two are within `search.resolution` of the inside's distance from x0.
  struct Bracket {
    double in, out;
  };
  Bracket Edge(const std::function<bool(double)>& pots, double x0, double guess, double limit,
               const EdgeSearch& search) {
    const double bracket = search.bracket;
    // A guess at x0 itself (a window of no width) brackets nothing: a small step toward the limit.
    if (!(std::abs(guess - x0) >= kSmallestEdge * std::abs(limit - x0))) {
      guess = x0 + kSmallestEdge * (limit - x0);
    }
    const auto at = [&](double fraction) {
      const double x = x0 + fraction * (guess - x0);
      return std::abs(x - x0) > std::abs(limit - x0) ? limit : x;
    };
    double in = x0, out = at(1.0 - bracket);
    if (pots(out)) {
      in = out;
      out = at(1.0 + bracket);
      if (!pots(out)) return {in, out};  // within the bracket
      double fraction = 1.0 + 4.0 * bracket;
      for (out = at(fraction); pots(out); out = at(fraction)) {  // further out until it misses
        in = out;
        if (out == limit) return {limit, limit};
        fraction *= 2.0;  // at() stops at the limit
      }
    } else if (pots(at(1.0 - 4.0 * bracket))) {  // short of the guess: a wider bracket first
      in = at(1.0 - 4.0 * bracket);
    }
    // To the resolution of the edge, or to 2^-halvings of the bracket where the edge is at x0.
    const double floor = std::ldexp(std::abs(out - in), -search.halvings);
    while (std::abs(out - in) > std::max(search.resolution * std::abs(in - x0), floor)) {
      const double mid = 0.5 * (in + out);
      (pots(mid) ? in : out) = mid;
    }
    return {in, out};
  }

  // The heading margin [rad] from a bracket of its edge about `centre`: the one of which
  // 1 - kMarginTolerance is the inside, a heading played (near a jaw the window may have holes:
  // what is between the aim and the inside is not all known to pot), its 1 + kMarginTolerance
  // beyond the outside; or the inside where the bracket is wider than that (an edge at the aim
  // itself).
  static double Margin(const Bracket& b, double centre) {
    const double in = std::abs(b.in - centre), out = std::abs(b.out - centre);
    const double margin = in / (1.0 - kMarginTolerance);
    return (1.0 + kMarginTolerance) * margin >= out - kSameHeading ? margin : in;
  }

  // Margin(), its far side played: where the heading 1 + kMarginTolerance of it out still pots
  // (K drops again past a hole in the window at the outside), the margin is the one whose
  // 1 + kMarginTolerance is the outside, a heading played that misses.
  static double PlayedMargin(const std::function<bool(double)>& pots, const Bracket& b, double centre) {
    const double margin = Margin(b, centre);
    const double side = b.out >= centre ? 1.0 : -1.0;
    const double beyond = centre + side * (1.0 + kMarginTolerance) * margin;
    if (margin <= 0.0 || std::abs(beyond - b.out) <= kSameHeading || !pots(beyond)) return margin;
    return std::abs(b.out - centre) / (1.0 + kMarginTolerance);
  }

  // Margin, speed window and the check against the truth.
  // `placed`: position play's truth aim, kept as it is (the rest point it was solved for moves
  // with the smallest turn once the cue ball has met a cushion or two).
  std::variant<PotPlan, Refusal> Finish(const Route& route, const StrokeShape& shape,
                                        const Aimed& aimed, const Drop& drop,
                                        const std::optional<Aimed>& placed) {
    PotPlan plan;
    plan.kind = route.kind;
    plan.rail = route.rail;
    // The truth's own aim: the motion it runs (5-DOF while the cue ball slides) meets K a little
    // differently.
    std::optional<Aimed> truth = placed ? placed : AimAt(shape, aimed.heading, drop.Middle(), true, aimed.slope);
    if (!truth) return Refusal{PotStatus::kNoStroke, "under the full model the cue ball misses ball " + std::to_string(object_id_)};
    // A bank's window moves with K's state at the rail, which the truth's slide changes: it is
    // found again on the truth, from the search's, and the margin measured there.
    Drop window = drop;
    // The window found again on the truth, and the aim at its middle.
    const auto on_the_truth = [&]() -> std::optional<Refusal> {
      std::optional<Drop> w = DropWindow(truth->contact, drop.Middle(), kDirectScan, 0.0, kWindowResolution, drop, true);
      if (!w) return Refusal{PotStatus::kNoStroke, "under the full model ball " + std::to_string(object_id_) + " does not drop in " + pocket_.name};
      window = *w;
      truth = AimAt(shape, truth->heading, window.Middle(), true, truth->slope);
      if (!truth) return Refusal{PotStatus::kNoStroke, "under the full model the cue ball misses ball " + std::to_string(object_id_)};
      return std::nullopt;
    };
    if (route.kind == ShotKind::kBank && !placed) {
      if (std::optional<Refusal> r = on_the_truth()) return *r;
    }
    plan.stroke = shape.At(truth->heading);
    Played played = Play(plan.stroke, true);
    // Where the search's jaws (kSearchCushion) let K rattle in and the truth's do not: the
    // window on the truth.
    if (!played.outcome.legal && route.kind != ShotKind::kBank && !placed &&
        played.outcome.first_contact == object_id_) {
      if (std::optional<Refusal> r = on_the_truth()) return *r;
      plan.stroke = shape.At(truth->heading);
      played = Play(plan.stroke, true);
    }
    if (!played.outcome.legal) return Refusal{PotStatus::kNoStroke, Illegal(played.outcome)};

    // The margin on the truth: near a jaw whether K rattles in turns on its speed and spin there,
    // which the truth's slide sets. The window's edges mapped to headings through d departure /
    // d heading give each edge's first bracket.
    // Played to rest: the cue ball may scratch after K drops, as near an edge it may.
    const auto pots_heading = [&](double heading) {
      return Play(shape.At(heading), true).outcome.legal;
    };
    const Aimed& centre = *truth;
    const double slope = std::isfinite(centre.slope) && std::abs(centre.slope) > 1e-9 ? centre.slope : 1.0;
    const double up = (slope > 0.0 ? window.hi - window.Middle() : window.Middle() - window.lo) / std::abs(slope);
    const double down = (slope > 0.0 ? window.Middle() - window.lo : window.hi - window.Middle()) / std::abs(slope);
    const Bracket left = Edge(pots_heading, centre.heading, centre.heading + up, centre.heading + 0.5 * M_PI,
                              kHeadingEdge);
    const Bracket right = Edge(pots_heading, centre.heading, centre.heading - down, centre.heading - 0.5 * M_PI,
                               kHeadingEdge);
    plan.margin_left_deg = PlayedMargin(pots_heading, left, centre.heading) / kDegree;
    plan.margin_right_deg = PlayedMargin(pots_heading, right, centre.heading) / kDegree;
    const auto pots_speed = [&](double speed) {
      StrokeShape s = shape;
      s.speed = speed;
      return Play(s.At(aimed.heading), false, false).outcome.legal;
    };
    // The slowest: where the pace's fit brings K to the capture line at no speed; the fastest
    // often the cue's top speed.
    const double slowest = pace_slope_ > 0.0
        ? std::sqrt(std::max(0.0, shape.speed * shape.speed - arrival_ * arrival_ / pace_slope_))
        : 0.8 * shape.speed;
    plan.speed_lo = Edge(pots_speed, shape.speed, std::max(kSlowestCue, slowest), kSlowestCue,
                         kSpeedEdge).in;
    plan.speed_hi = pots_speed(params_.cue.max_speed)
        ? params_.cue.max_speed
        : Edge(pots_speed, shape.speed, std::min(params_.cue.max_speed, 1.25 * shape.speed),
               params_.cue.max_speed, kSpeedEdge).in;

    const std::size_t cue = IndexOf(*played.sim, 0);
    plan.v0 = played.sim->StateAt(cue, 0.0).segment<2>(physics::kVx);
    plan.w0 = played.sim->StateAt(cue, 0.0).segment<3>(physics::kWx);
    plan.cut_deg = CutAngle(Unit(Angle(truth->contact.cue_before.segment<2>(physics::kVx))),
                            Unit(truth->contact.departure)) / kDegree;
    plan.cue_rest = played.outcome.cue_rest;
    plan.departure = window.Middle();
    Describe(*played.sim, &plan);
    plan.status = PotStatus::kOk;
    return plan;
  }

  // The truth's events and every moving ball's path.
  void Describe(const TableSimulation& sim, PotPlan* plan) const {
    plan->events = sim.events();
    for (std::size_t i = 0; i < sim.ball_count(); ++i) {
      if (sim.segments(i).size() < 2 && sim.segments(i).front().phase() == table::MotionPhase::kStationary) continue;
      BallPath path{sim.id(i), {}};
      double end = sim.time();
      for (const TableEvent& e : sim.events()) {
        if (e.type == EventType::kBallPocket && e.ball == sim.id(i)) end = e.time;
      }
      for (double t = 0.0; t < end; t += options_.path_sample_dt) path.points.push_back(sim.StateAt(i, t).head<2>());
      path.points.push_back(StateBefore(sim, i, end).head<2>());
      plan->paths.push_back(path);
    }
  }

  std::string Illegal(const PotOutcome& o) const {
    if (o.first_contact != object_id_) {
      return o.first_contact < 0 ? "the cue ball touches no ball"
                                 : "the cue ball touches ball " + std::to_string(o.first_contact) + " first";
    }
    if (o.cue_pocket) return "the cue ball follows into " + *o.cue_pocket + " (a scratch)";
    return "ball " + std::to_string(object_id_) + " does not drop in " + pocket_.name;
  }

  std::string BlockedReason(const StrokeShape& shape, double heading) {
    const Contact c = FirstContact(shape.At(heading), false);
    std::ostringstream s;
    if (c.ball >= 0 && c.ball != object_id_) {
      s << "the cue ball meets ball " << c.ball << " before ball " << object_id_;
    } else {
      s << "no heading near the route meets ball " << object_id_;
    }
    return s.str();
  }

  const table::TableGeometry& table_;
  const physics::ModelParameters& params_;
  std::vector<SceneBall> balls_;
  int object_id_;
  const table::Pocket& pocket_;
  PotOptions options_;
  std::optional<CueTarget> target_;
  double r_;
  decltype(table::TableSimulationOptions::five_dof) truth_motion_;
  std::size_t cue_ = 0, object_ = 0;
  Eigen::Vector2d cue_position_ = Eigen::Vector2d::Zero();
  int simulations_ = 0;
  // The pace's last fit: d (arrival speed^2) / d (cue speed^2), and the arrival speed at the pace.
  double pace_slope_ = 0.0, arrival_ = 0.0;
  std::vector<SceneBall> near_;  // the search's scene of a direct route; empty: the whole
  bool rails_matter_ = false;    // the search's cushions are the truth's (else kSearchCushion)
};


// The routes of a kind for K into P from where the balls are, with the balls geometry says lie
// across them (a bank off the pocket's own rail and a kick whose bounce falls outside its rail
// are no routes).
struct Candidate {
  Route route;
  std::vector<int> blockers;  // on the object's line, then on the cue ball's
  std::string blocked;        // in words, when not clear
};

std::string BlockedWords(const std::string& what, const std::vector<int>& ids) {
  std::ostringstream s;
  s << what << " is blocked by ball";
  if (ids.size() > 1) s << "s";
  for (std::size_t i = 0; i < ids.size(); ++i) s << (i ? ", " : " ") << ids[i];
  return s.str();
}

std::vector<Candidate> Routes(ShotKind kind, const table::TableGeometry& table,
                              const physics::ModelParameters& params,
                              const std::vector<SceneBall>& balls, int object,
                              const table::Pocket& pocket) {
  const double r = params.ball.radius;
  Eigen::Vector2d cue = Eigen::Vector2d::Zero(), k = Eigen::Vector2d::Zero();
  for (const SceneBall& b : balls) {
    if (b.id == 0) cue = b.state.head<2>();
    if (b.id == object) k = b.state.head<2>();
  }
  const double clearance = 2.0 * r;
  std::vector<Candidate> out;
  const auto add = [&](Route route, const std::vector<Eigen::Vector2d>& object_legs,
                       const std::vector<Eigen::Vector2d>& cue_legs, bool check_cue) {
    Candidate c{route, {}, {}};
    for (std::size_t i = 0; i + 1 < object_legs.size(); ++i) {
      for (int id : BallsAcross(balls, object_legs[i], object_legs[i + 1], clearance, {0, object})) {
        c.blockers.push_back(id);
      }
    }
    if (!c.blockers.empty()) c.blocked = BlockedWords("ball " + std::to_string(object) + "'s line to the pocket", c.blockers);
    std::vector<int> cue_blockers;
    for (std::size_t i = 0; check_cue && i + 1 < cue_legs.size(); ++i) {
      for (int id : BallsAcross(balls, cue_legs[i], cue_legs[i + 1], clearance, {0, object})) {
        cue_blockers.push_back(id);
      }
    }
    if (!cue_blockers.empty()) {
      if (!c.blocked.empty()) c.blocked += "; ";
      c.blocked += BlockedWords("the cue ball's line to the ghost ball", cue_blockers);
      c.blockers.insert(c.blockers.end(), cue_blockers.begin(), cue_blockers.end());
    }
    out.push_back(c);
  };
  const Eigen::Vector2d straight = (pocket.centre - k).normalized();
  const Eigen::Vector2d ghost = GhostBall(k, straight, r);
  switch (kind) {
    case ShotKind::kDirect:
      add({ShotKind::kDirect, -1, pocket.centre, ghost}, {k, pocket.centre}, {cue, ghost}, true);
      break;
    case ShotKind::kBank:
      for (int rail = 0; rail < RailCount(table); ++rail) {
        const std::optional<Eigen::Vector2d> bounce = RailBounce(table, rail, k, pocket.centre, r);
        // A rail the pocket lies on is no bank: the rebound would run along it.
        if (!bounce || (bounce->head<2>() - pocket.centre).norm() < 4.0 * r) continue;
        const Eigen::Vector2d g = GhostBall(k, (*bounce - k).normalized(), r);
        add({ShotKind::kBank, rail, *bounce, g}, {k, *bounce, pocket.centre}, {cue, g}, true);
      }
      break;
    case ShotKind::kKick:
      for (int rail = 0; rail < RailCount(table); ++rail) {
        const std::optional<Eigen::Vector2d> bounce = RailBounce(table, rail, cue, ghost, r);
        if (!bounce) continue;
        add({ShotKind::kKick, rail, pocket.centre, *bounce}, {k, pocket.centre}, {cue, *bounce, ghost}, true);
      }
      break;
    case ShotKind::kCurve:
      for (double elevation : kCurveElevations) {
        for (double side : kCurveSides) {
          Route route{ShotKind::kCurve, -1, pocket.centre, ghost};
          route.elevation = elevation;
          route.tip_side = side * params.cue.max_tip_offset * r;
          add(route, {k, pocket.centre}, {}, false);
        }
      }
      break;
  }
  // Shortest first: the ball travels least, its errors grow least.
  const auto length = [&](const Candidate& c) {
    const Eigen::Vector2d ghost_of = GhostBall(k, (c.route.object_aim - k).normalized(), r);
    return (c.route.cue_aim - cue).norm() + (ghost_of - c.route.cue_aim).norm() +
           (c.route.object_aim - k).norm() + (pocket.centre - c.route.object_aim).norm();
  };
  std::stable_sort(out.begin(), out.end(), [&](const Candidate& a, const Candidate& b) {
    return length(a) < length(b);
  });
  return out;
}

double SmallerMargin(const PotPlan& p) { return std::min(p.margin_left_deg, p.margin_right_deg); }

// The request's own mistakes, before anything is simulated.
std::optional<Refusal> CheckRequest(const table::TableGeometry& table,
                                    const physics::ModelParameters& params,
                                    const std::vector<SceneBall>& balls, const PotRequest& request) {
  try {
    physics::ValidateParameters(params);
  } catch (const std::invalid_argument& e) {
    return Refusal{PotStatus::kInvalid, e.what()};
  }
  const auto has = [&](int id) {
    return std::any_of(balls.begin(), balls.end(), [id](const SceneBall& b) { return b.id == id; });
  };
  if (!has(0)) return Refusal{PotStatus::kInvalid, "there is no cue ball (id 0) on the table"};
  if (request.ball == 0) return Refusal{PotStatus::kNoSuchBall, "ball 0 is the cue ball"};
  if (!has(request.ball)) {
    return Refusal{PotStatus::kNoSuchBall, "there is no ball " + std::to_string(request.ball) + " on the table"};
  }
  if (!table.PocketNamed(request.pocket)) {
    std::string names;
    for (const table::Pocket& p : table.pockets) names += (names.empty() ? "" : ", ") + p.name;
    return Refusal{PotStatus::kNoSuchPocket, "no pocket '" + request.pocket + "' on " + table.name +
                                                 (names.empty() ? " (it has none)" : " (" + names + ")")};
  }
  if (request.cue_target) {
    const CueTarget& t = *request.cue_target;
    if (!t.point.allFinite() || !std::isfinite(t.radius) || t.radius < 0.0) {
      return Refusal{PotStatus::kInvalid, "the cue-ball target must be finite, its radius >= 0"};
    }
    if (!table.OnSurface(t.point, params.ball.radius)) {
      return Refusal{PotStatus::kTargetUnreachable, "the cue-ball target is off the playing surface"};
    }
  }
  try {
    table::ValidateScene(table, params.ball.radius, balls);
  } catch (const std::invalid_argument& e) {
    return Refusal{PotStatus::kInvalid, e.what()};
  }
  return std::nullopt;
}

// The order refusals are told in when every route fails: the one that got furthest.
int Rank(PotStatus s) {
  switch (s) {
    case PotStatus::kTargetUnreachable: return 4;
    case PotStatus::kNoStroke: return 3;
    case PotStatus::kTooThin: return 2;
    default: return 1;
  }
}

}  // namespace

PotPlan PlanPot(const table::TableGeometry& table, const physics::ModelParameters& params,
                const std::vector<SceneBall>& balls, const PotRequest& request,
                const PotOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  PotPlan plan;
  plan.ball = request.ball;
  plan.pocket = request.pocket;
  const auto finish = [&](PotPlan p, int simulations) {
    p.ball = request.ball;
    p.pocket = request.pocket;
    p.simulations = simulations;
    p.solve_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    return p;
  };
  std::vector<SceneBall> settled = balls;
  if (options.settle_overlap > 0.0) {
    try {
      settled = table::SettledScene(table, params.ball.radius, balls, options.settle_overlap);
    } catch (const std::invalid_argument&) {
      // CheckRequest says what is wrong with the scene as it was given.
    }
  }
  if (std::optional<Refusal> bad = CheckRequest(table, params, settled, request)) {
    plan.status = bad->status;
    plan.reason = bad->reason;
    return finish(plan, 0);
  }
  const table::Pocket& pocket = *table.PocketNamed(request.pocket);
  PotSearch search(table, params, settled, request.ball, pocket, options, request.cue_target);

  std::vector<ShotKind> kinds = {ShotKind::kDirect, ShotKind::kBank, ShotKind::kKick, ShotKind::kCurve};
  if (request.kind) kinds = {*request.kind};
  std::optional<PotPlan> best;
  std::optional<Refusal> worst;
  std::vector<std::string> tried;
  int alternatives = 0;
  std::string direct_blocked;
  bool direct_object_closed = false;
  const auto refused = [&](const Refusal& r, const Route& route) {
    if (route.kind == ShotKind::kDirect) {
      direct_blocked = r.reason;
      direct_object_closed = r.object_route_closed;
    }
    if (!worst || Rank(r.status) > Rank(worst->status)) worst = r;
    std::string label = ShotKindName(route.kind);
    if (route.rail >= 0) label += " off rail " + std::to_string(route.rail);
    tried.push_back(label + ": " + r.reason);
  };
  const auto attempt = [&](const Route& route, bool place_cue) -> std::variant<PotPlan, Refusal> {
    try {
      return search.Plan(route, place_cue);
    } catch (const std::exception& e) {  // a stroke no cue gives, a scene out of events
      return Refusal{PotStatus::kNoStroke, e.what()};
    }
  };
  for (ShotKind kind : kinds) {
    // A curve is for a cue ball's line that is blocked (or too thin) when no bank or kick plans,
    // and K's own route is open; asked for, it is tried anyway.
    if (kind == ShotKind::kCurve && !request.kind &&
        (direct_blocked.empty() || direct_object_closed || best)) {
      continue;
    }
    std::vector<std::pair<PotPlan, Route>> planned;
    int searched = 0;
    for (const Candidate& c : Routes(kind, table, params, search.balls(), request.ball, pocket)) {
      // Of a bank, a kick or a curve, the shortest route that plans, of the kRoutesSearched
      // shortest whose lines are clear (each costs a search).
      if (kind != ShotKind::kDirect && !planned.empty() && !request.cue_target) break;
      if (kind != ShotKind::kCurve && c.blocked.empty() && ++searched > kRoutesSearched) {
        refused(Refusal{PotStatus::kBlocked, "longer than the " + std::to_string(kRoutesSearched) +
                                                 " shortest routes of its kind, not searched"}, c.route);
        continue;
      }
      const std::variant<PotPlan, Refusal> result =
          c.blocked.empty() ? attempt(c.route, false) : Refusal{PotStatus::kBlocked, c.blocked};
      if (const auto* p = std::get_if<PotPlan>(&result)) {
        planned.emplace_back(*p, c.route);
      } else {
        refused(std::get<Refusal>(result), c.route);
      }
    }
    std::sort(planned.begin(), planned.end(), [](const auto& a, const auto& b) {
      return SmallerMargin(a.first) > SmallerMargin(b.first);
    });
    alternatives += static_cast<int>(planned.size());
    if (!request.cue_target) {
      if (!planned.empty() && (!best || SmallerMargin(planned.front().first) > SmallerMargin(*best))) {
        best = planned.front().first;
      }
    } else {
      // Position play on the widest of this kind's pots first: it costs a search of its own.
      for (std::size_t i = 0; i < planned.size() && i < kPositionRoutes && !best; ++i) {
        const std::variant<PotPlan, Refusal> placed = attempt(planned[i].second, true);
        if (const auto* p = std::get_if<PotPlan>(&placed)) {
          best = *p;
        } else {
          refused(std::get<Refusal>(placed), planned[i].second);
        }
      }
    }
    // The direct pot, when it plans, is the shot: the others are for a blocked line.
    if (kind == ShotKind::kDirect && best) break;
    if (request.cue_target && best) break;
  }
  if (!best) {
    plan.status = worst ? worst->status : PotStatus::kBlocked;
    if (worst && worst->status == PotStatus::kBlocked && kinds.size() > 1) {
      plan.reason = "every kind tried: ";
    }
    std::string all;
    for (const std::string& t : tried) all += (all.empty() ? "" : "; ") + t;
    plan.reason += kinds.size() > 1 || tried.size() > 1 ? all : (worst ? worst->reason : all);
    return finish(plan, search.simulations());
  }
  std::ostringstream why;
  why.precision(3);
  if (best->kind == ShotKind::kDirect) {
    why << "direct: the straight lines are clear";
  } else {
    why << ShotKindName(best->kind);
    if (best->rail >= 0) why << " off rail " << best->rail;
    why << ": the widest margin (" << SmallerMargin(*best) << " deg) of " << alternatives << " plan"
        << (alternatives > 1 ? "s" : "");
    if (!direct_blocked.empty() && !request.kind) why << "; direct: " << direct_blocked;
  }
  best->why = why.str();
  return finish(*best, search.simulations());
}

namespace {

const table::Pocket& PocketOf(const table::TableGeometry& table, const std::string& name) {
  const table::Pocket* p = table.PocketNamed(name);
  if (!p) throw std::invalid_argument("no pocket '" + name + "'");
  return *p;
}

}  // namespace

std::optional<double> GhostBallHeading(const table::TableGeometry& table,
                                       const physics::ModelParameters& params,
                                       const std::vector<SceneBall>& balls, const PotPlan& plan,
                                       const PotOptions& options) {
  PotSearch search(table, params, balls, plan.ball, PocketOf(table, plan.pocket), options);
  return search.GhostHeading(plan);
}

PotOutcome PlayStroke(const table::TableGeometry& table, const physics::ModelParameters& params,
                      const std::vector<SceneBall>& balls, int ball, const std::string& pocket,
                      const CueStroke& stroke, const PotOptions& options) {
  PotSearch search(table, params, balls, ball, PocketOf(table, pocket), options);
  return search.Play(stroke, true).outcome;
}

const char* ShotKindName(ShotKind kind) {
  switch (kind) {
    case ShotKind::kDirect: return "direct";
    case ShotKind::kBank: return "bank";
    case ShotKind::kKick: return "kick";
    case ShotKind::kCurve: return "curve";
  }
  return "direct";
}

std::optional<ShotKind> ParseShotKind(const std::string& name, bool* known) {
  *known = true;
  for (ShotKind k : {ShotKind::kDirect, ShotKind::kBank, ShotKind::kKick, ShotKind::kCurve}) {
    if (name == ShotKindName(k)) return k;
  }
  *known = name == "any";
  return std::nullopt;
}

const char* PotStatusName(PotStatus status) {
  switch (status) {
    case PotStatus::kOk: return "ok";
    case PotStatus::kInvalid: return "invalid";
    case PotStatus::kNoSuchBall: return "no_such_ball";
    case PotStatus::kNoSuchPocket: return "no_such_pocket";
    case PotStatus::kBlocked: return "blocked";
    case PotStatus::kTooThin: return "too_thin";
    case PotStatus::kNoStroke: return "no_stroke";
    case PotStatus::kTargetUnreachable: return "target_unreachable";
  }
  return "invalid";
}

}  // namespace billiard::pot
