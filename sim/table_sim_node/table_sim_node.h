// The table simulator node: stands in for the robot and the camera, and drives a session of
// shots through the other two nodes.
//
// For each shot it shows the ball at rest to the camera (CAMERA_IMAGE frames rendered by
// table_renderer.h, JPEG) until the estimator reports it, asks the planner (SHOT_REQUEST) to send
// the ball estimated nearest the true one to a seeded random target, executes the CUE_COMMAND
// with the cue strike model (cue_strike.h, with optional execution noise on speed, heading and
// tip offset), simulates the 5-DOF ball until it rests, and publishes the truth (TABLE_TRUTH) and
// the frames all the way. The miss is the truth's final point against the target.
//
// Clocks: lockstep (each frame waits for the estimator's TABLE_STATE of that frame; as fast as
// the loop goes, and the same bytes every run) or real time (frames at the camera rate).
//
// Faults: the loop goes on when a node restarts. A frame or a request that gets no answer within
// retry_interval is sent again (the planner answers a repeated request from memory), and a
// refusal that time can cure (no state of the ball yet, a stale state, a busy planner, a table
// the planner never saw at rest) is retried after the ball has been shown again; in a game, a
// shot still refused not_at_rest played nothing and is neither a shot nor a visit. Fault injection makes the link to the nodes lossy on
// purpose: frames dropped, reordered or sent twice, requests sent twice, from a seeded generator
// of its own (the shots stay the same).
//
// The replies are decoded and checked (message_checks.h); only the latest of each is kept. Counts
// go out on NODE_STATUS (node_health.h), the first before the first frame with the clock among
// them (messages::kRealtimeClockSetting), so that a log of the session says how it was clocked.
//
// The class is implemented in four files, by the sessions it runs: table_sim_node.cc (the link
// to the nodes, the frames, the requests, the shots to random targets), scene_session.cc
// (RunScene), game_session.cc (RunGame) and match_session.cc (a match's racks). What a frame
// shows is truth_frame.h's, how a command is executed stroke_execution.h's, and a game shot's
// judgement the rules' (sim/rules/: nine-ball's and eight-ball's, the rulesets the planner's own
// games and matches are judged by).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <lcm/lcm-cpp.hpp>
#include <map>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/image_t.hpp"
#include "lcmtypes/billiard/node_status_t.hpp"
#include "lcmtypes/billiard/shot_request_t.hpp"
#include "lcmtypes/billiard/table_state_t.hpp"
#include "lcmtypes/node/node_health.h"
#include "sim/camera/camera_model.h"
#include "sim/params/execution_noise.h"
#include "sim/physics/ball_state.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/render/table_renderer.h"
#include "sim/rules/ruleset.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"
#include "sim/table/table_simulation.h"
#include "sim/table_sim_node/stroke_execution.h"
#include "sim/table_sim_node/truth_frame.h"

namespace billiard::table_sim_node {

// The robot's execution noise (sim/params/execution_noise.h): none unless asked for.
using ExecutionNoise = params::ExecutionNoise;

// What a lossy link between the table and the nodes does, each a probability per message.
struct FaultInjection {
  double drop_frames = 0.0;     // a frame is lost
  double reorder_frames = 0.0;  // a frame is held back and sent after the next one
  double duplicate = 0.0;       // a frame or a request is sent twice
  std::uint32_t seed = 7;
};

// A game's new rack is shown this many settle times before its first shot: longer than the
// estimator coasts the last rack's tracks (estimator::TrackerOptions::max_coast).
inline constexpr int kNewLayoutSettles = 4;

// A match's player by a name the planner knows no player by: the session's bad input.
struct UnknownPlayer : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// A pot to play in a whole-table session: ball `ball` (the truth's id) into pocket `pocket`.
struct PotShot {
  int ball = 0;
  std::string pocket;
};

struct TableSimOptions {
  int shots = 20;
  std::uint32_t seed = 1;
  ExecutionNoise noise;
  bool lockstep = true;
  double camera_rate = 30.0;    // frames per second [Hz]
  double settle_time = 0.3;     // frames shown of a ball at rest before a request [s]
  double reply_timeout = 10.0;  // longest wait for the estimator or the planner [s]
  double retry_interval = 0.5;  // a frame or a request unanswered this long is sent again [s]
  int max_retries = 3;          // retries of a shot refused for want of a (fresh) state
  FaultInjection faults;
  Eigen::Vector2d start{0.6, 0.635};  // where the ball starts [m]
  double target_margin = 0.15;        // targets at least this far inside the cushions [m]
  double min_distance = 0.3;          // and at least this far from the ball [m]
  // The spin style of shot k is spins[k % spins.size()] (shot_request_t's SPIN_ constants).
  std::vector<std::int8_t> spins{shot_request_t::SPIN_NATURAL};
  int jpeg_quality = 90;
  // A whole-table session instead of shots to random targets: "break" (the eight-ball rack of
  // `seed` on the pool-9ft table) or a scene file (sim/params/scene_file.h, every ball at rest).
  // The cue ball (id 0) is struck once, rolling, at the ball nearest it, which it meets at
  // break_speed.
  std::string scene;
  double break_speed = 5.0;  // [m/s]
  // With a scene, these pots in turn instead of the one strike: each asked of the planner
  // (shot_request_t::MODE_POT, the object ball the estimator's track nearest ball K, or K itself
  // when the scene has no ball K), executed with the noise and played out from where the last
  // left the balls.
  std::vector<PotShot> pots;
  // A game instead (RunGame): "nine-ball" (the nine-ball rack of seed + k broken by the cue
  // ball rolling into its apex at break_speed) or "drill" (table::SeededNineBallLayout of
  // seed + k, the cue ball in hand), for racks k = 0 .. racks - 1, each played under nine-ball
  // rules shot by shot (shot_request_t::MODE_CHOOSE) until it is cleared or shot_limit shots.
  std::string game;
  int racks = 1;
  int shot_limit = 40;
  // A match instead of one controller playing alone (RunGame's nine-ball or eight-ball): two
  // players by name (planner/players/players.h), each MODE_CHOOSE request naming whose turn it
  // is, the racks refereed by sim/rules' RackState (a miss or a foul hands the table to the
  // other, rack k broken by player k % 2 with the game's stored break, asked of the planner as
  // shot_request_t::MODE_BREAK). Empty: the controller alone as before; eight-ball is always a
  // match (SessionOptions makes it ours against ours).
  std::vector<std::string> players;
  // The table's own physics when it differs from the nodes' (--plant-params): the session checks
  // the nodes against the parameter set it is given and plays the balls with this one (of the
  // same table and balls), so that a controller can be seen learning a table it does not know.
  std::optional<physics::ModelParameters> plant;
  // The robot that plays the strokes (table_sim_node --robot, "gantry" by default): a commanded
  // stroke its cue cannot make (stroke_execution.h, Unmakeable) is refused, the balls left as
  // they were, the reason logged and NODE_STATUS's last error, the "cue_blocked" counter counted.
  // None: every stroke is played.
  std::optional<cue::Robot> robot;
};

struct ShotResult {
  Eigen::Vector2d from = Eigen::Vector2d::Zero();  // truth, where the ball was struck from
  Eigen::Vector2d target = Eigen::Vector2d::Zero();
  Eigen::Vector2d final_point = Eigen::Vector2d::Zero();  // truth, where the ball rests
  double miss_m = 0.0;
  double plan_ms = 0.0;
  // The planner's ("ok", or why not); a shot to a target whose ball dropped, "pocketed"
  // (kPocketedStatus), its reason the pocket.
  std::string status;
  std::string reason;
  int retries = 0;  // requests refused for a cause that time cures, and asked again
};

// The status of a shot to a target whose ball came to rest off the playing surface: dropped, and
// put back where it was struck from (TableSimNode::Run).
inline constexpr char kPocketedStatus[] = "pocketed";

// How the estimator followed one ball of a whole-table session, frame by frame (lockstep): the
// error of the track associated with the ball (the nearest within a ball's radius), the frames
// without a track there, how often its track changed, and the class the track was published with.
struct BallTracking {
  int id = 0;
  int frames = 0;    // frames with the ball tracked
  int lost = 0;      // frames of the ball on the table without a track within a diameter
  int misnamed = 0;  // of the tracked frames, those whose track was published as another ball
  int unnamed = 0;   // and those whose track was published without a class
  bool named_at_end = false;  // its track had its own class in its last frame on the table
  double sum_squared_error = 0.0;
  double max_error = 0.0;  // [m]
};

struct TrackingReport {
  std::vector<BallTracking> balls;  // in the scene's order
  int swaps = 0;                    // a ball's nearest track was another ball's
  int reacquired = 0;               // a ball's track changed to a new one
};

// One pot of a whole-table session: the plan (the planner's status and reason, the kind, the
// margin, the predicted cue-ball rest) against what the table did with it.
struct PotResult {
  PotShot asked;
  ShotResult shot;   // the target is the plan's cue-ball rest; the miss, the cue ball's rest there
  std::string kind;  // the planner's choice ("" when refused)
  double margin_left_deg = 0.0, margin_right_deg = 0.0;
  double speed_lo = 0.0, speed_hi = 0.0;  // the plan's speed window [m/s]
  std::string dropped;                    // the pocket ball K dropped into, "" if none
  bool potted = false;                    // ball K dropped in the pocket asked for
  bool scratch = false;                   // the cue ball dropped
  int first_contact = -1;  // the ball the cue ball touched first (the truth's id), -1 if none
};

// A whole-table session: the one shot (the cue ball at the ball nearest it), or the pots in turn,
// where every ball ended, the events, and the tracking.
struct SceneResult {
  ShotResult shot;  // the target is the contact point; the miss, the cue ball's centre there
                    // (with pots: the last pot's shot)
  std::vector<PotResult> pots;
  std::vector<table::SceneBall> final_balls;
  std::vector<std::string> pockets;  // per ball: the pocket it dropped into, or ""
  int events = 0;                    // of every shot
  TrackingReport tracking;
};

// One shot of a game: what the planner chose (by the truth's ids), what the table did with it,
// the rules' verdict, and how the estimator saw the table the choice was made on.
struct GameShot {
  int number = 0;  // from 1 in its rack
  int visit = 1;
  int player = 0;  // in a match, who shot it (0 or 1, TableSimOptions::players)
  bool break_shot = false;
  bool ball_in_hand = false;
  std::optional<Eigen::Vector2d> cue_placement;  // where the cue ball was placed
  std::string status;  // the planner's ("ok", or why not)
  std::string reason;
  int called = -1;  // the called ball (the truth ball nearest the track the planner named)
  std::string pocket;
  std::string kind;
  double predicted = -1.0;  // the planner's probability of a legal pot, -1 without one
  bool safety = false;      // the planner played a safety (cue_command_t::safety)
  int first_contact = -1;
  std::vector<int> potted;  // object balls dropped, ascending
  bool called_potted = false;
  bool foul = false;
  std::string foul_reason;
  double decision_ms = 0.0;  // the planner's
  // The estimator's latest state when the planner was asked: its error on the balls on the
  // table (each against its nearest track), the balls without a track within a radius, and the
  // balls whose track's class is not the ball's number (CLASS_CUE the cue ball's).
  double position_rms_mm = 0.0, position_max_mm = 0.0;
  int untracked = 0;
  int misidentified = 0;
};

struct GameResult {
  std::uint32_t seed = 0;  // of the rack or layout
  std::vector<GameShot> shots;
  bool cleared = false;  // the 9 potted legally, or no object ball left; a match's: decided
  int visits = 0;
  // A match's: who broke, who won (-1 undecided: the shot limit) and why, and whether the
  // breaker won with the other never at the table.
  int breaker = 0;
  int winner = -1;
  std::string reason;
  bool break_and_run = false;
};

// The referee of a game shot as played: its judgement (and, in a match, the rack advanced).
using Judge = std::function<rules::Judgement(const rules::Shot&)>;

// The request of game shot `shot`: the cue ball by class, the planner's choice
// (shot_request_t::MODE_CHOOSE) under `rules` (shot_request_t::RULES_*) with ball in hand as
// `shot` says, decided by `player` ("": the planner's own, in a rack played alone, which the
// request says: shot_request_t::alone).
shot_request_t ChoiceRequest(int8_t rules, const GameShot& shot, const std::string& player);

// The estimator or the planner runs with other physics than the simulator, or is another version
// of the project: a session would plan and track one ball and simulate another.
struct PeerMismatch : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The nodes a session needs, by the names they announce in NODE_STATUS.
inline const std::vector<std::string> kSessionPeers = {"estimator_node", "planner_node"};

class TableSimNode {
 public:
  using Log = std::function<void(const std::string& line)>;

  TableSimNode(lcm::LCM& lcm, const physics::ModelParameters& params,
               const camera::CameraModel& camera, TableSimOptions options, Log log = nullptr);
  ~TableSimNode();
  TableSimNode(const TableSimNode&) = delete;
  TableSimNode& operator=(const TableSimNode&) = delete;

  // Runs the session once the estimator and the planner have announced themselves (NODE_STATUS)
  // with the simulator's physics (the same params::ParameterHash) and version (kVersion). Throws
  // PeerMismatch when they run other physics or another version, std::runtime_error when a node
  // does not answer in time. A shot whose ball drops does not end it (PutBackIfPocketed): the
  // session plays options.shots shots.
  std::vector<ShotResult> Run();

  // Runs the whole-table session of options.scene (same preconditions and throws as Run; also
  // std::invalid_argument for a scene that does not load, is not at rest or lies on another
  // table than the parameter set's).
  SceneResult RunScene();

  // Plays options.game, rack by rack (same preconditions and throws as Run).
  std::vector<GameResult> RunGame();

  // Other nodes' work, called between messages while the session waits: the estimator and the
  // planner when they run in this process (node_loop.h's `work`).
  void RunAlongside(std::function<bool()> work) { alongside_ = std::move(work); }

  // The node's counters; TakeStatus() on it starts a new latency period.
  nodes::NodeHealth& health() { return health_; }

  // The execution noise the robot drew over the strokes it played.
  DrawnNoise Drawn() const { return execution_.Drawn(); }

 private:
  // The message in `rbuf`, or nothing when it fails its checks (counted and logged).
  template <class Message>
  std::optional<Message> Receive(const lcm::ReceiveBuffer* rbuf, const std::string& channel);
  void OnTableState(const lcm::ReceiveBuffer* rbuf, const std::string& channel);
  void OnCueCommand(const lcm::ReceiveBuffer* rbuf, const std::string& channel);
  void OnNodeStatus(const lcm::ReceiveBuffer* rbuf, const std::string& channel);
  // Waits for the peers' NODE_STATUS and compares their physics and version with the
  // simulator's.
  void AwaitPeersOfTheSameBuildAndPhysics();
  // Publishes the balls' true states at time t (sim time) and the camera's frame of them and, in
  // lockstep, waits for the estimator's state of that frame (and scores it, with tracking_).
  void Frame(const std::vector<TruthBall>& balls, double t);
  // Shows the balls at rest at `at` for the settle time.
  void ShowAtRest(const std::vector<table::SceneBall>& balls);
  // Asks the planner to send the ball estimated nearest `ball` (again after refusals that time
  // cures) and waits for the answer; a pot's object ball, with `object`, the one estimated
  // nearest there.
  cue_command_t Request(int shot, const std::vector<table::SceneBall>& shown,
                        const Eigen::Vector2d& ball, const shot_request_t& ask, ShotResult& result,
                        const std::optional<Eigen::Vector2d>& object = std::nullopt);
  // Whether the shot's ball, come to rest at result.final_point, left the playing surface of
  // `geometry`: then it is counted (NODE_STATUS's "pocketed"), the shot's status says so, the
  // ball is put back at result.from and shown there until the estimator has forgotten its fall.
  bool PutBackIfPocketed(const table::TableGeometry& geometry, ShotResult& result);
  // The estimator's track nearest `at` in its latest state, nullopt if it has none.
  std::optional<std::int32_t> NearestTrack(const Eigen::Vector2d& at) const;
  // Whether options.robot refuses `command` on `balls` (a stroke its cue cannot make on
  // `geometry`, stroke_execution.h's Unmakeable): counted cue_blocked, the reason logged and the
  // last error of NODE_STATUS. With `refuse` false (the shots session, whose point planner cannot
  // raise its cue yet) it is said and counted cue_blocked_played, and not refused.
  bool RobotRefuses(const table::TableGeometry& geometry, const std::vector<table::SceneBall>& balls,
                    const cue_command_t& command, bool refuse = true);
  // Strikes the cue ball of `balls` as `command` says (with the noise; not at all when it is a
  // refusal or the robot refuses it, options.robot), simulates the table to rest with `motion` and shows it to the camera frame by
  // frame; returns the simulation.
  table::TableSimulation PlayOut(const table::TableGeometry& geometry,
                                 const std::vector<table::SceneBall>& balls,
                                 const cue_command_t& command,
                                 const table::TableSimulationOptions& motion);
  // A whole-table session's pots in turn (options.pots) from `balls`, which become those left.
  SceneResult PlayPots(const table::TableGeometry& geometry, std::vector<table::SceneBall>& balls);
  // A whole-table session's one strike: the cue ball rolled into the ball nearest it.
  SceneResult PlayBreak(const table::TableGeometry& geometry,
                        const std::vector<table::SceneBall>& balls);
  // Asks the planner for pot `pot` (request `id`) on `balls`; its plan into `result`.
  cue_command_t RequestPot(int id, const PotShot& pot, const std::vector<table::SceneBall>& balls,
                           PotResult& result);
  // Asks for pot `pot` (request `id`) on `balls`, plays it out and scores it; `balls` become
  // those left on the table, at rest.
  PotResult PlayPot(int id, const PotShot& pot, const table::TableGeometry& geometry,
                    std::vector<table::SceneBall>& balls, SceneResult& scene);
  // The break of a session: the cue ball rolled into the ball nearest it at break_speed, asked
  // of the planner as request `id` (a point request: the cue ball's centre at contact).
  cue_command_t RequestBreak(int id, const std::vector<table::SceneBall>& balls,
                             ShotResult& result);
  // Rack `rack` of options.game played alone until it is cleared or the shot limit, its
  // requests numbered from *id on.
  GameResult PlayRack(int rack, const table::TableGeometry& geometry, int* id);
  // Rack `rack` of a match (options.players; match_session.cc) played until the rules end it
  // or the shot limit, its requests numbered from *id on.
  GameResult PlayMatchRack(int rack, const table::TableGeometry& geometry, int* id);
  // Asks the planner for game shot `shot` (request `id`) as `ask` says (a choice, or a match's
  // break); a break alone is the old point request (RequestBreak).
  cue_command_t RequestGameShot(int id, const GameShot& shot, const shot_request_t& ask,
                                const std::vector<table::SceneBall>& balls);
  // Plays shot `shot` of a game on `balls` (at rest; the cue ball on the table), asked as `ask`
  // says, under `constraints`, and judges it with `judge`; `balls` become those left, the cue
  // ball back in the kitchen after a scratch and the balls the rules put back on their spots;
  // *rack_over whether the rules end the rack there. A refused shot plays nothing and is not
  // judged.
  GameShot PlayGameShot(int id, GameShot shot, const shot_request_t& ask,
                        const rules::Constraints& constraints, const Judge& judge,
                        const table::TableGeometry& geometry,
                        std::vector<table::SceneBall>& balls, bool* rack_over);
  // The estimator's latest state against the truth `balls`, into `shot`.
  void ScoreEstimate(const std::vector<table::SceneBall>& balls, GameShot& shot) const;
  // Scores the estimator's state of a frame against the truth of its balls at t.
  void Track(const std::vector<TruthBall>& balls, double t, const table_state_t& estimate);
  // Handles messages until `done` holds, calling `resend` every retry interval; throws after the
  // reply timeout.
  void WaitFor(const std::function<bool()>& done, const std::string& what,
               const std::function<void()>& resend);
  template <class Message>
  void Publish(const char* channel, const Message& message);
  std::int64_t Utime(double t) const;

  lcm::LCM& lcm_;
  physics::ModelParameters params_;  // the nodes'
  physics::ModelParameters plant_;   // the table's: options.plant, else params_
  TableSimOptions options_;
  render::TableRenderer renderer_;
  Log log_;
  nodes::NodeHealth health_;
  // The targets and the execution noise from streams of their own, both from --seed: turning
  // the noise on leaves the targets as they were, and a run with noise differs from one without
  // by the noise alone.
  std::mt19937 target_rng_;
  StrokeExecution execution_;
  std::mt19937 fault_rng_;
  std::function<bool()> alongside_;
  std::vector<lcm::Subscription*> subscriptions_;
  Eigen::Vector2d ball_;
  double time_ = 0.0;                           // sim time [s]
  std::optional<table_state_t> state_;          // the estimator's latest
  std::optional<cue_command_t> command_;        // the planner's latest
  std::optional<image_t> held_frame_;           // reordered: sent after the next
  std::map<std::string, node_status_t> peers_;  // the latest status of each peer
  std::optional<TrackingReport> tracking_;      // a whole-table session's, while it runs
  std::map<int, std::int32_t> track_of_;        // ball id -> the estimator's track id
};

}  // namespace billiard::table_sim_node
