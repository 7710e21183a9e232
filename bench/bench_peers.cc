// bench_peers: our RODAS4 against Boost.Odeint's rosenbrock4, SUNDIALS CVODE's BDF and the floor
// on the paper's Figs. 6-10 (peer_comparison.h says how each is measured). The comparison as
// JSON on stdout (PeerComparisonJson), progress on stderr. `billiard bench` runs the same and
// puts it in its report; this binary is the comparison alone, in seconds.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/peer_comparison.h"
#include "bench/scene_suite.h"
#include "sim/params/parameter_sets.h"

namespace {

constexpr char kProgram[] = "bench_peers";

int Run(const std::string& params_name) {
  const billiard::physics::ModelParameters p = billiard::params::LoadParameters(params_name);
  const billiard::bench::PeerComparison comparison = billiard::bench::ComparePeers(
      p, billiard::bench::ScenesOfGroup(billiard::bench::SceneSuite(p, 0, 0), "figure"),
      [](const std::string& line) { std::cerr << kProgram << ": " << line << '\n'; });
  nlohmann::json out = billiard::bench::PeerComparisonJson(comparison);
  out["params"] = billiard::params::ParameterSetLabel(p);
  std::cout << out.dump() << std::endl;
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "bench_peers: our RODAS4 against Odeint's rosenbrock4, CVODE's BDF and the floor on "
      "Figs. 6-10 (JSON on stdout)"};
  // The figures' states belong to the paper's 20 mm ball (as `billiard bench`).
  std::string params = "paper";
  app.add_option("--params", params, "paper | pool | path to a JSON parameter file")
      ->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return 0;
  } catch (const CLI::ParseError& e) {
    std::cerr << kProgram << ": " << e.what() << '\n';
    return 2;
  }
  try {
    return Run(params);
  } catch (const std::invalid_argument& e) {  // an unknown or bad parameter set
    std::cerr << kProgram << ": " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << kProgram << ": " << e.what() << '\n';
    return 1;
  }
}
