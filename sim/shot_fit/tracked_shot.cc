#include "sim/shot_fit/tracked_shot.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace billiard::shot_fit {

double TrackedShot::Duration() const {
  double end = 0.0;
  for (const TrackedBall& b : balls)
    if (!b.t.empty()) end = std::max(end, b.t.back());
  return end;
}

std::size_t TrackedShot::SampleCount() const {
  std::size_t n = 0;
  for (const TrackedBall& b : balls) n += b.t.size();
  return n;
}

namespace {

std::vector<double> Numbers(const nlohmann::json& j, const char* key, const std::string& where) {
  if (!j.contains(key) || !j.at(key).is_array())
    throw std::invalid_argument(where + ": missing array \"" + key + "\"");
  std::vector<double> out;
  for (const nlohmann::json& v : j.at(key)) {
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      throw std::invalid_argument(where + ": \"" + key + "\" holds a value that is no finite number");
    out.push_back(v.get<double>());
  }
  return out;
}

TrackedBall ParseBall(const std::string& name, const nlohmann::json& j, const std::string& where) {
  if (!j.is_object()) throw std::invalid_argument(where + ": is not an object");
  TrackedBall ball;
  ball.name = name;
  ball.t = Numbers(j, "t", where);
  const std::vector<double> x = Numbers(j, "x", where), y = Numbers(j, "y", where);
  if (x.size() != ball.t.size() || y.size() != ball.t.size())
    throw std::invalid_argument(where + ": \"t\", \"x\" and \"y\" differ in length");
  if (ball.t.empty()) throw std::invalid_argument(where + ": has no samples");
  for (std::size_t i = 0; i < x.size(); ++i) {
    // Equal times are answered (the real recordings repeat one, a rounding of their clock);
    // both samples count.
    if (i > 0 && ball.t[i] < ball.t[i - 1])
      throw std::invalid_argument(where + ": times decrease");
    ball.position.emplace_back(x[i], y[i]);
  }
  return ball;
}

std::string IdText(const nlohmann::json& id) {
  return id.is_string() ? id.get<std::string>() : id.dump();
}

}  // namespace

TrackedShots ParseTrackedShots(const std::string& json_text, const std::string& origin) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(json_text);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::invalid_argument(origin + ": invalid JSON (" + e.what() + ")");
  }
  if (!j.is_object() || !j.contains("shots") || !j.at("shots").is_array())
    throw std::invalid_argument(origin + ": expected an object with an array \"shots\"");
  TrackedShots out;
  if (j.contains("_source") && j.at("_source").is_string()) out.source = j.at("_source");
  if (j.contains("table") && j.at("table").is_object()) {
    const nlohmann::json& t = j.at("table");
    auto number = [&](const char* key) -> std::optional<double> {
      if (t.contains(key) && t.at(key).is_number()) return t.at(key).get<double>();
      return std::nullopt;
    };
    out.length = number("length");
    out.width = number("width");
    out.ball_radius = number("ball_radius");
  }
  std::size_t index = 0;
  for (const nlohmann::json& s : j.at("shots")) {
    const std::string where_shot =
        origin + ": shot " + (s.is_object() && s.contains("id") ? IdText(s.at("id"))
                                                                 : "#" + std::to_string(index));
    ++index;
    if (!s.is_object() || !s.contains("balls") || !s.at("balls").is_object() ||
        !s.contains("cue_ball"))
      throw std::invalid_argument(where_shot + ": expected \"cue_ball\" and an object \"balls\"");
    TrackedShot shot;
    shot.id = s.contains("id") ? IdText(s.at("id")) : std::to_string(index - 1);
    const std::string cue = IdText(s.at("cue_ball"));
    bool has_cue = false;
    for (const auto& [name, ball] : s.at("balls").items()) {
      if (name == cue) {
        shot.cue = shot.balls.size();
        has_cue = true;
      }
      shot.balls.push_back(ParseBall(name, ball, where_shot + ", ball " + name));
    }
    if (!has_cue)
      throw std::invalid_argument(where_shot + ": has no ball \"" + cue + "\" (its cue_ball)");
    out.shots.push_back(std::move(shot));
  }
  return out;
}

TrackedShots ReadTrackedShots(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot read the file");
  std::stringstream text;
  text << in.rdbuf();
  return ParseTrackedShots(text.str(), path);
}

std::string TrackedShotsJson(const TrackedShots& shots) {
  nlohmann::json j;
  if (!shots.source.empty()) j["_source"] = shots.source;
  if (shots.length) j["table"]["length"] = *shots.length;
  if (shots.width) j["table"]["width"] = *shots.width;
  if (shots.ball_radius) j["table"]["ball_radius"] = *shots.ball_radius;
  j["shots"] = nlohmann::json::array();
  for (const TrackedShot& shot : shots.shots) {
    nlohmann::json s = {{"id", shot.id}, {"cue_ball", shot.balls.at(shot.cue).name}};
    for (const TrackedBall& b : shot.balls) {
      nlohmann::json x = nlohmann::json::array(), y = nlohmann::json::array();
      for (const Eigen::Vector2d& p : b.position) {
        x.push_back(p.x());
        y.push_back(p.y());
      }
      s["balls"][b.name] = {{"t", b.t}, {"x", x}, {"y", y}};
    }
    j["shots"].push_back(s);
  }
  return j.dump();
}

}  // namespace billiard::shot_fit
