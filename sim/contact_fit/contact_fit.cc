#include "sim/contact_fit/contact_fit.h"

#include <ceres/ceres.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "sim/physics/approximate_friction.h"
#include "sim/physics/gauss_legendre.h"

namespace billiard::contact_fit {

namespace {

struct Sample {
  physics::ContactKinematics<double> kinematics;
  double weight;                                // Gauss weight of the node in D
  physics::FrictionResultant<double> integral;  // the integral model at the node
};

physics::FrictionResultant<double> Approximation(const physics::ContactKinematics<double>& k,
                                                 double b_t, double m_t, double b_m, double m_m) {
  physics::ContactParameters c;  // eps_t = 0: the unregularized model of eq. 13
  c.b_t = b_t;
  c.m_t = m_t;
  c.b_m = b_m;
  c.m_m = m_m;
  return physics::ApproximateFriction(k, c);
}

// Residuals sqrt(w) (T - T^I) at one node, as a function of (b_T, m_T).
struct ForceResidual {
  const Sample* sample;
  bool operator()(const double* b, const double* m, double* residual) const {
    const auto f = Approximation(sample->kinematics, *b, *m, 1.0, 2.0);
    const double s = std::sqrt(sample->weight);
    residual[0] = s * (sample->integral.tsx - f.tsx);
    residual[1] = s * (sample->integral.tsy - f.tsy);
    return std::isfinite(residual[0]) && std::isfinite(residual[1]);
  }
};

// Residual sqrt(w) (Ms - Ms^I) at one node, as a function of (b_M, m_M).
struct MomentResidual {
  const Sample* sample;
  bool operator()(const double* b, const double* m, double* residual) const {
    const auto f = Approximation(sample->kinematics, 1.0, 2.0, *b, *m);
    residual[0] = std::sqrt(sample->weight) * (sample->integral.ms - f.ms);
    return std::isfinite(residual[0]);
  }
};

// Solves one of the two fits; returns F (= 2 x Ceres' cost, which halves the sum of squares).
template <class Residual, int kResiduals>
double Solve(const std::vector<Sample>& samples, const std::optional<double>& fixed_m, double* b,
             double* m) {
  ceres::Problem problem;
  for (const Sample& s : samples) {
    problem.AddResidualBlock(
        new ceres::NumericDiffCostFunction<Residual, ceres::CENTRAL, kResiduals, 1, 1>(
            new Residual{&s}),
        nullptr, b, m);
  }
  problem.SetParameterLowerBound(b, 0, 1e-3);
  problem.SetParameterUpperBound(b, 0, 10.0);
  problem.SetParameterLowerBound(m, 0, 1.0);
  problem.SetParameterUpperBound(m, 0, 12.0);
  if (fixed_m) problem.SetParameterBlockConstant(m);
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.num_threads = 1;
  options.function_tolerance = 1e-14;
  options.parameter_tolerance = 1e-12;
  options.max_num_iterations = 200;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  if (!summary.IsSolutionUsable()) {
    throw std::runtime_error("contact fit failed: " + summary.message);
  }
  return 2.0 * summary.final_cost;
}

}  // namespace

ContactFit FitContactApproximation(const ContactFitOptions& options,
                                   const std::function<void(const std::string&)>& progress) {
  if (options.nodes_d < 1 || options.nodes_gamma < 1 || options.nodes_theta < 2) {
    throw std::invalid_argument("contact fit needs at least 1 x 1 x 2 nodes over D");
  }
  if (options.fixed_m && !(*options.fixed_m >= 1.0)) {
    throw std::invalid_argument("--fix-m must be a number >= 1");
  }
  constexpr double kPi = 3.14159265358979323846;
  const auto say = [&](const std::string& line) {
    if (progress) progress(line);
  };

  ContactFit fit;
  fit.quadrature = physics::CalibrateQuadrature(0.0, 1.0, options.quadrature_tolerance);
  const physics::IntegralFriction integral(fit.quadrature.order);
  say("integral model: " + std::to_string(fit.quadrature.order.angular) + " x " +
      std::to_string(fit.quadrature.order.radial) + " nodes, estimated error " +
      std::to_string(fit.quadrature.error_estimate));

  // Gauss-Legendre over each axis of D, mapped from [-1, 1].
  const physics::QuadratureRule rd = physics::GaussLegendre(options.nodes_d);
  const physics::QuadratureRule rg = physics::GaussLegendre(options.nodes_gamma);
  const physics::QuadratureRule rt = physics::GaussLegendre(options.nodes_theta);
  std::vector<Sample> samples;
  samples.reserve(rd.nodes.size() * rg.nodes.size() * rt.nodes.size());
  for (std::size_t i = 0; i < rd.nodes.size(); ++i) {
    const double d = 0.5 * (1.0 + rd.nodes[i]);
    for (std::size_t j = 0; j < rg.nodes.size(); ++j) {
      const double gamma = 0.5 * kPi * (1.0 + rg.nodes[j]);
      for (std::size_t l = 0; l < rt.nodes.size(); ++l) {
        const double theta = 0.5 * kPi * rt.nodes[l];
        Sample s;
        s.kinematics = {std::cos(theta), 0.0, std::sin(theta), d * std::cos(gamma),
                        d * std::sin(gamma)};
        s.weight = 0.5 * rd.weights[i] * 0.5 * kPi * rg.weights[j] * 0.5 * kPi * rt.weights[l];
        s.integral = integral.Evaluate(s.kinematics, 0.0);
        samples.push_back(s);
      }
    }
    say("integral model over D: " + std::to_string(100 * (i + 1) / rd.nodes.size()) + " %");
  }
  fit.samples = static_cast<int>(samples.size());

  fit.b_t = 0.7;
  fit.b_m = 0.5;
  fit.m_t = fit.m_m = options.fixed_m.value_or(2.0);
  fit.cost_t = Solve<ForceResidual, 2>(samples, options.fixed_m, &fit.b_t, &fit.m_t);
  say("force fit done: b_T = " + std::to_string(fit.b_t) + ", m_T = " + std::to_string(fit.m_t));
  fit.cost_m = Solve<MomentResidual, 1>(samples, options.fixed_m, &fit.b_m, &fit.m_m);
  say("moment fit done: b_M = " + std::to_string(fit.b_m) + ", m_M = " + std::to_string(fit.m_m));
  return fit;
}

}  // namespace billiard::contact_fit
