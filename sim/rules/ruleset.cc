#include "sim/rules/ruleset.h"

#include <algorithm>
#include <string>
#include <utility>

#include "sim/table/rack.h"

namespace billiard::rules {

std::vector<int> ObjectBalls(const std::vector<table::SceneBall>& balls) {
  std::vector<int> ids;
  for (const table::SceneBall& b : balls) {
    if (b.id > 0) ids.push_back(b.id);
  }
  std::sort(ids.begin(), ids.end());
  return ids;
}

std::string PocketGameFoul(const Shot& shot) {
  if (!shot.struck) return "miscue";
  if (shot.scratch) return "scratch";
  if (shot.first_contact < 0) return "no contact";
  return "";
}

Judgement PocketGameJudgement(const Shot& shot, std::string foul_reason) {
  Judgement j;
  j.foul = !foul_reason.empty();
  j.foul_reason = std::move(foul_reason);
  j.turn_over = j.foul || shot.potted.empty();
  j.ball_in_hand = j.foul;
  return j;
}

std::string NoRailAfterContact(const Shot& shot) {
  if (shot.first_contact < 0 || !shot.potted.empty() || !shot.to_rail_after_contact.empty()) {
    return "";
  }
  return "no rail after contact";
}

std::string IllegalBreak(const Shot& shot) {
  if (!shot.potted.empty()) return "";
  const auto railed = static_cast<int>(std::count_if(
      shot.to_rail_after_contact.begin(), shot.to_rail_after_contact.end(),
      [](int id) { return id > 0; }));
  if (railed >= kBreakRailBalls) return "";
  return "break: no ball potted and " + std::to_string(railed) + " object balls to a rail, not " +
         std::to_string(kBreakRailBalls);
}

bool RunOut(bool cleared, int visits, int first_visit_after_break) {
  return cleared && visits == std::max(1, first_visit_after_break);
}

bool Contains(const std::vector<int>& ids, int id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

void PlaceRespotted(const table::TableGeometry& table, double radius,
                    const std::vector<Respot>& respots, double step, double clearance,
                    std::vector<table::SceneBall>* balls) {
  for (const Respot& r : respots) {
    table::SceneBall ball;
    ball.id = r.ball;
    ball.state.head<2>() =
        table::FreeSpotFrom(table, radius, *balls, r.spot, step * r.toward, clearance);
    balls->push_back(ball);
  }
}

}  // namespace billiard::rules
