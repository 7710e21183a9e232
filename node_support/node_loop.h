// What every LCM node's main shares: stop cleanly on SIGINT or SIGTERM, and handle messages
// until then.
#pragma once

#include <lcm/lcm-cpp.hpp>
#include <string>

namespace billiard::nodes {

// Installs the SIGINT and SIGTERM handlers (without SA_RESTART, so that a signal also ends the
// wait in handleTimeout at once).
void StopOnSignals();

// Whether SIGINT or SIGTERM has arrived since StopOnSignals.
bool StopRequested();

// Handles messages until a signal asks to stop: 0 then, 1 (with the reason on stderr) if LCM
// stops working. `name` prefixes the log lines.
int HandleUntilStopped(lcm::LCM& lcm, const std::string& name);

// "the default URL" or "'URL'", for log lines.
std::string DescribeUrl(const std::string& lcm_url);

}  // namespace billiard::nodes
