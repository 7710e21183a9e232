// The rules' verdict on one shot of a nine-ball game the table simulator plays (RunGame): the
// fouls of nine-ball (WPA Rules of Play, as choice::PlayGame judges them) and what follows from
// them, from the shot's facts alone.
//
// Fouls, the first that applies: the cue ball dropped ("scratch"); it touched no ball ("no
// contact"); away from the break, the first ball it touched was not the lowest on the table
// ("first contact N, not the lowest M"). A called ball dropped in its pocket counts only on a
// legal shot; the 9 dropped on a legal shot wins the rack, on a foul it goes back on the foot
// spot (or the nearest free place behind it toward the foot rail).
//
// One function, its inputs and outputs explicit, so that a shared ruleset can take its place.
//
// Module: billiard::table_sim_node.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::table_sim_node {

// What a game shot was and what the table did with it, as the rules need it.
struct GameShotFacts {
  // The call: the break, or else the ball the cue ball must meet first (the lowest object ball
  // on the table before the shot), and whether the called ball dropped in the called pocket.
  bool break_shot = false;
  int lowest = -1;
  bool called_potted = false;
  int first_contact = -1;   // the ball the cue ball touched first (the truth's id), -1 if none
  std::vector<int> potted;  // the object balls dropped, ascending
  bool scratch = false;     // the cue ball dropped
};

struct GameVerdict {
  std::string foul_reason;     // "" for a legal shot
  bool called_potted = false;  // the called ball dropped in its pocket on a legal shot
  bool nine_legal = false;     // the 9 dropped on a legal shot: the rack is won
  // Where the 9 goes back, when it dropped on a foul: the foot spot (x = 3/4 length), or the
  // nearest free place from it toward the foot rail.
  std::optional<Eigen::Vector2d> nine_spot;
};

// The verdict on `shot` played on `geometry` with balls of `radius`, `left` the balls at rest
// on the table after it (where a respotted 9 must be clear of).
GameVerdict JudgeNineBallShot(const GameShotFacts& shot, const table::TableGeometry& geometry,
                              double radius, const std::vector<table::SceneBall>& left);

}  // namespace billiard::table_sim_node
