// The pieces of the view's state in the page's terms: ball numbers and looks, the table's
// geometry, a cue command's stroke in a player's units.
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "lcmtypes/billiard/ball_state_t.hpp"
#include "lcmtypes/billiard/shot_request_t.hpp"
#include "plot/ball_look.h"
#include "tools/viewer_node/viewer_node.h"

namespace billiard::viewer {

namespace {

constexpr int kHighestNumber = 15;  // pool's object balls, 1-15
constexpr double kDegreesPerRadian = 180.0 / M_PI;
constexpr double kMillimetresPerMetre = 1e3;
// A stroke's tip offsets and angles below these are printed as 0 (a planner's -1.7e-18 m is
// "centre ball" to a player).
constexpr double kTinyMillimetres = 0.05;
constexpr double kTinyDegrees = 0.005;

std::string Css(const plot::Rgb& c) {
  const auto byte = [](double v) { return static_cast<int>(std::lround(255.0 * v)); };
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
  return text;
}

nlohmann::json Point(const Eigen::Vector2d& p) { return {p.x(), p.y()}; }

double Shown(double value, double tiny) { return std::abs(value) < tiny ? 0.0 : value; }

// The class of the ball the message calls `id`, unknown when no estimate named it.
int ClassOf(int id, const std::map<int, int>& class_of) {
  const auto it = class_of.find(id);
  return it == class_of.end() ? ball_state_t::CLASS_UNKNOWN : it->second;
}

// Snooker's colour of class `ball_class`, if it is one (ball_state_t's CLASS_RED to CLASS_BLACK
// in plot::SnookerBall's order).
std::optional<plot::SnookerBall> SnookerBallOf(int ball_class) {
  if (ball_class < ball_state_t::CLASS_RED || ball_class > ball_state_t::CLASS_BLACK) return std::nullopt;
  return static_cast<plot::SnookerBall>(ball_class - ball_state_t::CLASS_RED);
}

nlohmann::json Points(const std::vector<std::vector<double>>& path) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : path) out.push_back({p[0], p[1]});
  return out;
}

}  // namespace

int BallNumber(int ball_class) {
  if (ball_class == ball_state_t::CLASS_CUE) return 0;
  if (ball_class >= 1 && ball_class <= kHighestNumber) return ball_class;
  return -1;
}

std::string BallName(int ball_class) {
  static const char* const kSnookerNames[] = {"red", "yellow", "green", "brown", "blue", "pink", "black"};
  if (const std::optional<plot::SnookerBall> snooker = SnookerBallOf(ball_class)) {
    return kSnookerNames[static_cast<int>(*snooker)];
  }
  const int number = BallNumber(ball_class);
  return number == 0 ? "cue ball" : number < 0 ? "?" : std::to_string(number);
}

std::string BallLabel(int ball_class) {
  const int number = BallNumber(ball_class);
  if (number == 0 || SnookerBallOf(ball_class)) return "";
  return number < 0 ? "?" : std::to_string(number);
}

nlohmann::json LookJson(int ball_class) {
  if (const std::optional<plot::SnookerBall> snooker = SnookerBallOf(ball_class)) {
    const std::string colour = Css(plot::SnookerLookOf(*snooker).body);
    return {{"body", colour}, {"band", nullptr}, {"path", colour}, {"dashed", false}};
  }
  const int number = BallNumber(ball_class);
  if (number < 0) return {{"body", "#9a9a9a"}, {"band", nullptr}, {"path", "#9a9a9a"},
                          {"dashed", false}};
  const plot::BallLook look = plot::LookOf(number);
  return {{"body", Css(look.body)},
          {"band", look.band ? nlohmann::json(Css(*look.band)) : nlohmann::json(nullptr)},
          {"path", Css(plot::PathColour(number))},
          {"dashed", plot::DashedPath(number)}};
}

nlohmann::json TableJson(const table::TableGeometry& table) {
  nlohmann::json outline = nlohmann::json::array(), cushions = nlohmann::json::array(),
                 pockets = nlohmann::json::array();
  for (const Eigen::Vector2d& p : table.outline) outline.push_back(Point(p));
  for (const table::CushionLine& line : table.lines) cushions.push_back({Point(line.a), Point(line.b)});
  // A pocket drawn as plot draws it: a hole across its capture line.
  for (const table::Pocket& pocket : table.pockets) {
    pockets.push_back({{"name", pocket.name},
                       {"centre", Point(0.5 * (pocket.capture_a + pocket.capture_b))},
                       {"radius", 0.5 * (pocket.capture_a - pocket.capture_b).norm()}});
  }
  return {{"name", table.name}, {"length", table.length}, {"width", table.width},
          {"outline", outline}, {"cushions", cushions}, {"pockets", pockets}};
}

nlohmann::json PlanJson(const cue_command_t& m, const std::map<int, int>& class_of) {
  nlohmann::json ball_paths = nlohmann::json::array();
  for (const ball_path_t& b : m.ball_paths) {
    const int ball_class = ClassOf(b.ball_id, class_of);
    ball_paths.push_back({{"number", BallNumber(ball_class)},
                          {"look", LookJson(ball_class)},
                          {"points", Points(b.points)}});
  }
  const int object_class = ClassOf(m.object_ball_id, class_of);
  const bool pot = m.mode != shot_request_t::MODE_TO_POINT && m.object_ball_id >= 0;
  return {{"utime", m.utime},
          {"status", m.status},
          {"reason", m.reason},
          {"choice", m.mode == shot_request_t::MODE_CHOOSE},
          {"object_ball", pot ? nlohmann::json(BallNumber(object_class)) : nullptr},
          {"object_name", pot ? nlohmann::json(BallName(object_class)) : nullptr},
          {"pocket", m.pocket},
          {"cue_speed_m_s", m.cue_speed},
          {"heading_deg", Shown(kDegreesPerRadian * m.heading, kTinyDegrees)},
          {"elevation_deg", Shown(kDegreesPerRadian * m.elevation, kTinyDegrees)},
          {"tip_side_mm", Shown(kMillimetresPerMetre * m.tip_side, kTinyMillimetres)},
          {"tip_height_mm", Shown(kMillimetresPerMetre * m.tip_height, kTinyMillimetres)},
          {"probability", m.mode == shot_request_t::MODE_CHOOSE && m.object_ball_id >= 0
                              ? nlohmann::json(m.success_probability) : nullptr},
          {"probability_stderr", m.probability_stderr},
          {"path", Points(m.path)},
          {"ball_paths", ball_paths}};
}

}  // namespace billiard::viewer
