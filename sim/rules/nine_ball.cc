#include "sim/rules/nine_ball.h"

#include <algorithm>
#include <string>

namespace billiard::rules {

namespace {

// A wrong first contact: the first ball met not the lowest on the table (on the break too).
std::string WrongFirstContact(const Shot& shot) {
  const std::vector<int>& lowest = shot.constraints.legal_targets;
  if (lowest.empty() || shot.first_contact == lowest.front()) return "";
  return "first contact " + std::to_string(shot.first_contact) + ", not the lowest " +
         std::to_string(lowest.front());
}

// The fouls of a shot that is not a push-out, in the order they are called.
std::string Foul(const Shot& shot) {
  std::string foul = PocketGameFoul(shot);
  if (foul.empty()) foul = WrongFirstContact(shot);
  if (foul.empty()) foul = shot.break_shot ? IllegalBreak(shot) : NoRailAfterContact(shot);
  return foul;
}

// A push-out's fouls: a miscue or a scratch alone (it need meet no ball), or one declared when
// the rules do not allow it.
std::string PushOutFoul(const Shot& shot) {
  if (!shot.constraints.push_out_allowed) return "push-out not allowed";
  if (!shot.struck) return "miscue";
  return shot.scratch ? "scratch" : "";
}

Respot NineOnTheFootSpot(const table::TableGeometry& table) {
  return {NineBall::kNine, FootSpot(table), Eigen::Vector2d::UnitX()};
}

}  // namespace

std::vector<int> NineBall::LegalTargets(const std::vector<table::SceneBall>& balls) const {
  std::vector<int> ids = ObjectBalls(balls);
  if (ids.size() > 1) ids.resize(1);
  return ids;
}

bool NineBall::RackOver(const std::vector<table::SceneBall>& balls) const {
  if (LegalTargets(balls).empty()) return true;
  return std::none_of(balls.begin(), balls.end(),
                      [](const table::SceneBall& b) { return b.id == kNine; });
}

Judgement NineBall::Judge(const table::TableGeometry& table, const Shot& shot) const {
  const bool nine_potted = Contains(shot.potted, kNine);
  if (shot.push_out) {
    Judgement j = PocketGameJudgement(shot, PushOutFoul(shot));
    j.turn_over = true;
    j.opponent_may_pass = j.legal();
    if (nine_potted) j.respots.push_back(NineOnTheFootSpot(table));
    return j;
  }
  Judgement j = PocketGameJudgement(shot, Foul(shot));
  if (j.foul && nine_potted) j.respots.push_back(NineOnTheFootSpot(table));
  if (j.legal() && nine_potted) {
    j.rack_over = j.shooter_wins = true;
    j.rack_reason = "9 potted legally";
  } else if (shot.object_balls_left == 0 && j.respots.empty()) {
    j.rack_over = true;
    j.shooter_wins = j.legal();
    j.rack_reason = "no object ball left";
  }
  return j;
}

Eigen::Vector2d FootSpot(const table::TableGeometry& table) {
  return {0.75 * table.length, 0.5 * table.width};
}

}  // namespace billiard::rules
