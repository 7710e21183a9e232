#include "tools/python/match_functions.h"

#include <pybind11/stl.h>

#include <array>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "planner/game/match.h"
#include "planner/game/match_summary.h"
#include "sim/batch/thread_pool.h"
#include "sim/params/execution_noise.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "tools/python/conversions.h"

namespace billiard::python {

namespace {

// What names a match, as `billiard match`'s options do.
struct MatchArgs {
  std::string game;
  std::vector<std::string> players;
  std::string noise;
  std::uint64_t seed = 1;
  int shot_limit = 200;
};

// The match's options as `billiard match` makes them; ValueError naming the argument at fault.
game::MatchOptions OptionsOf(const MatchArgs& args) {
  if (args.players.size() != 2) throw py::value_error("players: give two names, [A, B]");
  if (args.shot_limit < 1) throw py::value_error("shot_limit must be >= 1");
  try {
    // One rack: play_rack plays a rack by its index, whatever the match's length.
    return game::OptionsOf({args.game, {args.players[0], args.players[1]}, args.noise, args.seed,
                            /*racks=*/1, args.shot_limit});
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
}

py::dict TallyDict(const game::PlayerTally& t) {
  py::dict d;
  d["attempts"] = t.attempts;
  d["pots"] = t.pots;
  d["safeties"] = t.safeties;
  d["safeties_that_worked"] = t.safeties_that_worked;
  d["fouls"] = t.fouls;
  d["foul_reasons"] = t.foul_reasons;
  d["decisions_us"] = t.decisions_us;
  return d;
}

py::dict RackDict(const game::RackResult& r, const std::array<game::PlayerTally, 2>& tallies) {
  py::dict d;
  d["rack"] = r.rack;
  d["breaker"] = r.breaker;
  d["winner"] = r.winner < 0 ? py::object(py::none()) : py::cast(r.winner);
  d["reason"] = r.reason;
  d["break_and_run"] = r.break_and_run;
  d["shots"] = r.shots.size();
  d["players"] = py::make_tuple(TallyDict(tallies[0]), TallyDict(tallies[1]));
  return d;
}

// play_rack: rack `rack` of the match, on `threads` threads (the record does not depend on them).
py::dict PlayRack(const MatchArgs& args, int rack, int threads) {
  if (rack < 0) throw py::value_error("rack must be >= 0");
  if (threads < 0) throw py::value_error("threads must be >= 0");
  const game::MatchOptions options = OptionsOf(args);
  const physics::ModelParameters params = Params(params::kDefaultParameterSet);
  const table::TableGeometry table = Table(params::kDefaultTable);
  batch::ThreadPool pool(threads > 0 ? threads : batch::DefaultThreadCount());
  std::array<game::PlayerTally, 2> tallies;
  game::RackResult result;
  {
    py::gil_scoped_release release;  // seconds of simulation: a Dask worker's own threads run
    result = game::PlayRack(table, params, rack, options, pool, &tallies);
  }
  return RackDict(result, tallies);
}

// Field `key` of a record's dict as a T; ValueError naming the record otherwise.
template <typename T>
T Field(const py::dict& d, const char* key, const std::string& where) {
  if (!d.contains(key)) throw py::value_error(where + ": no '" + key + "'");
  try {
    return d[key].cast<T>();
  } catch (const py::cast_error&) {
    throw py::value_error(where + ": '" + key + "' is not a " + py::type_id<T>());
  }
}

game::PlayerTally TallyOf(const py::dict& d, const std::string& where) {
  game::PlayerTally t;
  t.attempts = Field<int>(d, "attempts", where);
  t.pots = Field<int>(d, "pots", where);
  t.safeties = Field<int>(d, "safeties", where);
  t.safeties_that_worked = Field<int>(d, "safeties_that_worked", where);
  t.fouls = Field<int>(d, "fouls", where);
  t.foul_reasons = Field<std::map<std::string, int>>(d, "foul_reasons", where);
  t.decisions_us = Field<std::vector<double>>(d, "decisions_us", where);
  return t;
}

game::RackFigures FiguresOf(const py::dict& record, const std::string& where) {
  game::RackFigures figures;
  const bool undecided = record.contains("winner") && record["winner"].is_none();
  figures.winner = undecided ? -1 : Field<int>(record, "winner", where);
  if (!undecided && figures.winner != 0 && figures.winner != 1) {
    throw py::value_error(where + ": 'winner' is not 0, 1 or None");
  }
  figures.break_and_run = Field<bool>(record, "break_and_run", where);
  const auto tallies = Field<std::vector<py::dict>>(record, "players", where);
  if (tallies.size() != 2) throw py::value_error(where + ": 'players' is not two tallies");
  for (int p = 0; p < 2; ++p) {
    figures.players[p] = TallyOf(tallies[p], where + " player " + std::to_string(p));
  }
  return figures;
}

// match_summary: the records summed, as `billiard match --json` prints the match.
py::object MatchSummary(const std::vector<py::dict>& records, const MatchArgs& args) {
  const game::MatchOptions options = OptionsOf(args);
  game::MatchRecord match;
  for (int p = 0; p < 2; ++p) match.players[p].name = options.players[p]->Name();
  for (std::size_t i = 0; i < records.size(); ++i) {
    game::AddRack(FiguresOf(records[i], "record " + std::to_string(i)), &match);
  }
  const nlohmann::json j = game::MatchJson(match, {args.game, args.noise, args.seed});
  return py::module_::import("json").attr("loads")(j.dump());
}

}  // namespace

void AddMatchFunctions(py::module_& m) {
  using py::arg;
  m.def(
      "play_rack",
      [](const std::string& game, const std::vector<std::string>& players, int rack,
         std::uint64_t seed, const std::string& noise, int shot_limit, int threads) {
        return PlayRack({game, players, noise, seed, shot_limit}, rack, threads);
      },
      arg("game"), arg("players"), arg("rack"), arg("seed") = 1,
      arg("noise") = params::kDefaultNoise, arg("shot_limit") = 200, arg("threads") = 1,
      "Rack `rack` (0 the first) of billiard match --game GAME --players A,B --seed SEED: "
      "seeded from the seed and the rack alone, broken by player rack % 2. Its record: 'rack', "
      "'breaker', 'winner' (0, 1, None when undecided), 'reason', 'break_and_run', 'shots', and "
      "'players' (each one's attempts, pots, safeties, safeties_that_worked, fouls, "
      "foul_reasons, decisions_us)");
  m.def(
      "match_summary",
      [](const std::vector<py::dict>& records, const std::string& game,
         const std::vector<std::string>& players, std::uint64_t seed, const std::string& noise) {
        return MatchSummary(records, {game, players, noise, seed});
      },
      arg("records"), arg("game"), arg("players"), arg("seed") = 1,
      arg("noise") = params::kDefaultNoise,
      "play_rack's records summed into the match billiard match --json prints: 'game', "
      "'racks', 'players' (racks won, win rate, interval95, pots, attempts, fouls, ...), "
      "'decision_us'");
}

}  // namespace billiard::python
