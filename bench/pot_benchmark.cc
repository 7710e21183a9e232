#include "bench/pot_benchmark.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "bench/format.h"
#include "bench/speed_error.h"
#include "planner/pot/testing/pot_layouts.h"
#include "sim/model_choice/model_choice.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/physics/cue_strike.h"
#include "sim/table/seeded_uniform.h"
#include "sim/table/table_simulation.h"

namespace billiard::bench {

namespace {

constexpr double kDegree = M_PI / 180.0;
// The margin is checked on issue 47's grid [deg]: every heading this far apart inside it pots
// legally, and the first past it does not (the margin is the largest the grid allows).
constexpr double kMarginGridDeg = 0.01;
// Position targets lie within this distance of the object ball [m].
constexpr double kTargetReach = 0.5;
// The cut-angle bins of the throw's table [deg].
constexpr double kCutBins[] = {0, 15, 30, 45, 60, 80};

struct Table {
  std::string name, params;
  table::TableGeometry geometry;
  physics::ModelParameters p;
};

// What `billiard simulate --scene` makes of the scene with the cue ball launched at v0, w0 (and its
// hop): its default models (model_choice::TableMotion, Mathavan's cushion), to rest.
struct Check {
  bool potted = false, legal = false;
  int first_contact = -1;
  std::optional<std::string> cue_pocket;
  Eigen::Vector2d rest = Eigen::Vector2d::Zero();
};

Check Simulate(const Table& t, std::vector<table::SceneBall> balls,
               const table::SceneBall& launched, int k, const std::string& pocket) {
  std::size_t cue = 0, object = 0;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (balls[i].id == 0) cue = i;
    if (balls[i].id == k) object = i;
  }
  balls[cue] = launched;
  table::TableSimulationOptions o;
  o.five_dof = model_choice::TableMotion(t.p);
  table::TableSimulation sim(t.geometry, t.p, balls, o);
  sim.Run();
  Check c;
  c.first_contact = table::FirstBallMet(sim.events(), 0);
  c.potted = sim.pocket(object) && *sim.pocket(object) == pocket;
  c.cue_pocket = sim.pocket(cue);
  c.legal = c.potted && c.first_contact == k && !c.cue_pocket;
  c.rest = sim.State(cue).head<2>();
  return c;
}

table::SceneBall LaunchOf(const Table& t, const std::vector<table::SceneBall>& balls,
                          const physics::CueStroke& stroke) {
  for (const table::SceneBall& b : balls) {
    if (b.id == 0) return table::Struck(0, stroke, b.state.head<2>(), t.p);
  }
  return table::SceneBall(0);
}

table::SceneBall PlannedLaunch(const std::vector<table::SceneBall>& balls,
                               const pot::PotPlan& plan) {
  for (const table::SceneBall& b : balls) {
    if (b.id == 0) {
      return {0,
              physics::MakeBallState(b.state.x(), b.state.y(), plan.v0.x(), plan.v0.y(),
                                     plan.w0.x(), plan.w0.y(), plan.w0.z()),
              plan.flight};
    }
  }
  return table::SceneBall(0);
}

bool PotsTurned(const Table& t, const PotRun& run, const std::vector<table::SceneBall>& balls,
                double turn_deg) {
  physics::CueStroke s = run.plan.stroke;
  s.heading += turn_deg * kDegree;
  return Simulate(t, balls, LaunchOf(t, balls, s), run.plan.ball, run.plan.pocket).legal;
}

// The grid's headings at or inside a margin [deg] (a margin of n steps is n * 0.01 degree
// converted to radians and back: a part in a million more than its floor is still n).
int StepsInside(double margin_deg) { return static_cast<int>(std::floor(margin_deg / kMarginGridDeg + 1e-6)); }

// Whether the grid's headings 1 .. `steps` toward `side` (+1: left) each pot legally.
bool GridPots(const Table& t, const PotRun& run, const std::vector<table::SceneBall>& balls, double side, int steps) {
  for (int j = 1; j <= steps; ++j) {
    if (!PotsTurned(t, run, balls, side * j * kMarginGridDeg)) return false;
  }
  return true;
}

double ThreadCpuUs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e6 * static_cast<double>(t.tv_sec) + 1e-3 * static_cast<double>(t.tv_nsec);
}

std::string Percent(int n, int of) { return of > 0 ? Fixed(100.0 * n / of, 1) + " %" : "-"; }

}  // namespace

PotBenchmarkResult RunPotBenchmark(const PotBenchmarkOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<Table> tables;
  for (const auto& [name, params] :
       {std::pair<std::string, std::string>{params::kDefaultTable, "pool"},
        {"snooker-12ft", "snooker"}}) {
    tables.push_back({name, params, table::BuildTable(params::LoadTableSpec(name)), params::LoadParameters(params)});
  }
  PotBenchmarkResult result;
  result.options = options;
  pot::PotOptions plan_options;
  plan_options.robot = options.robot;
  int margins = 0;
  for (int i = 0; i < options.layouts; ++i) {
    const std::uint64_t seed = options.seed + static_cast<std::uint64_t>(i);
    const bool snooker = options.snooker_every > 0 && i % options.snooker_every == options.snooker_every - 1;
    const Table& t = tables[snooker ? 1 : 0];
    const pot::testing::PotLayout layout = pot::testing::SeededPotLayout(t.geometry, t.p.ball.radius, seed);
    PotRun run;
    run.seed = seed;
    run.table = t.name;
    run.balls = static_cast<int>(layout.balls.size());
    run.straight_clear = pot::testing::StraightLineClear(t.geometry, t.p.ball.radius, layout.balls,
                                                         layout.request.ball, layout.request.pocket,
                                                         pot::testing::kClearCutDeg);
    const double cpu_start = ThreadCpuUs();
    run.plan = pot::PlanPot(t.geometry, t.p, layout.balls, layout.request, plan_options);
    run.cpu_us = ThreadCpuUs() - cpu_start;
    if (run.plan.status == pot::PotStatus::kOk) {
      const Check c = Simulate(t, layout.balls, PlannedLaunch(layout.balls, run.plan), run.plan.ball, run.plan.pocket);
      run.verified = c.legal;
      if (!c.legal) {
        run.verify_failure = !c.potted ? "ball does not drop" : c.cue_pocket ? "scratch" : "foul first contact";
      }
      if (const std::optional<double> heading = pot::GhostBallHeading(t.geometry, t.p, layout.balls, run.plan)) {
        physics::CueStroke ghost = run.plan.stroke;
        ghost.heading = *heading;
        run.ghost_pots = Simulate(t, layout.balls, LaunchOf(t, layout.balls, ghost), run.plan.ball, run.plan.pocket).legal;
      }
      if (margins < options.margin_checks) {
        ++margins;
        const int left = StepsInside(run.plan.margin_left_deg), right = StepsInside(run.plan.margin_right_deg);
        run.inner_left = GridPots(t, run, layout.balls, 1.0, left);
        run.inner_right = GridPots(t, run, layout.balls, -1.0, right);
        run.outer_left = !PotsTurned(t, run, layout.balls, (left + 1) * kMarginGridDeg);
        run.outer_right = !PotsTurned(t, run, layout.balls, -(right + 1) * kMarginGridDeg);
      }
    }
    result.runs.push_back(run);
    if ((i + 1) % 50 == 0) options.progress("bench-pot: " + std::to_string(i + 1) + " / " + std::to_string(options.layouts) + " layouts");
  }
  // Position play: the first layouts on pool that plan, a seeded target near the object ball.
  table::SeededUniform random(options.seed);
  const Table& pool = tables[0];
  for (std::size_t i = 0; i < result.runs.size() && static_cast<int>(result.positions.size()) < options.position_targets; ++i) {
    const PotRun& run = result.runs[i];
    if (run.table != pool.name || run.plan.status != pot::PotStatus::kOk) continue;
    pot::testing::PotLayout layout = pot::testing::SeededPotLayout(pool.geometry, pool.p.ball.radius, run.seed);
    Eigen::Vector2d k = Eigen::Vector2d::Zero();
    for (const table::SceneBall& b : layout.balls) if (b.id == layout.request.ball) k = b.state.head<2>();
    PositionRun pr;
    pr.seed = run.seed;
    do {
      const double radius = kTargetReach * std::sqrt(random.Next());
      const double angle = 2.0 * M_PI * random.Next();
      pr.target = k + radius * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    } while (!pool.geometry.OnSurface(pr.target, pool.p.ball.radius));
    layout.request.cue_target = pot::CueTarget{pr.target, 0.0};
    pr.plan = pot::PlanPot(pool.geometry, pool.p, layout.balls, layout.request, plan_options);
    if (pr.plan.status == pot::PotStatus::kOk) {
      const Check c = Simulate(pool, layout.balls, PlannedLaunch(layout.balls, pr.plan), pr.plan.ball, pr.plan.pocket);
      pr.legal = c.legal;
      pr.rest_error_m = (c.rest - pr.target).norm();
    }
    result.positions.push_back(pr);
    if (result.positions.size() % 20 == 0) options.progress("bench-pot: " + std::to_string(result.positions.size()) + " / " + std::to_string(options.position_targets) + " cue-ball targets");
  }
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

namespace {

// Whether a refusal is the hop's (sim/cue/stroke_limits.h): a stroke that would hop the ball
// beyond what the table's motion covers, or a pot out of reach at the fastest pace within it
// (planner/pot/pace.cc).
bool HeldByTheHop(const pot::PotPlan& plan) {
  return plan.status != pot::PotStatus::kOk &&
         (plan.reason.find("would hop the ball") != std::string::npos ||
          plan.reason.find("whose hop the table's motion covers") != std::string::npos);
}

// The cue's share: the robot, the elevation every ok plan is played at, the pots refused because
// its cue clears at no elevation (cue_blocked) or by the hop.
nlohmann::json CueSummary(const PotBenchmarkResult& r) {
  std::vector<double> elevations;
  int blocked = 0, lifted = 0, elevated = 0;
  for (const PotRun& run : r.runs) {
    blocked += run.plan.status == pot::PotStatus::kCueBlocked;
    lifted += HeldByTheHop(run.plan);
    if (run.plan.status != pot::PotStatus::kOk) continue;
    elevations.push_back(run.plan.stroke.elevation * 180.0 / M_PI);
    elevated += run.plan.stroke.elevation > 0.0;
  }
  return {{"robot", r.options.robot ? r.options.robot->name : "none (level cue, unchecked)"},
          {"cue_blocked", blocked}, {"held_by_hop", lifted}, {"elevated", elevated},
          {"elevation_deg", {{"median", Quantile(elevations, 0.5)}, {"p90", Quantile(elevations, 0.9)},
                             {"max", elevations.empty() ? 0.0 : *std::max_element(elevations.begin(), elevations.end())}}}};
}

}  // namespace

nlohmann::json PotSummaryJson(const PotBenchmarkResult& r) {
  int ok = 0, verified = 0, clear = 0, clear_ok = 0, blocked_ok = 0;
  std::map<std::string, int> blocked_by_kind, kinds;
  std::vector<double> pool_us, all_us, pool_cpu, direct_cpu;
  int inner = 0, outer = 0, checked = 0;
  std::map<int, std::pair<int, int>> throw_bins;  // bin -> (plans, misses)
  for (const PotRun& run : r.runs) {
    const bool is_ok = run.plan.status == pot::PotStatus::kOk;
    all_us.push_back(run.plan.solve_us);
    if (run.table == params::kDefaultTable) {
      pool_us.push_back(run.plan.solve_us);
      pool_cpu.push_back(run.cpu_us);
      if (run.plan.status == pot::PotStatus::kOk && run.plan.kind == pot::ShotKind::kDirect) direct_cpu.push_back(run.cpu_us);
    }
    if (run.straight_clear) ++clear;
    if (!is_ok) continue;
    ++ok;
    ++kinds[pot::ShotKindName(run.plan.kind)];
    verified += run.verified;
    if (run.straight_clear) ++clear_ok;
    else {
      ++blocked_ok;
      ++blocked_by_kind[pot::ShotKindName(run.plan.kind)];
    }
    if (run.inner_left) {
      ++checked;
      inner += *run.inner_left + *run.inner_right;
      outer += *run.outer_left + *run.outer_right;
    }
    if (run.ghost_pots && run.plan.kind == pot::ShotKind::kDirect) {
      int bin = 0;
      while (bin + 2 < static_cast<int>(std::size(kCutBins)) && run.plan.cut_deg >= kCutBins[bin + 1]) ++bin;
      ++throw_bins[bin].first;
      throw_bins[bin].second += !*run.ghost_pots;
    }
  }
  int feasible = 0, within_1cm = 0;
  double worst = 0.0;
  for (const PositionRun& p : r.positions) {
    if (p.plan.status != pot::PotStatus::kOk) continue;
    ++feasible;
    within_1cm += p.legal && p.rest_error_m <= 0.01;
    worst = std::max(worst, p.rest_error_m);
  }
  nlohmann::json j;
  j["layouts"] = r.runs.size();
  j["ok"] = ok;
  j["truth"] = {{"ok", ok}, {"verified", verified}};
  j["coverage"] = {{"straight_clear", clear}, {"planned", clear_ok},
                   {"fraction", clear > 0 ? static_cast<double>(clear_ok) / clear : 0.0},
                   {"blocked_made", blocked_ok}, {"blocked_made_by_kind", blocked_by_kind}};
  j["kinds"] = kinds;
  j["margin"] = {{"plans", checked}, {"inner_pot", inner}, {"outer_miss", outer}, {"of", 2 * checked}};
  nlohmann::json bins = nlohmann::json::array();
  for (const auto& [bin, counts] : throw_bins) {
    bins.push_back({{"cut_deg", {kCutBins[bin], kCutBins[bin + 1]}}, {"plans", counts.first}, {"ghost_misses", counts.second}});
  }
  j["throw"] = bins;
  j["position"] = {{"targets", r.positions.size()}, {"feasible", feasible},
                   {"fraction", r.positions.empty() ? 0.0 : static_cast<double>(feasible) / r.positions.size()},
                   {"within_1cm", within_1cm}, {"worst_m", worst}};
  j["solve_us"] = {{"pool_median", Quantile(pool_us, 0.5)}, {"pool_p95", Quantile(pool_us, 0.95)},
                   {"all_median", Quantile(all_us, 0.5)}, {"all_p95", Quantile(all_us, 0.95)}};
  j["cpu_us"] = {{"pool_median", Quantile(pool_cpu, 0.5)}, {"pool_p95", Quantile(pool_cpu, 0.95)},
                 {"pool_direct_median", Quantile(direct_cpu, 0.5)}, {"pool_direct_p95", Quantile(direct_cpu, 0.95)}};
  j["cue"] = CueSummary(r);
  j["wall_s"] = r.wall_s;
  return j;
}

namespace {

std::string Flag(const std::optional<bool>& b) { return b ? (*b ? "1" : "0") : ""; }

// Every layout and every cue-ball target, a row each.
void WritePotResults(const PotBenchmarkResult& r, const std::string& dir) {
  std::ofstream out = OpenForWriting(dir + "/pot_results.csv");
  out << "seed,table,balls,straight_clear,status,kind,rail,cut_deg,margin_left_deg,margin_right_deg,"
         "speed_lo,speed_hi,solve_us,simulations,verified,ghost_pots,inner_left,inner_right,"
         "outer_left_misses,outer_right_misses,target_x,target_y,rest_error_m,cpu_us\n";
  const auto row = [&](std::uint64_t seed, const std::string& table, int balls, bool clear, const pot::PotPlan& p) {
    const bool ok = p.status == pot::PotStatus::kOk;
    out << seed << "," << table << "," << balls << "," << clear << "," << pot::PotStatusName(p.status)
        << "," << (ok ? pot::ShotKindName(p.kind) : "") << "," << (ok && p.rail >= 0 ? std::to_string(p.rail) : "")
        << "," << (ok ? Fixed(p.cut_deg, 2) : "") << "," << (ok ? Fixed(p.margin_left_deg, 4) : "")
        << "," << (ok ? Fixed(p.margin_right_deg, 4) : "") << "," << (ok ? Fixed(p.speed_lo, 3) : "")
        << "," << (ok ? Fixed(p.speed_hi, 3) : "") << "," << Fixed(p.solve_us, 0) << "," << p.simulations;
  };
  for (const PotRun& run : r.runs) {
    row(run.seed, run.table, run.balls, run.straight_clear, run.plan);
    out << "," << (run.plan.status == pot::PotStatus::kOk ? (run.verified ? "1" : "0") : "") << ","
        << Flag(run.ghost_pots) << "," << Flag(run.inner_left) << "," << Flag(run.inner_right) << ","
        << Flag(run.outer_left) << "," << Flag(run.outer_right) << ",,,," << Fixed(run.cpu_us, 0) << "\n";
  }
  for (const PositionRun& p : r.positions) {
    row(p.seed, params::kDefaultTable, 0, false, p.plan);
    out << "," << (p.plan.status == pot::PotStatus::kOk ? (p.legal ? "1" : "0") : "") << ",,,,,,"
        << Fixed(p.target.x(), 4) << "," << Fixed(p.target.y(), 4) << ","
        << (p.rest_error_m >= 0.0 ? Sci(p.rest_error_m) : "") << ",\n";
  }
}

// The report's coverage: the clear pairs planned, what the other routes made, the clear pairs
// refused and why, and every layout's status.
void WriteCoverage(const PotBenchmarkResult& r, const nlohmann::json& s, std::ofstream& out) {
  out << "\n## Coverage\n\n"
      << "Of the " << s["coverage"]["straight_clear"].get<int>() << " pots whose straight ghost-ball "
      << "line is clear (no ball within a ball's width of either line, the object ball's line clear of the "
      << "pocket's jaws, cut below 80 deg), "
      << s["coverage"]["planned"].get<int>() << " planned ok ("
      << Percent(s["coverage"]["planned"].get<int>(), s["coverage"]["straight_clear"].get<int>())
      << "). Where it is not clear, " << s["coverage"]["blocked_made"].get<int>() << " pots were made by:";
  for (const auto& [kind, n] : s["coverage"]["blocked_made_by_kind"].items()) out << " " << kind << " " << n.get<int>() << ";";
  out << "\n\n";
  // A clear pair refused, by the reason of its first route (the direct pot; the routes' reasons
  // are joined by "; ", and the rest are the banks, kicks and curves it tried next).
  for (const PotRun& run : r.runs) {
    if (run.straight_clear && run.plan.status != pot::PotStatus::kOk) {
      out << "- clear, refused: seed " << run.seed << " (" << run.table << "), "
          << pot::PotStatusName(run.plan.status) << ": " << run.plan.reason.substr(0, run.plan.reason.find("; "))
          << "\n";
    }
  }
  out << "\n| status | layouts |\n|---|---|\n";
  std::map<std::string, int> statuses;
  for (const PotRun& run : r.runs) ++statuses[pot::PotStatusName(run.plan.status)];
  for (const auto& [status, n] : statuses) out << "| " << status << " | " << n << " |\n";
}

}  // namespace

void WritePotReport(const PotBenchmarkResult& r, const std::string& dir) {
  std::filesystem::create_directories(dir);
  WritePotResults(r, dir);
  const nlohmann::json s = PotSummaryJson(r);
  std::ofstream out = OpenForWriting(dir + "/pot_report.md");
  out << "# Potting against the table simulation\n\n"
      << "`billiard bench-pot --out docs/benchmarks` (seed " << r.options.seed
      << "): " << r.runs.size()
      << " seeded layouts of 2-16 balls (planner/pot/testing/pot_layouts.h), every "
      << r.options.snooker_every << "th on snooker-12ft, the rest on " << params::kDefaultTable
      << "; a random object ball and pocket each, planned with `--kind any`. Every plan is checked "
      << "on its own: its v0, w0 and hop simulated from the scene with the default models of "
      << "`billiard simulate --scene` (`--model auto`, Mathavan et al. 2010's cushion). "
      << Fixed(r.wall_s, 1) << " s in all.\n\n";
  out << "## Truth\n\n" << s["truth"]["verified"].get<int>() << " of " << s["truth"]["ok"].get<int>()
      << " ok plans pot ball K in pocket P with a legal first contact and no scratch.\n\n";
  for (const PotRun& run : r.runs) {
    if (run.plan.status == pot::PotStatus::kOk && !run.verified) {
      out << "- seed " << run.seed << " (" << run.table << "): " << run.verify_failure << "\n";
    }
  }
  const nlohmann::json& cue = s["cue"];
  out << "\n## The cue\n\nRobot: " << cue["robot"].get<std::string>()
      << ". The ok plans' cue elevation "
      << "(the least that clears plus 1 deg, planner/pot/cue_elevation.h): median "
      << Fixed(cue["elevation_deg"]["median"].get<double>(), 2) << " deg, p90 "
      << Fixed(cue["elevation_deg"]["p90"].get<double>(), 2) << " deg, max "
      << Fixed(cue["elevation_deg"]["max"].get<double>(), 2) << " deg; "
      << cue["elevated"].get<int>() << " of " << s["ok"].get<int>()
      << " above level. Refused: " << cue["cue_blocked"].get<int>()
      << " cue_blocked (the cue clears at no elevation), " << cue["held_by_hop"].get<int>()
      << " held by the hop (the reason of the best route tried: its cue would hop the ball beyond "
      << "the tenth of a radius the table's motion covers, or the pot is out of reach at the "
      << "fastest pace within it).\n";
  WriteCoverage(r, s, out);
  out << "\n## The margin is true\n\n"
      << "On " << s["margin"]["plans"].get<int>() << " plans, every heading " << kMarginGridDeg
      << " deg apart inside the margin pots legally on " << s["margin"]["inner_pot"].get<int>() << " of "
      << s["margin"]["of"].get<int>() << " sides, and the first past it misses on "
      << s["margin"]["outer_miss"].get<int>() << " of " << s["margin"]["of"].get<int>() << ".\n\n";
  out << "## Throw\n\nThe direct plans aimed through the ghost ball alone (the line of centres along "
      << "the drop window's middle, the same speed and spin: throw not corrected), simulated without "
      << "noise:\n\n| cut [deg] | plans | miss |\n|---|---|---|\n";
  for (const nlohmann::json& b : s["throw"]) {
    out << "| " << b["cut_deg"][0].get<double>() << "-" << b["cut_deg"][1].get<double>() << " | "
        << b["plans"].get<int>() << " | " << b["ghost_misses"].get<int>() << " ("
        << Percent(b["ghost_misses"].get<int>(), b["plans"].get<int>()) << ") |\n";
  }
  out << "\n## Position\n\n" << s["position"]["targets"].get<int>() << " random cue-ball targets "
      << "within " << kTargetReach << " m of the object ball (pool layouts that plan): "
      << s["position"]["feasible"].get<int>() << " feasible ("
      << Percent(s["position"]["feasible"].get<int>(), s["position"]["targets"].get<int>())
      << "); of those, " << s["position"]["within_1cm"].get<int>() << " stop within 1 cm of the "
      << "target when simulated (worst " << Fixed(1e3 * s["position"]["worst_m"].get<double>(), 2) << " mm).\n\n";
  out << "## Speed\n\nEach plan on one thread. CPU time of the plan's thread (what it costs one core, "
      << "whatever else the machine runs): pool layouts median "
      << Fixed(1e-3 * s["cpu_us"]["pool_median"].get<double>(), 2) << " ms, p95 "
      << Fixed(1e-3 * s["cpu_us"]["pool_p95"].get<double>(), 2) << " ms (refusals included: a "
      << "blocked pot tries every kind); the direct pots alone median "
      << Fixed(1e-3 * s["cpu_us"]["pool_direct_median"].get<double>(), 2) << " ms, p95 "
      << Fixed(1e-3 * s["cpu_us"]["pool_direct_p95"].get<double>(), 2) << " ms. Wall time: pool "
      << "layouts median " << Fixed(1e-3 * s["solve_us"]["pool_median"].get<double>(), 2) << " ms, p95 "
      << Fixed(1e-3 * s["solve_us"]["pool_p95"].get<double>(), 2) << " ms.\n\n"
      << "| outcome | plans | CPU median [ms] | CPU p95 [ms] |\n|---|---|---|---|\n";
  std::map<std::string, std::vector<double>> by_outcome;
  for (const PotRun& run : r.runs) {
    if (run.table != params::kDefaultTable) continue;
    const bool ok = run.plan.status == pot::PotStatus::kOk;
    by_outcome[ok ? std::string("ok, ") + pot::ShotKindName(run.plan.kind) : pot::PotStatusName(run.plan.status)].push_back(run.cpu_us);
  }
  for (const auto& [outcome, us] : by_outcome) {
    out << "| " << outcome << " | " << us.size() << " | " << Fixed(1e-3 * Quantile(us, 0.5), 2) << " | "
        << Fixed(1e-3 * Quantile(us, 0.95), 2) << " |\n";
  }
}

}  // namespace billiard::bench
