// Potting: the cue stroke that sends ball K into pocket P, planned against the whole-table
// simulation (sim/table/), and, when asked, leaves the cue ball at a target.
//
// A pot is a route for each ball and a stroke that joins them:
//  - the object ball's route: straight at the pocket (direct, kick, curve) or off one rail
//    (bank), its aim the pocket's mouth or the pocket's mirror image in the rail;
//  - the cue ball's route to the ghost ball (where it touches K with the line of centres along
//    K's route): straight (direct, bank), off one rail first (kick), or bent by an elevated cue
//    with side spin (curve: the slide's parabola on the cloth, Kudra et al. 2016's massé);
//  - the stroke (sim/physics/cue_strike.h: Alciatore's TP A.30 impact and TP A.31 squirt).
// The plan is found in named steps, each on the simulation rather than on geometry alone:
//  1. the drop window: the directions in which K, leaving the cue ball's contact with its
//     post-impact state, still drops in P, found by bisection on simulations of K among the
//     still balls; the plan aims at the window's middle, not merely anywhere that drops;
//  2. the aim: the ghost ball for that direction, corrected for throw by the ball-ball impact
//     model the simulation uses (Alciatore's TP A.14: the cut- and spin-induced throw, solved
//     for the contact normal that sends K along the window's middle with the cue ball's state
//     at contact), then the heading refined by the secant method on simulations until K leaves
//     along the window's middle to 1e-6 rad;
//  3. the speed: the slowest cue speed that still drops K (bisection), and the stroke that lands
//     K in the pocket with some pace to spare; with a cue-ball target, the speed and the
//     follow/draw (tip height) that stop the cue ball there, by Newton's method on the
//     simulated rest point from the best of a coarse grid;
//  4. the margin: how far the cue's heading may turn either way with every heading of a
//     0.01-degree grid still potting legally on the truth (walked out from the aim), and the cue
//     speeds between which K drops;
//  5. the check against the truth: the plan simulated with the motion `billiard simulate --scene`
//     runs by default (sim/model_choice/, `--model auto`), re-aimed there, and refused if it does
//     not pot legally (K in P, the cue ball's first contact K, no scratch).
// Searching runs the closed form (Jaroukh 2019) between events, which is exact for the
// level-cue paths that most pots are and 30-100 times cheaper; the check runs the truth.
// Each step has a header of its own beside this one (README, "A pot in named steps"): routes.h
// and lone_path.h, aim.h, pace.h, drop_window.h, truth.h, margin.h and position.h, on the search
// context they share (search_context.h).
//
// Module: billiard::pot. Includes the physics, the table, the parameter sets and the table's
// motion rule (sim/model_choice/).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "sim/cue/clearance.h"
#include "sim/cue/robot.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/table/table_geometry.h"
#include "sim/table/table_simulation.h"

namespace billiard::pot {

enum class ShotKind { kDirect, kBank, kKick, kCurve };

// "direct", "bank", "kick", "curve".
const char* ShotKindName(ShotKind kind);
// A kind by name; std::nullopt for "any" (every kind) and for an unknown name (*known false).
std::optional<ShotKind> ParseShotKind(const std::string& name, bool* known);

enum class PotStatus {
  kOk,
  kInvalid,             // a non-finite number, a scene the simulation refuses, no cue ball
  kNoSuchBall,          // ball K is not on the table (or is the cue ball)
  kNoSuchPocket,        // the table has no pocket of that name
  kBlocked,             // every kind tried: another ball or the table is in the way
  kTooThin,             // the cut needed is thinner than max_cut_deg
  kNoStroke,            // no stroke within the cue's limits pots it
  kTargetUnreachable,   // it pots, but no stroke within the limits stops the cue ball there
  kCueBlocked,          // the robot's cue meets a ball, the table or its own body at every elevation
};

// "ok", "invalid", "no_such_ball", "no_such_pocket", "blocked", "too_thin", "no_stroke",
// "target_unreachable", "cue_blocked".
const char* PotStatusName(PotStatus status);

struct CueTarget {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  double radius = 0.0;  // 0: the point itself, within PotOptions::position_tolerance
};

struct PotRequest {
  int ball = -1;                  // K, the object ball's id
  std::string pocket;             // P, as TableGeometry names it
  std::optional<ShotKind> kind;   // none: any kind, direct first
  std::optional<CueTarget> cue_target;
};

struct PotOptions {
  // The motion the plan is checked against and reported in: `simulate --scene`'s default when
  // empty (model_choice::TableMotion). The search always runs the closed form.
  decltype(table::TableSimulationOptions::five_dof) truth_motion;
  table::CushionModel cushion_model = table::CushionModel::kMathavan2010;
  // Cuts thinner than this are refused as too thin [deg]: near 90 degrees the drop window in
  // heading shrinks as cos(cut) and the throw grows past any robot's aim.
  double max_cut_deg = 80.0;
  // K's speed as it crosses the capture line on a plain pot [m/s]: firm enough to drop through
  // a slightly-off jaw, slow enough not to drag the cue ball into a scratch.
  double arrival_speed = 0.6;
  // A cue-ball target without a radius is met when the rest point is this close [m].
  double position_tolerance = 5e-3;
  // The predicted paths are sampled at this interval [s] (and at their ends).
  double path_sample_dt = 0.02;
  // A scene from a camera: balls that overlap each other or a cushion by up to this [m] are
  // settled first (table::SettledScene) and the plan made on the settled scene; 0, the default
  // (plan-pot, like simulate --scene): the scene must be valid as it is.
  double settle_overlap = 0.0;
  // The robot whose cue plays the stroke (params::LoadRobot; the commands' and nodes' --robot,
  // "gantry" by default): every route is planned at the elevation its cue needs to clear the
  // balls, the rails and its body (cue_elevation.h), and refused (cue_blocked) where none does.
  // None: the cue is not checked (a stroke at the route's own elevation, level but for a curve).
  std::optional<cue::Robot> robot;
  // The heading margin's walk (margin.h). By default in full: every 0.01-degree heading played out
  // to a quarter turn, the margin a plan states. A planner that only ranks plans by their margin
  // and finds their chance by sampling the noise (planner/choice/) may stop at `margin_cap`
  // [rad] (a margin that reaches it is at least that wide) and play every `margin_stride`-th
  // heading, the edge found by bisection on the grid: the same margin unless a hole narrower
  // than a stride lies inside it. StateMargins walks such a plan's margin in full.
  std::optional<double> margin_cap;
  int margin_stride = 1;
};

struct BallPath {
  int id = 0;
  std::vector<Eigen::Vector2d> points;
};

struct PotPlan {
  PotStatus status = PotStatus::kInvalid;
  std::string reason;  // why not, when status != kOk; empty when ok
  int ball = -1;
  std::string pocket;
  ShotKind kind = ShotKind::kDirect;
  std::string why;  // why this kind (the lines it found blocked, the alternatives' margins)
  int rail = -1;    // bank, kick: the rail (index of TableGeometry::lines)

  physics::CueStroke stroke;
  Eigen::Vector2d v0 = Eigen::Vector2d::Zero();  // the cue ball's launch, squirt included
  Eigen::Vector3d w0 = Eigen::Vector3d::Zero();
  physics::Flight flight;  // the cue ball's hop at launch (table::Struck), for an elevated cue
  double cut_deg = 0.0;  // angle between the cue ball's approach and K's departure

  // Heading window: the cue may turn this far either way [deg] (left: counterclockwise) with
  // every heading 0.01 degree apart still potting legally on the truth (margin.h: a multiple of
  // 0.01 degree, 0 where the first step fails); the cue speeds [m/s] at the planned heading
  // between which K drops.
  double margin_left_deg = 0.0, margin_right_deg = 0.0;
  double speed_lo = 0.0, speed_hi = 0.0;

  Eigen::Vector2d cue_rest = Eigen::Vector2d::Zero();  // where the truth leaves the cue ball
  std::vector<table::TableEvent> events;                // the truth's events, to rest
  std::vector<BallPath> paths;                          // of every ball that moves
  double solve_us = 0.0;
  int simulations = 0;  // table simulations run for the plan, closed form and truth
  double departure = 0.0;  // the direction K leaves in: its drop window's middle [rad]
  // The stroke's cue against the robot's (PotOptions::robot; none without one): it clears, the
  // obstacle nearest the cue and its distance. The stroke's elevation is the least that clears
  // plus a margin (cue_elevation.h).
  std::optional<cue::CueClearance> clearance;
};

// Plans the pot of `request` on `table` from `balls` (id 0 the cue ball, at rest or moving: the
// stroke is played from where it is, at rest). Never throws on a bad request: the status and
// reason say what is wrong.
PotPlan PlanPot(const table::TableGeometry& table, const physics::ModelParameters& params,
                const std::vector<table::SceneBall>& balls, const PotRequest& request,
                const PotOptions& options = {});

// `plan`'s heading margin walked in full (options' margin_cap and margin_stride aside), on the
// scene it was planned on: the margin to state of a plan whose walk was cut short. Its
// simulations are added to plan->simulations and returned; none for a plan that is not ok.
int StateMargins(const table::TableGeometry& table, const physics::ModelParameters& params,
                 const std::vector<table::SceneBall>& balls, PotPlan* plan,
                 const PotOptions& options = {});

// The heading [rad] that aims `plan`'s stroke (its speed, offsets, elevation) through the ghost ball
// alone: the line of centres along plan.departure, the throw not corrected. What aiming without
// the ball-ball model would do; std::nullopt where no heading near the plan's meets K.
std::optional<double> GhostBallHeading(const table::TableGeometry& table,
                                       const physics::ModelParameters& params,
                                       const std::vector<table::SceneBall>& balls,
                                       const PotPlan& plan, const PotOptions& options = {});

// The same plan's stroke turned by `heading_offset` [rad] and played at `speed` [m/s] (the cue
// speed; the plan's own when not given), simulated with the truth: whether K drops in P legally
// (no scratch, the cue ball's first contact K). For the margin's checks and the noise studies.
struct PotOutcome {
  bool potted = false;   // K dropped in P
  bool legal = false;    // potted, the cue ball touched K first and did not drop
  int first_contact = -1;
  std::optional<std::string> cue_pocket;
  Eigen::Vector2d cue_rest = Eigen::Vector2d::Zero();
};
PotOutcome PlayStroke(const table::TableGeometry& table, const physics::ModelParameters& params,
                      const std::vector<table::SceneBall>& balls, int ball,
                      const std::string& pocket, const physics::CueStroke& stroke,
                      const PotOptions& options = {});

}  // namespace billiard::pot
