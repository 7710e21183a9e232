#include "sim/rules/eight_ball.h"

#include <algorithm>
#include <string>

#include "sim/rules/nine_ball.h"

namespace billiard::rules {

namespace {

constexpr int kLastSolid = 7;
constexpr int kLastStripe = 15;

// What the legal first contacts are, named for a foul's reason.
std::string TargetsName(const std::vector<int>& targets) {
  if (targets == std::vector<int>{EightBall::kEight}) return "the 8";
  const bool solids = std::any_of(targets.begin(), targets.end(),
                                  [](int id) { return GroupOf(id) == Group::kSolids; });
  const bool stripes = std::any_of(targets.begin(), targets.end(),
                                   [](int id) { return GroupOf(id) == Group::kStripes; });
  if (solids && stripes) return "a solid or a stripe";
  return solids ? "a solid" : "a stripe";
}

// Whether `shot` potted its called ball, a legal target, in the called pocket.
bool CalledPot(const Shot& shot) {
  if (!Contains(shot.constraints.legal_targets, shot.call.ball)) return false;
  for (std::size_t i = 0; i < shot.potted.size() && i < shot.pockets.size(); ++i) {
    if (shot.potted[i] == shot.call.ball && shot.pockets[i] == shot.call.pocket) return true;
  }
  return false;
}

// The fouls of a shot after the break, in the order they are called.
std::string Foul(const Shot& shot) {
  std::string foul = PocketGameFoul(shot);
  if (!foul.empty()) return foul;
  const std::vector<int>& targets = shot.constraints.legal_targets;
  if (!Contains(targets, shot.first_contact)) {
    return "first contact " + std::to_string(shot.first_contact) + ", not " + TargetsName(targets);
  }
  if (!CalledPot(shot) && shot.to_rail_after_contact.empty()) return "no rail after contact";
  return "";
}

// The break: the pocket games' fouls, then its own; the 8 potted on it spotted.
Judgement JudgeBreak(const table::TableGeometry& table, const Shot& shot) {
  std::string foul = PocketGameFoul(shot);
  if (foul.empty()) foul = IllegalBreak(shot);
  Judgement j = PocketGameJudgement(shot, std::move(foul));
  if (Contains(shot.potted, EightBall::kEight)) {
    j.respots.push_back({EightBall::kEight, FootSpot(table), Eigen::Vector2d::UnitX()});
  }
  return j;
}

// The 8 potted after the break: the rack over, won or lost and why.
void EightPotted(const Shot& shot, Judgement* j) {
  j->rack_over = true;
  const bool cleared = shot.constraints.legal_targets == std::vector<int>{EightBall::kEight};
  if (j->foul) {
    j->rack_reason = "8 potted on a foul (" + j->foul_reason + ")";
  } else if (!cleared) {
    j->rack_reason = "8 potted before its group was cleared";
  } else if (!CalledPot(shot)) {
    j->rack_reason = "8 potted, not as called";
  } else {
    j->shooter_wins = true;
    j->rack_reason = "8 potted as called";
  }
}

}  // namespace

Group GroupOf(int id) {
  if (id >= 1 && id <= kLastSolid) return Group::kSolids;
  if (id > EightBall::kEight && id <= kLastStripe) return Group::kStripes;
  return Group::kOpen;
}

Group OtherGroup(Group group) {
  switch (group) {
    case Group::kSolids: return Group::kStripes;
    case Group::kStripes: return Group::kSolids;
    case Group::kOpen: return Group::kOpen;
  }
  return Group::kOpen;
}

const char* EightBall::Name() const {
  switch (group_) {
    case Group::kSolids: return "eight-ball-solids";
    case Group::kStripes: return "eight-ball-stripes";
    case Group::kOpen: return "eight-ball";
  }
  return "eight-ball";
}

std::vector<int> EightBall::LegalTargets(const std::vector<table::SceneBall>& balls) const {
  std::vector<int> targets;
  bool eight = false;
  for (int id : ObjectBalls(balls)) {
    eight = eight || id == kEight;
    const Group g = GroupOf(id);
    if (g != Group::kOpen && (group_ == Group::kOpen || g == group_)) targets.push_back(id);
  }
  if (targets.empty() && eight) targets.push_back(kEight);
  return targets;
}

bool EightBall::RackOver(const std::vector<table::SceneBall>& balls) const {
  return std::none_of(balls.begin(), balls.end(),
                      [](const table::SceneBall& b) { return b.id == kEight; });
}

Judgement EightBall::Judge(const table::TableGeometry& table, const Shot& shot) const {
  if (shot.break_shot) return JudgeBreak(table, shot);
  Judgement j = PocketGameJudgement(shot, Foul(shot));
  const bool called = j.legal() && CalledPot(shot);
  j.turn_over = !called;
  if (Contains(shot.potted, kEight)) {
    EightPotted(shot, &j);
  } else if (called && group_ == Group::kOpen) {
    j.group_ball = shot.call.ball;
  }
  return j;
}

}  // namespace billiard::rules
