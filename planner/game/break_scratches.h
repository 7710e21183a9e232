// Where and by which path a break's cue ball scratches: read from the break's own events.
//
// Why: the remedy for a scratching break depends on how the cue ball gets to the pocket. A cue
// ball that goes on from the rack into a pocket with no rail between (it follows through the
// apex, or a ball of the rack sends it there) is stopped by less follow at the apex (a stun or
// draw tip, a softer stroke); one that rebounds off one or more rails into a pocket is steered
// by where it leaves the rack (the cue ball's place, a cut on the apex). So each scratch of a
// break on seeded racks (the samples of break_search.h, the same racks and noise) is classed by
// the cue ball's events between its last ball contact and its drop, and counted by pocket.
//
// The paths (`ScratchPath`):
//  - kDirect: no cushion or jaw between the cue ball's last ball contact and the drop;
//  - kOffRails: one or more cushions or jaws between them (`rails` counts them);
//  - kHanging: no drop in the simulation, the cue ball at rest past a pocket's mouth line
//    (choice::DropHangingBalls dropped it);
//  - kNoBall: the cue ball dropped without meeting a ball (a miss of the rack).
//
// Module: billiard::game.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "planner/game/break_search.h"
#include "sim/batch/thread_pool.h"
#include "sim/table/table_simulation.h"

namespace billiard::game {

enum class ScratchPath { kDirect, kOffRails, kHanging, kNoBall };

// "direct", "off_rails", "hanging", "no_ball".
const char* ScratchPathName(ScratchPath path);

// One scratch, as the cue ball's events tell it.
struct ScratchRecord {
  std::string pocket;  // the pocket's name ("" for kHanging: the events name none)
  ScratchPath path = ScratchPath::kDirect;
  int balls_met = 0;  // the cue ball's ball contacts before the drop
  int rails = 0;      // its cushion and jaw contacts after its last ball contact
};

// The scratch `events` show for the cue ball (id 0); none when the cue ball did not drop in
// them and `scratched` is false. A scratch with no drop in the events is kHanging.
std::optional<ScratchRecord> CueBallScratch(const std::vector<table::TableEvent>& events,
                                            bool scratched);

// The scratches of break `b` on racks [0, samples) of `seed`, counted by pocket and path.
struct ScratchTally {
  int samples = 0;
  int scratches = 0;
  // (pocket, path name) -> scratches; the pocket "" for the hanging ones.
  std::map<std::pair<std::string, std::string>, int> by_pocket_and_path;
  std::map<std::string, int> by_path;    // path name -> scratches
  std::map<std::string, int> balls_met;  // path name -> the sum of their balls_met
};

ScratchTally TallyBreakScratches(const BreakSetting& setting, const Break& b, int samples,
                                 std::uint64_t seed, batch::ThreadPool& pool);

}  // namespace billiard::game
