#include "estimator/ball_model.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "estimator/ball_identity.h"
#include "estimator/identity_fit.h"

namespace billiard::estimator {

namespace {

constexpr const char* kFormat = "billiard-ball-model";
constexpr int kVersion = 1;

// The class a model's colour or learnt list names in `set`, or the reason it is not one.
BallClass ClassOf(const nlohmann::json& name, BallSet set, const std::string& origin) {
  if (name.is_string()) {
    if (const auto c = BallClassNamed(name.get<std::string>(), set)) return *c;
  }
  throw std::invalid_argument(origin + ": " + name.dump() + " is no class of " + BallSetName(set) +
                              " balls");
}

BallSet SetOf(const nlohmann::json& name, const std::string& origin) {
  if (name.is_string()) {
    if (const auto set = BallSetNamed(name.get<std::string>())) return *set;
  }
  throw std::invalid_argument(origin + ": " + name.dump() + " is none of the ball sets (" +
                              kBallSetNames + ")");
}

// The member `key` of object `j`, or the reason it is missing.
const nlohmann::json& Member(const nlohmann::json& j, const char* key, const std::string& origin) {
  if (!j.is_object() || !j.contains(key)) {
    throw std::invalid_argument(origin + ": missing \"" + key + "\"");
  }
  return j.at(key);
}

double FiniteNumber(const nlohmann::json& x, const std::string& what, const std::string& origin) {
  if (!x.is_number() || !std::isfinite(x.get<double>())) {
    throw std::invalid_argument(origin + ": " + what + " must be a finite number");
  }
  return x.get<double>();
}

// A share of a ball's disc, in [0, 1].
double Share(const nlohmann::json& shares, const char* key, const std::string& origin) {
  const double share = FiniteNumber(Member(shares, key, origin), key, origin);
  if (share < 0 || share > 1) {
    throw std::invalid_argument(origin + ": \"" + key + "\" must lie in [0, 1]");
  }
  return share;
}

ColourPrototype ColourOf(const nlohmann::json& c, const std::string& origin) {
  ColourPrototype colour;
  colour.table = SetOf(Member(c, "table", origin), origin);
  colour.ball_class = ClassOf(Member(c, "class", origin), colour.table, origin);
  const nlohmann::json& lab = Member(c, "lab", origin);
  if (!lab.is_array() || lab.size() != 3) {
    throw std::invalid_argument(origin + ": a colour's \"lab\" must hold 3 numbers");
  }
  for (int i = 0; i < 3; ++i) {
    colour.lab[i] = static_cast<float>(FiniteNumber(lab[i], "a colour's \"lab\"", origin));
  }
  return colour;
}

}  // namespace

std::vector<int> MatchPlacedBalls(const std::vector<PlacedBall>& placed,
                                  const std::vector<BallDetection>& balls) {
  std::vector<int> matched(placed.size(), -1);
  std::vector<int> taken_by(balls.size(), -1);
  for (std::size_t p = 0; p < placed.size(); ++p) {
    double nearest = HUGE_VAL;
    for (std::size_t b = 0; b < balls.size(); ++b) {
      const double d = (balls[b].pixel - placed[p].pixel).norm();
      if (d <= balls[b].radius_px && d < nearest) {
        nearest = d;
        matched[p] = static_cast<int>(b);
      }
    }
    if (matched[p] < 0) continue;
    int& owner = taken_by[matched[p]];
    if (owner >= 0) {
      throw std::invalid_argument("balls " + BallClassName(placed[owner].ball_class) + " and " +
                                  BallClassName(placed[p].ball_class) +
                                  " are placed on the same ball");
    }
    owner = static_cast<int>(p);
  }
  return matched;
}

BallModel LearnBallModel(const cv::Mat& bgr, const std::vector<BallDetection>& balls,
                         const std::vector<PlacedBall>& placed, const std::vector<int>& matched,
                         BallSet set) {
  const std::vector<BallLook> looks = LookAtBalls(bgr, balls, set);
  std::vector<KnownBall> known;
  BallModel model;
  model.set = set;
  for (std::size_t p = 0; p < placed.size(); ++p) {
    if (matched[p] < 0) continue;
    KnownBall ball;
    ball.look = looks[matched[p]];
    ball.set = set;
    ball.ball_class = placed[p].ball_class;
    known.push_back(ball);
    model.learnt.push_back(placed[p].ball_class);
  }
  model.identity = FitIdentity(known, HandSetIdentity()).parameters;
  return model;
}

std::string BallModelJson(const BallModel& model) {
  nlohmann::json learnt = nlohmann::json::array(), colours = nlohmann::json::array();
  for (const BallClass c : model.learnt) learnt.push_back(BallClassName(c));
  for (const ColourPrototype& c : model.identity.colours) {
    colours.push_back({{"table", BallSetName(c.table)},
                       {"class", BallClassName(c.ball_class)},
                       {"lab", {c.lab[0], c.lab[1], c.lab[2]}}});
  }
  const IdentityParameters& p = model.identity;
  const nlohmann::json j = {{"format", kFormat},
                            {"version", kVersion},
                            {"ball_set", BallSetName(model.set)},
                            {"learnt", learnt},
                            {"shares",
                             {{"cue_white", p.cue_white},
                              {"cue_colour", p.cue_colour},
                              {"black_share", p.black_share},
                              {"stripe_plain", p.stripe_plain}}},
                            {"colours", colours}};
  return j.dump(2);
}

BallModel ParseBallModel(const std::string& json_text, const std::string& origin) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(json_text);
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(origin + ": not valid JSON (" + e.what() + ")");
  }
  if (Member(j, "format", origin) != kFormat || Member(j, "version", origin) != kVersion) {
    throw std::invalid_argument(origin + ": not a " + kFormat + " of version " +
                                std::to_string(kVersion) + " (billiard learn-balls writes one)");
  }
  BallModel model;
  model.set = SetOf(Member(j, "ball_set", origin), origin);
  const nlohmann::json& learnt = Member(j, "learnt", origin);
  const nlohmann::json& colours = Member(j, "colours", origin);
  if (!learnt.is_array() || !colours.is_array() || colours.empty()) {
    throw std::invalid_argument(origin + ": \"learnt\" and \"colours\" must be lists, " +
                                "\"colours\" not empty");
  }
  for (const nlohmann::json& c : learnt) model.learnt.push_back(ClassOf(c, model.set, origin));
  for (const nlohmann::json& c : colours) model.identity.colours.push_back(ColourOf(c, origin));
  const nlohmann::json& shares = Member(j, "shares", origin);
  model.identity.cue_white = Share(shares, "cue_white", origin);
  model.identity.cue_colour = Share(shares, "cue_colour", origin);
  model.identity.black_share = Share(shares, "black_share", origin);
  model.identity.stripe_plain = Share(shares, "stripe_plain", origin);
  return model;
}

BallModel LoadBallModel(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("cannot read ball model file '" + path + "'");
  std::stringstream text;
  text << in.rdbuf();
  return ParseBallModel(text.str(), path);
}

}  // namespace billiard::estimator
