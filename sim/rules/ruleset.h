// A ruleset: the referee of a pocket game. It turns a shot as played into its judgement (legal
// or a foul and why, whether the visit and the rack are over, the balls the rules put back)
// and says what the next shot may do (ball in hand, the balls the cue ball may hit first).
//
// The shape is pooltool's `ruleset/` (Kiefl 2024: a ruleset's legality, turn over, game over
// and the next shot's constraints, one file per game): the table simulator (the referee of the
// closed loop) and the planner's games judge with the same code, and a game is a file of its
// own (any.h, nine_ball.h; rules.h names them).
//
// A shot is judged alone here (a visit lasts while its shots pot legally); what
// a rack between two players keeps from shot to shot (whose turn, the fouls in a row, the
// groups) is rack_state.h's. Nothing here plays or simulates a shot: what the shot did (its
// first contact, the balls it potted, the scratch) comes from the table simulation that played
// it.
//
// Module: billiard::rules. Includes the table (its geometry, the scene's balls) and the physics.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::rules {

// What the rules allow a shot: pooltool's ShotConstraints.
struct Constraints {
  bool ball_in_hand = false;       // the cue ball may be placed anywhere on the table first
  std::vector<int> legal_targets;  // the object balls the cue ball may hit first, ascending
  bool call_required = false;      // a pot counts only as called, ball and pocket (eight-ball)
  bool push_out_allowed = false;   // the shot may be a push-out (nine-ball, after the break)
};

// A called shot: the ball and the pocket named before the stroke (a pocket's name in
// TableGeometry), -1 and "" when none was called.
struct Call {
  int ball = -1;
  std::string pocket;
};

// A shot as it was played.
struct Shot {
  Constraints constraints;  // what the rules allowed it (its legal first contacts)
  bool break_shot = false;
  bool struck = true;       // false: no stroke reached the ball (the cue refused it: a miscue)
  int first_contact = -1;   // the first ball the cue ball touched, -1 none
  std::vector<int> potted;  // the object balls that dropped
  std::vector<std::string> pockets;  // the pocket each of `potted` dropped in, in its order
  bool scratch = false;     // the cue ball dropped
  int object_balls_left = 0;  // object balls at rest on the table after it
  // The balls (the cue ball's id 0 among them) that met a rail after the cue ball's first
  // contact, each once (table::BallsToRailAfterFirstContact).
  std::vector<int> to_rail_after_contact;
  Call call;              // the player's call, when one was made
  bool push_out = false;  // declared a push-out (Constraints::push_out_allowed)
};

// A ball the rules put back on the table: on `spot`, or the first free place from it in the
// direction `toward` (the referee steps along it; PlaceRespotted).
struct Respot {
  int ball = -1;
  Eigen::Vector2d spot = Eigen::Vector2d::Zero();
  Eigen::Vector2d toward = Eigen::Vector2d::UnitX();
};

// The judgement of a shot: pooltool's ShotInfo.
struct Judgement {
  bool foul = false;
  // Why, when a foul: "miscue", "scratch", "no contact", or the game's own ("first contact 3,
  // not the lowest 2" under nine-ball). Empty when legal.
  std::string foul_reason;
  bool turn_over = false;  // the visit ends: a foul, or nothing potted
  bool rack_over = false;
  // With rack_over: whether the player at the table won it (false: lost it, eight-ball's 8
  // potted early or on a foul), and why the rack ended ("9 potted legally").
  bool shooter_wins = false;
  std::string rack_reason;
  // Eight-ball on an open table: the called ball potted legally, whose group the shooter takes;
  // -1 when none.
  int group_ball = -1;
  // After a push-out the incoming player may take the table or hand it back (RackState).
  bool opponent_may_pass = false;
  // The next shot: with ball in hand (after a foul), and the balls put back before it.
  bool ball_in_hand = false;
  std::vector<Respot> respots;

  bool legal() const { return !foul; }
};

class Ruleset {
 public:
  virtual ~Ruleset() = default;

  // "any", "nine-ball".
  virtual const char* Name() const = 0;

  // The object balls the cue ball may hit first (and a called shot pot) on `balls`: ids > 0,
  // ascending.
  virtual std::vector<int> LegalTargets(const std::vector<table::SceneBall>& balls) const = 0;

  // Whether nothing is left to play on `balls` as they lie (a lookahead's table after a pot).
  virtual bool RackOver(const std::vector<table::SceneBall>& balls) const = 0;

  // The judgement of `shot`, played on `table`.
  virtual Judgement Judge(const table::TableGeometry& table, const Shot& shot) const = 0;

  // Whether a shot must call its ball and pocket (eight-ball).
  virtual bool CallsShots() const { return false; }

  // The fouls in a row (by one player, without a legal shot between) that lose the rack; 0:
  // none do.
  virtual int FoulsThatLose() const { return 0; }

  // Whether the shot after the break may be a push-out (nine-ball).
  virtual bool PushOutAfterBreak() const { return false; }
};

// The object balls of `balls` (ids > 0), ascending.
std::vector<int> ObjectBalls(const std::vector<table::SceneBall>& balls);

// The fouls of every pocket game, in the order they are called: no stroke ("miscue"), the cue
// ball potted ("scratch"), the cue ball touching no ball ("no contact"); "" when none.
std::string PocketGameFoul(const Shot& shot);

// The judgement common to the pocket games of a single player at the table, given the foul
// found (`foul_reason`, "" when legal): a foul gives the next shot ball in hand, and the visit
// ends on a foul or when nothing drops. Respots and the rack's end are the game's.
Judgement PocketGameJudgement(const Shot& shot, std::string foul_reason);

// No Rail after Contact (WPA Rules of Play, Standard Fouls): a shot that met a ball, potted
// nothing and drove no ball to a rail after the contact is a foul, "no rail after contact";
// "" otherwise.
std::string NoRailAfterContact(const Shot& shot);

// The legal break of nine-ball and eight-ball (WPA Rules of Play; FastFiz's eight-ball counts
// rail contacts alike): a ball potted, or at least kBreakRailBalls object balls driven to a
// rail; the foul's reason ("break: no ball potted and 2 object balls to a rail, not 4"), ""
// when legal.
inline constexpr int kBreakRailBalls = 4;
std::string IllegalBreak(const Shot& shot);

// Whether a rack was run out: cleared in one turn at the table from the first shot after the
// break, the breaker's where the break kept the table (the break and the rest in one visit), the
// incoming player's where a dry or fouled break gave it up. `cleared` in `visits` visits, the
// first shot after the break in visit `first_visit_after_break` (0 when the break ended the
// rack, which is a run-out of one shot).
bool RunOut(bool cleared, int visits, int first_visit_after_break);

// The visit of the first of `shots` (records with `break_shot` and `visit`, as the games and the
// table simulator keep them) after the break, the first shot's where nobody broke; 0 when none.
template <class ShotRecords>
int FirstVisitAfterBreak(const ShotRecords& shots) {
  for (const auto& shot : shots) {
    if (!shot.break_shot) return shot.visit;
  }
  return 0;
}

// Whether `ids` holds `id`.
bool Contains(const std::vector<int>& ids, int id);

// `balls` with each of `respots` placed on the table: on its spot, or the first free place
// (table::FreeSpotFrom, at least `clearance` from every ball) in steps of `step` toward its
// direction.
void PlaceRespotted(const table::TableGeometry& table, double radius,
                    const std::vector<Respot>& respots, double step, double clearance,
                    std::vector<table::SceneBall>* balls);

}  // namespace billiard::rules
