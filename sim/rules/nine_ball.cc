#include "sim/rules/nine_ball.h"

#include <algorithm>
#include <string>

namespace billiard::rules {

namespace {

bool Contains(const std::vector<int>& ids, int id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

// A wrong first contact: not on the break, the first ball met not the lowest on the table.
std::string WrongFirstContact(const Shot& shot) {
  const std::vector<int>& lowest = shot.constraints.legal_targets;
  if (shot.break_shot || lowest.empty() || shot.first_contact == lowest.front()) return "";
  return "first contact " + std::to_string(shot.first_contact) + ", not the lowest " +
         std::to_string(lowest.front());
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
  std::string foul = PocketGameFoul(shot);
  if (foul.empty()) foul = WrongFirstContact(shot);
  Judgement j = PocketGameJudgement(shot, std::move(foul));
  const bool nine_potted = Contains(shot.potted, kNine);
  if (j.foul && nine_potted) j.respots.push_back({kNine, FootSpot(table), Eigen::Vector2d::UnitX()});
  j.rack_over = (j.legal() && nine_potted) || (shot.object_balls_left == 0 && j.respots.empty());
  return j;
}

Eigen::Vector2d FootSpot(const table::TableGeometry& table) {
  return {0.75 * table.length, 0.5 * table.width};
}

}  // namespace billiard::rules
