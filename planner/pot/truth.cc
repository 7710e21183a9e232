#include "planner/pot/truth.h"

#include "planner/pot/pot_geometry.h"

namespace billiard::pot {

using table::EventType;
using table::TableEvent;
using table::TableSimulation;

namespace {

// The truth's events and every moving ball's path.
void Describe(const TableSimulation& sim, double sample_dt, PotPlan* plan) {
  plan->events = sim.events();
  for (std::size_t i = 0; i < sim.ball_count(); ++i) {
    if (sim.segments(i).size() < 2 && sim.segments(i).front().phase() == table::MotionPhase::kStationary) continue;
    BallPath path{sim.id(i), {}};
    double end = sim.time();
    for (const TableEvent& e : sim.events()) {
      if (e.type == EventType::kBallPocket && e.ball == sim.id(i)) end = e.time;
    }
    for (double t = 0.0; t < end; t += sample_dt) path.points.push_back(sim.StateAt(i, t).head<2>());
    path.points.push_back(StateBefore(sim, i, end).head<2>());
    plan->paths.push_back(path);
  }
}

}  // namespace

std::variant<TruthShot, Refusal> PlayOnTheTruth(SearchContext& search, const Route& route,
                                                const StrokeShape& shape, const Aimed& aimed,
                                                const Drop& drop, const std::optional<Aimed>& placed) {
  const std::string misses = "under the full model the cue ball misses ball " + std::to_string(search.object_id());
  // The truth's own aim: the motion it runs (5-DOF while the cue ball slides) meets K a little
  // differently.
  std::optional<Aimed> truth = placed ? placed : AimAt(search, shape, aimed.heading, drop.Middle(), true, aimed.slope);
  if (!truth) return Refusal{PotStatus::kNoStroke, misses};
  // A bank's window moves with K's state at the rail, which the truth's slide changes: it is
  // found again on the truth, from the search's, and the margin measured there.
  Drop window = drop;
  // The window found again on the truth, and the aim at its middle.
  const auto on_the_truth = [&]() -> std::optional<Refusal> {
    std::optional<Drop> w = DropWindow(search, truth->contact, drop.Middle(), kDirectScan, 0.0, kWindowResolution, drop, true);
    if (!w) return Refusal{PotStatus::kNoStroke, "under the full model ball " + std::to_string(search.object_id()) + " does not drop in " + search.pocket().name};
    window = *w;
    truth = AimAt(search, shape, truth->heading, window.Middle(), true, truth->slope);
    if (!truth) return Refusal{PotStatus::kNoStroke, misses};
    return std::nullopt;
  };
  if (route.kind == ShotKind::kBank && !placed) {
    if (std::optional<Refusal> r = on_the_truth()) return *r;
  }
  physics::CueStroke stroke = shape.At(truth->heading);
  Played played = search.Play(stroke, true);
  // Where the search's jaws (kSearchCushion) let K rattle in and the truth's do not: the
  // window on the truth.
  if (!played.outcome.legal && route.kind != ShotKind::kBank && !placed &&
      played.outcome.first_contact == search.object_id()) {
    if (std::optional<Refusal> r = on_the_truth()) return *r;
    stroke = shape.At(truth->heading);
    played = search.Play(stroke, true);
  }
  if (!played.outcome.legal) return Refusal{PotStatus::kNoStroke, Illegal(search, played.outcome)};
  return TruthShot{*truth, window, stroke, std::move(played)};
}

std::string Illegal(const SearchContext& search, const PotOutcome& o) {
  const int object = search.object_id();
  if (o.first_contact != object) {
    return o.first_contact < 0 ? "the cue ball touches no ball"
                               : "the cue ball touches ball " + std::to_string(o.first_contact) + " first";
  }
  if (o.cue_pocket) return "the cue ball follows into " + *o.cue_pocket + " (a scratch)";
  return "ball " + std::to_string(object) + " does not drop in " + search.pocket().name;
}

void DescribeShot(const TruthShot& shot, double sample_dt, PotPlan* plan) {
  const TableSimulation& sim = *shot.played.sim;
  const std::size_t cue = IndexOf(sim, 0);
  plan->stroke = shot.stroke;
  plan->v0 = sim.StateAt(cue, 0.0).segment<2>(physics::kVx);
  plan->w0 = sim.StateAt(cue, 0.0).segment<3>(physics::kWx);
  plan->flight = sim.segments(cue).front().FlightAt(0.0);
  plan->cut_deg = CutAngle(Unit(Angle(shot.aimed.contact.cue_before.segment<2>(physics::kVx))),
                           Unit(shot.aimed.contact.departure)) / kDegree;
  plan->cue_rest = shot.played.outcome.cue_rest;
  plan->departure = shot.window.Middle();
  Describe(sim, sample_dt, plan);
}

}  // namespace billiard::pot
