#include "bench/labelled_set.h"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace billiard::bench {

namespace {

std::vector<Eigen::Vector2d> Points(const nlohmann::json& entry, const char* key,
                                    const std::string& where) {
  std::vector<Eigen::Vector2d> points;
  if (!entry.contains(key)) return points;
  const auto& list = entry.at(key);
  if (!list.is_array()) throw std::invalid_argument(where + ": '" + key + "' is not a list");
  for (const auto& p : list) {
    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number()) {
      throw std::invalid_argument(where + ": '" + key + "' holds an entry that is not [u, v]");
    }
    points.emplace_back(p[0].get<double>(), p[1].get<double>());
  }
  return points;
}

// The JSON object in a file; throws std::invalid_argument naming the file when it is not one.
nlohmann::json ReadJsonObject(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("cannot read '" + path + "'");
  nlohmann::json object;
  try {
    in >> object;
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument("'" + path + "' is not JSON: " + e.what());
  }
  if (!object.is_object()) throw std::invalid_argument("'" + path + "' is not a JSON object");
  return object;
}

}  // namespace

std::vector<LabelledFrame> LoadLabelledSet(const std::string& directory) {
  const std::string path = directory + "/labels.json";
  const nlohmann::json labels = ReadJsonObject(path);
  std::vector<LabelledFrame> frames;
  for (const auto& [file, entry] : labels.items()) {
    if (!file.empty() && file[0] == '_') continue;  // notes
    const std::string where = path + ": '" + file + "'";
    if (!entry.is_object()) throw std::invalid_argument(where + " is not an object");
    LabelledFrame frame;
    frame.file = file;
    frame.balls = Points(entry, "balls", where);
    for (const char* key : {"in_pocket", "ignore"}) {
      const auto more = Points(entry, key, where);
      frame.ignored.insert(frame.ignored.end(), more.begin(), more.end());
    }
    if (!entry.contains("ball_radius_px") || !entry.at("ball_radius_px").is_number() ||
        !(entry.at("ball_radius_px").get<double>() > 0)) {
      throw std::invalid_argument(where + ": 'ball_radius_px' is not a positive number");
    }
    frame.radius_px = entry.at("ball_radius_px").get<double>();
    if (entry.contains("view")) {
      frame.view = entry.at("view").is_string() ? entry.at("view").get<std::string>() : "";
      if (frame.view != "overhead" && frame.view != "oblique") {
        throw std::invalid_argument(where + ": 'view' is neither \"overhead\" nor \"oblique\"");
      }
    }
    if (entry.contains("source") && entry.at("source").is_string()) {
      frame.source = entry.at("source").get<std::string>();
    }
    if (entry.contains("kind")) {
      frame.kind = entry.at("kind").is_string() ? entry.at("kind").get<std::string>() : "";
      if (frame.kind != "pool" && frame.kind != "snooker" && frame.kind != "carom") {
        throw std::invalid_argument(where + ": 'kind' is none of \"pool\", \"snooker\", \"carom\"");
      }
    }
    if (entry.contains("classes")) {
      const auto& classes = entry.at("classes");
      if (!classes.is_array() || classes.size() != frame.balls.size()) {
        throw std::invalid_argument(where + ": 'classes' is not a list as long as 'balls'");
      }
      for (const auto& c : classes) {
        if (!c.is_null() && !c.is_string()) {
          throw std::invalid_argument(where + ": 'classes' holds an entry that is not a name");
        }
        frame.classes.push_back(c.is_string() ? c.get<std::string>() : "");
      }
    }
    frames.push_back(frame);
  }
  if (frames.empty()) throw std::invalid_argument("'" + path + "' labels no frame");
  return frames;
}

void LoadTableCorners(const std::string& path, std::vector<LabelledFrame>* frames) {
  const nlohmann::json labels = ReadJsonObject(path);
  for (LabelledFrame& frame : *frames) {
    if (!labels.contains(frame.file)) continue;
    const std::string where = path + ": '" + frame.file + "'";
    const auto& entry = labels.at(frame.file);
    if (!entry.is_object()) throw std::invalid_argument(where + " is not an object");
    const std::vector<Eigen::Vector2d> corners = Points(entry, "corners", where);
    if (corners.size() != 4) throw std::invalid_argument(where + ": 'corners' is not 4 [u, v]");
    frame.corners = {corners[0], corners[1], corners[2], corners[3]};
    frame.unseen_side = -1;
    if (entry.contains("unseen_side")) {
      const auto& side = entry.at("unseen_side");
      if (!side.is_number_integer() || side.get<int>() < 0 || side.get<int>() > 3) {
        throw std::invalid_argument(where + ": 'unseen_side' is not a side (0..3)");
      }
      frame.unseen_side = side.get<int>();
    }
  }
}

estimator::BallSet BallSetFor(const LabelledFrame& frame) {
  if (frame.kind == "snooker") return estimator::BallSet::kSnooker;
  if (frame.kind == "carom") return estimator::BallSet::kCarom;
  const bool by_colour = std::any_of(frame.classes.begin(), frame.classes.end(), [](const auto& c) {
    return c == "red" || c == "yellow";
  });
  return by_colour ? estimator::BallSet::kBlackball : estimator::BallSet::kPool;
}

bool ClassMatches(const std::string& label, estimator::BallClass detected) {
  const std::string name = estimator::BallClassName(detected);
  if (label == name) return true;
  if (label == "white") return detected == estimator::BallClass::kCue;
  const int number = static_cast<int>(detected);
  if (label == "solid") return number >= 1 && number <= 7;
  if (label == "stripe") return number >= 9 && number <= 15;
  if (label == "eight") return number == 8 || detected == estimator::BallClass::kBlack;
  if (label == "black") return number == 8;
  return false;
}

}  // namespace billiard::bench
