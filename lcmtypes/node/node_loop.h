// What every LCM node's main shares: stop cleanly on SIGINT or SIGTERM, and handle messages
// until then.
#pragma once

#include <functional>
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
//
// `work`, when given, is the node's own work, one item per call, returning whether more is
// waiting. Every message that has arrived is handled before the next item, so that a node
// working through a queue still sees (and can refuse) what arrives meanwhile, and LCM's own
// queue never overflows unseen. It is also called at least every 100 ms when idle (a node's
// status report).
int HandleUntilStopped(lcm::LCM& lcm, const std::string& name,
                       const std::function<bool()>& work = nullptr);

// Handles every message already waiting and the work it causes (`work` as above, called until it
// returns false), until neither is left: one process on memq://, where nothing arrives that was
// not published here (in-process runs, replays, tests).
void HandleUntilIdle(lcm::LCM& lcm, const std::function<bool()>& work = nullptr);

// What a node's main does once its options are read: stops on SIGINT or SIGTERM, opens LCM at
// `lcm_url`, lets `start` make the node on it (returning the node's work, as above; the node
// lives as long as the work), and handles messages until a signal. Returns the exit status: 0
// when stopped by a signal, 1 when LCM cannot be opened or stops working or the node throws (the
// reason on stderr, prefixed by `name`).
using StartNode = std::function<std::function<bool()>(lcm::LCM& lcm)>;
int RunNodeUntilStopped(const std::string& name, const std::string& lcm_url,
                        const StartNode& start);

// The receive buffer a burst needs: a node reads one message at a time, so a burst (a queue of
// shot requests, camera frames while the estimator is busy) waits in the socket's buffer, and
// what overflows it is dropped by the kernel, unseen by LCM and the node.
inline constexpr long kBurstReceiveBufferBytes = 4 << 20;
// LCM's URL when none is given and $LCM_DEFAULT_URL is not set.
inline constexpr char kLcmDefaultUrl[] = "udpm://239.255.76.67:7667?ttl=0";

// What to do, in one line, when the UDP multicast URL `lcm_url` ("" for $LCM_DEFAULT_URL, else
// LCM's default) leaves a burst too small a receive buffer: when it asks for none (the kernel's
// default, `rmem_default` bytes) or for more than the kernel grants (`rmem_max`,
// net.core.rmem_max). "" when the buffer is large enough or the URL is not UDP multicast.
std::string ReceiveBufferAdvice(const std::string& lcm_url, long rmem_default, long rmem_max);

// ReceiveBufferAdvice for this machine (its /proc/sys/net/core), printed on stderr prefixed by
// `name` when there is any.
void WarnAboutTheReceiveBuffer(const std::string& name, const std::string& lcm_url);

// "the default URL" or "'URL'", for log lines.
std::string DescribeUrl(const std::string& lcm_url);

}  // namespace billiard::nodes
