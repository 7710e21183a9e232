#include "planner/game/match_report.h"

namespace billiard::game {

namespace {

constexpr char kScratch[] = "scratch";  // the rules' foul reason (sim/rules/README.md)

bool Kept(const ShotRecord& break_shot) { return !break_shot.foul && !break_shot.potted.empty(); }

// Whether `player` had a visit in `rack` after its break (the breaker's first continuing the
// break when the break kept the table), and whether it won the rack in the first it had.
struct FirstVisit {
  bool had = false;
  bool cleared = false;
};

FirstVisit FirstVisitOf(const RackResult& rack, int player) {
  FirstVisit v;
  std::size_t i = Kept(rack.shots.front()) ? 0 : 1;
  while (i < rack.shots.size() && rack.shots[i].player != player) ++i;
  if (i == rack.shots.size()) return v;
  v.had = true;
  while (i < rack.shots.size() && rack.shots[i].player == player) ++i;
  v.cleared = i == rack.shots.size() && rack.winner == player;
  return v;
}

}  // namespace

MatchBreaks BreaksOf(const MatchRecord& match) {
  MatchBreaks b;
  for (const RackResult& rack : match.racks) {
    if (rack.shots.empty() || !rack.shots.front().break_shot) continue;
    const ShotRecord& shot = rack.shots.front();
    ++b.racks;
    b.legal += !shot.foul;
    b.potted += !shot.potted.empty();
    b.kept += Kept(shot);
    b.scratches += shot.foul && shot.foul_reason == kScratch;
  }
  return b;
}

std::array<OneVisitClears, 2> OneVisitClearsOf(const MatchRecord& match) {
  std::array<OneVisitClears, 2> clears;
  for (const RackResult& rack : match.racks) {
    if (rack.shots.empty() || rack.shots.front().foul) continue;
    for (int player = 0; player < 2; ++player) {
      const FirstVisit v = FirstVisitOf(rack, player);
      clears[player].chances += v.had;
      clears[player].clears += v.cleared;
    }
  }
  return clears;
}

}  // namespace billiard::game
