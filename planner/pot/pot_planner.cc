#include "planner/pot/pot_planner.h"

#include <algorithm>
#include <chrono>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <variant>

#include "planner/pot/aim.h"
#include "planner/pot/cue_elevation.h"
#include "planner/pot/drop_window.h"
#include "planner/pot/lone_path.h"
#include "planner/pot/margin.h"
#include "planner/pot/pace.h"
#include "planner/pot/position.h"
#include "planner/pot/pot_geometry.h"
#include "planner/pot/routes.h"
#include "planner/pot/search_context.h"
#include "planner/pot/truth.h"

namespace billiard::pot {

namespace {

using table::SceneBall;

// Of the banks and the kicks, the shortest this many routes with clear lines are searched.
constexpr int kRoutesSearched = 3;
// Position play is tried on this many of a kind's pots, the widest first.
constexpr std::size_t kPositionRoutes = 2;

Refusal TooThin(double cut, double limit) {
  return Refusal{PotStatus::kTooThin, "the cut is " + Degrees(cut) + ", beyond " + Degrees(limit)};
}

// Steps 5 and 6: the search's plan on the truth, its margin and speed window.
// `placed`: position play's truth aim, kept as it is (the rest point it was solved for moves
// with the smallest turn once the cue ball has met a cushion or two).
std::variant<PotPlan, Refusal> Finish(SearchContext& search, const Route& route, const StrokeShape& shape,
                                      const Aimed& aimed, const Drop& drop, const std::optional<Aimed>& placed) {
  std::variant<TruthShot, Refusal> truth = PlayOnTheTruth(search, route, shape, aimed, drop, placed);
  if (const Refusal* refused = std::get_if<Refusal>(&truth)) return *refused;
  const TruthShot& shot = std::get<TruthShot>(truth);
  PotPlan plan;
  // The cue: the final stroke (the aim's heading, position play's offsets) clears and keeps the
  // ball on the cloth.
  if (std::optional<Refusal> cue = CheckCue(search, shot.stroke, &plan.clearance)) return *cue;
  plan.kind = route.kind;
  plan.rail = route.rail;
  // The margin on the truth: near a jaw whether K rattles in turns on its speed and spin there,
  // which the truth's slide sets.
  const HeadingMargin margin = HeadingMargins(search, shape, shot.aimed.heading);
  plan.margin_left_deg = margin.left / kDegree;
  plan.margin_right_deg = margin.right / kDegree;
  const SpeedWindow speeds = SpeedWindowAt(search, shape, aimed.heading);
  plan.speed_lo = speeds.lo;
  plan.speed_hi = speeds.hi;
  DescribeShot(shot, search.options().path_sample_dt, &plan);
  plan.status = PotStatus::kOk;
  return plan;
}

// The pot along `route` in the named steps: the plan, or why not.
// With `place_cue` the speed and follow/draw are chosen for the cue-ball target.
std::variant<PotPlan, Refusal> PlanRoute(SearchContext& search, const Route& route, bool place_cue) {
  // A bank's and a kick's route is the rail's rebound: the search meets it as the truth does.
  // So is position play's: where the cue ball stops turns on every rail it meets.
  // A curve bends away from its lines: its search has every ball.
  search.SearchAmong(route.kind == ShotKind::kCurve ? std::vector<SceneBall>{} : NearRoute(search, route),
                     route.kind == ShotKind::kBank || route.kind == ShotKind::kKick ||
                         (place_cue && search.target()));
  // 1. The route's first guesses.
  const double max_cut = search.options().max_cut_deg * kDegree;
  const Eigen::Vector2d object = search.object_ball().state.head<2>();
  const Eigen::Vector2d departure = (route.object_aim - object).normalized();
  const Eigen::Vector2d ghost = GhostBall(object, departure, search.radius());
  const Eigen::Vector2d approach =
      (ghost - (route.kind == ShotKind::kKick ? route.cue_aim : search.cue_position())).normalized();
  if (route.kind != ShotKind::kCurve && CutAngle(approach, departure) > max_cut) {
    return TooThin(CutAngle(approach, departure), max_cut);
  }
  StrokeShape shape{kFirstCueSpeed, route.tip_side, route.tip_height, route.elevation};
  double first_heading = FirstHeading(search, route, shape, ghost);
  // 1b. The cue's elevation: the least that clears what lies behind the cue ball, and a margin;
  // the aim, the pace and the truth are found at it.
  const std::variant<double, Refusal> elevation = NeededElevation(search, shape, first_heading);
  if (const Refusal* blocked = std::get_if<Refusal>(&elevation)) return *blocked;
  shape.elevation = std::get<double>(elevation);
  // Its first pace within the hop the table's motion covers at that elevation (TopCueSpeed); a
  // curve's at it, where its bend is largest (pace.h).
  const double top = TopCueSpeed(search, shape, first_heading);
  shape.speed = route.kind == ShotKind::kCurve ? top : std::min(shape.speed, top);
  if (shape.elevation != route.elevation || shape.speed != kFirstCueSpeed) {
    first_heading = FirstHeading(search, route, shape, ghost);
  }
  if (route.kind == ShotKind::kCurve) {
    if (std::optional<Refusal> thin = CurveTooThin(search, shape, first_heading, ghost, departure)) return *thin;
  }
  // 2. The aim along K's line.
  std::optional<Aimed> aimed = AimAt(search, shape, first_heading, Angle(departure), false, 0.0);
  if (!aimed) return Refusal{PotStatus::kBlocked, BlockedReason(search, shape, first_heading)};
  const double cut_angle = CutAngle(Unit(Angle(aimed->contact.cue_before.segment<2>(physics::kVx))),
                                    Unit(aimed->contact.departure));
  if (cut_angle > max_cut) return TooThin(cut_angle, max_cut);
  // 3. The pace, along the route's own line where K drops along it; else along the middle of
  // the window of a ball that gets there.
  std::optional<Drop> drop;
  double line = Angle(departure);
  // A bank's rebound is the cushion model's, not a mirror's: K's line is found on its own path
  // off the rail, the secant method on the side of the pocket it passes.
  if (route.kind == ShotKind::kBank) line = BankLine(search, aimed->contact, line);
  const double scan = route.kind == ShotKind::kBank ? kRailScan : kDirectScan;
  if (!Drops(search, aimed->contact, line, ReachScale(aimed->contact))) {
    drop = DropWindow(search, aimed->contact, line, scan, kReachSpeed, kCoarseWindowResolution);
    if (!drop) {
      return Refusal{PotStatus::kBlocked,
                     "ball " + std::to_string(search.object_id()) + " does not drop in " + search.pocket().name +
                         " along its route (a ball or a jaw is in the way)",
                     true};
    }
    aimed = AimAt(search, shape, aimed->heading, drop->Middle(), false, aimed->slope);
    if (!aimed) return Refusal{PotStatus::kBlocked, BlockedReason(search, shape, first_heading)};
  }
  if (std::optional<Refusal> paced = Pace(search, route, ghost, &shape, &*aimed, drop ? drop->Middle() : line)) {
    return *paced;
  }
  // 4. The drop window at that pace, and the aim at its middle.
  drop = DropWindow(search, aimed->contact, drop ? drop->Middle() : line, scan, 0.0, kWindowResolution, drop);
  if (!drop) {
    return Refusal{PotStatus::kNoStroke, "ball " + std::to_string(search.object_id()) +
                                             " does not drop at the pace it needs"};
  }
  aimed = AimAt(search, shape, aimed->heading, drop->Middle(), false, aimed->slope);
  if (!aimed) return Refusal{PotStatus::kBlocked, "the aim at the drop window's middle is blocked"};
  // 7. Position play, with a target.
  std::optional<Aimed> placed_aim;  // position play's truth aim, whose rest met the target
  if (place_cue && search.target()) {
    std::optional<Refusal> placed = Position(search, *search.target(), &shape, &*aimed, *drop, &placed_aim);
    if (placed) return *placed;
  }
  // 5, 6. The truth and the margin.
  return Finish(search, route, shape, *aimed, *drop, placed_aim);
}

// A route's plan, or the refusal of a stroke no cue gives or a scene out of events. A final
// stroke the aim turned into the cue's way is planned again, once, at the elevation it needs.
std::variant<PotPlan, Refusal> Attempt(SearchContext& search, Route route, bool place_cue) {
  try {
    std::variant<PotPlan, Refusal> result = PlanRoute(search, route, place_cue);
    const Refusal* refused = std::get_if<Refusal>(&result);
    if (refused && refused->elevation_needed && *refused->elevation_needed > route.elevation) {
      route.elevation = *refused->elevation_needed;
      result = PlanRoute(search, route, place_cue);
    }
    return result;
  } catch (const std::exception& e) {
    return Refusal{PotStatus::kNoStroke, e.what()};
  }
}

double SmallerMargin(const PotPlan& p) { return std::min(p.margin_left_deg, p.margin_right_deg); }

// The order refusals are told in when every route fails: the one that got furthest.
int Rank(PotStatus s) {
  switch (s) {
    case PotStatus::kTargetUnreachable: return 4;
    case PotStatus::kNoStroke: return 3;
    case PotStatus::kTooThin:
    case PotStatus::kCueBlocked: return 2;
    default: return 1;
  }
}

// What the routes tried so far came to: the best plan, the most telling refusal, each refusal in
// words, and why the direct pot was refused.
struct Tally {
  std::optional<PotPlan> best;
  std::optional<Refusal> worst;
  std::vector<std::pair<std::string, int>> tried;  // each reason in words, and the routes it refused
  int alternatives = 0;
  std::string direct_blocked;
  bool direct_object_closed = false;

  // A route refused: told in words, the furthest-got refusal kept.
  void Refused(const Refusal& r, const Route& route) {
    if (route.kind == ShotKind::kDirect) {
      direct_blocked = r.reason;
      direct_object_closed = r.object_route_closed;
    }
    if (!worst || Rank(r.status) > Rank(worst->status)) worst = r;
    std::string label = ShotKindName(route.kind);
    if (route.rail >= 0) label += " off rail " + std::to_string(route.rail);
    // Routes of a kind that differ only in the stroke (a curve's elevations and sides) are
    // refused alike: the reason is told once, with how many routes it stopped.
    const std::string told = label + ": " + r.reason;
    const auto same =
        std::find_if(tried.begin(), tried.end(), [&](const auto& t) { return t.first == told; });
    if (same == tried.end()) {
      tried.emplace_back(told, 1);
    } else {
      ++same->second;
    }
  }

  // A curve is for a cue ball's line that is blocked (or too thin) when no bank or kick plans,
  // and K's own route is open.
  bool CurveWanted() const { return !direct_blocked.empty() && !direct_object_closed && !best; }

  // The plan refused when every route of `kinds` kinds failed.
  PotPlan EveryRouteRefused(std::size_t kinds) const {
    PotPlan plan;
    plan.status = worst ? worst->status : PotStatus::kBlocked;
    if (worst && worst->status == PotStatus::kBlocked && kinds > 1) {
      plan.reason = "every kind tried: ";
    }
    std::string all;
    for (const auto& [told, routes] : tried) {
      all += (all.empty() ? "" : "; ") + told;
      if (routes > 1) all += " (" + std::to_string(routes) + " routes)";
    }
    const bool one_route = tried.size() == 1 && tried.front().second == 1;
    plan.reason += kinds > 1 || !one_route ? all : (worst ? worst->reason : all);
    return plan;
  }

  // Why the best plan's kind, in words; a margin walked no further than `margin_cap` [rad] is
  // said to be at least that.
  std::string Why(const PotRequest& request, const std::optional<double>& margin_cap) const {
    std::ostringstream why;
    why.precision(3);
    if (best->kind == ShotKind::kDirect) {
      why << "direct: the straight lines are clear";
    } else {
      why << ShotKindName(best->kind);
      if (best->rail >= 0) why << " off rail " << best->rail;
      const double margin = SmallerMargin(*best);
      const bool capped = margin_cap && margin >= (*margin_cap - kMarginGrid) / kDegree;
      why << ": the widest margin (" << (capped ? "at least " : "") << margin << " deg) of "
          << alternatives << " plan"
          << (alternatives > 1 ? "s" : "");
      if (!direct_blocked.empty() && !request.kind) why << "; direct: " << direct_blocked;
    }
    return why.str();
  }
};

using Planned = std::vector<std::pair<PotPlan, Route>>;

// The pots of one kind that plan, the widest first. Of a bank, a kick or a curve, the shortest
// route that plans, of the kRoutesSearched shortest whose lines are clear (each costs a search).
Planned PlanKind(SearchContext& search, ShotKind kind, const PotRequest& request, Tally* tally) {
  Planned planned;
  int searched = 0;
  for (const Candidate& c : Routes(search, kind)) {
    if (kind != ShotKind::kDirect && !planned.empty() && !request.cue_target) break;
    if (kind != ShotKind::kCurve && c.blocked.empty() && ++searched > kRoutesSearched) {
      tally->Refused(Refusal{PotStatus::kBlocked, "longer than the " + std::to_string(kRoutesSearched) +
                                                      " shortest routes of its kind, not searched"}, c.route);
      continue;
    }
    const std::variant<PotPlan, Refusal> result =
        c.blocked.empty() ? Attempt(search, c.route, false) : Refusal{PotStatus::kBlocked, c.blocked};
    if (const auto* p = std::get_if<PotPlan>(&result)) {
      planned.emplace_back(*p, c.route);
    } else {
      tally->Refused(std::get<Refusal>(result), c.route);
    }
  }
  std::sort(planned.begin(), planned.end(), [](const auto& a, const auto& b) {
    return SmallerMargin(a.first) > SmallerMargin(b.first);
  });
  return planned;
}

// The best of a kind's pots: without a target the widest, where it is wider than the best so
// far; with one, position play on the widest first (it costs a search of its own).
void Choose(SearchContext& search, const Planned& planned, const PotRequest& request, Tally* tally) {
  tally->alternatives += static_cast<int>(planned.size());
  if (!request.cue_target) {
    if (!planned.empty() && (!tally->best || SmallerMargin(planned.front().first) > SmallerMargin(*tally->best))) {
      tally->best = planned.front().first;
    }
    return;
  }
  for (std::size_t i = 0; i < planned.size() && i < kPositionRoutes && !tally->best; ++i) {
    const std::variant<PotPlan, Refusal> placed = Attempt(search, planned[i].second, true);
    if (const auto* p = std::get_if<PotPlan>(&placed)) {
      tally->best = *p;
    } else {
      tally->Refused(std::get<Refusal>(placed), planned[i].second);
    }
  }
}

// The scene settled where PotOptions::settle_overlap asks (else as given).
std::vector<SceneBall> Settled(const table::TableGeometry& table, const physics::ModelParameters& params,
                               const std::vector<SceneBall>& balls, const PotOptions& options) {
  std::vector<SceneBall> settled = balls;
  if (options.settle_overlap > 0.0) {
    try {
      settled = table::SettledScene(table, params.ball.radius, balls, options.settle_overlap);
    } catch (const std::invalid_argument&) {
      // CheckRequest says what is wrong with the scene as it was given.
    }
  }
  return settled;
}

// The request's own mistakes, before anything is simulated.
std::optional<Refusal> CheckRequest(const table::TableGeometry& table,
                                    const physics::ModelParameters& params,
                                    const std::vector<SceneBall>& balls, const PotRequest& request) {
  try {
    physics::ValidateParameters(params);
  } catch (const std::invalid_argument& e) {
    return Refusal{PotStatus::kInvalid, e.what()};
  }
  const auto has = [&](int id) {
    return std::any_of(balls.begin(), balls.end(), [id](const SceneBall& b) { return b.id == id; });
  };
  if (!has(0)) return Refusal{PotStatus::kInvalid, "there is no cue ball (id 0) on the table"};
  if (request.ball == 0) return Refusal{PotStatus::kNoSuchBall, "ball 0 is the cue ball"};
  if (!has(request.ball)) {
    return Refusal{PotStatus::kNoSuchBall, "there is no ball " + std::to_string(request.ball) + " on the table"};
  }
  if (!table.PocketNamed(request.pocket)) {
    std::string names;
    for (const table::Pocket& p : table.pockets) names += (names.empty() ? "" : ", ") + p.name;
    return Refusal{PotStatus::kNoSuchPocket, "no pocket '" + request.pocket + "' on " + table.name +
                                                 (names.empty() ? " (it has none)" : " (" + names + ")")};
  }
  if (request.cue_target) {
    const CueTarget& t = *request.cue_target;
    if (!t.point.allFinite() || !std::isfinite(t.radius) || t.radius < 0.0) {
      return Refusal{PotStatus::kInvalid, "the cue-ball target must be finite, its radius >= 0"};
    }
    if (!table.OnSurface(t.point, params.ball.radius)) {
      return Refusal{PotStatus::kTargetUnreachable, "the cue-ball target is off the playing surface"};
    }
  }
  try {
    table::ValidateScene(table, params.ball.radius, balls);
  } catch (const std::invalid_argument& e) {
    return Refusal{PotStatus::kInvalid, e.what()};
  }
  return std::nullopt;
}

const table::Pocket& PocketOf(const table::TableGeometry& table, const std::string& name) {
  const table::Pocket* p = table.PocketNamed(name);
  if (!p) throw std::invalid_argument("no pocket '" + name + "'");
  return *p;
}

}  // namespace

PotPlan PlanPot(const table::TableGeometry& table, const physics::ModelParameters& params,
                const std::vector<SceneBall>& balls, const PotRequest& request,
                const PotOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const auto finish = [&](PotPlan p, int simulations) {
    p.ball = request.ball;
    p.pocket = request.pocket;
    p.simulations = simulations;
    p.solve_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    return p;
  };
  const std::vector<SceneBall> settled = Settled(table, params, balls, options);
  if (std::optional<Refusal> bad = CheckRequest(table, params, settled, request)) {
    PotPlan plan;
    plan.status = bad->status;
    plan.reason = bad->reason;
    return finish(plan, 0);
  }
  SearchContext search(table, params, settled, request.ball, *table.PocketNamed(request.pocket), options,
                       request.cue_target);
  std::vector<ShotKind> kinds = {ShotKind::kDirect, ShotKind::kBank, ShotKind::kKick, ShotKind::kCurve};
  if (request.kind) kinds = {*request.kind};
  Tally tally;
  for (ShotKind kind : kinds) {
    // A curve is for a blocked cue ball's line; asked for, it is tried anyway.
    if (kind == ShotKind::kCurve && !request.kind && !tally.CurveWanted()) continue;
    Choose(search, PlanKind(search, kind, request, &tally), request, &tally);
    // The direct pot, when it plans, is the shot: the others are for a blocked line.
    if (kind == ShotKind::kDirect && tally.best) break;
    if (request.cue_target && tally.best) break;
  }
  if (!tally.best) return finish(tally.EveryRouteRefused(kinds.size()), search.simulations());
  tally.best->why = tally.Why(request, options.margin_cap);
  return finish(*tally.best, search.simulations());
}

int StateMargins(const table::TableGeometry& table, const physics::ModelParameters& params,
                 const std::vector<SceneBall>& balls, PotPlan* plan, const PotOptions& options) {
  if (plan->status != PotStatus::kOk) return 0;
  PotOptions full = options;
  full.margin_cap.reset();
  full.margin_stride = 1;
  SearchContext search(table, params, Settled(table, params, balls, full), plan->ball,
                       PocketOf(table, plan->pocket), full);
  const physics::CueStroke& s = plan->stroke;
  const HeadingMargin margin =
      HeadingMargins(search, {s.speed, s.tip_side, s.tip_height, s.elevation}, s.heading);
  plan->margin_left_deg = margin.left / kDegree;
  plan->margin_right_deg = margin.right / kDegree;
  plan->simulations += search.simulations();
  return search.simulations();
}

std::optional<double> GhostBallHeading(const table::TableGeometry& table,
                                       const physics::ModelParameters& params,
                                       const std::vector<SceneBall>& balls, const PotPlan& plan,
                                       const PotOptions& options) {
  SearchContext search(table, params, balls, plan.ball, PocketOf(table, plan.pocket), options);
  const StrokeShape shape{plan.stroke.speed, plan.stroke.tip_side, plan.stroke.tip_height, plan.stroke.elevation};
  const std::optional<Aimed> ghost = AimAt(search, shape, plan.stroke.heading, plan.departure, true, 0.0, false);
  if (!ghost) return std::nullopt;
  return ghost->heading;
}

PotOutcome PlayStroke(const table::TableGeometry& table, const physics::ModelParameters& params,
                      const std::vector<SceneBall>& balls, int ball, const std::string& pocket,
                      const physics::CueStroke& stroke, const PotOptions& options) {
  SearchContext search(table, params, balls, ball, PocketOf(table, pocket), options);
  return search.Play(stroke, true).outcome;
}

const char* ShotKindName(ShotKind kind) {
  switch (kind) {
    case ShotKind::kDirect: return "direct";
    case ShotKind::kBank: return "bank";
    case ShotKind::kKick: return "kick";
    case ShotKind::kCurve: return "curve";
  }
  return "direct";
}

std::optional<ShotKind> ParseShotKind(const std::string& name, bool* known) {
  *known = true;
  for (ShotKind k : {ShotKind::kDirect, ShotKind::kBank, ShotKind::kKick, ShotKind::kCurve}) {
    if (name == ShotKindName(k)) return k;
  }
  *known = name == "any";
  return std::nullopt;
}

const char* PotStatusName(PotStatus status) {
  switch (status) {
    case PotStatus::kOk: return "ok";
    case PotStatus::kInvalid: return "invalid";
    case PotStatus::kNoSuchBall: return "no_such_ball";
    case PotStatus::kNoSuchPocket: return "no_such_pocket";
    case PotStatus::kBlocked: return "blocked";
    case PotStatus::kTooThin: return "too_thin";
    case PotStatus::kNoStroke: return "no_stroke";
    case PotStatus::kTargetUnreachable: return "target_unreachable";
    case PotStatus::kCueBlocked: return "cue_blocked";
  }
  return "invalid";
}

}  // namespace billiard::pot
