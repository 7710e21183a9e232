#include "tools/viewer_node/viewer_node.h"

#include <cmath>

#include "lcmtypes/message_checks.h"
#include "lcmtypes/names.h"

namespace billiard::viewer {

namespace {

nlohmann::json BallsJson(const table_state_t& m, bool with_uncertainty) {
  nlohmann::json balls = nlohmann::json::array();
  for (const ball_state_t& b : m.balls) {
    nlohmann::json j = {{"id", b.ball_id}, {"x", b.position[0]}, {"y", b.position[1]},
                        {"class", b.ball_class}};
    // The position's standard deviations: the covariance is of the 7-state, row-major.
    if (with_uncertainty) {
      j["sx"] = std::sqrt(std::max(b.covariance[0], 0.0));
      j["sy"] = std::sqrt(std::max(b.covariance[8], 0.0));
      j["confidence"] = b.class_confidence;
    }
    balls.push_back(j);
  }
  return {{"utime", m.utime}, {"balls", balls}};
}

}  // namespace

ViewState::ViewState(lcm::LCM& lcm, const physics::ModelParameters& params) {
  state_ = {{"table", {{"length", params.table.length}, {"width", params.table.width}}},
            {"ball_radius", params.ball.radius},
            {"scale_px_per_m", kPixelsPerMetre},
            {"margin_px", kMarginPx},
            {"estimate", nullptr},
            {"truth", nullptr},
            {"plan", nullptr},
            {"nodes", nlohmann::json::object()}};
  lcm.subscribe(messages::kTableStateChannel, &ViewState::OnTableState, this);
  lcm.subscribe(messages::kTableTruthChannel, &ViewState::OnTableState, this);
  lcm.subscribe(messages::kCueCommandChannel, &ViewState::OnCueCommand, this);
  lcm.subscribe(messages::kNodeStatusChannel, &ViewState::OnNodeStatus, this);
}

// A message that fails its checks is not drawn: the view shows what the nodes would accept.
void ViewState::OnTableState(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
  table_state_t m;
  if (!messages::DecodeChecked(rbuf->data, rbuf->data_size, m).empty()) return;
  const bool truth = channel == messages::kTableTruthChannel;
  std::lock_guard<std::mutex> lock(mutex_);
  state_[truth ? "truth" : "estimate"] = BallsJson(m, !truth);
}

void ViewState::OnCueCommand(const lcm::ReceiveBuffer* rbuf, const std::string&) {
  cue_command_t m;
  if (!messages::DecodeChecked(rbuf->data, rbuf->data_size, m).empty()) return;
  const auto points = [](const std::vector<std::vector<double>>& path) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& p : path) out.push_back({p[0], p[1]});
    return out;
  };
  nlohmann::json ball_paths = nlohmann::json::array();
  for (const ball_path_t& b : m.ball_paths) {
    ball_paths.push_back({{"ball_id", b.ball_id}, {"points", points(b.points)}});
  }
  std::lock_guard<std::mutex> lock(mutex_);
  state_["plan"] = {{"utime", m.utime},
                    {"ball_id", m.ball_id},
                    {"status", m.status},
                    {"path", points(m.path)},
                    {"ball_paths", ball_paths},
                    {"predicted_final", {m.predicted_final[0], m.predicted_final[1]}}};
}

void ViewState::OnNodeStatus(const lcm::ReceiveBuffer* rbuf, const std::string&) {
  node_status_t m;
  if (!messages::DecodeChecked(rbuf->data, rbuf->data_size, m).empty()) return;
  std::lock_guard<std::mutex> lock(mutex_);
  state_["nodes"][m.node] = {{"params", m.params},
                             {"uptime_s", 1e-6 * m.uptime_us},
                             {"received", m.received},
                             {"dropped", m.dropped},
                             {"last_error", m.last_error}};
}

nlohmann::json ViewState::Json() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return state_;
}

}  // namespace billiard::viewer
