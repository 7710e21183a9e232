// The eight-ball break: the rack of a seed on the 9-ft pool table, the cue ball sent at the apex
// ball at 7 m/s, every ball simulated event by event until all rest or drop. Prints one JSON
// object: the events by type, the balls pocketed and the cue ball's final place.
//
//   simulate_break [SEED]
#include <cmath>
#include <exception>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "billiard/sim/params/parameter_sets.h"
#include "billiard/sim/params/table_specs.h"
#include "billiard/sim/table/rack.h"
#include "billiard/sim/table/table_simulation.h"

namespace table = billiard::table;

int main(int argc, char** argv) {
  try {
    const unsigned long seed = argc > 1 ? std::stoul(argv[1]) : 1;
    // The built-in sets, compiled into the library; a path to a JSON file of the same format
    // (share/billiard/params/) works the same.
    const billiard::physics::ModelParameters params = billiard::params::LoadParameters("pool");
    const table::TableGeometry geometry =
        table::BuildTable(billiard::params::LoadTableSpec(billiard::params::kDefaultTable));
    std::vector<table::SceneBall> balls =
        table::Rack(table::RackKind::kEightBall, geometry, params.ball.radius, seed);

    // The cue ball (id 0, first) rolled straight at the apex ball (id 1 is on the foot spot).
    table::SceneBall& cue = balls.front();
    billiard::physics::BallState apex = billiard::physics::BallState::Zero();
    for (const table::SceneBall& b : balls) {
      if (b.id == 1) apex = b.state;
    }
    const double dx = apex[0] - cue.state[0], dy = apex[1] - cue.state[1];
    const double distance = std::hypot(dx, dy), speed = 7.0;
    cue.state[2] = speed * dx / distance;
    cue.state[3] = speed * dy / distance;
    // Rolling: the spin that makes the contact point's velocity zero (w = z x v / R).
    cue.state[4] = -cue.state[3] / params.ball.radius;
    cue.state[5] = cue.state[2] / params.ball.radius;

    table::TableSimulation simulation(geometry, params, balls);
    simulation.Run();

    std::map<std::string, int> events;
    for (const table::TableEvent& e : simulation.events()) ++events[table::EventTypeName(e.type)];
    std::cout << "{\"seed\":" << seed << ",\"t\":" << simulation.time()
              << ",\"at_rest\":" << (simulation.AtRest() ? "true" : "false") << ",\"events\":{";
    const char* separator = "";
    for (const auto& [type, count] : events) {
      std::cout << separator << "\"" << type << "\":" << count;
      separator = ",";
    }
    std::cout << "},\"pocketed\":[";
    separator = "";
    for (std::size_t i = 0; i < simulation.ball_count(); ++i) {
      if (!simulation.pocket(i)) continue;
      std::cout << separator << "{\"id\":" << simulation.id(i) << ",\"pocket\":\""
                << *simulation.pocket(i) << "\"}";
      separator = ",";
    }
    const billiard::physics::BallState final_cue = simulation.State(0);
    std::cout << "],\"cue_ball\":[" << final_cue[0] << "," << final_cue[1] << "]}" << std::endl;
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "simulate_break: " << e.what() << std::endl;
    return 1;
  }
}
