// The planner node: answers every SHOT_REQUEST with a CUE_COMMAND planned from the latest
// TABLE_STATE: one ball to a point (MODE_TO_POINT, to_point_request.h), a pot (MODE_POT,
// pot_request.h), the pot it chooses to play (MODE_CHOOSE, choose_request.h; the player the
// request names decides, each made once and kept) or a game's break (MODE_BREAK,
// break_request.h). This is its
// message loop: the table states kept, the requests queued and answered, the ball each names
// (named_ball.h), a repeated request answered from memory, its health on NODE_STATUS.
//
//   TABLE_STATE   table_state_t    keeps the latest state received of each ball_id (a message
//                                  naming some balls leaves the others as they were)
//   SHOT_REQUEST  shot_request_t   one cue_command_t per request, ok or refused
//   CUE_COMMAND   cue_command_t    utime, request_id and ball_id of the request
//
// The answer depends only on the messages received, never on the clock: its utime is the
// request's, so a logged run replays to the same commands (all but solve_us, the planning wall
// time the message carries by design).
//
// Refusals (status != STATUS_OK, the reason in words, the stroke fields zero; the plan fields say
// what the planner measured, zero when it did not run):
//   STATUS_INVALID        a request that fails messages::Check (an unknown spin value, a
//                         non-finite number, ...)
//   STATUS_NOT_AT_REST    the table did not come to rest within max_rest_wait (below), or the
//                         ball's own latest state moving
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
//   STATUS_INVALID        also a pot among balls that overlap or lie off the table
//   the others            PlanShot's status (shot_planner.h) or PlanPot's (no_such_pocket,
//                         blocked, too_thin, no_stroke, target_unreachable; pot_planner.h)
//
// The table at rest: a request is planned only when every ball of the latest rest_states table
// states is slower than max_ball_speed (PlannerNodeOptions; a table never seen moving is at rest).
// Until then the oldest request is held, unanswered, and the others wait behind it: a loop whose
// estimator lags behind its frames (a busy machine) asks while the states still show the last
// shot's balls rolling, and the states at rest come soon after. A request held max_rest_wait (in
// the states' time past its own, or on the node's clock once no state has come for that long
// since it arrived: the states stopped) is refused STATUS_NOT_AT_REST with the ball still
// moving: the one answer that depends on the clock, and only when the states stop coming (a
// loop slower than real time waits in the states' time, so that its log replays bit for bit).
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
// Noise learning (PlannerNodeOptions::learn_noise): the same shots, each launch measured against
// its stroke before the next plan (noise_learning.h); the choice plans for the noise learned,
// which is logged and on NODE_STATUS (learned_noise_launches, learned_heading_udeg,
// learned_speed_ppm, learned_tip_um).
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
#include "planner/node/noise_learning.h"
#include "planner/node/planner_node_options.h"
#include "planner/players/player.h"
#include "sim/batch/thread_pool.h"
#include "sim/physics/parameters.h"
#include "sim/shot_fit/shot_recorder.h"
#include "sim/table/table_geometry.h"

namespace billiard::planner_node {

// At most this many balls are remembered; beyond it the longest unseen is forgotten.
inline constexpr std::size_t kMaxRememberedBalls = 256;
// The shots an online identification is fitted to: the latest so many.
inline constexpr std::size_t kIdentifyWindow = 40;
// Answers remembered for requests sent again.
inline constexpr std::size_t kRememberedAnswers = 64;

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
  // whether more requests can be planned now (false while the oldest is held for the table to
  // come to rest). The node's main loop calls it between messages (nodes::HandleUntilStopped).
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
  // Whether the node cuts its own shots (for identification or noise learning).
  bool RecordsShots() const { return options_.identify_every > 0 || options_.learn_noise; }
  // When identify_every more shots have closed since the last fit, fits the constants to the
  // latest shots and plans with them.
  void IdentifyIfDue();
  // With learn_noise, measures the shots closed since the last time and fits the noise again.
  void LearnNoiseIfDue();

  std::optional<Unfit> UnfitToPlanFrom(const shot_request_t& q, const ball_state_t& s) const;

  // Why the table is not at rest yet (a ball of the latest state moving, or at rest for fewer
  // than rest_states states); empty when it is, or when no state has come.
  std::string TableNotAtRest() const;
  // Whether `w`, held for the table, has waited max_rest_wait: in the table states' time past
  // its request's, or on the node's clock with no state coming since it arrived.
  bool WaitedForRestTooLong(const Waiting& w) const;
  // Answers the oldest waiting request: planned, or refused not_at_rest for `not_at_rest`.
  void AnswerOldest(const std::string& not_at_rest);
  // Counts the table state `state` toward the table at rest (states_at_rest_, last_motion_).
  void NoteMotion(const table_state_t& state);

  // Who decides a MODE_CHOOSE request: the player it names (made by name at its first request
  // and kept, players::MakePlayer), the node's own (options_.player) when it names none; throws
  // std::invalid_argument for a name no player has.
  const players::Player& PlayerFor(const shot_request_t& q) const;

  // The balls of the latest table state, none before the first.
  std::vector<const ball_state_t*> OnTable() const;
  // The balls a request's balls are looked for among: a pot's, a choice's or a break's, the
  // latest table state's; a point request's, the latest state of every ball.
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
  nodes::NodeHealth::Clock::time_point latest_table_arrival_;  // on the node's clock
  // Table states in a row with every ball at rest (counted up to rest_states, which a table never
  // seen moving starts at), and the latest moving ball seen, for the reason.
  int states_at_rest_;
  std::string last_motion_;
  bool holding_ = false;  // the oldest request is held for the table (logged once)
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
  std::unique_ptr<players::Player> player_;                 // who chooses (options_.player)
  // The players requests named (a match's two), by name, made at their first request.
  mutable std::map<std::string, std::unique_ptr<players::Player>> players_;
  NoiseLearner noise_learner_;                              // options_.learn_noise
  static constexpr double kLongestShot = 60.0;              // [s]
  static constexpr double kShotThinning = 0.002;            // [m], as the real recordings
  lcm::Subscription* table_state_subscription_ = nullptr;
  lcm::Subscription* shot_request_subscription_ = nullptr;
};

}  // namespace billiard::planner_node
