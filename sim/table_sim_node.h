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
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <lcm/lcm-cpp.hpp>
#include <random>
#include <string>
#include <vector>

#include "billiard/cue_command_t.hpp"
#include "billiard/table_state_t.hpp"
#include "ball_state.h"
#include "camera_model.h"
#include "cue_strike.h"
#include "parameters.h"
#include "table_renderer.h"

namespace billiard {

struct ExecutionNoise {
  double speed = 0.0;       // relative standard deviation of the cue speed
  double heading = 0.0;     // standard deviation of the heading [rad]
  double tip_offset = 0.0;  // standard deviation of each tip offset [m]
};

struct TableSimOptions {
  int shots = 20;
  std::uint32_t seed = 1;
  ExecutionNoise noise;
  bool lockstep = true;
  double camera_rate = 30.0;        // frames per second [Hz]
  double settle_time = 0.3;         // frames shown of a ball at rest before a request [s]
  double reply_timeout = 10.0;      // longest wait for the estimator or the planner [s]
  Eigen::Vector2d start{0.6, 0.635};  // where the ball starts [m]
  double target_margin = 0.15;      // targets at least this far inside the cushions [m]
  double min_distance = 0.3;        // and at least this far from the ball [m]
  int jpeg_quality = 90;
};

struct ShotResult {
  Eigen::Vector2d target = Eigen::Vector2d::Zero();
  Eigen::Vector2d final_point = Eigen::Vector2d::Zero();  // truth, where the ball rests
  double miss_m = 0.0;
  double plan_ms = 0.0;
  std::string status;  // the planner's ("ok", or why not)
  std::string reason;
};

class TableSimNode {
 public:
  using Log = std::function<void(const std::string& line)>;

  TableSimNode(lcm::LCM& lcm, const ModelParameters& params, const CameraModel& camera,
               TableSimOptions options, Log log = nullptr);
  ~TableSimNode();
  TableSimNode(const TableSimNode&) = delete;
  TableSimNode& operator=(const TableSimNode&) = delete;

  // Runs the session; throws std::runtime_error when a node does not answer in time.
  std::vector<ShotResult> Run();

 private:
  void OnTableState(const lcm::ReceiveBuffer*, const std::string&, const table_state_t* m);
  void OnCueCommand(const lcm::ReceiveBuffer*, const std::string&, const cue_command_t* m);
  // Publishes the ball's true state at time t (sim time) and the camera's frame of it and, in
  // lockstep, waits for the estimator's state of that frame.
  void Frame(const std::function<BallState(double)>& state, double t);
  // Handles messages until `done` holds; throws after the reply timeout.
  void WaitFor(const std::function<bool()>& done, const std::string& what);
  std::int64_t Utime(double t) const;
  CueStroke WithNoise(CueStroke stroke);

  lcm::LCM& lcm_;
  ModelParameters params_;
  TableSimOptions options_;
  TableRenderer renderer_;
  Log log_;
  std::mt19937 rng_;
  std::vector<lcm::Subscription*> subscriptions_;
  Eigen::Vector2d ball_;
  double time_ = 0.0;  // sim time [s]
  std::vector<table_state_t> states_;
  std::vector<cue_command_t> commands_;
};

}  // namespace billiard
