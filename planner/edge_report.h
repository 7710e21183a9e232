// The simulator and the planner with contact parameters at the edge of their range, measured for
// the reliability report: no friction (mu = 0, which needs d = 0), no rolling resistance (d = 0),
// regularization 1e-9 (eps_t and eps_r together and each alone), their combinations, two sets the
// model refuses, and planner runs whose iteration or step budget is too small.
#pragma once

#include <nlohmann/json.hpp>

namespace billiard::planner {

// Runs every set (about 1 s on one core) and returns
//   {"sets": [{"name", "mu", "d", "eps_t", "eps_r", "valid", "reason" (when not valid),
//              "simulations": [{"scene", "initial", "t_end", "steps", "rejected_steps",
//                               "rhs_evals", "wall_us", "final", "rest_time" (null: never
//                               stopped), "energy_start_J", "energy_end_J", "max_energy_rise_J",
//                               "closed_form_final" and "closed_form_gap_m" (scenes without side
//                               spin), or "error"}],
//              "plans": [{"request", "status", "reason", "iterations", "simulations", "solve_us",
//                         "launch_speed", "refined_miss_m", "resimulated_miss_m" (ok plans, at the
//                         simulator's default tolerance)}]}],
//    "non_convergence": [{"case", and the fields of a plan above}]}
// Simulations are of the approximate 5-DOF model with the simulator's defaults (RODAS4, tolerance
// 1e-6) over 8 s; plans use PlanShot's defaults on the paper set's table and cue.
nlohmann::json EdgeParameterReport();

}  // namespace billiard::planner
