#include "sim/model_choice/model_choice.h"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace billiard::model_choice {

namespace internal {
const char* MeasuredModelChoiceJson();
}

std::string SceneKindOf(const physics::BallState& s, const physics::ModelParameters& p) {
  if (s[physics::kWz] != 0.0) return "side-spin";
  const double slip = physics::ClothSlip(s, p.ball.radius).norm();
  return slip <= 1e-9 + 1e-6 * s.segment<2>(physics::kVx).norm() ? "rolling" : "sliding";
}

ModelChoice ChooseModel(const physics::BallState& initial, const physics::ModelParameters& p,
                        double accuracy_m) {
  if (!std::isfinite(accuracy_m) || accuracy_m <= 0.0) {
    throw std::invalid_argument("accuracy must be a positive number of metres");
  }
  static const nlohmann::json table = nlohmann::json::parse(internal::MeasuredModelChoiceJson());
  ModelChoice choice;
  choice.kind = SceneKindOf(initial, p);
  const nlohmann::json* cheapest = nullptr;
  const nlohmann::json* most_accurate = nullptr;
  for (const nlohmann::json& row : table.at("kinds").at(choice.kind)) {
    const std::string model = row.at("model");
    if (choice.kind == "side-spin" && model == physics::ModelName(physics::Model::kClosedForm))
      continue;
    const double error = row.at("p95_error_m"), us = row.at("median_us");
    if (!most_accurate || error < most_accurate->at("p95_error_m").get<double>()) {
      most_accurate = &row;
    }
    if (error <= accuracy_m && (!cheapest || us < cheapest->at("median_us").get<double>())) {
      cheapest = &row;
    }
  }
  if (!most_accurate) throw std::runtime_error("the measured model table has no " + choice.kind);
  choice.accuracy_met = cheapest != nullptr;
  const nlohmann::json& row = cheapest ? *cheapest : *most_accurate;
  choice.options.model = *physics::ParseModel(row.at("model"));
  choice.options.integrator = *physics::ParseIntegrator(row.at("integrator"));
  choice.options.tolerance = row.at("tolerance");
  choice.options.quadrature_tolerance = row.at("quadrature_tolerance");
  choice.expected_error_m = row.at("p95_error_m");
  choice.expected_us = row.at("median_us");
  return choice;
}

physics::SimulationOptions TableMotionMethod(const physics::ModelParameters& p,
                                             double accuracy_m) {
  return ChooseModel(physics::MakeBallState(0, 0, 1, 0, 0, 0, 1), p, accuracy_m).options;
}

decltype(table::TableSimulationOptions::five_dof) TableMotion(const physics::ModelParameters& p,
                                                             double accuracy_m) {
  const physics::SimulationOptions method = TableMotionMethod(p, accuracy_m);
  return [method, p](const physics::BallState& state) {
    return table::FiveDofWhereNeeded(state, p, method);
  };
}

}  // namespace billiard::model_choice
