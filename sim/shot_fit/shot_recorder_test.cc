#include "sim/shot_fit/shot_recorder.h"

#include <gtest/gtest.h>

namespace billiard::shot_fit {
namespace {

// A loop's messages cut into shots: the balls of the last state before the strike at rest at
// time 0, the later states as samples, a track that appears mid-shot not followed, a strike
// commanded again (same utime) ignored, one of an unknown track skipped.
TEST(ShotRecorder, CutsStrikesAndStatesIntoShots) {
  ShotRecorder recorder;
  recorder.State(1000000, {{7, {1.0, 0.5}}, {9, {2.0, 0.5}}});
  recorder.Strike(1020000, 7);
  recorder.State(1040000, {{7, {1.1, 0.5}}, {9, {2.0, 0.5}}, {12, {0.3, 0.3}}});
  recorder.Strike(1020000, 7);  // the same answer again
  recorder.State(1060000, {{7, {1.2, 0.5}}});
  recorder.Strike(1070000, 42);  // no such track: closes the shot, starts none
  recorder.Finish();
  ASSERT_EQ(recorder.shots().size(), 1u);
  EXPECT_EQ(recorder.skipped(), 1);
  EXPECT_EQ(recorder.strike_utimes(), (std::vector<std::int64_t>{1020000}));
  const TrackedShot& shot = recorder.shots()[0];
  ASSERT_EQ(shot.balls.size(), 2u);
  EXPECT_EQ(shot.cue, 0u);
  EXPECT_EQ(shot.balls[0].t, (std::vector<double>{0.0, 0.04, 0.06}));
  EXPECT_DOUBLE_EQ(shot.balls[0].position[2].x(), 1.2);
  EXPECT_EQ(shot.balls[1].t.size(), 2u);
}

}  // namespace
}  // namespace billiard::shot_fit
