#include "lcmtypes/node/node_loop.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
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
  WarnAboutTheReceiveBuffer(name, lcm_url);
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

namespace {

// The integer after `key=` in a URL's options, 0 when absent.
long UrlOption(const std::string& url, const std::string& key) {
  const std::size_t options = url.find('?');
  if (options == std::string::npos) return 0;
  std::size_t at = options;
  while (at != std::string::npos) {
    const std::size_t start = at + 1;
    if (url.compare(start, key.size() + 1, key + "=") == 0) {
      return std::strtol(url.c_str() + start + key.size() + 1, nullptr, 10);
    }
    at = url.find('&', start);
  }
  return 0;
}

long ReadLong(const char* path) {
  std::ifstream file(path);
  long value = 0;
  return file >> value ? value : 0;
}

}  // namespace

std::string ReceiveBufferAdvice(const std::string& lcm_url, long rmem_default, long rmem_max) {
  const char* from_environment = std::getenv("LCM_DEFAULT_URL");
  const std::string url = !lcm_url.empty()                                ? lcm_url
                          : from_environment && *from_environment != '\0' ? from_environment
                                                                          : kLcmDefaultUrl;
  if (url.rfind("udpm://", 0) != 0) return "";
  const long asked = UrlOption(url, "recv_buf_size");
  const std::string wanted = std::to_string(kBurstReceiveBufferBytes);
  if (asked == 0 && rmem_default < kBurstReceiveBufferBytes) {
    return "LCM URL '" + url + "' keeps the kernel's default UDP receive buffer of " +
           std::to_string(rmem_default) + " bytes, where a burst of messages overflows and is " +
           "lost unseen: add recv_buf_size=" + wanted + " to the URL (launch_scripts/" +
           "lcm_network.sh sets LCM_DEFAULT_URL so)";
  }
  if (asked > rmem_max) {
    return "LCM URL '" + url + "' asks for a " + std::to_string(asked) +
           "-byte UDP receive buffer but the kernel grants at most " + std::to_string(rmem_max) +
           " (net.core.rmem_max), where a burst of messages overflows and is lost unseen: run "
           "'sysctl -w net.core.rmem_max=" +
           std::to_string(asked) + "' as root (launch_scripts/setup.sh does it when run as root)";
  }
  return "";
}

void WarnAboutTheReceiveBuffer(const std::string& name, const std::string& lcm_url) {
  const std::string advice =
      ReceiveBufferAdvice(lcm_url, ReadLong("/proc/sys/net/core/rmem_default"),
                          ReadLong("/proc/sys/net/core/rmem_max"));
  if (!advice.empty()) std::cerr << name << ": " << advice << std::endl;
}

std::string DescribeUrl(const std::string& lcm_url) {
  return lcm_url.empty() ? "the default URL" : "'" + lcm_url + "'";
}

}  // namespace billiard::nodes
