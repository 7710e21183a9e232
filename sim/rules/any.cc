#include "sim/rules/any.h"

namespace billiard::rules {

std::vector<int> AnyBall::LegalTargets(const std::vector<table::SceneBall>& balls) const {
  return ObjectBalls(balls);
}

bool AnyBall::RackOver(const std::vector<table::SceneBall>& balls) const {
  return LegalTargets(balls).empty();
}

Judgement AnyBall::Judge(const table::TableGeometry& /*table*/, const Shot& shot) const {
  Judgement j = PocketGameJudgement(shot, PocketGameFoul(shot));
  j.rack_over = shot.object_balls_left == 0;
  return j;
}

}  // namespace billiard::rules
