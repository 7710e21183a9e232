#include "tools/billiard/fit_contact_command.h"

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "sim/contact_fit/contact_fit.h"
#include "tools/billiard/command_line.h"

namespace billiard::cli {

namespace {

struct FitContactArgs {
  double fix_m = 0.0;
  bool fix_m_given = false;
  contact_fit::ContactFitOptions options;
  bool json = false;
};

void Run(const FitContactArgs& args) {
  contact_fit::ContactFitOptions options = args.options;
  if (args.fix_m_given) {
    RequireFinite(args.fix_m, "--fix-m");
    if (args.fix_m < 1.0) throw UsageError("--fix-m must be >= 1");
    options.fixed_m = args.fix_m;
  }
  const contact_fit::ContactFit fit = contact_fit::FitContactApproximation(
      options, [](const std::string& line) { std::cerr << "fit-contact: " << line << std::endl; });
  if (args.json) {
    nlohmann::json j = {{"bT", fit.b_t},
                        {"mT", fit.m_t},
                        {"bM", fit.b_m},
                        {"mM", fit.m_m},
                        {"cost", fit.cost()},
                        {"cost_T", fit.cost_t},
                        {"cost_M", fit.cost_m},
                        {"samples", fit.samples},
                        {"quadrature_error", fit.quadrature.error_estimate}};
    std::cout << j.dump() << std::endl;
  } else {
    std::cerr << "b_T = " << fit.b_t << ", m_T = " << fit.m_t << ", b_M = " << fit.b_m
              << ", m_M = " << fit.m_m << ", F_T + F_M = " << fit.cost() << "\n";
  }
}

}  // namespace

void AddFitContactCommand(CLI::App& app) {
  auto args = std::make_shared<FitContactArgs>();
  CLI::App* cmd = app.add_subcommand(
      "fit-contact", "Fit the approximate friction model (eq. 17) to the integral model over D");
  cmd->add_option("--fix-m", args->fix_m, "Fix m_T = m_M to this value and fit b_T, b_M only")
      ->each([args](const std::string&) { args->fix_m_given = true; });
  cmd->add_option("--nodes-d", args->options.nodes_d, "Gauss nodes over d")->capture_default_str();
  cmd->add_option("--nodes-gamma", args->options.nodes_gamma, "Gauss nodes over gamma")
      ->capture_default_str();
  cmd->add_option("--nodes-theta", args->options.nodes_theta, "Gauss nodes over theta_s")
      ->capture_default_str();
  cmd->add_option("--quadrature-tol", args->options.quadrature_tolerance,
                  "Error target of the integral model")
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->callback([args] { Run(*args); });
}

}  // namespace billiard::cli
