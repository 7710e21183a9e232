#include "tools/viewer_node/viewer_node.h"

#include <cmath>

#include "lcmtypes/message_checks.h"
#include "lcmtypes/names.h"

namespace billiard::viewer {

namespace {

// A ball's path grows by a point once it is this far from the last: a few points a ball
// diameter, a still ball one point.
constexpr double kPathStepM = 0.002;
// The most points a path keeps (10 m of travel at kPathStepM): a view left running for hours
// holds no more.
constexpr std::size_t kMaxPathPoints = 5000;

nlohmann::json BallsJson(const table_state_t& m, bool with_uncertainty) {
  nlohmann::json balls = nlohmann::json::array();
  for (const ball_state_t& b : m.balls) {
    nlohmann::json j = {{"id", b.ball_id},
                        {"number", BallNumber(b.ball_class)},
                        {"label", BallLabel(b.ball_class)},
                        {"x", b.position[0]},
                        {"y", b.position[1]},
                        {"class", b.ball_class},
                        {"look", LookJson(b.ball_class)}};
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

ViewState::ViewState(lcm::LCM& lcm, const physics::ModelParameters& params,
                     const table::TableGeometry& table) {
  state_ = {{"table", TableJson(table)},
            {"ball_radius", params.ball.radius},
            {"scale_px_per_m", kPixelsPerMetre},
            {"margin_px", kMarginPx},
            {"estimate", nullptr},
            {"truth", nullptr},
            {"plan", nullptr},
            {"strokes", 0},
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
  if (!truth) {
    class_of_track_.clear();
    for (const ball_state_t& b : m.balls) class_of_track_[b.ball_id] = b.ball_class;
  }
  // The paths from the truth where a simulator publishes it, else (a camera) from the estimate.
  if (truth && !truth_seen_) paths_.clear();
  truth_seen_ = truth_seen_ || truth;
  if (truth == truth_seen_) ExtendPaths(m);
}

void ViewState::ExtendPaths(const table_state_t& m) {
  for (const ball_state_t& b : m.balls) {
    if (b.ball_class == ball_state_t::CLASS_UNKNOWN) continue;
    const bool red = b.ball_class == ball_state_t::CLASS_RED;
    std::vector<Eigen::Vector2d>& path = paths_[{b.ball_class, red ? b.ball_id : -1}];
    const Eigen::Vector2d p(b.position[0], b.position[1]);
    if (path.size() < kMaxPathPoints && (path.empty() || (p - path.back()).norm() >= kPathStepM)) {
      path.push_back(p);
    }
  }
}

// A stroke the planner sends for a new request starts a shot: the paths drawn from then on are
// that shot's. A request the session sent again is answered again, and is the same shot.
void ViewState::OnCueCommand(const lcm::ReceiveBuffer* rbuf, const std::string&) {
  cue_command_t m;
  if (!messages::DecodeChecked(rbuf->data, rbuf->data_size, m).empty()) return;
  std::lock_guard<std::mutex> lock(mutex_);
  state_["plan"] = PlanJson(m, class_of_track_);
  if (m.status != cue_command_t::STATUS_OK || m.request_id == last_stroke_request_) return;
  last_stroke_request_ = m.request_id;
  state_["strokes"] = state_["strokes"].get<int>() + 1;
  paths_.clear();  // the next frame, still at rest, starts each path where its ball stands
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
  nlohmann::json state = state_;
  nlohmann::json paths = nlohmann::json::array();
  for (const auto& [ball, points] : paths_) {
    if (points.size() < 2) continue;  // a ball that has not moved
    nlohmann::json xy = nlohmann::json::array();
    for (const Eigen::Vector2d& p : points) xy.push_back({p.x(), p.y()});
    const int ball_class = ball.first;
    paths.push_back({{"number", BallNumber(ball_class)}, {"look", LookJson(ball_class)}, {"points", xy}});
  }
  state["paths"] = paths;
  return state;
}

}  // namespace billiard::viewer
