// The pieces of the view's state in the page's terms: ball numbers and looks, the table's
// geometry, a cue command's stroke in a player's units.
#include <cmath>
#include <cstdio>

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

// The number of the ball the message calls `id`, -1 when no estimate named it.
int NumberOf(int id, const std::map<int, int>& number_of) {
  const auto it = number_of.find(id);
  return it == number_of.end() ? -1 : it->second;
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

nlohmann::json LookJson(int number) {
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

nlohmann::json PlanJson(const cue_command_t& m, const std::map<int, int>& number_of) {
  nlohmann::json ball_paths = nlohmann::json::array();
  for (const ball_path_t& b : m.ball_paths) {
    const int number = NumberOf(b.ball_id, number_of);
    ball_paths.push_back({{"number", number}, {"look", LookJson(number)}, {"points", Points(b.points)}});
  }
  const bool pot = m.mode != shot_request_t::MODE_TO_POINT && m.object_ball_id >= 0;
  return {{"utime", m.utime},
          {"status", m.status},
          {"reason", m.reason},
          {"choice", m.mode == shot_request_t::MODE_CHOOSE},
          {"object_ball", pot ? nlohmann::json(NumberOf(m.object_ball_id, number_of)) : nullptr},
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
