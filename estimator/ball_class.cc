#include "estimator/ball_class.h"

#include <algorithm>
#include <stdexcept>

namespace billiard::estimator {

BallSet BallSetOf(const std::string& parameter_set_name) {
  if (parameter_set_name == "snooker") return BallSet::kSnooker;
  if (parameter_set_name == "carom") return BallSet::kCarom;
  return BallSet::kPool;
}

std::optional<BallSet> BallSetNamed(const std::string& name) {
  if (name == "pool") return BallSet::kPool;
  if (name == "snooker") return BallSet::kSnooker;
  if (name == "carom") return BallSet::kCarom;
  if (name == "blackball") return BallSet::kBlackball;
  return std::nullopt;
}

BallClass PoolBall(int number) {
  if (number < 1 || number > 15) throw std::invalid_argument("pool balls are numbered 1..15");
  return static_cast<BallClass>(number);
}

std::vector<BallClass> ClassesIn(BallSet set) {
  std::vector<BallClass> classes = {BallClass::kCue};
  switch (set) {
    case BallSet::kPool:
      for (int number = 1; number <= 15; ++number) classes.push_back(PoolBall(number));
      break;
    case BallSet::kSnooker:
      classes.insert(classes.end(), {BallClass::kRed, BallClass::kYellow, BallClass::kGreen,
                                     BallClass::kBrown, BallClass::kBlue, BallClass::kPink,
                                     BallClass::kBlack});
      break;
    case BallSet::kCarom:
      classes.insert(classes.end(), {BallClass::kRed, BallClass::kYellow});
      break;
    case BallSet::kBlackball:
      classes.insert(classes.end(), {BallClass::kRed, BallClass::kYellow, BallClass::kBlack});
      break;
  }
  return classes;
}

int CountIn(BallSet set, BallClass ball_class) {
  constexpr int kSnookerReds = 15, kCaromReds = 2, kBlackballGroup = 7;
  const std::vector<BallClass> classes = ClassesIn(set);
  if (std::find(classes.begin(), classes.end(), ball_class) == classes.end()) return 0;
  switch (set) {
    case BallSet::kSnooker:
      return ball_class == BallClass::kRed ? kSnookerReds : 1;
    case BallSet::kCarom:
      return ball_class == BallClass::kRed ? kCaromReds : 1;
    case BallSet::kBlackball:
      return ball_class == BallClass::kRed || ball_class == BallClass::kYellow ? kBlackballGroup
                                                                              : 1;
    case BallSet::kPool:
      break;
  }
  return 1;
}

std::string BallClassName(BallClass ball_class) {
  switch (ball_class) {
    case BallClass::kUnknown:
      return "unknown";
    case BallClass::kCue:
      return "cue";
    case BallClass::kRed:
      return "red";
    case BallClass::kYellow:
      return "yellow";
    case BallClass::kGreen:
      return "green";
    case BallClass::kBrown:
      return "brown";
    case BallClass::kBlue:
      return "blue";
    case BallClass::kPink:
      return "pink";
    case BallClass::kBlack:
      return "black";
  }
  return std::to_string(static_cast<int>(ball_class));  // pool's numbers
}

std::optional<BallClass> BallClassNamed(const std::string& name, BallSet set) {
  for (const BallClass c : ClassesIn(set)) {
    if (BallClassName(c) == name) return c;
  }
  return std::nullopt;
}

std::string BallSetName(BallSet set) {
  switch (set) {
    case BallSet::kPool:
      return "pool";
    case BallSet::kSnooker:
      return "snooker";
    case BallSet::kCarom:
      return "carom";
    case BallSet::kBlackball:
      return "blackball";
  }
  return "pool";
}

}  // namespace billiard::estimator
