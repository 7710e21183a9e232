#include "lcmtypes/node/node_loop.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <exception>
#include <iostream>

namespace billiard::nodes {

namespace {

volatile std::sig_atomic_t stop_requested = 0;

void RequestStop(int) { stop_requested = 1; }

}  // namespace

void StopOnSignals() {
  for (int signal_number : {SIGINT, SIGTERM}) {
    struct sigaction action {};
    action.sa_handler = RequestStop;
    sigemptyset(&action.sa_mask);
    sigaction(signal_number, &action, nullptr);
  }
}

bool StopRequested() { return stop_requested != 0; }

int HandleUntilStopped(lcm::LCM& lcm, const std::string& name, const std::function<bool()>& work) {
  bool more_work = false;
  while (!stop_requested) {
    errno = 0;
    int handled;
    while ((handled = lcm.handleTimeout(more_work ? 0 : 100)) > 0) more_work = true;
    if (handled < 0 && errno != EINTR && !stop_requested) {
      std::cerr << name << ": LCM stopped working" << (errno ? ": " : "")
                << (errno ? std::strerror(errno) : "") << std::endl;
      return 1;
    }
    more_work = work && work();
  }
  std::cerr << name << ": stopped" << std::endl;
  return 0;
}

void HandleUntilIdle(lcm::LCM& lcm, const std::function<bool()>& work) {
  bool more_work = true;
  while (more_work) {
    while (lcm.handleTimeout(0) > 0) {
    }
    more_work = work && work();
  }
  while (lcm.handleTimeout(0) > 0) {  // what the last item published
  }
}

int RunNodeUntilStopped(const std::string& name, const std::string& lcm_url,
                        const StartNode& start) {
  StopOnSignals();
  lcm::LCM lcm(lcm_url);
  if (!lcm.good()) {
    std::cerr << name << ": cannot initialise LCM with " << DescribeUrl(lcm_url) << std::endl;
    return 1;
  }
  // What the node throws is a bug: an internal failure with its reason, not an abort.
  try {
    const std::function<bool()> work = start(lcm);
    return HandleUntilStopped(lcm, name, work);
  } catch (const std::exception& e) {
    std::cerr << name << ": error: " << e.what() << std::endl;
    return 1;
  }
}

std::string DescribeUrl(const std::string& lcm_url) {
  return lcm_url.empty() ? "the default URL" : "'" + lcm_url + "'";
}

}  // namespace billiard::nodes
