// build/bin/viewer_node: a live view of the table in a web browser. It follows LCM (the
// estimator's TABLE_STATE with each ball's uncertainty and class, the simulator's TABLE_TRUTH,
// the latest CUE_COMMAND's predicted paths, every node's NODE_STATUS) and serves, with
// cpp-httplib, a page that draws them (GET /) and the state it draws (GET /state.json). Every
// other request gets an error status and nothing else; it listens on 127.0.0.1 unless told.
//
// Module: billiard::viewer (tools/viewer_node/). lcmtypes/, lcmtypes/node/, sim/params/,
// sim/physics/.
#pragma once

#include <lcm/lcm-cpp.hpp>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>

#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/node_status_t.hpp"
#include "lcmtypes/billiard/table_state_t.hpp"
#include "sim/physics/parameters.h"

namespace billiard::viewer {

// The page's frame, as billiard plot's (plot/table_picture.h): 400 px a metre, y up, the
// playing surface's corner (0, 0) at (kMarginPx, kMarginPx + 400 W) px on the page's canvas.
inline constexpr double kPixelsPerMetre = 400.0;
inline constexpr double kMarginPx = 40.0;

// What the page draws, from LCM; thread-safe (LCM's thread writes, the server's read).
class ViewState {
 public:
  ViewState(lcm::LCM& lcm, const physics::ModelParameters& params);
  nlohmann::json Json() const;

 private:
  void OnTableState(const lcm::ReceiveBuffer* rbuf, const std::string& channel);
  void OnCueCommand(const lcm::ReceiveBuffer* rbuf, const std::string& channel);
  void OnNodeStatus(const lcm::ReceiveBuffer* rbuf, const std::string& channel);

  mutable std::mutex mutex_;
  nlohmann::json state_;
};

// The page (HTML and its script).
const char* PageHtml();

}  // namespace billiard::viewer
