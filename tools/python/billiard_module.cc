// The `billiard` Python module (pybind11): simulate one ball or a table scene, strike a ball
// with the cue, plan a shot, choose one and play a rack (choice_functions.h), play a match rack
// by rack (match_functions.h), and detect the balls of a camera frame, NumPy arrays in and out.
// Bad input raises ValueError (the CLI's exit 2); an answer that is no (a refused plan, a frame
// without a table) raises billiard.Refused (the CLI's exit 3), its message the CLI's reason.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <map>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "estimator/ball_detector.h"
#include "planner/cue_planning.h"
#include "planner/pot/pot_planner.h"
#include "planner/shot_planner.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/robots.h"
#include "sim/params/table_specs.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/hop.h"
#include "sim/physics/simulator.h"
#include "sim/table/table_simulation.h"
#include "tools/python/choice_functions.h"
#include "tools/python/conversions.h"
#include "tools/python/match_functions.h"

namespace billiard::python {

namespace {

py::dict Simulate(const Array& state, double t_end, const std::string& model,
                  const std::string& params_name, std::optional<double> sample_dt) {
  const auto s = Numbers(state, 7, "state [X, Y, vx, vy, wx, wy, wz]");
  if (!(t_end >= 0.0 && std::isfinite(t_end))) throw py::value_error("t_end must be >= 0");
  const auto m = physics::ParseModel(model);
  if (!m) throw py::value_error("unknown model '" + model + "' (approx, integral, closed-form)");
  if (sample_dt && !(*sample_dt > 0.0 && std::isfinite(*sample_dt))) {
    throw py::value_error("sample_dt must be a positive number of seconds");
  }
  const physics::ModelParameters p = Params(params_name);
  physics::SimulationOptions options;
  options.model = *m;
  const physics::BallState initial = Eigen::Map<const physics::BallState>(s.data());
  physics::SimulationResult r;
  try {
    r = physics::Simulate(p, initial, t_end, options);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
  py::dict out;
  out["state"] = StateArray(r.final_state);
  out["t"] = t_end;
  out["rest_time"] = r.rest_time >= 0.0 ? py::cast(r.rest_time) : py::none();
  out["steps"] = r.stats.steps;
  if (sample_dt) {
    const std::size_t n = static_cast<std::size_t>(std::floor(t_end / *sample_dt)) + 1;
    Array samples({n, std::size_t{8}});
    auto a = samples.mutable_unchecked<2>();
    for (std::size_t k = 0; k < n; ++k) {
      const double t = std::min(k * *sample_dt, t_end);
      const physics::BallState x = r.trajectory->At(t);
      a(k, 0) = t;
      for (int j = 0; j < 7; ++j) a(k, j + 1) = x[j];
    }
    out["trajectory"] = samples;
  }
  return out;
}

Array Strike(double speed, double heading, double tip_side, double tip_height, double elevation,
             const Array& at, const std::string& params_name) {
  const auto p0 = Numbers(at, 2, "at [X, Y]");
  try {
    return StateArray(physics::StrikeBall({speed, heading, tip_side, tip_height, elevation},
                                          Eigen::Vector2d(p0[0], p0[1]), Params(params_name)));
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
}

double LaunchUpSpeed(double speed, double heading, double tip_side, double tip_height,
                     double elevation, const std::string& params_name) {
  const physics::CueStroke stroke{speed, heading, tip_side, tip_height, elevation};
  try {
    return physics::LaunchUpSpeed(stroke,
                                  physics::StrikeBall(stroke, {0.0, 0.0}, Params(params_name)));
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
}

py::dict SimulateScene(const Array& states, std::optional<std::vector<int>> ids,
                       const std::string& table_name, const std::string& params_name,
                       std::optional<double> t_end, std::optional<std::vector<double>> up_speeds) {
  std::vector<table::SceneBall> balls = SceneBalls(states, ids);
  const std::size_t n = balls.size();
  if (up_speeds) {
    if (up_speeds->size() != n)
      throw py::value_error("up_speeds must give every ball's (N of them)");
    for (std::size_t i = 0; i < n; ++i) balls[i].flight.vertical_speed = (*up_speeds)[i];
  }
  const physics::ModelParameters p = Params(params_name);
  std::unique_ptr<table::TableSimulation> sim;
  try {
    const table::TableGeometry geometry = table::BuildTable(params::LoadTableSpec(table_name));
    table::TableSimulationOptions options;  // the closed form between events
    sim = std::make_unique<table::TableSimulation>(geometry, p, balls, options);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
  if (t_end && !(*t_end >= 0.0 && std::isfinite(*t_end))) {
    throw py::value_error("t_end must be >= 0");
  }
  sim->Run(t_end.value_or(std::numeric_limits<double>::infinity()));
  Array final_states({n, std::size_t{7}});
  auto f = final_states.mutable_unchecked<2>();
  py::list pocketed, out_ids, events;
  for (std::size_t i = 0; i < n; ++i) {
    const physics::BallState s = sim->State(i);
    for (int j = 0; j < 7; ++j) f(i, j) = s[j];
    out_ids.append(sim->id(i));
    pocketed.append(sim->pocket(i) ? py::cast(*sim->pocket(i)) : py::none());
  }
  for (const table::TableEvent& e : sim->events()) {
    py::dict d;
    d["t"] = e.time;
    d["type"] = table::EventTypeName(e.type);
    d["balls"] = e.other >= 0 ? std::vector<int>{e.ball, e.other} : std::vector<int>{e.ball};
    if (e.type == table::EventType::kBallPocket) d["pocket"] = e.pocket;
    events.append(d);
  }
  py::dict out;
  out["ids"] = out_ids;
  out["states"] = final_states;
  out["pocketed"] = pocketed;
  out["events"] = events;
  out["t"] = sim->time();
  out["at_rest"] = sim->AtRest();
  return out;
}

py::dict Plan(const Array& from, const Array& to, double final_speed, const std::string& spin,
              double side_spin, const std::string& params_name, const std::string& robot,
              const std::string& table_name) {
  const auto a = Numbers(from, 2, "from [X, Y]"), b = Numbers(to, 2, "to [X, Y]");
  if (!std::isfinite(final_speed) || !std::isfinite(side_spin)) {
    throw py::value_error("final_speed and side_spin must be finite");
  }
  const auto style = planner::ParseSpinStyle(spin);
  if (!style) throw py::value_error("unknown spin '" + spin + "' (stun, natural, follow, draw)");
  planner::ShotRequest request;
  request.from = {a[0], a[1]};
  request.to = {b[0], b[1]};
  request.final_speed = final_speed;
  request.style = *style;
  request.side_spin = side_spin;
  const physics::ModelParameters params = Params(params_name);
  const planner::ShotPlan plan =
      planner::PlanShotForRobot(request, params, {}, planner::CueSetting{Robot(robot), Table(table_name), {}});
  if (plan.status != planner::PlanStatus::kOk) {
    Refuse(planner::PlanStatusName(plan.status) + ": " + plan.reason);
  }
  py::dict out;
  out["v0"] = Array(2, plan.v0.data());
  out["w0"] = Array(3, plan.w0.data());
  out["cue"] = CueJson(plan.stroke, plan.clearance);
  out["predicted_final"] = Array(2, plan.predicted_final.data());
  out["arrival_time"] = plan.arrival_time;
  out["refined_miss_m"] = plan.refined_miss_m;
  return out;
}

py::dict PlanPot(const Array& states, std::optional<std::vector<int>> ids, int ball,
                 const std::string& pocket, const std::string& kind,
                 std::optional<Array> cue_to, double cue_radius, const std::string& table_name,
                 const std::string& params_name, const std::string& robot) {
  pot::PotRequest request;
  request.ball = ball;
  request.pocket = pocket;
  bool known = false;
  request.kind = pot::ParseShotKind(kind, &known);
  if (!known) throw py::value_error("unknown kind '" + kind + "' (direct, bank, kick, curve, any)");
  if (cue_to) {
    const auto t = Numbers(*cue_to, 2, "cue_to [X, Y]");
    request.cue_target = pot::CueTarget{{t[0], t[1]}, cue_radius};
  }
  pot::PotOptions options;
  options.robot = Robot(robot);
  const pot::PotPlan plan =
      pot::PlanPot(Table(table_name), Params(params_name), SceneBalls(states, ids), request, options);
  if (plan.status != pot::PotStatus::kOk) {
    Refuse(std::string(pot::PotStatusName(plan.status)) + ": " + plan.reason);
  }
  py::dict out;
  out["kind"] = pot::ShotKindName(plan.kind);
  out["why"] = plan.why;
  out["v0"] = Array(2, plan.v0.data());
  out["w0"] = Array(3, plan.w0.data());
  out["cue"] = CueJson(plan.stroke, plan.clearance);
  out["cut_deg"] = plan.cut_deg;
  out["margin_deg"] = std::vector<double>{plan.margin_left_deg, plan.margin_right_deg};
  out["speed_window"] = std::vector<double>{plan.speed_lo, plan.speed_hi};
  out["cue_rest"] = Array(2, plan.cue_rest.data());
  py::dict paths;
  for (const pot::BallPath& path : plan.paths) {
    Array points({path.points.size(), std::size_t{2}});
    auto m = points.mutable_unchecked<2>();
    for (std::size_t i = 0; i < path.points.size(); ++i) {
      m(i, 0) = path.points[i].x();
      m(i, 1) = path.points[i].y();
    }
    paths[py::int_(path.id)] = points;
  }
  out["paths"] = paths;
  out["solve_us"] = plan.solve_us;
  return out;
}

py::dict Detect(const py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>& image,
                const std::string& ball_set) {
  if (!(image.ndim() == 2 || (image.ndim() == 3 && image.shape(2) == 3))) {
    throw py::value_error("image must be H x W (grey) or H x W x 3 (BGR, as OpenCV reads it)");
  }
  const cv::Mat frame(static_cast<int>(image.shape(0)), static_cast<int>(image.shape(1)),
                      image.ndim() == 2 ? CV_8UC1 : CV_8UC3,
                      const_cast<std::uint8_t*>(image.data()));
  estimator::DetectorOptions options;
  const auto set = estimator::BallSetNamed(ball_set);
  if (!set) {
    throw py::value_error("unknown ball set '" + ball_set + "' (" + estimator::kBallSetNames + ")");
  }
  options.ball_set = *set;
  estimator::BallDetector detector(options);
  const auto balls = detector.Detect(frame);
  // No cloth either: refused. No table but its cloth: the balls on it, and why no table.
  if (!detector.table()) Refuse(detector.failure());
  Array found({balls.size(), std::size_t{4}});
  auto f = found.mutable_unchecked<2>();
  py::list classes;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    f(i, 0) = balls[i].pixel.x();
    f(i, 1) = balls[i].pixel.y();
    f(i, 2) = balls[i].radius_px;
    f(i, 3) = balls[i].score;
    classes.append(estimator::BallClassName(balls[i].ball_class));
  }
  py::dict out;
  out["balls"] = found;
  out["classes"] = classes;
  out["no_table"] = detector.knows_table() ? py::object(py::none()) : py::str(detector.failure());
  return out;
}

}  // namespace

}  // namespace billiard::python

PYBIND11_MODULE(billiard, m) {
  using namespace billiard::python;
  using py::arg;
  m.doc() = "Robot billiard physics, planning and vision (docs/python.md)";
  RefusedType() = py::reinterpret_borrow<py::object>(
      PyErr_NewException("billiard.Refused", PyExc_Exception, nullptr));
  m.attr("Refused") = RefusedType();
  m.def("simulate", &Simulate, arg("state"), arg("t_end"), arg("model") = "approx",
        arg("params") = "pool", arg("sample_dt") = py::none(),
        "One ball on an endless cloth from state [X, Y, vx, vy, wx, wy, wz] to t_end: a dict "
        "with the final 'state', 't', 'rest_time', 'steps' and, with sample_dt, 'trajectory' "
        "(rows t, X, Y, vx, vy, wx, wy, wz)");
  m.def("strike", &Strike, arg("speed"), arg("heading"), arg("tip_side") = 0.0,
        arg("tip_height") = 0.0, arg("elevation") = 0.0,
        arg("at") = Array(2, std::array<double, 2>{0, 0}.data()), arg("params") = "pool",
        "The state a cue stroke launches a ball at `at` with (cue strike model with squirt): "
        "tip_side > 0 right english, tip_height > 0 follow, < 0 draw");
  m.def("launch_up_speed", &LaunchUpSpeed, arg("speed"), arg("heading"), arg("tip_side") = 0.0,
        arg("tip_height") = 0.0, arg("elevation") = 0.0, arg("params") = "pool",
        "The speed [m/s] a ball struck by that stroke leaves the cloth upward at: the slate's "
        "return of what an elevated cue drives it down with (0 for a level cue)");
  m.def("simulate_scene", &SimulateScene, arg("states"), arg("ids") = py::none(),
        arg("table") = billiard::params::kDefaultTable, arg("params") = "pool",
        arg("t_end") = py::none(), arg("up_speeds") = py::none(),
        "Every ball of a table scene (N x 7 states, ids default 0..N-1, id 0 the cue ball), event "
        "by event, the closed form between events, a ball given an upward speed (up_speeds, "
        "launch_up_speed's) flown until it lands: 'ids', final 'states', 'pocketed', 'events'");
  m.def("plan", &Plan, arg("from_"), arg("to"), arg("final_speed") = 0.0, arg("spin") = "natural",
        arg("side_spin") = 0.0, arg("params") = "pool",
        arg("robot") = billiard::params::kDefaultRobot,
        arg("table") = billiard::params::kDefaultTable,
        "The launch and cue stroke that send a ball from `from_` to `to`, at the elevation the "
        "robot's cue needs on the table; raises Refused");
  m.def("plan_pot", &PlanPot, arg("states"), arg("ids") = py::none(), arg("ball") = 1,
        arg("pocket") = "upper_right", arg("kind") = "any", arg("cue_to") = py::none(),
        arg("cue_radius") = 0.0, arg("table") = billiard::params::kDefaultTable,
        arg("params") = "pool", arg("robot") = billiard::params::kDefaultRobot,
        "The stroke that pots `ball` in `pocket` from a scene (N x 7 states, id 0 the cue ball), "
        "planned against the whole-table simulation: 'kind', 'why', 'v0', 'w0', 'cue', "
        "'margin_deg', 'speed_window', 'cue_rest', 'paths'; raises Refused");
  AddChoiceFunctions(m);
  AddMatchFunctions(m);
  m.def("detect", &Detect, arg("image"), arg("ball_set") = "pool",
        "The balls of a BGR (H x W x 3) or grey frame: 'balls' (N x 4: u, v, radius_px, score) "
        "and 'classes'; raises Refused when the frame shows no table");
}
