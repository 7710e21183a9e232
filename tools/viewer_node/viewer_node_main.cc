// build/bin/viewer_node [--lcm-url URL] [--params SET] [--table NAME|FILE] [--host ADDRESS]
//                       [--port N] [--version]
#include <CLI/CLI.hpp>
#include <atomic>
#include <chrono>

#include <iostream>
#include <memory>
#include <thread>

#include "lcmtypes/node/node_command_line.h"
#include "lcmtypes/node/node_loop.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "tools/viewer_node/viewer_node.h"
// After Eigen (in viewer_node.h): httplib's <resolv.h> defines _res, a name Eigen's headers use.
#include <httplib.h>

namespace {

// Two pages and nothing else: any other path is 404, any other method 405 (httplib answers a
// request it cannot parse with 400), and no file is ever served. The state is `*view`'s, made
// once LCM is open (until then no request is served: the server listens after).
void ServeTwoPages(httplib::Server* server, std::unique_ptr<billiard::viewer::ViewState>* view) {
  server->Get("/", [view](const httplib::Request&, httplib::Response& res) {
    res.set_header("Cache-Control", "no-store");
    res.set_content(billiard::viewer::PageHtml((*view)->Json()), "text/html; charset=utf-8");
  });
  server->Get("/state.json", [view](const httplib::Request&, httplib::Response& res) {
    res.set_header("Cache-Control", "no-store");
    res.set_content((*view)->Json().dump(), "application/json");
  });
  const auto refuse = [](const httplib::Request&, httplib::Response& res) { res.status = 405; };
  server->Post(".*", refuse);
  server->Put(".*", refuse);
  server->Delete(".*", refuse);
  server->Patch(".*", refuse);
  server->Options(".*", refuse);
  server->set_payload_max_length(1 << 16);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("viewer_node: a live view of the table in a web browser, from LCM");
  billiard::nodes::OneLineErrors(app, "viewer_node");
  billiard::nodes::VersionFlag(app, "viewer_node");
  std::string lcm_url, params_name = "pool", table_name = billiard::params::kDefaultTable,
                       host = "127.0.0.1";
  int port = 8765;
  app.add_option("--lcm-url", lcm_url, "LCM URL (default: $LCM_DEFAULT_URL, else LCM's default)");
  app.add_option("--params", params_name, "Parameter set (its table's size)")->capture_default_str();
  app.add_option("--table", table_name,
                 "The table drawn (its cushions and pockets): a built-in table or a table file, "
                 "the planner's --table")
      ->capture_default_str();
  app.add_option("--host", host, "Address to listen on (127.0.0.1: this host alone)")
      ->capture_default_str();
  app.add_option("--port", port, "TCP port")->capture_default_str()->check(CLI::Range(1, 65535));
  if (auto status = billiard::nodes::ParseCommandLine(app, argc, argv)) return *status;
  billiard::physics::ModelParameters params;
  billiard::table::TableGeometry table;
  try {
    params = billiard::params::LoadParameters(params_name);
    table = billiard::table::BuildTable(billiard::params::LoadTableSpec(table_name));
  } catch (const std::invalid_argument& e) {
    std::cerr << "viewer_node: " << e.what() << std::endl;
    return 2;
  }
  httplib::Server server;
  std::unique_ptr<billiard::viewer::ViewState> view;
  ServeTwoPages(&server, &view);
  // The port before LCM: one that is taken (another viewer_node, another run's view) is an
  // output that cannot be made, a usage error said at once (docs/exit-codes.md).
  if (!server.bind_to_port(host.c_str(), port)) {
    std::cerr << "viewer_node: cannot listen on " << host << ":" << port
              << " (the port is in use, or the address is not this host's); choose another with "
                 "--port or --host"
              << std::endl;
    return 2;
  }
  std::unique_ptr<std::thread> serving;
  std::atomic<bool> listening_ended{false};
  const int status = billiard::nodes::RunNodeUntilStopped(
      "viewer_node", lcm_url, [&](lcm::LCM& lcm) -> std::function<bool()> {
        view = std::make_unique<billiard::viewer::ViewState>(lcm, params, table);
        std::cerr << "viewer_node: http://" << host << ":" << port << "/" << std::endl;
        serving = std::make_unique<std::thread>([&] {
          server.listen_after_bind();
          listening_ended = true;
        });
        // httplib's stop() does nothing until the listening loop has started, and a stop that
        // came first would leave the loop (and the join below) running for ever.
        while (!server.is_running() && !listening_ended) {
          std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        return nullptr;
      });
  server.stop();
  if (serving) serving->join();
  return status;
}
