// Every ball on the table, event by event.
//
// Between events each ball moves in closed form (`sim/table/ball_motion.h`: sliding, rolling,
// spinning, at rest, in the air; its centre on a parabola), so the next event of every kind is the first
// root of a polynomial in time, found exactly (`sim/table/polynomial_roots.h`):
//  - ball-ball: |p_a(t) - p_b(t)|^2 = (2 r)^2, a quartic;
//  - ball-cushion: the centre at distance r from a cushion's nose line (a quadratic) or at
//    r + rho from a jaw's rounded nose of radius rho (a quartic);
//  - ball-pocket: the centre crossing a pocket's capture line (a quadratic);
//  - each ball's phase transitions, in closed form.
// A root counts only where the distance is closing, so balls touching and parting (a rack, a
// ball leaving a cushion) are no event; touching and closing is an event at once (frozen balls,
// Newton's cradle: one impact after another at the same time, in a fixed order). Bodies that
// close by their accelerations alone, or slower than an impact, are held in contact with the
// forces that keep them from closing (`sim/table/held_contacts.h`), not met as a run of tiny
// impacts; a ball that moves along a cushion it touches, pressed to it or not, is a state like
// any other. The simulation
// jumps from event to event, resolves it (`ball_collision.h`, `cushion_impact.h`) and recomputes
// only the next events of the balls it changed. Ties go to the lower ball index and the event
// kinds in the order transitions, balls, cushions, pockets: the same scene gives the same events,
// bit for bit.
//
// A ball off the cloth (SceneBall::flight: an elevated cue's hop, `sim/physics/hop.h`) flies
// straight until it lands, a transition (the bed's impulse, then the next bounce or the cloth).
// Its impacts in the air keep its flight: with another ball they are taken in the plane (the
// line of centres of a ball h above the cloth is asin(h / 2r) out of it, sim/cue/stroke_limits.h
// says how high that holds); a cushion's nose meets it lower on the ball, by its height.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "sim/physics/ball_state.h"
#include "sim/physics/parameters.h"
#include "sim/physics/simulator.h"
#include "sim/table/ball_motion.h"
#include "sim/table/cushion_impact.h"
#include "sim/table/scene.h"
#include "sim/table/scene_validation.h"
#include "sim/table/table_geometry.h"

namespace billiard::table {

// kBallPush: touching bodies pressed together by their accelerations (a ball pushed by another
// or by its own spin into a cushion, a cluster pushed as one) held in contact, their contact
// forces solved (`sim/table/held_contacts.h`); one such event each time a cluster's forces are
// solved again (a held motion ends, or an impact or a pocket takes a ball from it).
enum class EventType { kTransition, kBallBall, kBallCushion, kBallJaw, kBallPocket, kBallPush };

// "transition", "ball_ball", "ball_cushion", "ball_jaw", "ball_pocket", "ball_push".
const char* EventTypeName(EventType type);

struct TableEvent {
  double time = 0.0;
  EventType type = EventType::kTransition;
  int ball = -1;       // the ball's id
  int other = -1;      // ball_ball: the other ball's id
  int cushion = -1;    // ball_cushion: index of TableGeometry::lines; ball_jaw: of points
  std::string pocket;  // ball_pocket: the pocket's name
  MotionPhase from = MotionPhase::kStationary, to = MotionPhase::kStationary;  // transition
  double impulse = 0.0;  // the normal impulse of an impact [N s]
};

// The id of the first ball that ball `id` meets in `events` (a kBallBall event), -1 if none:
// what a stroke's legality turns on.
int FirstBallMet(const std::vector<TableEvent>& events, int id);

// Whether `e` settles FirstBallMet for ball `id`: it meets a ball, or drops (nothing later
// changes what it met first). What a search that asks only the first contact runs a table until.
bool SettlesFirstBallMet(const TableEvent& e, int id);

struct TableSimulationOptions {
  CushionModel cushion_model = CushionModel::kMathavan2010;
  // kMathavan2010's steps per approach momentum (ResolveCushionImpact): fewer for a search that
  // the default checks.
  double mathavan_steps = kMathavanSteps;
  // How a ball moves between events, asked whenever a moving ball starts a new motion, from its
  // state: the 5-DOF model with the options returned, or the closed form (std::nullopt; always,
  // when this is empty).
  std::function<std::optional<physics::SimulationOptions>(const physics::BallState&)> five_dof;
  // A scene that needs more events than this is refused (std::runtime_error): a break takes a
  // few hundred.
  std::int64_t max_events = 1000000;
};

class TableSimulation {
 public:
  // Throws std::invalid_argument, naming the ball, for an invalid scene (ValidateScene).
  TableSimulation(const TableGeometry& table, const physics::ModelParameters& params,
                  const std::vector<SceneBall>& balls, const TableSimulationOptions& options = {});

  // Runs the events up to time t_end (infinite: until every ball rests or is pocketed).
  void Run(double t_end = std::numeric_limits<double>::infinity());
  // The same, stopping at the first event for which `stop` is true (time() is then that event's):
  // what a planner asks when only the start of a shot matters (the first contact, a ball's drop).
  // Returns whether it stopped there; Run or RunUntil goes on from there.
  bool RunUntil(const std::function<bool(const TableEvent&)>& stop,
                double t_end = std::numeric_limits<double>::infinity());

  double time() const { return time_; }
  bool AtRest() const;
  const std::vector<TableEvent>& events() const { return events_; }
  std::size_t ball_count() const { return balls_.size(); }
  int id(std::size_t i) const { return balls_[i].id; }
  // The state of ball i at time t, 0 <= t <= time() (a pocketed ball: where it dropped, at rest).
  physics::BallState StateAt(std::size_t i, double t) const;
  physics::BallState State(std::size_t i) const { return StateAt(i, time_); }
  // The pocket ball i dropped into by time(), if any.
  const std::optional<std::string>& pocket(std::size_t i) const { return balls_[i].pocket; }
  // The motion segments of ball i so far, in time order.
  const std::vector<MotionSegment>& segments(std::size_t i) const { return balls_[i].segments; }

 private:
  struct Ball {
    int id;
    std::vector<MotionSegment> segments;  // the last one is the current motion
    std::optional<std::string> pocket;    // dropped: its last segment starts at the drop
  };
  struct Candidate {  // the next event of one kind for one ball or pair
    double time = std::numeric_limits<double>::infinity();
    EventType type = EventType::kTransition;
    int index = -1;  // cushion line, jaw point or pocket
    // No event: a search by advancement that spent its steps; it goes on from `time`.
    bool resume = false;
  };

  // A 5-DOF motion, or a held one, runs until the ball rests or this long, then starts again.
  static constexpr double kFiveDofHorizon = 60.0;  // [s]

  const MotionSegment& Current(std::size_t i) const { return balls_[i].segments.back(); }
  bool Active(std::size_t i) const { return !balls_[i].pocket; }
  std::size_t PairIndex(std::size_t i, std::size_t j) const;

  void Recompute(std::size_t i);
  Candidate NextBallBall(std::size_t i, std::size_t j) const;
  Candidate NextBoundary(std::size_t i) const;
  // The same for a ball or pair that moves by the 5-DOF model: by conservative advancement.
  Candidate BallBallByAdvancement(std::size_t i, std::size_t j) const;
  Candidate BoundaryByAdvancement(std::size_t i) const;
  void Apply(const TableEvent& event, std::size_t i, std::size_t j, int index);
  // Ball i's next motion from `state`, off the cloth where `flight` is airborne.
  void StartSegment(std::size_t i, const physics::BallState& state,
                    const physics::Flight& flight = {});
  // Solves the contact forces of the balls touching `seeds` (transitively) and of the cushions
  // they touch, and starts the motions they give; returns the balls whose motion changed.
  std::vector<std::size_t> ResolveHeld(const std::vector<std::size_t>& seeds);
  // The balls touching ball i whose motions are held ones.
  std::vector<std::size_t> HeldNeighbours(std::size_t i) const;
  double Gap(std::size_t i, std::size_t j) const;  // between the surfaces, now
  // Ball state `s` after meeting the cushion of inward `normal`, its centre `height` above its
  // place on the cloth; its normal impulse in `*impulse`.
  physics::BallState CushionImpact(const physics::BallState& s, const Eigen::Vector2d& normal,
                                   double height, double* impulse) const;

  TableGeometry table_;
  physics::ModelParameters params_;
  ClothParameters cloth_;
  TableSimulationOptions options_;
  std::vector<Ball> balls_;
  double time_ = 0.0;
  std::vector<TableEvent> events_;
  std::vector<Candidate> boundary_;  // per ball: cushion, jaw or pocket
  std::vector<Candidate> pair_;      // per pair i < j: the next ball-ball contact
  std::vector<double> last_impact_;  // per pair i < j: the time of its last impact
};

// The motion `--model auto` gives a ball on the table, phase by phase: the closed form while it
// rolls with little side spin (slip below 1e-3 m/s, |wz| below 20 rad/s: rolling 7 m at 1 m/s
// with 20 rad/s of side spin, the 5-DOF path bends by 0.9 mm, at 5 rad/s by 0.05 mm; measured
// with `billiard simulate`), the 5-DOF model with `options` otherwise: while it slides (the
// point contact has no rolling resistance during the slide, a few centimetres over a shot) and
// while its side spin curves it.
std::optional<physics::SimulationOptions> FiveDofWhereNeeded(
    const physics::BallState& state, const physics::ModelParameters& params,
    const physics::SimulationOptions& options);

}  // namespace billiard::table
