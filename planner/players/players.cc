#include "planner/players/players.h"

#include <stdexcept>

#include "planner/players/easiest_looking_player.h"
#include "planner/players/ours_player.h"

namespace billiard::players {

std::vector<std::string> PlayerNames() {
  return {Ours().Name(), Ours(false).Name(), EasiestLooking().Name()};
}

std::unique_ptr<Player> MakePlayer(const std::string& name) {
  if (name == Ours().Name()) return std::make_unique<Ours>();
  if (name == kOursNoSafety) return std::make_unique<Ours>(true, false, kOursNoSafety);
  if (name == kOursOneLevel) return std::make_unique<Ours>(true, true, kOursOneLevel, false);
  if (name == Ours(false).Name()) return std::make_unique<Ours>(false);
  if (name == EasiestLooking().Name()) return std::make_unique<EasiestLooking>();
  std::string known;
  for (const std::string& n : PlayerNames()) known += (known.empty() ? "" : ", ") + n;
  known += std::string(", ") + kOursNoSafety + ", " + kOursOneLevel;
  throw std::invalid_argument("unknown player '" + name + "' (" + known + ")");
}

}  // namespace billiard::players
