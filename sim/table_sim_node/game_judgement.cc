#include "sim/table_sim_node/game_judgement.h"

#include <algorithm>

#include "sim/table/rack.h"
#include "sim/table_sim_node/session_balls.h"

namespace billiard::table_sim_node {

GameVerdict JudgeNineBallShot(const GameShotFacts& shot, const table::TableGeometry& geometry,
                              double radius, const std::vector<table::SceneBall>& left) {
  GameVerdict verdict;
  // Nine-ball's fouls (WPA Rules of Play), as choice::PlayGame judges them.
  if (shot.scratch) {
    verdict.foul_reason = "scratch";
  } else if (shot.first_contact < 0) {
    verdict.foul_reason = "no contact";
  } else if (!shot.break_shot && shot.first_contact != shot.lowest) {
    verdict.foul_reason = "first contact " + std::to_string(shot.first_contact) +
                          ", not the lowest " + std::to_string(shot.lowest);
  }
  const bool foul = !verdict.foul_reason.empty();
  verdict.called_potted = shot.called_potted && !foul;
  const bool nine = std::find(shot.potted.begin(), shot.potted.end(), 9) != shot.potted.end();
  verdict.nine_legal = nine && !foul;
  if (nine && foul) {
    verdict.nine_spot =
        table::FreeSpotFrom(geometry, radius, left, {0.75 * geometry.length, 0.5 * geometry.width},
                            {kPlacementStep, 0.0}, kPlacementClearance);
  }
  return verdict;
}

}  // namespace billiard::table_sim_node
