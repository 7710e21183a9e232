#include "planner/game/break_scratches.h"

#include "sim/table/rail_contacts.h"

namespace billiard::game {

namespace {

constexpr int kCueBall = 0;

// Whether `e` is a ball-ball impact of the cue ball (either side of the pair).
bool CueBallMeetsBall(const table::TableEvent& e) {
  return e.type == table::EventType::kBallBall && (e.ball == kCueBall || e.other == kCueBall);
}

}  // namespace

const char* ScratchPathName(ScratchPath path) {
  switch (path) {
    case ScratchPath::kDirect:
      return "direct";
    case ScratchPath::kOffRails:
      return "off_rails";
    case ScratchPath::kHanging:
      return "hanging";
    case ScratchPath::kNoBall:
      return "no_ball";
  }
  return "";
}

std::optional<ScratchRecord> CueBallScratch(const std::vector<table::TableEvent>& events,
                                            bool scratched) {
  ScratchRecord r;
  for (const table::TableEvent& e : events) {
    if (CueBallMeetsBall(e)) {
      ++r.balls_met;
      r.rails = 0;  // rails count from the last ball contact
    } else if (e.ball == kCueBall && table::IsRailContact(e.type)) {
      ++r.rails;
    } else if (e.ball == kCueBall && e.type == table::EventType::kBallPocket) {
      r.pocket = e.pocket;
      r.path = r.balls_met == 0 ? ScratchPath::kNoBall
               : r.rails == 0   ? ScratchPath::kDirect
                                : ScratchPath::kOffRails;
      return r;
    }
  }
  if (!scratched) return std::nullopt;
  r.path = ScratchPath::kHanging;
  return r;
}

ScratchTally TallyBreakScratches(const BreakSetting& setting, const Break& b, int samples,
                                 std::uint64_t seed, batch::ThreadPool& pool) {
  const auto records = pool.Map(static_cast<std::size_t>(samples), [&](std::size_t sample) {
    std::vector<table::TableEvent> events;
    const BreakOutcome outcome = PlayBreak(setting, b, seed, sample, &events);
    return CueBallScratch(events, outcome.scratch);
  });
  ScratchTally tally;
  for (const auto& record : records) {
    ++tally.samples;
    if (!record.ok() || !*record.value) continue;  // a throw, or no scratch
    const ScratchRecord& r = **record.value;
    const std::string path = ScratchPathName(r.path);
    ++tally.scratches;
    ++tally.by_pocket_and_path[{r.pocket, path}];
    ++tally.by_path[path];
    tally.balls_met[path] += r.balls_met;
  }
  return tally;
}

}  // namespace billiard::game
