#include "sim/table/rail_contacts.h"

#include <algorithm>

namespace billiard::table {

bool IsRailContact(EventType type) {
  return type == EventType::kBallCushion || type == EventType::kBallJaw;
}

std::vector<int> BallsToRailAfterFirstContact(const std::vector<TableEvent>& events, int id) {
  std::vector<int> ids;
  bool contact = false;
  for (const TableEvent& e : events) {
    if (!contact) {
      contact = e.type == EventType::kBallBall && (e.ball == id || e.other == id);
    } else if (IsRailContact(e.type)) {
      ids.push_back(e.ball);
    }
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

}  // namespace billiard::table
