// build/bin/viewer_node: a live view of the table in a web browser, drawn as a player reads a
// table. It follows LCM (the estimator's TABLE_STATE with each ball's uncertainty and class, the
// simulator's TABLE_TRUTH, the latest CUE_COMMAND's stroke, probability and predicted paths,
// every node's NODE_STATUS) and serves, with cpp-httplib, a page that draws them (GET /) and the
// state it draws (GET /state.json). Every other request gets an error status and nothing else;
// it listens on 127.0.0.1 unless told.
//
// Each ball is drawn by its number (the class the estimator or the simulator gives it, not the
// estimator's track id) in the standard pool colours, stripes as stripes, or snooker's by their
// colours (plot/ball_look.h, the same table billiard plot draws with); the table with its cushions and pockets is the one the
// planner plans on (sim/table/), and the paths the balls took since the last stroke are kept.
// The state is never cleared: when the loop ends the page keeps its last table.
//
// Module: billiard::viewer (tools/viewer_node/). lcmtypes/, lcmtypes/node/, sim/params/,
// sim/physics/, sim/table/, plot/ (the balls' looks).
#pragma once

#include <Eigen/Core>
#include <lcm/lcm-cpp.hpp>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/node_status_t.hpp"
#include "lcmtypes/billiard/table_state_t.hpp"
#include "sim/physics/parameters.h"
#include "sim/table/table_geometry.h"

namespace billiard::viewer {

// The page's frame, as billiard plot's (plot/table_picture.h): 400 px a metre, y up, the
// playing surface's corner (0, 0) at (kMarginPx, kMarginPx + 400 W) px on the page's canvas.
inline constexpr double kPixelsPerMetre = 400.0;
inline constexpr double kMarginPx = 40.0;

// The number a player reads on a ball of class `ball_class` (ball_state_t): 0 the cue ball,
// 1-15 pool's numbers, -1 a ball not (or not yet) told (unknown, or a snooker colour).
int BallNumber(int ball_class);

// The table as the page draws it: size, the boundary's outline, the cushion lines and each
// pocket's centre and radius (half its capture line), in table coordinates [m].
nlohmann::json TableJson(const table::TableGeometry& table);

// What a player calls a ball of class `ball_class`: pool's number ("9"), "cue ball", a snooker
// colour ("red", "pink"), "?" for a ball not told.
std::string BallName(int ball_class);

// The text on a ball of class `ball_class` as the page draws it: pool's number, "?" for a ball
// not told, nothing on the cue ball and on snooker's (told by their colours).
std::string BallLabel(int ball_class);

// A ball of class `ball_class` as the page draws it, its look: "body" and, for a stripe, "band",
// as CSS colours; "path" the colour of its path and "dashed" whether that path is dashed. Pool's
// numbers in pool's colours, snooker's colours in theirs, a ball not told grey.
nlohmann::json LookJson(int ball_class);

// The stroke of a cue command in a player's units (degrees, mm, m/s), its pot (the object ball's
// number, or -1, and its name) and probability; `class_of` maps the message's ball ids (the
// estimator's track ids) to their classes.
nlohmann::json PlanJson(const cue_command_t& m, const std::map<int, int>& class_of);

// What the page draws, from LCM; thread-safe (LCM's thread writes, the server's read).
class ViewState {
 public:
  ViewState(lcm::LCM& lcm, const physics::ModelParameters& params,
            const table::TableGeometry& table);
  nlohmann::json Json() const;

 private:
  void OnTableState(const lcm::ReceiveBuffer* rbuf, const std::string& channel);
  void OnCueCommand(const lcm::ReceiveBuffer* rbuf, const std::string& channel);
  void OnNodeStatus(const lcm::ReceiveBuffer* rbuf, const std::string& channel);
  // Extends each ball's path of the current shot by its position in `m`.
  void ExtendPaths(const table_state_t& m);

  mutable std::mutex mutex_;
  nlohmann::json state_;
  std::map<int, int> class_of_track_;  // the estimator's track id -> ball class, latest
  int64_t last_stroke_request_ = -1;    // the request of the last stroke that started a shot
  bool truth_seen_ = false;             // paths from the truth once it is heard, else estimates
  // (ball class, the ball's id for a red, else -1: the reds are alike) -> centres since the
  // stroke.
  std::map<std::pair<int, int>, std::vector<Eigen::Vector2d>> paths_;
};

// The page (HTML and its script) with `state` (ViewState::Json()) drawn at once, before the
// first request for /state.json: a page saved or captured at load shows the table.
std::string PageHtml(const nlohmann::json& state);

}  // namespace billiard::viewer
