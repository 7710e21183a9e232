// The planner node: answers every SHOT_REQUEST with a CUE_COMMAND planned from the latest
// TABLE_STATE: one ball to a point (MODE_TO_POINT, shot_planner.h), a pot (MODE_POT,
// planner/pot/pot_planner.h) or the pot it chooses to play (MODE_CHOOSE,
// planner/choice/shot_choice.h).
//
//   TABLE_STATE   table_state_t    keeps the latest state received of each ball_id (a message
//                                  naming some balls leaves the others as they were)
//   SHOT_REQUEST  shot_request_t   one cue_command_t per request, ok or refused
//   CUE_COMMAND   cue_command_t    utime, request_id and ball_id of the request
//
// A pot is planned on the node's table (PlannerNodeOptions::table) among the balls of the latest
// TABLE_STATE, every ball its publisher knows of (one it no longer names is gone: pocketed, or
// lost by the estimator), each at rest where it was seen; the cue ball and the object ball are
// looked for there. The struck ball is the cue ball (id 0
// of pot::PlanPot's scene, whatever the estimator calls it); the answer names the balls, in
// object_ball_id and the paths, by the table state's ids.
//
// The answer depends only on the messages received, never on the clock: its utime is the
// request's, so a logged run replays to the same commands (all but solve_us, the planning wall
// time the message carries by design).
//
// A choice (MODE_CHOOSE) is made among the balls of the latest TABLE_STATE as a pot is, on the
// node's table, under the request's rules, with ball in hand when the request says so (the cue
// ball lifted and placed: the answer's cue_placement). The balls are named by the estimator's
// classes (BallNumbers: the rules need the numbers) and the answer names them back by the table
// state's ids. Its noise samples are seeded by PlannerNodeOptions::choice.seed and the
// request_id, so that a logged run replays to the same choice. An object ball seen further
// over a pocket's mouth (or into a cushion) than pot.settle_overlap is taken for dropping and
// left out. When no pot plans, the answer is
// ok with object_ball_id -1 and the choice's fallback stroke (the first legal ball hit full).
//
// Refusals (status != STATUS_OK, the reason in words, the stroke fields zero; the plan fields say
// what the planner measured, zero when it did not run):
//   STATUS_INVALID        a request that fails messages::Check (an unknown spin value, a
//                         non-finite number, ...), a ball moving faster than max_ball_speed
//   STATUS_NO_BALL_STATE  no table state received has that ball_id
//   STATUS_STALE_STATE    the ball's latest state and the request are further apart in time than
//                         max_state_age: the estimator may have stopped and the ball moved since,
//                         so the planner does not act on it
//   STATUS_BUSY           the queue of requests waiting to be planned was full
//   STATUS_NOT_CONVERGED  also when the planner throws (an integrator giving up): the request
//                         gets an answer all the same
//   STATUS_OFF_TABLE      also a pot's cue-ball target off the table's playing surface
//   STATUS_NO_SUCH_BALL   a pot's object ball is not in the latest table state (by id, or by
//                         class at kMinClassConfidence), or is the struck ball; a choice's
//                         table state has no object ball
//   STATUS_INVALID        also a pot among balls that overlap or lie off the table, or with any
//                         of them moving faster than max_ball_speed
//   the others            PlanShot's status (shot_planner.h) or PlanPot's (no_such_pocket,
//                         blocked, too_thin, no_stroke, target_unreachable; pot_planner.h)
//
// Requests wait in a bounded queue and are planned one at a time by Work(), so a burst of them
// costs bounded memory and each gets an answer: planned, or refused busy at once. A request
// identical to one answered before, for a ball whose state has not changed since, gets the same
// answer again without planning (a sender retrying after a lost answer).
//
// Table states: one that fails messages::Check is dropped, and so is one older than the latest
// (a late or reordered message), unless the publisher has started a new clock (message_clock.h):
// then what the node knew of the old one is forgotten.
//
// Online identification (PlannerNodeOptions::identify_every): the node cuts its own shots as
// `billiard identify` cuts a log (sim/shot_fit/shot_recorder.h): each ok answer a strike of its
// ball, the table states the shot's samples, the shot closed when the next request is planned
// (the balls at rest by then). The fit runs there, before that plan, so the answers still depend
// on the messages alone; each one is logged, counted ("identified") and announced on
// NODE_STATUS, whose parameter set is then "<set>-identified" with its own hash.
//
// A node never dies on a message: a payload that does not decode is logged and dropped, and every
// handler catches what it throws. Counts and latencies go out on NODE_STATUS (node_health.h).
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <lcm/lcm-cpp.hpp>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "lcmtypes/billiard/ball_state_t.hpp"
#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/shot_request_t.hpp"
#include "lcmtypes/billiard/table_state_t.hpp"
#include "lcmtypes/node/message_clock.h"
#include "lcmtypes/node/node_health.h"
#include "planner/choice/shot_choice.h"
#include "planner/pot/pot_planner.h"
#include "planner/shot_planner.h"
#include "sim/batch/thread_pool.h"
#include "sim/physics/parameters.h"
#include "sim/shot_fit/shot_fit.h"
#include "sim/shot_fit/shot_recorder.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::planner_node {

struct PlannerNodeOptions {
  planner::PlannerOptions planner;
  // A ball faster than this [m/s] is still moving: a plan from where it is now would start from
  // the wrong place, so the request is refused. The default is above an estimator's noise on a
  // ball at rest and below any ball that will roll on for more than a few millimetres.
  double max_ball_speed = 0.05;
  // The most a ball's state and a request may be apart in time [s] (their utimes).
  double max_state_age = 1.0;
  // Requests waiting to be planned; more are answered STATUS_BUSY.
  int queue_capacity = 32;
  // The table pots are planned on (its cushions and pockets); kDefaultPotTable when not given.
  std::optional<table::TableGeometry> table;
  pot::PotOptions pot = CameraPotOptions();
  // Online identification of the table (0: off): after every `identify_every` shots the node
  // commanded and saw tracked, the constants `identify` are fitted jointly to its latest
  // kIdentifyWindow shots (sim/shot_fit/shot_fit.h, from the constants it plans with) and its
  // plans use them from then on; what the shots do not excite is kept.
  int identify_every = 0;
  std::vector<shot_fit::Constant> identify = {shot_fit::Constant::kMu,
                                              shot_fit::Constant::kRolling};
  // MODE_CHOOSE: the choice's samples, noise (the robot's, the table simulator's own) and seed;
  // its rules and pot options are the request's and `pot`.
  choice::ChoiceOptions choice;
  int choice_threads = batch::DefaultThreadCount();

  // Pots are planned on what the camera saw: touching balls measured a fraction of a millimetre
  // into each other (or into a cushion) are settled apart first (pot::PotOptions::settle_overlap),
  // by up to 2 mm, some four times the estimator's position error.
  static pot::PotOptions CameraPotOptions() {
    pot::PotOptions o;
    o.settle_overlap = 2e-3;
    return o;
  }
};

// The table of a node started without one: the table of the default parameter set's size.
inline constexpr char kDefaultPotTable[] = "pool-9ft";

// At most this many balls are remembered; beyond it the longest unseen is forgotten.
inline constexpr std::size_t kMaxRememberedBalls = 256;
// The shots an online identification is fitted to: the latest so many.
inline constexpr std::size_t kIdentifyWindow = 40;
// Answers remembered for requests sent again.
inline constexpr std::size_t kRememberedAnswers = 64;
// The pool numbers a choice knows the balls of `table` by, by their table state ids: the cue ball
// `cue` 0; every other ball the number (1-15) its class names at kMinClassConfidence or more, the
// surer (then the lower id) when two claim one; then, of the numbers left, those named by less
// confident classes, as surely; the rest take the numbers no ball claims (a rack has one of
// each), ascending, in the order of their ids, and 16 up when those run out.
std::unordered_map<int32_t, int> BallNumbers(const table_state_t& table, int32_t cue);

// A ball asked for by class (shot_request_t::BALL_BY_CLASS) must be of that class with at least
// this confidence: an even guess between two classes is no ball to strike.
inline constexpr float kMinClassConfidence = 0.5f;

class PlannerNode {
 public:
  using Log = std::function<void(const std::string& line)>;

  // Subscribes on `lcm`, which must outlive the node; `log` gets one line per event (stderr by
  // default). Nothing is planned until Work() is called.
  PlannerNode(lcm::LCM& lcm, physics::ModelParameters params, PlannerNodeOptions options = {},
              Log log = nullptr);
  ~PlannerNode();  // unsubscribes
  PlannerNode(const PlannerNode&) = delete;
  PlannerNode& operator=(const PlannerNode&) = delete;

  // The answer to `request` from the states received so far: what the node publishes.
  cue_command_t Answer(const shot_request_t& request) const;

  // Plans the oldest waiting request and publishes its answer, and NODE_STATUS when due. Returns
  // whether more requests wait. The node's main loop calls it between messages
  // (nodes::HandleUntilStopped).
  bool Work();

  // The node's counters; TakeStatus() on it starts a new latency period.
  nodes::NodeHealth& health() { return health_; }

 private:
  using Bytes = std::vector<std::uint8_t>;
  struct Waiting {
    shot_request_t request;
    Bytes bytes;
    nodes::NodeHealth::Clock::time_point arrived;
  };
  struct Answered {
    Bytes request;
    std::int64_t state_utime;  // of the ball's state the answer came from, -1 if none
    cue_command_t command;
  };

  // Why the ball's latest state is no start for a plan (stale, or the ball still moving).
  struct Unfit {
    int8_t status;
    std::string reason;
  };
  // Closes the shot in progress and, when identify_every more have closed since the last fit,
  // fits the constants to the latest shots and plans with them.
  void IdentifyIfDue();

  std::optional<Unfit> UnfitToPlanFrom(const shot_request_t& q, const ball_state_t& s) const;

  // The pot of a checked MODE_POT request, struck at `cue` (whose state is fit to plan from),
  // into `c` (the reply with the cue ball's id and start).
  cue_command_t AnswerPot(const shot_request_t& q, const ball_state_t& cue, cue_command_t c) const;
  // The choice of a checked MODE_CHOOSE request, the cue ball `cue`, into `c`.
  cue_command_t AnswerChoice(const shot_request_t& q, const ball_state_t& cue,
                             cue_command_t c) const;
  // The balls of the latest table state at rest, the one of `cue_track` id 0 and the others by
  // `scene_id` (their message ids kept in `message_id`); nullopt and `moving` set when a ball
  // moves faster than max_ball_speed.
  std::optional<std::vector<table::SceneBall>> SceneAtRest(
      int32_t cue_track, const std::function<int(int32_t)>& scene_id,
      std::unordered_map<int, int32_t>* message_id, std::string* moving) const;
  // The pot's object ball, by id or by class; nullptr when there is none.
  const ball_state_t* ObjectBallFor(const shot_request_t& q) const;
  // The balls a request's balls are looked for among: a pot's, the latest table state's; a
  // point request's, the latest state of every ball.
  std::vector<const ball_state_t*> Candidates(const shot_request_t& q) const;

  // Raw handlers: the node decodes the payload itself so that a failure is logged its way.
  void OnTableState(const lcm::ReceiveBuffer* rbuf, const std::string& channel);
  void OnShotRequest(const lcm::ReceiveBuffer* rbuf, const std::string& channel);

  lcm::LCM& lcm_;
  physics::ModelParameters params_;  // changed only by IdentifyIfDue
  const PlannerNodeOptions options_;
  const table::TableGeometry table_;
  void Publish(const cue_command_t& command, nodes::NodeHealth::Clock::time_point arrived);
  // The ball a request strikes: by its id, or by class the one of the latest table state the
  // estimator is surest of (at least kMinClassConfidence; a choice's cue ball at any confidence,
  // a rack having one, and when none has the class, the ball it was last given to if it is still
  // seen); nullptr when there is none.
  const ball_state_t* BallFor(const shot_request_t& q) const;
  // The utime of that ball's latest state (a pot's: of the latest table state, which its answer
  // depends on), -1 if none.
  std::int64_t StateUtime(const shot_request_t& q) const;

  const Log log_;
  nodes::NodeHealth health_;
  std::unordered_map<int32_t, ball_state_t> balls_;
  std::optional<table_state_t> latest_table_;
  // The ball each class was last given to (the surest of it in the latest table state naming
  // one): a choice's cue ball when the estimator names none for a while.
  std::map<int8_t, int32_t> last_of_class_;
  nodes::MessageClock state_clock_;
  std::deque<Waiting> waiting_;
  std::deque<Answered> answered_;
  bool refusing_busy_ = false;
  shot_fit::ShotRecorder shots_{kLongestShot, kShotThinning};
  std::size_t identified_shots_ = 0;  // closed shots at the latest fit
  std::unique_ptr<batch::ThreadPool> fit_pool_;
  mutable std::unique_ptr<batch::ThreadPool> choice_pool_;  // made at the first choice
  static constexpr double kLongestShot = 60.0;     // [s]
  static constexpr double kShotThinning = 0.002;   // [m], as the real recordings
  lcm::Subscription* table_state_subscription_ = nullptr;
  lcm::Subscription* shot_request_subscription_ = nullptr;
};

}  // namespace billiard::planner_node
