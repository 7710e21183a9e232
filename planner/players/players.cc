#include "planner/players/players.h"

#include <stdexcept>

#include "planner/players/easiest_looking_player.h"
#include "planner/players/ours_player.h"

namespace billiard::players {

std::vector<std::string> PlayerNames() {
  return {Ours().Name(), Ours(false).Name(), EasiestLooking().Name()};
}

std::vector<std::string> KnownPlayerNames() {
  std::vector<std::string> names = PlayerNames();
  names.insert(names.end(), {kOursNoSafety, kOursOneLevel});
  return names;
}

std::string KnownPlayerList() {
  std::string list;
  for (const std::string& n : KnownPlayerNames()) list += (list.empty() ? "" : ", ") + n;
  return list;
}

std::unique_ptr<Player> MakePlayer(const std::string& name) {
  if (name == Ours().Name()) return std::make_unique<Ours>();
  if (name == kOursNoSafety) return std::make_unique<Ours>(true, false, kOursNoSafety, false);
  if (name == kOursOneLevel) return std::make_unique<Ours>(true, true, kOursOneLevel, false);
  if (name == Ours(false).Name()) return std::make_unique<Ours>(false);
  if (name == EasiestLooking().Name()) return std::make_unique<EasiestLooking>();
  throw std::invalid_argument("unknown player '" + name + "' (" + KnownPlayerList() + ")");
}

}  // namespace billiard::players
