#include "planner/node/ball_numbers.h"

#include <algorithm>
#include <map>
#include <vector>

#include "planner/node/named_ball.h"

namespace billiard::planner_node {

std::unordered_map<int32_t, int> BallNumbers(const table_state_t& table, int32_t cue) {
  constexpr int kHighestNumber = 15;
  std::vector<const ball_state_t*> balls = BallsOf(table);
  std::sort(balls.begin(), balls.end(),
            [](const ball_state_t* a, const ball_state_t* b) { return a->ball_id < b->ball_id; });
  // Each number's surest claimant: first among the confident, then, for the numbers still
  // free, among the others (a faint stripe is still likelier its own number than any other).
  std::map<int, const ball_state_t*> claimant;
  std::unordered_map<int32_t, int> number;
  for (const bool confident : {true, false}) {
    std::map<int, const ball_state_t*> surest;
    for (const ball_state_t* b : balls) {
      if (b->ball_id == cue || number.count(b->ball_id) || b->ball_class < 1 ||
          b->ball_class > kHighestNumber || claimant.count(b->ball_class) ||
          (b->class_confidence >= kMinClassConfidence) != confident) {
        continue;
      }
      const ball_state_t*& s = surest[b->ball_class];
      if (s == nullptr || b->class_confidence > s->class_confidence) s = b;
    }
    for (const auto& [n, b] : surest) {
      claimant[n] = b;
      number[b->ball_id] = n;
    }
  }
  number[cue] = 0;
  int free = 1;
  for (const ball_state_t* b : balls) {
    if (number.count(b->ball_id)) continue;
    while (free <= kHighestNumber && claimant.count(free)) ++free;
    number[b->ball_id] = free++;
  }
  return number;
}

}  // namespace billiard::planner_node
