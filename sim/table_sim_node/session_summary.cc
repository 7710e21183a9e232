#include "sim/table_sim_node/session_summary.h"

#include <algorithm>
#include <cmath>

#include "sim/rules/match_standing.h"
#include "sim/rules/ruleset.h"

namespace billiard::table_sim_node {

namespace {

// The game's totals over its racks, and what its decisions saw.
struct GameTotals {
  int cleared = 0, run_outs = 0, shots = 0, attempts = 0, pots = 0, fouls = 0, visits = 0,
      balls = 0, misidentified = 0, untracked = 0, decided = 0;
  std::vector<double> decisions, rms;  // per decision: its time [ms], the estimator's RMS [mm]
  double worst = 0.0;                  // the estimator's largest error at a decision [mm]
};

// One shot of a rack as the summary lists it.
nlohmann::json GameShotJson(const GameShot& s) {
  nlohmann::json shot = {{"number", s.number},
                         {"visit", s.visit},
                         {"break", s.break_shot},
                         {"ball_in_hand", s.ball_in_hand},
                         {"status", s.status},
                         {"potted", s.potted},
                         {"called_potted", s.called_potted},
                         {"foul", s.foul},
                         {"decision_ms", s.decision_ms},
                         {"estimator",
                          {{"position_rms_mm", s.position_rms_mm},
                           {"position_max_mm", s.position_max_mm},
                           {"untracked", s.untracked},
                           {"misidentified", s.misidentified}}}};
  shot["first_contact"] = s.first_contact < 0 ? nlohmann::json() : nlohmann::json(s.first_contact);
  if (!s.reason.empty()) shot["reason"] = s.reason;
  if (s.foul) shot["foul_reason"] = s.foul_reason;
  if (s.cue_placement) shot["cue_placement"] = {s.cue_placement->x(), s.cue_placement->y()};
  if (s.safety) shot["safety"] = true;
  if (s.called >= 0) {
    shot["called"] = {
        {"ball", s.called}, {"pocket", s.pocket}, {"kind", s.kind}, {"predicted", s.predicted}};
  }
  return shot;
}

bool RackRunOut(const GameResult& game) {
  return rules::RunOut(game.cleared, game.visits, rules::FirstVisitAfterBreak(game.shots));
}

// A match's rack: who broke, who won and why, each shot's player, all added to the players'.
void AddMatchRack(const GameResult& game, const std::vector<std::string>& players,
                  nlohmann::json* rack, std::vector<rules::MatchPlayerCounts>* totals) {
  (*rack)["breaker"] = players[game.breaker];
  (*rack)["winner"] = game.winner < 0 ? nlohmann::json() : nlohmann::json(players[game.winner]);
  (*rack)["reason"] = game.reason;
  (*rack)["break_and_run"] = game.break_and_run;
  if (game.winner >= 0) {
    ++(*totals)[game.winner].racks_won;
    (*totals)[game.winner].break_and_runs += game.break_and_run;
  }
  for (std::size_t i = 0; i < game.shots.size(); ++i) {
    const GameShot& s = game.shots[i];
    (*rack)["shots"][i]["player"] = players[s.player];
    rules::MatchPlayerCounts& p = (*totals)[s.player];
    p.fouls += s.foul;
    p.safeties += s.safety;
    if (s.called >= 0) {
      ++p.attempts;
      p.pots += s.called_potted;
    }
  }
}

// One rack: its shots and counts, added to `totals`.
nlohmann::json RackJson(const GameResult& game, GameTotals* totals) {
  nlohmann::json rack = {{"seed", game.seed},
                         {"cleared", game.cleared},
                         {"visits", game.visits},
                         {"run_out", RackRunOut(game)}};
  int rack_attempts = 0, rack_pots = 0, rack_fouls = 0, rack_balls = 0;
  for (const GameShot& s : game.shots) {
    if (s.called >= 0) {
      ++rack_attempts;
      rack_pots += s.called_potted;
    }
    rack_fouls += s.foul;
    if (!s.foul) rack_balls += static_cast<int>(s.potted.size());
    if (!s.break_shot && s.status == "ok") {
      ++totals->decided;
      totals->decisions.push_back(s.decision_ms);
      totals->rms.push_back(s.position_rms_mm);
      totals->worst = std::max(totals->worst, s.position_max_mm);
      totals->misidentified += s.misidentified;
      totals->untracked += s.untracked;
    }
    rack["shots"].push_back(GameShotJson(s));
  }
  rack["attempts"] = rack_attempts;
  rack["pots"] = rack_pots;
  rack["fouls"] = rack_fouls;
  rack["balls_potted"] = rack_balls;
  totals->cleared += game.cleared;
  totals->run_outs += RackRunOut(game);
  totals->shots += static_cast<int>(game.shots.size());
  totals->attempts += rack_attempts;
  totals->pots += rack_pots;
  totals->fouls += rack_fouls;
  totals->visits += game.visits;
  totals->balls += rack_balls;
  return rack;
}

// The upper median: the middle of an odd count, the greater middle of an even one; 0 of none.
double UpperMedian(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

nlohmann::json TotalsJson(const GameTotals& t, std::size_t racks) {
  return {{"racks", racks},
          {"cleared", t.cleared},
          {"run_outs", t.run_outs},
          {"shots", t.shots},
          {"attempts", t.attempts},
          {"pots", t.pots},
          {"pots_per_attempt", t.attempts ? static_cast<double>(t.pots) / t.attempts : 0.0},
          {"fouls", t.fouls},
          {"visits", t.visits},
          {"balls_per_visit", t.visits ? static_cast<double>(t.balls) / t.visits : 0.0},
          {"median_decision_ms", UpperMedian(t.decisions)},
          {"max_decision_ms",
           t.decisions.empty() ? 0.0 : *std::max_element(t.decisions.begin(), t.decisions.end())},
          {"decisions", t.decided},
          {"median_position_rms_mm", UpperMedian(t.rms)},
          {"max_position_error_mm", t.worst},
          {"misidentified_ball_decisions", t.misidentified},
          {"untracked_ball_decisions", t.untracked}};
}

// A pot of a whole-table session as the summary lists it.
nlohmann::json PotJson(const PotResult& pot) {
  const ShotResult& shot = pot.shot;
  nlohmann::json p = {{"ball", pot.asked.ball}, {"pocket", pot.asked.pocket},
                      {"status", shot.status},  {"potted", pot.potted},
                      {"scratch", pot.scratch}, {"plan_ms", shot.plan_ms},
                      {"retries", shot.retries}};
  p["dropped"] = pot.dropped.empty() ? nlohmann::json() : nlohmann::json(pot.dropped);
  p["first_contact"] = pot.first_contact < 0 ? nlohmann::json() : nlohmann::json(pot.first_contact);
  if (!shot.reason.empty()) p["reason"] = shot.reason;
  if (shot.status == "ok") {
    p["kind"] = pot.kind;
    p["margin_deg"] = {pot.margin_left_deg, pot.margin_right_deg};
    p["speed_window"] = {pot.speed_lo, pot.speed_hi};
    p["planned_cue_rest"] = {shot.target.x(), shot.target.y()};
    p["cue_rest_error_m"] = shot.miss_m;
  }
  p["cue_rest"] = {shot.final_point.x(), shot.final_point.y()};
  return p;
}

// How the estimator tracked each ball of a whole-table session, and over all of them.
nlohmann::json TrackingJson(const TrackingReport& t) {
  nlohmann::json j;
  double sum = 0.0, worst = 0.0;
  int frames = 0, lost = 0, misnamed = 0, unnamed = 0, named_at_end = 0;
  for (const BallTracking& b : t.balls) {
    nlohmann::json ball = {{"id", b.id},           {"frames", b.frames},
                           {"lost", b.lost},       {"misnamed", b.misnamed},
                           {"unnamed", b.unnamed}, {"named_at_end", b.named_at_end}};
    if (b.frames > 0) {
      ball["rms_error_mm"] = 1e3 * std::sqrt(b.sum_squared_error / b.frames);
      ball["max_error_mm"] = 1e3 * b.max_error;
    }
    j["balls"].push_back(ball);
    sum += b.sum_squared_error;
    frames += b.frames;
    lost += b.lost;
    misnamed += b.misnamed;
    unnamed += b.unnamed;
    named_at_end += b.named_at_end;
    worst = std::max(worst, b.max_error);
  }
  j["rms_error_mm"] = frames > 0 ? 1e3 * std::sqrt(sum / frames) : 0.0;
  j["max_error_mm"] = 1e3 * worst;
  j["lost_ball_frames"] = lost;
  j["misnamed_ball_frames"] = misnamed;
  j["unnamed_ball_frames"] = unnamed;
  j["named_at_end"] = named_at_end;
  j["swaps"] = t.swaps;
  j["reacquired"] = t.reacquired;
  return j;
}

}  // namespace

nlohmann::json SessionSummary(const std::vector<ShotResult>& shots, const node_status_t& health,
                              double wall_s) {
  nlohmann::json j;
  std::vector<double> misses;
  for (const ShotResult& s : shots) {
    nlohmann::json shot = {{"from", {s.from.x(), s.from.y()}},
                           {"target", {s.target.x(), s.target.y()}},
                           {"final", {s.final_point.x(), s.final_point.y()}},
                           {"miss_m", s.miss_m},
                           {"plan_ms", s.plan_ms},
                           {"status", s.status},
                           {"retries", s.retries}};
    if (!s.reason.empty()) shot["reason"] = s.reason;
    j["shots"].push_back(shot);
    misses.push_back(s.miss_m);
  }
  if (!misses.empty()) {
    std::sort(misses.begin(), misses.end());
    const std::size_t n = misses.size();
    j["median_miss_m"] = n % 2 ? misses[n / 2] : 0.5 * (misses[n / 2 - 1] + misses[n / 2]);
    j["max_miss_m"] = misses.back();
    double mean = 0.0, spread = 0.0;
    for (double m : misses) mean += m / n;
    for (double m : misses) spread += (m - mean) * (m - mean) / n;
    j["mean_miss_m"] = mean;
    j["stddev_miss_m"] = std::sqrt(spread);
  }
  for (int i = 0; i < health.num_counters; ++i) {
    j["counters"][health.counter_names[i]] = health.counter_values[i];
  }
  j["received"] = health.received;
  j["dropped"] = health.dropped;
  j["wall_s"] = wall_s;
  return j;
}

nlohmann::json GameSummary(const std::vector<GameResult>& games, const std::string& kind,
                           std::vector<std::string> players) {
  // A player against itself: the two told apart as billiard match's progress tells them.
  if (players.size() == 2 && players[0] == players[1]) {
    players = {players[0] + " (A)", players[1] + " (B)"};
  }
  nlohmann::json j = {{"kind", kind}};
  GameTotals totals;
  std::vector<rules::MatchPlayerCounts> player_totals(players.size());
  for (const GameResult& game : games) {
    nlohmann::json rack = RackJson(game, &totals);
    if (!players.empty()) AddMatchRack(game, players, &rack, &player_totals);
    j["racks"].push_back(std::move(rack));
  }
  j["summary"] = TotalsJson(totals, games.size());
  for (std::size_t k = 0; k < players.size(); ++k) {
    j["players"].push_back(
        rules::MatchPlayerJson(players[k], player_totals[k], static_cast<int>(games.size())));
  }
  return j;
}

nlohmann::json SceneSummary(const SceneResult& scene, const std::string& name) {
  nlohmann::json j = {{"name", name}, {"events", scene.events}};
  for (std::size_t k = 0; k < scene.final_balls.size(); ++k) {
    const table::SceneBall& b = scene.final_balls[k];
    nlohmann::json ball = {{"id", b.id}, {"final", {b.state[physics::kX], b.state[physics::kY]}}};
    ball["pocketed"] =
        scene.pockets[k].empty() ? nlohmann::json() : nlohmann::json(scene.pockets[k]);
    j["balls"].push_back(ball);
  }
  for (const PotResult& pot : scene.pots) j["pots"].push_back(PotJson(pot));
  j["tracking"] = TrackingJson(scene.tracking);
  return j;
}

nlohmann::json DrawnNoiseJson(const DrawnNoise& drawn) {
  return {{"strokes", drawn.strokes},
          {"speed_fraction", drawn.speed_fraction},
          {"heading_deg", drawn.heading * 180.0 / M_PI},
          {"tip_mm", drawn.tip * 1e3}};
}

}  // namespace billiard::table_sim_node
